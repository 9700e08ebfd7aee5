// How every benchmark reports: one line a figure, with its target and a
// verdict, e.g.
//   cli.startup_mean          1.21 ms    target <= 10 ms      ok
// bench/run collects these lines; a figure that misses its target makes the
// benchmark exit 1.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace k528::bench {

enum class Better { Lower, Higher };

struct Report {
    bool allMet = true;

    // Prints one figure and remembers whether it met the target.
    void figure(const std::string& name, double value, const std::string& unit, double target,
                Better better) {
        const bool met = better == Better::Lower ? value <= target : value >= target;
        allMet = allMet && met;
        std::printf("%-40s %12.3f %-8s target %s %g %-8s %s\n", name.c_str(), value, unit.c_str(),
                    better == Better::Lower ? "<=" : ">=", target, unit.c_str(), met ? "ok" : "MISSED");
        std::fflush(stdout);
    }
    int exitCode() const { return allMet ? 0 : 1; }
};

// Wall-clock seconds since an arbitrary point (benchmarks only; core never
// reads the clock).
inline double nowSeconds() {
    using namespace std::chrono;
    return duration<double>(steady_clock::now().time_since_epoch()).count();
}

} // namespace k528::bench
