#include "link_record.h"

#include "db/location.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace k528::cli {

namespace fs = std::filesystem;

std::optional<TransferRecord> TransferRecord::open(const Args& args, const std::string& fileMachine,
                                                   const std::string& line) {
    try {
        const auto given = args.value("--db");
        const db::Location where = given ? db::Location::parse(*given) : db::defaultDatabaseLocation();
        if (where.isFile()) {
            std::error_code ec;
            if (!fs::exists(where.file(), ec)) {
                if (given) {
                    std::fprintf(stderr,
                                 "k528 link: no database at %s for the transfer log (create one "
                                 "with: k528 db init --db %s)\n",
                                 where.file().c_str(), where.file().c_str());
                    return std::nullopt;
                }
                fs::create_directories(where.file().parent_path(), ec);
            }
        }
        db::Database d = db::Database::open(where);
        transfer::Context c;
        c.controller = line;
        if (const auto m = args.value("--machine")) {
            if (!d.hasMachine(*m)) {
                std::fprintf(stderr, "k528 link: no machine \"%s\" in %s\n", m->c_str(),
                             where.text().c_str());
                return std::nullopt;
            }
            c.machine = *m;
        } else if (!fileMachine.empty() && d.hasMachine(fileMachine)) {
            c.machine = fileMachine;
        }
        if (!c.machine.empty())
            c.revision = d.machine(c.machine)->revision;
        return TransferRecord(std::move(d), std::move(c));
    } catch (const db::Error& e) {
        std::fprintf(stderr, "k528 link: the transfer log: %s\n", e.what());
        return std::nullopt;
    }
}

bool TransferRecord::mayPush(const link::PushPlan& plan) {
    if (where_.machine.empty())
        return true;
    try {
        const transfer::ReleaseCheck check = transfer::checkReleased(db_, where_.machine, plan);
        if (check.overridden)
            std::fprintf(stderr, "k528 link: pushing programs that are not released (machine %s "
                                 "allows it: push.unreleased)\n",
                         where_.machine.c_str());
        if (!check.allowed)
            std::fprintf(stderr, "k528 link: %s\n", check.message.c_str());
        return check.allowed;
    } catch (const db::Error& e) {
        std::fprintf(stderr, "k528 link: %s\n", e.what());
        return false;
    }
}

void TransferRecord::record(const db::TransferEntry& e) {
    try {
        const db::TransferEntry stored = db_.recordTransfer(e);
        std::fprintf(stderr, "on record: transfer %lld in %s\n", static_cast<long long>(stored.id),
                     db_.location().text().c_str());
    } catch (const db::Error& err) {
        std::fprintf(stderr, "k528 link: the transfer was not recorded: %s\n", err.what());
    }
}

void TransferRecord::recordPush(const link::RegisterMap& map, const link::PushPlan& plan,
                                const link::PushReport& report, const link::LinkError& error) {
    record(transfer::pushEntry(where_, map, plan, report, error));
}

void TransferRecord::recordPull(const link::RegisterMap& map, const link::PullResult& pulled,
                                const link::LinkError& error) {
    record(transfer::pullEntry(where_, map, pulled, error));
}

} // namespace k528::cli
