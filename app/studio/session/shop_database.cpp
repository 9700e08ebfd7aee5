#include "session/shop_database.h"
#include "session/database_texts.h"

#include "db/location.h"
#include "window_language.h"

#include <QCoreApplication>
#include <map>
#include <optional>
#include <sys/stat.h>

namespace k528::studio {

namespace fs = std::filesystem;

namespace {

struct Registry {
    std::mutex mutex;
    std::map<std::string, std::shared_ptr<ShopDatabase>> open;
    std::optional<db::Location> chosen;
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

ShopDatabase::ShopDatabase(db::Location location, db::Database db)
    : location_(std::move(location)), path_(db.path()), db_(std::move(db)), readOnly_(db_.readOnly()) {
    if (location_.isFile())
        identity(path_, device_, inode_);
}

ShopDatabase::~ShopDatabase() = default;

bool ShopDatabase::sameFile() const {
    if (!location_.isFile())
        return true; // a server's database
    dev_t device = 0;
    ino_t inode = 0;
    return identity(path_, device, inode) && device == device_ && inode == inode_;
}

db::Location ShopDatabase::current() {
    {
        Registry& r = registry();
        std::lock_guard lock(r.mutex);
        if (r.chosen)
            return *r.chosen;
    }
    return db::defaultDatabaseLocation();
}

void ShopDatabase::choose(const db::Location& where) {
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    r.chosen = where;
}

QString ShopDatabase::currentText() {
    try {
        return QString::fromStdString(current().text());
    } catch (const std::exception& e) {
        return QString::fromUtf8(e.what());
    }
}

std::shared_ptr<ShopDatabase> ShopDatabase::atText(const QString& location) {
    if (location.trimmed().isEmpty())
        return at(db::Location());
    return at(db::Location::parse(location.trimmed().toStdString()));
}

std::shared_ptr<ShopDatabase> ShopDatabase::at(const fs::path& given) {
    return at(given.empty() ? db::Location() : db::Location(given));
}

std::shared_ptr<ShopDatabase> ShopDatabase::at(const db::Location& given) {
    const bool byDefault = given.empty();
    db::Location where = byDefault ? current() : given;
    if (where.empty()) // $K528_DB names nothing: the user's file
        where = db::Location(db::defaultDatabasePath());
    const std::string key = where.isFile()
                                ? "sqlite:" + fs::absolute(where.file()).lexically_normal().string()
                                : where.uri();
    Registry& r = registry();
    // Opened under the registry's lock: two threads never open one database twice.
    std::lock_guard lock(r.mutex);
    if (const auto it = r.open.find(key); it != r.open.end()) {
        if (!it->second->sameFile())
            // Opening the new file beside a live connection of the old one
            // would mix them: the old -wal and -shm (named by the path) would
            // be read as the new file's. The old connection stays as it is.
            throw db::Error(db::ErrorKind::Io,
                            where.text() + ": the database file was replaced or removed while "
                                           "K528 Studio had it open; restart K528 Studio to use "
                                           "the file now at this path (nothing was written to either)");
        if (!it->second->db_.snapshotOutdated())
            return it->second;
        r.open.erase(it); // a read-only snapshot: read the file's new state afresh
    }
    if (byDefault && where.isFile()) {
        std::error_code ec;
        fs::create_directories(where.file().parent_path(), ec); // open() says why if this failed
    }
    auto shop = std::shared_ptr<ShopDatabase>(new ShopDatabase(where, db::Database::open(where)));
    r.open.emplace(key, shop);
    return shop;
}

void ShopDatabase::noteOwn(const std::string& machine, int revision) {
    std::lock_guard lock(ownMutex_);
    own_[machine].insert(revision);
}

bool ShopDatabase::isOwn(const std::string& machine, int revision) const {
    std::lock_guard lock(ownMutex_);
    const auto it = own_.find(machine);
    return it != own_.end() && it->second.count(revision) != 0;
}

bool ShopDatabase::allOwn(const std::string& machine, int from, int to) const {
    for (int r = from + 1; r <= to; ++r)
        if (!isOwn(machine, r))
            return false;
    return true;
}

bool ShopDatabase::isOpenDatabaseFile(const fs::path& file) {
    dev_t device = 0;
    ino_t inode = 0;
    if (!identity(file, device, inode))
        return false;
    Registry& r = registry();
    std::lock_guard lock(r.mutex);
    for (const auto& [key, shop] : r.open) {
        if (!shop->location_.isFile())
            continue;
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

QString databaseErrorKindText(db::ErrorKind kind) {
    // (the context of File > Database..., whose dialog says them first)
    switch (kind) {
    case db::ErrorKind::Invalid:
        return QCoreApplication::translate("k528::studio::DatabaseUi", "this is not a database location (a file path, sqlite:PATH or postgresql://HOST/NAME; "
                "a password is never written in it: use ~/.pgpass or a service file)");
    case db::ErrorKind::Io:
        return QCoreApplication::translate("k528::studio::DatabaseUi", "it cannot be reached, read or created");
    case db::ErrorKind::Foreign:
        return QCoreApplication::translate("k528::studio::DatabaseUi", "it is not a K528 Studio database");
    case db::ErrorKind::Corrupt:
        return QCoreApplication::translate("k528::studio::DatabaseUi", "it is damaged (nothing in it was changed)");
    case db::ErrorKind::TooNew:
        return QCoreApplication::translate("k528::studio::DatabaseUi", "it was written by a newer K528 Studio");
    case db::ErrorKind::Busy:
        return QCoreApplication::translate("k528::studio::DatabaseUi", "another program holds it too long");
    case db::ErrorKind::Denied:
        return QCoreApplication::translate("k528::studio::DatabaseUi", "the server refused this user");
    default:
        return QCoreApplication::translate("k528::studio::DatabaseUi", "an unexpected database error");
    }
}

namespace {

// What a Russian window says of what the library said: its own words where
// core kept them apart (SQLite speaks English only; libpq and the C library
// speak the window's language), else core's message: quoted, as said.
QString quotedDetail(const std::exception& e) {
    const auto* error = dynamic_cast<const db::Error*>(&e);
    if (error && error->detail().empty())
        return {}; // core's own English sentence: its kind says it (databaseErrorKindText)
    const std::string said = error ? error->detail() : std::string(e.what());
    return QStringLiteral("«%1»").arg(QString::fromUtf8(said.data(), static_cast<qsizetype>(said.size())).simplified());
}

// A sentence of the window's language: which database, what is wrong with
// it, and what the library said.
QString failedText(const db::Error& error, const std::exception& e) {
    const QString detail = quotedDetail(e);
    if (detail.isEmpty())
        return QCoreApplication::translate("k528::studio::ShopDatabase", "The database %1 failed: %2.")
            .arg(ShopDatabase::currentText(), databaseErrorKindText(error.kind()));
    return QCoreApplication::translate("k528::studio::ShopDatabase", "The database %1 failed: %2.\nDetails: %3")
        .arg(ShopDatabase::currentText(), databaseErrorKindText(error.kind()), detail);
}

} // namespace

// Core's and the database library's own sentence (what()) is English: an
// English window says it as it is; a Russian window says its own sentence
// around the library's words.
QString databaseErrorDetail(const std::exception& e) {
    // An error of the database's catalog is said whole in the window's
    // language (its detail is empty: quoting it gave «» in Russian).
    if (const auto* error = dynamic_cast<const db::Error*>(&e); error && !error->textId().empty())
        if (const QString text = databaseText(error->catalogText()); !text.isEmpty())
            return text;
    return inWindowLanguage(quotedDetail(e), QString::fromUtf8(e.what()));
}

QString databaseErrorText(const std::exception& e) {
    const auto* error = dynamic_cast<const db::Error*>(&e);
    if (!error)
        return QString::fromUtf8(e.what());
    // A text of the database's catalog (a read-only file, a role refusal, …):
    // its sentence in the window's language.
    if (!error->textId().empty())
        if (const QString text = databaseText(error->catalogText()); !text.isEmpty())
            return text;
    return inWindowLanguage(failedText(*error, e), QString::fromUtf8(e.what()));
}

} // namespace k528::studio
