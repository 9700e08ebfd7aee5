#include "toolpath/path_io.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace k528::toolpath {

namespace {
constexpr char kMagic[] = "K528PATH2\n";

template <class T> bool put(std::FILE* f, const T& v) {
    return std::fwrite(&v, sizeof v, 1, f) == 1;
}
template <class T> bool get(std::FILE* f, T& v) {
    return std::fread(&v, sizeof v, 1, f) == 1;
}
template <class T> bool putVec(std::FILE* f, const std::vector<T>& v) {
    const std::uint64_t n = v.size();
    return put(f, n) && (n == 0 || std::fwrite(v.data(), sizeof(T), n, f) == n);
}
template <class T> bool getVec(std::FILE* f, std::vector<T>& v, std::uint64_t max) {
    std::uint64_t n = 0;
    if (!get(f, n) || n > max)
        return false;
    v.resize(n);
    return n == 0 || std::fread(v.data(), sizeof(T), n, f) == n;
}
} // namespace

bool writePath(std::FILE* out, const ProgrammedPath& p, const std::string& ucg) {
    bool ok = std::fwrite(kMagic, 1, sizeof kMagic - 1, out) == sizeof kMagic - 1;
    ok = ok && put(out, p.program) && put(out, p.limitX) && put(out, p.limitZ) &&
         put(out, p.diameterX) && put(out, p.start) && put(out, p.end);
    const std::int32_t status = static_cast<std::int32_t>(p.run.status);
    const std::int64_t frames = p.run.frames;
    ok = ok && put(out, status) && put(out, frames);
    ok = ok && putVec(out, p.segments) && putVec(out, p.points);
    std::vector<Dwell> dw = p.dwells;
    ok = ok && putVec(out, dw) && putVec(out, p.wheel);
    std::vector<char> u(ucg.begin(), ucg.end());
    ok = ok && putVec(out, u);
    return ok && std::fflush(out) == 0;
}

bool readPath(std::FILE* in, ProgrammedPath& p, std::string& ucg, std::string& error) {
    char magic[sizeof kMagic - 1];
    if (std::fread(magic, 1, sizeof magic, in) != sizeof magic ||
        std::memcmp(magic, kMagic, sizeof magic) != 0) {
        error = "not a K528 path stream";
        return false;
    }
    std::int32_t status = 0;
    std::int64_t frames = 0;
    std::vector<char> u;
    const bool ok = get(in, p.program) && get(in, p.limitX) && get(in, p.limitZ) &&
                    get(in, p.diameterX) && get(in, p.start) && get(in, p.end) &&
                    get(in, status) && get(in, frames) &&
                    getVec(in, p.segments, 200'000'000) && getVec(in, p.points, 1'000'000'000) &&
                    getVec(in, p.dwells, 100'000'000) &&
                    getVec(in, p.wheel, 100'000'000) && getVec(in, u, 4096);
    if (!ok || status < 0 || status > static_cast<std::int32_t>(engine::PreviewStatus::Cancelled)) {
        error = "the path stream is truncated or damaged";
        return false;
    }
    for (const Segment& s : p.segments)
        if (std::uint64_t(s.firstPoint) + s.pointCount > p.points.size()) {
            error = "the path stream is damaged (points)";
            return false;
        }
    p.run.status = static_cast<engine::PreviewStatus>(status);
    p.run.frames = frames;
    ucg.assign(u.begin(), u.end());
    return true;
}

} // namespace k528::toolpath
