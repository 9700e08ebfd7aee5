#include "link_record.h"

#include "cli_texts.h"
#include "db/location.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace k528::cli {

namespace fs = std::filesystem;

namespace {

// A database error in the command's language.
std::string said(const db::Error& e, bool ru) {
    return e.text(ru ? db::Lang::Ru : db::Lang::En);
}

} // namespace

bool TransferRecord::open(const Args& args, const std::string& line, bool ru,
                          std::optional<TransferRecord>& record) {
    const auto given = args.value("--db");
    const char* env = std::getenv("K528_DB");
    const auto machine = args.value("--machine");
    const bool required = given || (env && *env) || machine;
    std::string where = given ? *given : cliText("link.record.default-db", {}, ru);
    try {
        const db::Location loc = given ? db::Location::parse(*given) : db::defaultDatabaseLocation();
        where = loc.text();
        db::OpenOptions o;
        if (loc.isFile()) {
            std::error_code ec;
            if (!fs::exists(loc.file(), ec)) {
                if (given) {
                    std::fprintf(stderr, "%s\n", cliText("link.record.no-db", {where}, ru).c_str());
                    return false;
                }
                fs::create_directories(loc.file().parent_path(), ec);
            }
        }
        db::Database d = db::Database::open(loc, o);
        transfer::Context c;
        c.controller = line;
        if (machine) {
            const auto m = d.machine(*machine);
            if (!m) {
                std::fprintf(stderr,
                             "%s\n", cliText("link.record.no-machine", {*machine, where}, ru).c_str());
                return false;
            }
            c.machine = *machine;
            c.revision = m->revision;
        }
        record.emplace(TransferRecord(std::move(d), std::move(c), ru));
        return true;
    } catch (const db::Error& e) {
        if (required) {
            std::fprintf(stderr, "%s\n", cliText("link.record.failed", {said(e, ru)}, ru).c_str());
            return false;
        }
        std::fprintf(stderr, "%s\n", cliText("link.record.not-recorded", {where, said(e, ru)}, ru).c_str());
        return true;
    }
}

bool TransferRecord::releasedPlan(link::PushPlan& plan) {
    try {
        plan = transfer::releasedPlan(db_, where_.machine, link::k528Map(), &where_.revision);
    } catch (const db::Error& e) {
        std::fprintf(stderr, "k528 link: %s\n", said(e, ru_).c_str());
        return false;
    } catch (const transfer::PlanError& e) {
        std::fprintf(stderr, "k528 link: %s\n", e.text(ru_).c_str());
        return false;
    }
    if (plan.programs.empty())
        std::fprintf(stderr, "%s\n", cliText("link.record.no-released", {where_.machine}, ru_).c_str());
    return true;
}

bool TransferRecord::mayPush(const link::PushPlan& plan) {
    if (where_.machine.empty())
        return true;
    try {
        const transfer::ReleaseCheck check = transfer::checkReleased(db_, where_.machine, plan);
        if (check.overridden)
            std::fprintf(stderr, "%s\n", cliText("link.record.unreleased", {where_.machine}, ru_).c_str());
        if (!check.allowed)
            std::fprintf(stderr, "%s\n", cliText("link.record.refused", {check.message(ru_)}, ru_).c_str());
        return check.allowed;
    } catch (const db::Error& e) {
        std::fprintf(stderr, "%s\n", cliText("link.record.nothing-sent", {said(e, ru_)}, ru_).c_str());
        return false;
    }
}

void TransferRecord::record(const db::TransferEntry& e) {
    try {
        const db::TransferEntry stored = db_.recordTransfer(e);
        std::fprintf(stderr, "%s\n",
                     cliText("link.record.recorded", {std::to_string(stored.id), db_.location().text()}, ru_).c_str());
    } catch (const db::Error& err) {
        std::fprintf(stderr, "%s\n", cliText("link.record.not-recorded-after", {said(err, ru_)}, ru_).c_str());
    }
}

void TransferRecord::recordPush(link::Link& l, const link::PushPlan& plan,
                                const link::PushReport& report, const link::LinkError& error) {
    transfer::identify(where_, l, error);
    record(transfer::pushEntry(where_, l.map(), plan, report, error));
}

void TransferRecord::recordPull(link::Link& l, const link::PullResult& pulled,
                                const link::LinkError& error) {
    transfer::identify(where_, l, error);
    record(transfer::pullEntry(where_, l.map(), pulled, error));
}

} // namespace k528::cli
