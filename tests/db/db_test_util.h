// Helpers of the database tests.
#pragma once

#include "db/database.h"

#include <QCryptographicHash>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>
#include <sqlite3.h>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <set>
#include <string>
#include <unistd.h>

// QCOMPARE of std::string prints both texts when they differ.
namespace QTest {
template <> inline char* toString(const std::string& s) {
    return qstrdup(s.c_str());
}
// ... and what a check found, kind and arguments.
template <> inline char* toString(const std::vector<k528::db::IntegrityProblem>& problems);
} // namespace QTest

namespace k528::testing {

// A clock that starts at 2024-05-17T08:30:00Z and advances one second a call:
// history timestamps are known in advance.
inline db::Clock steppingClock(std::int64_t start = 1715934600) {
    auto t = std::make_shared<std::int64_t>(start);
    return [t] { return (*t)++; };
}

inline db::OpenOptions testOptions(db::Clock clock = steppingClock()) {
    db::OpenOptions o;
    o.clock = std::move(clock);
    o.author = "tester";
    o.busyTimeoutMs = 20000;
    return o;
}

inline std::string fileBytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void writeBytes(const std::filesystem::path& p, const std::string& bytes) {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::filesystem::path tempPath(const QTemporaryDir& dir, const char* name) {
    return std::filesystem::path(dir.path().toStdString()) / name;
}

// A number from the environment (the length of a stress run by hand), else `fallback`.
inline double envNumber(const char* name, double fallback) {
    const QByteArray v = qgetenv(name);
    bool ok = false;
    const double d = v.toDouble(&ok);
    return ok ? d : fallback;
}

// The backend the suite runs on. CTest runs the database suite twice: on
// SQLite, and as db.*.postgresql inside `pg_virtualenv` (a throwaway
// cluster; the PG* variables point at it) with K528_TEST_BACKEND=postgresql.
inline bool onPostgres() {
    return qgetenv("K528_TEST_BACKEND") == "postgresql";
}

// Runs `sql` on the database as a program other than K528 Studio would
// (psql, or SQLite's library): "" or the error.
inline std::string runSql(const db::Location& where, const std::string& sql) {
    if (onPostgres()) {
        QProcess p;
        p.start("psql", {"-XAtq", "-v", "ON_ERROR_STOP=1", QString::fromStdString(where.uri()),
                         "-c", QString::fromStdString(sql)});
        if (!p.waitForFinished(60000) || p.exitCode() != 0)
            return "psql failed: " + p.readAllStandardError().toStdString();
        return {};
    }
    sqlite3* db = nullptr;
    if (sqlite3_open(where.file().c_str(), &db) != SQLITE_OK)
        return "cannot open";
    char* err = nullptr;
    std::string out;
    if (sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK)
        out = err ? err : "error";
    sqlite3_free(err);
    sqlite3_close(db);
    return out;
}

// What Database::checkIntegrity() found, as one line: each kind and its
// arguments, "; " between them ("" when nothing).
inline std::string integrityText(const std::vector<db::IntegrityProblem>& problems) {
    std::string s;
    for (const auto& p : problems) {
        s += (s.empty() ? "" : "; ") + std::string(db::integrityProblemName(p.kind));
        for (const std::string& a : p.args)
            s += " " + a;
    }
    return s;
}
// ... of a database: a QCOMPARE with "" prints what was found.
inline std::string integrityText(const db::Database& d) { return integrityText(d.checkIntegrity()); }

// A database of its own for one test: the SQLite file `name` in `dir`, or on
// PostgreSQL a new database (UTF-8) named after the test process, `dir` and
// `name` — the same location for the same dir and name, created empty on
// the first call.
inline db::Location testLocation(const QTemporaryDir& dir, const std::string& name) {
    const std::filesystem::path file = std::filesystem::path(dir.path().toStdString()) / name;
    if (!onPostgres())
        return db::Location(file);
    const QByteArray hash =
        QCryptographicHash::hash(QByteArray::fromStdString(file.string()), QCryptographicHash::Sha1)
            .toHex()
            .left(12);
    const std::string db = "k528t_" + std::to_string(::getpid()) + "_" + hash.toStdString();
    static std::set<std::string> made;
    if (made.insert(db).second) {
        QProcess p;
        p.start("createdb", {"--encoding=UTF8", "--template=template0", "--locale=C.UTF-8",
                             QString::fromStdString(db)});
        if (!p.waitForFinished(60000) || p.exitCode() != 0)
            qFatal("createdb %s: %s", db.c_str(), p.readAllStandardError().constData());
    }
    return db::Location::parse("postgresql:///" + db);
}

inline db::Location testLocation(const QTemporaryDir& dir, const char* name) {
    return testLocation(dir, std::string(name));
}

// A test that only SQLite's files can run (bytes, locks, permissions).
#define K528_SQLITE_ONLY()                                                                         \
    do {                                                                                           \
        if (::k528::testing::onPostgres())                                                         \
            QSKIP("a test of SQLite's files");                                                     \
    } while (false)

inline db::WriteOptions by(const std::string& author) {
    db::WriteOptions o;
    o.author = author;
    return o;
}

// Three English words in a row ("no machine named", "is not a"): a sentence a
// Russian run must not print (names such as training-lathe or
// constants.lock, options and paths are not words). What a library or the
// system said is quoted in a Russian sentence («disk I/O error»): the text
// inside «» is not ours and is left out when `quotedToo` is false.
inline bool hasEnglishSentence(QString text, bool quotedToo = true) {
    if (!quotedToo)
        text.remove(QRegularExpression(QStringLiteral("«[^«»]*»")));
    static const QRegularExpression words(QStringLiteral("(?:^|[\\s(«'\"])(?:[A-Za-z]+ ){2,}[A-Za-z]+(?=[\\s,;:)»'\"?!]|\\.(?:\\s|$)|$)"));
    return text.contains(words);
}

} // namespace k528::testing

template <> inline char* QTest::toString(const std::vector<k528::db::IntegrityProblem>& problems) {
    return qstrdup(k528::testing::integrityText(problems).c_str());
}
