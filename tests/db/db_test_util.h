// Helpers of the database tests.
#pragma once

#include "db/database.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>

// QCOMPARE of std::string prints both texts when they differ.
namespace QTest {
template <> inline char* toString(const std::string& s) {
    return qstrdup(s.c_str());
}
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

inline db::WriteOptions by(const std::string& author) {
    db::WriteOptions o;
    o.author = author;
    return o;
}

} // namespace k528::testing
