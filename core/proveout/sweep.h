// The region a rigid body sweeps moving straight from one place to another,
// in the (z, r) plane of a lathe: the convex hull of the body at both ends
// (the body is a box, so the hull is exact). r is signed here (a tool that
// crosses the spindle axis has r < 0); what it removes from a part that
// turns is the same at |r| (material.h maps it).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

namespace k528::proveout {

struct PointZR {
    double z = 0, r = 0;
};

// An axis-aligned box: z in [z0, z1], r in [r0, r1].
struct Box {
    double z0 = 0, z1 = 0, r0 = 0, r1 = 0;
    Box moved(PointZR p) const { return {z0 + p.z, z1 + p.z, r0 + p.r, r1 + p.r}; }
    // The same box on the other side of the spindle's axis.
    Box mirrored() const { return {z0, z1, -r1, -r0}; }
    // The box around this one placed at `a` and at `b` (a sweep's bounds).
    Box sweptBounds(PointZR a, PointZR b) const {
        return {z0 + std::min(a.z, b.z), z1 + std::max(a.z, b.z), r0 + std::min(a.r, b.r),
                r1 + std::max(a.r, b.r)};
    }
    // Overlaps `o` by more than eps along both axes.
    bool overlaps(const Box& o, double eps) const {
        return z1 > o.z0 + eps && z0 < o.z1 - eps && r1 > o.r0 + eps && r0 < o.r1 - eps;
    }
};

// The convex hull of box `b` placed at `from` and at `to` (b relative to the
// moving point), counter-clockwise, at most 8 vertices.
class Sweep {
public:
    Sweep(const Box& b, PointZR from, PointZR to);

    double zMin() const { return zMin_; }
    double zMax() const { return zMax_; }
    // The hull's extent in r along the line z (zMin <= z <= zMax): [lo, hi].
    // Successive calls with growing z walk the chains (amortised O(1)).
    void at(double z, double& lo, double& hi);
    void rewind() { li_ = ui_ = 0; }
    // The smallest lo and the largest hi over z in [za, zb] (a bound for a
    // block of columns).
    void range(double za, double zb, double& loMin, double& hiMax) const;

    // The hull as pieces along Z where both its lower and its upper edge are
    // straight: over [z0, z1], lo(z) = loA + loB·z and hi(z) = hiA + hiB·z.
    struct Piece {
        double z0 = 0, z1 = 0;
        double loA = 0, loB = 0, hiA = 0, hiB = 0;
    };
    std::size_t pieceCount() const { return np_; }
    const Piece& piece(std::size_t i) const { return pieces_[i]; }

    // True when the hull and the box `o` overlap with an area (more than
    // `eps` into each other along every separating direction).
    bool overlaps(const Box& o, double eps) const;
    std::size_t size() const { return n_; }
    PointZR vertex(std::size_t i) const { return v_[i]; }

private:
    void makePieces();
    std::array<PointZR, 8> v_{};
    std::size_t n_ = 0;
    // Lower and upper chains from zMin to zMax.
    std::array<PointZR, 8> lower_{}, upper_{};
    std::size_t nl_ = 0, nu_ = 0, li_ = 0, ui_ = 0;
    double zMin_ = 0, zMax_ = 0;
    std::array<Piece, 16> pieces_{};
    std::size_t np_ = 0;
};

} // namespace k528::proveout
