#include "backplot/path_geometry.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace k528::backplot {

void PathGeometry::build(const toolpath::ProgrammedPath& path) {
    x0_.clear(), y0_.clear(), x1_.clear(), y1_.clear(), seg_.clear(), cls_.clear();
    segCount_ = path.segments.size();
    double bx0 = 1e300, bx1 = -1e300, by0 = 1e300, by1 = -1e300;
    for (std::size_t i = 0; i < path.segments.size(); ++i) {
        const toolpath::Segment& s = path.segments[i];
        const LineClass c = s.outside                                  ? LineClass::Outside
                            : s.kind == toolpath::SegmentKind::Rapid ? LineClass::Rapid
                            : s.kind == toolpath::SegmentKind::Oscillation ? LineClass::Oscillation
                                                                       : LineClass::Feed;
        const toolpath::PointMm* p = path.pointsOf(s);
        for (int k = 1; k < s.pointCount; ++k) {
            x0_.push_back(static_cast<float>(p[k - 1].z));
            y0_.push_back(static_cast<float>(p[k - 1].x));
            x1_.push_back(static_cast<float>(p[k].z));
            y1_.push_back(static_cast<float>(p[k].x));
            seg_.push_back(static_cast<std::uint32_t>(i));
            cls_.push_back(c);
            bx0 = std::min({bx0, p[k - 1].z, p[k].z});
            bx1 = std::max({bx1, p[k - 1].z, p[k].z});
            by0 = std::min({by0, p[k - 1].x, p[k].x});
            by1 = std::max({by1, p[k - 1].x, p[k].x});
        }
    }
    if (seg_.empty()) {
        bx0 = path.start.z - 1, bx1 = path.start.z + 1, by0 = path.start.x - 1, by1 = path.start.x + 1;
    }
    if (bx1 - bx0 < 1e-6)
        bx0 -= 0.5, bx1 += 0.5;
    if (by1 - by0 < 1e-6)
        by0 -= 0.5, by1 += 0.5;
    bounds_[0] = bx0, bounds_[1] = bx1, bounds_[2] = by0, bounds_[3] = by1;

    // Axis-parallel legs: sorted lists; the rest: the grid.
    horizontal_.clear(), vertical_.clear();
    std::vector<std::uint32_t> others;
    for (std::size_t i = 0; i < seg_.size(); ++i) {
        if (y0_[i] == y1_[i])
            horizontal_.push_back(static_cast<std::uint32_t>(i));
        else if (x0_[i] == x1_[i])
            vertical_.push_back(static_cast<std::uint32_t>(i));
        else
            others.push_back(static_cast<std::uint32_t>(i));
    }
    std::sort(horizontal_.begin(), horizontal_.end(),
              [&](std::uint32_t a, std::uint32_t b) { return y0_[a] < y0_[b]; });
    std::sort(vertical_.begin(), vertical_.end(),
              [&](std::uint32_t a, std::uint32_t b) { return x0_[a] < x0_[b]; });
    hKey_.resize(horizontal_.size());
    vKey_.resize(vertical_.size());
    for (std::size_t k = 0; k < horizontal_.size(); ++k)
        hKey_[k] = y0_[horizontal_[k]];
    for (std::size_t k = 0; k < vertical_.size(); ++k)
        vKey_[k] = x0_[vertical_[k]];
    // Grid: about 4 of the other legs a cell, at most 256 × 256 cells.
    const double n = static_cast<double>(std::max<std::size_t>(others.size(), 1));
    const double aspect = (bx1 - bx0) / (by1 - by0);
    const double cells = std::min(n / 4 + 1, 256.0 * 256.0);
    gridW_ = std::clamp(static_cast<int>(std::sqrt(cells * aspect)), 1, 256);
    gridH_ = std::clamp(static_cast<int>(cells / gridW_), 1, 256);
    cellW_ = (bx1 - bx0) / gridW_;
    cellH_ = (by1 - by0) / gridH_;
    // The cells a leg passes through (stepping half a cell along it).
    const auto forCells = [&](std::size_t i, auto&& f) {
        const double ax = (x0_[i] - bx0) / cellW_, ay = (y0_[i] - by0) / cellH_;
        const double dx = (x1_[i] - bx0) / cellW_ - ax, dy = (y1_[i] - by0) / cellH_ - ay;
        const int steps = static_cast<int>(std::ceil(std::max(std::fabs(dx), std::fabs(dy)) * 2)) + 1;
        long last = -1;
        for (int k = 0; k <= steps; ++k) {
            const double t = static_cast<double>(k) / steps;
            const int cx = std::clamp(static_cast<int>(ax + t * dx), 0, gridW_ - 1);
            const int cy = std::clamp(static_cast<int>(ay + t * dy), 0, gridH_ - 1);
            const long c = static_cast<long>(cy) * gridW_ + cx;
            if (c != last)
                f(static_cast<std::size_t>(c));
            last = c;
        }
    };
    cellStart_.assign(static_cast<std::size_t>(gridW_) * gridH_ + 1, 0);
    for (std::uint32_t i : others)
        forCells(i, [&](std::size_t c) { ++cellStart_[c + 1]; });
    for (std::size_t k = 1; k < cellStart_.size(); ++k)
        cellStart_[k] += cellStart_[k - 1];
    cellLegs_.assign(cellStart_.back(), 0);
    std::vector<std::uint32_t> fill(cellStart_.begin(), cellStart_.end() - 1);
    for (std::uint32_t i : others)
        forCells(i, [&](std::size_t c) { cellLegs_[fill[c]++] = i; });
}

namespace {
struct KeyHash {
    std::size_t operator()(const std::uint64_t& k) const {
        std::uint64_t x = k * 0x9E3779B97F4A7C15ull;
        return static_cast<std::size_t>(x ^ (x >> 29));
    }
};
double segDist(double px, double py, double ax, double ay, double bx, double by) {
    const double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    const double qx = ax + t * dx - px, qy = ay + t * dy - py;
    return std::sqrt(qx * qx + qy * qy);
}
} // namespace

LodLines PathGeometry::simplify(const ViewWindow& w, std::size_t segmentLimit,
                                std::size_t maxPoints) const {
    LodLines out;
    const double q = std::max(w.worldPerPixel / 2, 1e-9); // half a pixel
    const double mx = (w.x1 - w.x0) / 2, my = (w.y1 - w.y0) / 2;
    const double wx0 = w.x0 - mx, wx1 = w.x1 + mx, wy0 = w.y0 - my, wy1 = w.y1 + my;
    // Grid coordinates relative to the window, 21 bits each (up to 1M half pixels).
    const auto gx = [&](double x) { return std::llround((x - wx0) / q); };
    const auto gy = [&](double y) { return std::llround((y - wy0) / q); };
    constexpr long long kMax = (1 << 20) - 1;
    std::unordered_set<std::uint64_t, KeyHash> seen, points;
    seen.reserve(1 << 16);
    bool withPoints = true;
    for (std::size_t i = 0; i < seg_.size() && seg_[i] < segmentLimit; ++i) {
        const double ax = x0_[i], ay = y0_[i], bx = x1_[i], by = y1_[i];
        if (std::max(ax, bx) < wx0 || std::min(ax, bx) > wx1 || std::max(ay, by) < wy0 ||
            std::min(ay, by) > wy1)
            continue;
        ++out.legsConsidered;
        long long a1 = gx(ax), a2 = gy(ay), b1 = gx(bx), b2 = gy(by);
        const auto clampG = [&](long long v) { return std::clamp(v, 0LL, kMax); };
        const bool clipped = a1 < 0 || a1 > kMax || a2 < 0 || a2 > kMax || b1 < 0 || b1 > kMax ||
                             b2 < 0 || b2 > kMax;
        if (withPoints && !clipped) {
            points.insert((static_cast<std::uint64_t>(b1) << 21) | static_cast<std::uint64_t>(b2));
            if (points.size() > maxPoints)
                withPoints = false;
        }
        if (a1 == b1 && a2 == b2)
            continue; // shorter than a quarter pixel
        std::uint64_t pa = (static_cast<std::uint64_t>(clampG(a1)) << 21) | clampG(a2);
        std::uint64_t pb = (static_cast<std::uint64_t>(clampG(b1)) << 21) | clampG(b2);
        if (pa > pb)
            std::swap(pa, pb);
        const std::uint64_t key =
            (pa * 0x100000001B3ull) ^ (pb + (static_cast<std::uint64_t>(cls_[i]) << 62));
        if (!clipped && !seen.insert(key).second)
            continue;
        std::vector<float>& dst = cls_[i] == LineClass::Outside ? out.outside
                                  : cls_[i] == LineClass::Rapid ? out.rapid
                                  : cls_[i] == LineClass::Oscillation ? out.oscillation
                                                                : out.feed;
        if (clipped) {
            dst.insert(dst.end(), {static_cast<float>(ax), static_cast<float>(ay),
                                   static_cast<float>(bx), static_cast<float>(by)});
        } else {
            dst.insert(dst.end(), {static_cast<float>(wx0 + a1 * q), static_cast<float>(wy0 + a2 * q),
                                   static_cast<float>(wx0 + b1 * q), static_cast<float>(wy0 + b2 * q)});
        }
    }
    if (withPoints)
        for (std::uint64_t k : points) {
            out.points.push_back(static_cast<float>(wx0 + static_cast<double>(k >> 21) * q));
            out.points.push_back(static_cast<float>(wy0 + static_cast<double>(k & kMax) * q));
        }
    return out;
}

long PathGeometry::pick(double x, double y, double radius) const {
    if (seg_.empty())
        return -1;
    const int cx0 = std::clamp(static_cast<int>((x - radius - bounds_[0]) / cellW_), 0, gridW_ - 1);
    const int cx1 = std::clamp(static_cast<int>((x + radius - bounds_[0]) / cellW_), 0, gridW_ - 1);
    const int cy0 = std::clamp(static_cast<int>((y - radius - bounds_[2]) / cellH_), 0, gridH_ - 1);
    const int cy1 = std::clamp(static_cast<int>((y + radius - bounds_[2]) / cellH_), 0, gridH_ - 1);
    if (x + radius < bounds_[0] || x - radius > bounds_[1] || y + radius < bounds_[2] ||
        y - radius > bounds_[3])
        return -1;
    double best = radius;
    long found = -1;
    const auto consider = [&](std::uint32_t i) {
        const double d = segDist(x, y, x0_[i], y0_[i], x1_[i], y1_[i]);
        // Nearest; of equals the later segment (drawn on top).
        if (d <= best && (found < 0 || d < best || seg_[i] > static_cast<std::uint32_t>(found))) {
            best = d;
            found = seg_[i];
        }
    };
    const auto band = [&](const std::vector<float>& key, const std::vector<std::uint32_t>& legs,
                          double at) {
        auto it = std::lower_bound(key.begin(), key.end(), static_cast<float>(at - radius));
        for (auto k = static_cast<std::size_t>(it - key.begin()); k < key.size() && key[k] <= at + radius; ++k)
            consider(legs[k]);
    };
    band(hKey_, horizontal_, y);
    band(vKey_, vertical_, x);
    for (int cy = cy0; cy <= cy1; ++cy)
        for (int cx = cx0; cx <= cx1; ++cx) {
            const std::size_t c = static_cast<std::size_t>(cy) * gridW_ + cx;
            for (std::uint32_t k = cellStart_[c]; k < cellStart_[c + 1]; ++k)
                consider(cellLegs_[k]);
        }
    return found;
}

} // namespace k528::backplot
