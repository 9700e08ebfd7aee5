// A studio-like process for tests/db/test_stress.cpp: it uses the shop's
// database as the desktop does — the process's one connection
// (studio::ShopDatabase), kept open, the constants dock's revisions
// (MachineStore::keep), the message history's batches (db::MessageLog) —
// and, now and then, a short extra connection of its own as a worker or the
// engine hook does (db::loadProfile). It runs until --seconds have passed
// and prints what it wrote:
//
//   db_stress_peer --db PATH --machine grinder-205 --r 150 --seconds 10
//   -> "revisions 412 last 412 messages 8240 extra-opens 41 busy 0 deleted 0
//       failures 0 conflicts 3"
// A change refused because `k528 db set` made a newer revision meanwhile
// (conflicts) is applied again on top, as the user does in the studio.
//
// R<r> gets 1, 2, 3, … (one revision each: every value differs from the last).
// Before each write it checks /proc/self/fd for a descriptor of the database,
// its -wal or -shm that is "(deleted)": the sign of another process having
// removed a live -wal. Exit 0 when every write succeeded or was only busy
// (counted), 1 when something else failed, 2 for a deleted descriptor.
#include "constants/machine_store.h"
#include "db/database.h"
#include "db/location.h"
#include "db/message_log.h"
#include "profile/builtin.h"
#include "session/shop_database.h"

#include <QCoreApplication>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

using namespace k528;
namespace fs = std::filesystem;

namespace {

// Descriptors of this process that point at a removed file of the database.
int deletedDescriptors(const std::string& dbPath) {
    int found = 0;
    DIR* d = opendir("/proc/self/fd");
    if (!d)
        return 0;
    while (const dirent* e = readdir(d)) {
        if (e->d_name[0] == '.')
            continue;
        char target[4096];
        const std::string link = std::string("/proc/self/fd/") + e->d_name;
        const ssize_t n = readlink(link.c_str(), target, sizeof target - 1);
        if (n <= 0)
            continue;
        target[n] = '\0';
        const std::string t = target;
        if (t.rfind(dbPath, 0) == 0 && t.find("(deleted)") != std::string::npos) {
            std::fprintf(stderr, "peer %d: %s -> %s\n", static_cast<int>(getpid()), link.c_str(),
                         target);
            ++found;
        }
    }
    closedir(d);
    return found;
}

} // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    std::string dbPath, machine = "grinder-205";
    int r = 150;
    double seconds = 10;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--db")
            dbPath = v;
        else if (k == "--machine")
            machine = v;
        else if (k == "--r")
            r = std::atoi(v.c_str());
        else if (k == "--seconds")
            seconds = std::atof(v.c_str());
    }
    if (dbPath.empty()) {
        std::fprintf(stderr, "usage: db_stress_peer --db PATH [--machine NAME] [--r N] [--seconds S]\n");
        return 1;
    }
    // The desktop's default location is this file (ShopDatabase::at(), MachineStore).
    setenv("K528_DB", dbPath.c_str(), 1);
    const std::string absolute = fs::absolute(dbPath).string();

    int revisions = 0, last = 0, busy = 0, extraOpens = 0, deleted = 0, failures = 0, conflicts = 0;
    long messages = 0;
    try {
        const auto shop = studio::ShopDatabase::at();
        const profile::MachineProfile base =
            shop->use([&](db::Database& d) { return d.loadMachine(machine); });
        const studio::MachineStore store(base);
        const std::int64_t run = shop->useLog([&](db::MessageLog& log) {
            return log.beginRun(machine, 1715934600000, "stress-peer");
        });
        std::int64_t seq = 0;
        const auto end = std::chrono::steady_clock::now() +
                         std::chrono::milliseconds(static_cast<long>(seconds * 1000));
        for (int i = 1; std::chrono::steady_clock::now() < end; ++i) {
            deleted += deletedDescriptors(absolute);
            // A revision from the constants dock.
            db::Edit e;
            e.r[r] = last + 1;
            const QString note = QString("stress %1").arg(last + 1);
            studio::MachineStore::Kept k = store.keep(e, note);
            if (k.revision == 0 && k.conflict) {
                // `k528 db set` made a newer revision since this window read
                // the machine: refused, and the user applies the change again
                // on top (the choice the constants dock's refusal offers).
                ++conflicts;
                k = store.keep(e, note, true);
            }
            if (k.revision > 0) {
                ++revisions;
                ++last;
            } else if (k.error.contains("busy") || k.error.contains("locked")) {
                ++busy;
            } else {
                std::fprintf(stderr, "peer %d: keep failed: %s\n", static_cast<int>(getpid()),
                             qPrintable(k.error));
                ++failures;
            }
            // A batch of the message history: 20 messages raised and cleared.
            std::vector<db::MessageEvent> events;
            for (int m = 0; m < 20; ++m) {
                db::MessageEvent raised;
                raised.kind = db::MessageEvent::Kind::Raised;
                raised.seq = ++seq;
                raised.machineMs = seq * 10;
                raised.dayMs = 1715934600000 + seq * 10;
                raised.message.source = db::MessageSource::Positioner;
                raised.message.number = 37;
                raised.message.text = "37. Ошибка N ДОС";
                events.push_back(raised);
                db::MessageEvent cleared;
                cleared.kind = db::MessageEvent::Kind::Cleared;
                cleared.seq = seq;
                cleared.machineMs = seq * 10 + 5;
                events.push_back(cleared);
            }
            try {
                shop->useLog([&](db::MessageLog& log) { log.write(run, events); });
                messages += 20;
            } catch (const db::Error& x) {
                if (x.kind() == db::ErrorKind::Busy) {
                    ++busy;
                    seq -= 20;
                } else {
                    std::fprintf(stderr, "peer %d: messages failed: %s\n", static_cast<int>(getpid()), x.what());
                    ++failures;
                    seq -= 20;
                }
            }
            // Now and then a short connection of its own beside the kept one.
            if (i % 5 == 0) {
                const profile::MachineProfile p = db::loadProfile(machine, dbPath);
                if (p.r.count(r) && p.r.at(r) > last) {
                    std::fprintf(stderr, "peer %d: R%d is %lld, above the %d written\n",
                                 static_cast<int>(getpid()), r, static_cast<long long>(p.r.at(r)), last);
                    ++failures;
                }
                ++extraOpens;
            }
        }
        deleted += deletedDescriptors(absolute);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "peer %d: %s\n", static_cast<int>(getpid()), e.what());
        ++failures;
    }
    std::printf("revisions %d last %d messages %ld extra-opens %d busy %d deleted %d failures %d conflicts %d\n",
                revisions, last, messages, extraOpens, busy, deleted, failures, conflicts);
    std::fflush(stdout);
    return deleted ? 2 : failures ? 1 : 0;
}
