#include "session/shop_database.h"

#include "db/location.h"

#include <QCoreApplication>
#include <map>
#include <sys/stat.h>

namespace k528::studio {

namespace fs = std::filesystem;

namespace {

struct Registry {
    std::mutex mutex;
    std::map<std::string, std::shared_ptr<ShopDatabase>> open;
};

Registry& registry() {
    static Registry r;
    return r;
}

bool identity(const fs::path& path, dev_t& device, ino_t& inode) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        return false;
    device = st.st_dev;
    inode = st.st_ino;
    return true;
}

} // namespace

ShopDatabase::ShopDatabase(fs::path path, db::Database db)
    : path_(std::move(path)), db_(std::move(db)), readOnly_(db_.readOnly()) {
    identity(path_, device_, inode_);
}

ShopDatabase::~ShopDatabase() = default;

bool ShopDatabase::sameFile() const {
    dev_t device = 0;
    ino_t inode = 0;
    return identity(path_, device, inode) && device == device_ && inode == inode_;
}

std::shared_ptr<ShopDatabase> ShopDatabase::at(const fs::path& given) {
    const fs::path path = given.empty() ? db::defaultDatabasePath() : given;
    const std::string key = fs::absolute(path).lexically_normal().string();
    Registry& r = registry();
    // Opened under the registry's lock: two threads never open one file twice.
    std::lock_guard lock(r.mutex);
    if (const auto it = r.open.find(key); it != r.open.end()) {
        if (!it->second->sameFile())
            // Opening the new file beside a live connection of the old one
            // would mix them: the old -wal and -shm (named by the path) would
            // be read as the new file's. The old connection stays as it is.
            throw db::Error(db::ErrorKind::Io,
                            path.string() + ": the database file was replaced or removed while "
                                            "K528 Studio had it open; restart K528 Studio to use "
                                            "the file now at this path (nothing was written to either)");
        if (!it->second->db_.snapshotOutdated())
            return it->second;
        r.open.erase(it); // a read-only snapshot: read the file's new state afresh
    }
    if (given.empty()) {
        std::error_code ec;
        fs::create_directories(path.parent_path(), ec); // open() says why if this failed
    }
    auto shop = std::shared_ptr<ShopDatabase>(new ShopDatabase(path, db::Database::open(path)));
    r.open.emplace(key, shop);
    return shop;
}

bool ShopDatabase::isOpenDatabaseFile(const fs::path& file) {
    dev_t device = 0;
    ino_t inode = 0;
    if (!identity(file, device, inode))
        return false;
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    for (const auto& [key, shop] : r.open) {
        if (shop->device_ == device && shop->inode_ == inode)
            return true;
        for (const char* suffix : {"-wal", "-shm", "-journal"}) {
            dev_t d = 0;
            ino_t i = 0;
            if (identity(shop->path_.string() + suffix, d, i) && d == device && i == inode)
                return true;
        }
    }
    return false;
}

QString databaseErrorText(const std::exception& e) {
    const auto* r = dynamic_cast<const db::ReadOnlyError*>(&e);
    if (!r)
        return QString::fromUtf8(e.what());
    // By db::ReadOnlyReason and db::ReadOnlyRefusal.
    static const char* const kReasons[] = {
        QT_TRANSLATE_NOOP("k528::studio::ShopDatabase", "permission denied"),
        QT_TRANSLATE_NOOP("k528::studio::ShopDatabase", "permission denied"),
        QT_TRANSLATE_NOOP("k528::studio::ShopDatabase", "no permission to create files in its folder"),
        QT_TRANSLATE_NOOP("k528::studio::ShopDatabase", "read-only file system"),
        QT_TRANSLATE_NOOP("k528::studio::ShopDatabase", "opened read-only"),
    };
    static const char* const kTexts[] = {
        QT_TRANSLATE_NOOP("k528::studio::ShopDatabase",
                          "The database is read-only: %1 (%2); nothing was written."),
        QT_TRANSLATE_NOOP("k528::studio::ShopDatabase",
                          "The database is read-only: %1 (%2); a new database cannot be created there."),
        QT_TRANSLATE_NOOP("k528::studio::ShopDatabase",
                          "The database is read-only: %1 (%2); its schema is older than this "
                          "program's and cannot be upgraded."),
        QT_TRANSLATE_NOOP("k528::studio::ShopDatabase",
                          "The database is read-only: %1 (%2); it has an unfinished transaction that "
                          "only a user who may write the file can roll back."),
    };
    const auto translated = [](const char* s) { return QCoreApplication::translate("k528::studio::ShopDatabase", s); };
    return translated(kTexts[static_cast<int>(r->refusal())])
        .arg(QString::fromStdString(r->path().string()), translated(kReasons[static_cast<int>(r->reason())]));
}

} // namespace k528::studio
