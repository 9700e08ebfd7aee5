// The shop's database on PostgreSQL beside SQLite, on the same data:
// a shop of 50 full machines (152 C, 269 R presets, 99 programs, 99
// messages, 80 PLC texts) with 200 revisions each, every revision a change
// of C022 and of one R-parameter (the history of one constant then has 200
// entries). Built on SQLite through the API, copied into PostgreSQL with
// Database::copyTo (k528 db copy). On a connection kept open, as the studio
// and a server process keep theirs:
//   - open a machine (Database::loadMachine)                       <= 20 ms
//   - db set: one constant as a new revision (Database::applyEdit) <= 30 ms
//   - history of one constant over 200 revisions (history(C022))   <= 20 ms
// each on PostgreSQL within 2x of SQLite (the ratio's target).
// For information: a new connection plus the load (SQLite runs its
// integrity check over the whole file at every open), the copy's time.
//
// The PostgreSQL server is a throwaway cluster of the benchmark's own: run
// without one, the program runs itself again inside `pg_virtualenv -t`
// (Debian's postgresql-common), which starts the server in a temporary
// folder, sets the PG* variables and removes it afterwards.
// Arguments: [MACHINES] [REVISIONS] [RUNS] (default 50 200 41).
#include "db/database.h"
#include "random_machine.h"
#include "report.h"
#include "stats.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

using namespace k528;
namespace fs = std::filesystem;

namespace {

std::string machineName(int i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "m%02d", i);
    return buf;
}

struct Figures {
    double load = 0, set = 0, history = 0, openLoad = 0;
};

// The three operations on one kept connection, then open + load anew.
Figures measure(const db::Location& where, int machines, int revisions, int runs) {
    Figures f;
    std::vector<double> load, set, history, openLoad;
    db::Database d = db::Database::open(where);
    for (int i = 0; i < runs; ++i) {
        const std::string name = machineName((i * 7) % machines);
        double t0 = bench::nowSeconds();
        const profile::MachineProfile p = d.loadMachine(name);
        load.push_back((bench::nowSeconds() - t0) * 1000.0);
        if (p.programs.size() != 99)
            std::exit(2);

        t0 = bench::nowSeconds();
        const auto h = d.history(name, std::string("C022"));
        history.push_back((bench::nowSeconds() - t0) * 1000.0);
        if (static_cast<int>(h.size()) < revisions) {
            std::fprintf(stderr, "the history of C022 of %s has %zu entries, not %d\n",
                         name.c_str(), h.size(), revisions);
            std::exit(2);
        }
    }
    // db set on the machines the history is not read from.
    for (int i = 0; i < runs; ++i) {
        const std::string name = machineName(machines - 1 - (i % machines));
        db::Edit e;
        e.c[23] = 1500 + i;
        const double t0 = bench::nowSeconds();
        const auto r = d.applyEdit(name, e);
        set.push_back((bench::nowSeconds() - t0) * 1000.0);
        if (!r.changed)
            std::exit(2);
    }
    for (int i = 0; i < std::max(5, runs / 4); ++i) {
        const double t0 = bench::nowSeconds();
        db::Database again = db::Database::open(where);
        const profile::MachineProfile p = again.loadMachine(machineName(i % machines));
        openLoad.push_back((bench::nowSeconds() - t0) * 1000.0);
        if (p.programs.size() != 99)
            std::exit(2);
    }
    return {bench::median(load), bench::median(set), bench::median(history), bench::median(openLoad)};
}

int runInCluster(int argc, char** argv) {
    if (std::getenv("K528_BENCH_IN_CLUSTER"))
        return -1;
    setenv("K528_BENCH_IN_CLUSTER", "1", 1);
    std::vector<char*> args{const_cast<char*>("pg_virtualenv"), const_cast<char*>("-t")};
    const std::string self = fs::canonical("/proc/self/exe").string();
    args.push_back(const_cast<char*>(self.c_str()));
    for (int i = 1; i < argc; ++i)
        args.push_back(argv[i]);
    args.push_back(nullptr);
    std::fflush(stdout);
    execvp("pg_virtualenv", args.data());
    std::perror("pg_virtualenv (Debian: postgresql-common and postgresql)");
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    if (const int rc = runInCluster(argc, argv); rc >= 0)
        return rc;
    const int machines = argc > 1 ? std::atoi(argv[1]) : 50;
    const int revisions = argc > 2 ? std::atoi(argv[2]) : 200;
    const int runs = argc > 3 ? std::atoi(argv[3]) : 41;
    if (machines < 1 || revisions < 2 || runs < 1)
        return 2;

    char tmpl[] = "/tmp/k528-bench-shop-XXXXXX";
    if (!mkdtemp(tmpl)) {
        std::perror("mkdtemp");
        return 2;
    }
    const fs::path dir = tmpl;
    const db::Location lite(dir / "shop.db");
    const double b0 = bench::nowSeconds();
    {
        db::OpenOptions o;
        o.seedBuiltins = false;
        db::Database d = db::Database::open(lite, o);
        for (int m = 0; m < machines; ++m) {
            const std::string name = machineName(m);
            d.createMachine(testing::randomMachine(static_cast<std::uint32_t>(100 + m), name));
            for (int r = 2; r <= revisions; ++r) {
                db::Edit e;
                e.c[22] = 1000 + r;
                e.r[r % 200] = r;
                d.applyEdit(name, e);
            }
        }
    }
    const double built = bench::nowSeconds() - b0;

    if (std::system("createdb --encoding=UTF8 --template=template0 k528bench") != 0) {
        std::fprintf(stderr, "createdb k528bench failed\n");
        return 2;
    }
    const db::Location pg = db::Location::parse("postgresql:///k528bench");
    const double c0 = bench::nowSeconds();
    db::CopyReport copied;
    {
        const db::Database d = db::Database::open(lite);
        copied = d.copyTo(pg);
    }
    const double copySeconds = bench::nowSeconds() - c0;
    std::error_code ec;
    std::printf("shop: %d machines x %d revisions (full machines), SQLite file %.1f MB built in "
                "%.1f s; copied to PostgreSQL (%lld rows, one transaction) in %.1f s\n",
                machines, revisions, static_cast<double>(fs::file_size(dir / "shop.db", ec)) / 1e6,
                built, static_cast<long long>(copied.rows), copySeconds);

    const Figures s = measure(lite, machines, revisions, runs);
    const Figures p = measure(pg, machines, revisions, runs);

    bench::Report report;
    report.figure("shop.pg_open_machine_median", p.load, "ms", 20, bench::Better::Lower);
    report.figure("shop.pg_db_set_median", p.set, "ms", 30, bench::Better::Lower);
    report.figure("shop.pg_history_200_median", p.history, "ms", 20, bench::Better::Lower);
    report.figure("shop.pg_vs_sqlite_open_machine", p.load / s.load, "x", 2, bench::Better::Lower);
    report.figure("shop.pg_vs_sqlite_db_set", p.set / s.set, "x", 2, bench::Better::Lower);
    report.figure("shop.pg_vs_sqlite_history_200", p.history / s.history, "x", 2,
                  bench::Better::Lower);
    std::printf("info: SQLite: open machine %.2f ms, db set %.2f ms, history %.2f ms\n", s.load,
                s.set, s.history);
    std::printf("info: a new connection + load: PostgreSQL %.2f ms, SQLite %.2f ms (its "
                "integrity check reads the whole file)\n",
                p.openLoad, s.openLoad);
    fs::remove_all(dir, ec);
    return report.exitCode();
}
