// The figures of a benchmark's repeated timings: a median and a percentile.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace k528::bench {

// The `percent`th percentile of `v`: the value at index count × percent / 100
// once sorted (the last one at most).
inline double percentile(std::vector<double> v, int percent) {
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, v.size() * static_cast<std::size_t>(percent) / 100)];
}
// The middle value (the upper one of an even count).
inline double median(std::vector<double> v) { return percentile(std::move(v), 50); }

} // namespace k528::bench
