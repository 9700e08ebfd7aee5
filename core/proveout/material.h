// The material of a lathe part for the prove-out: the blank (NC-200 UCG,
// core/stock) as columns along Z, each column the material between a bore
// radius and an outer radius (part coordinates, mm). A tool's sweep
// (sweep.h) is looked at column by column; a feed takes away what it
// sweeps.
//
// Columns are `resolutionMm` wide (0.01 mm, coarser for a blank longer than
// 655 mm: at most 65,536 columns); a column belongs to a sweep when its
// centre lies in the sweep's span of Z, so a face the tool left and a move
// along that face touch nothing. A column holds one interval: an outside tool
// cuts its outer radius down, a drill or a boring bar its bore open; a sweep
// buried inside the material (a collision in any case) opens the bore up to
// its top. Columns are grouped in blocks of 64 with the block's extremes, so a
// sweep through air costs a look at a few blocks.
#pragma once

#include "proveout/sweep.h"
#include "stock/stock.h"

#include <cstdint>
#include <vector>

namespace k528::proveout {

class LatheMaterial {
public:
    explicit LatheMaterial(const stock::Blank& blank, double resolutionMm = 0.01);

    // Where a sweep meets material: the column's Z and the radius at which
    // they overlap nearest to where the motion starts.
    struct Contact {
        bool touched = false;
        double z = 0, r = 0;
    };
    // False when a sweep within `bounds` cannot reach the material (it lies
    // beyond the blank's ends or its largest radius): a move through air
    // needs no sweep.
    bool mayTouch(const Box& bounds) const;
    // Does the sweep overlap the material by more than kEpsMm? (read only)
    bool touches(Sweep& s) const;
    // Takes away what the sweep covers. `dz`, `dr`: the direction of the motion
    // (for the depth of cut, measured across it). Returns what was cut.
    struct Cut {
        bool any = false;       // material was taken away
        double depthMm = 0;     // the cut's extent across the motion (a pass's depth of cut)
        double alongMm = 0;     // its extent along the motion
        double areaMm2 = 0;     // of the half profile
        // How far the body went into the material: the smaller extent (a
        // rapid along a diameter: across; a plunge: along).
        double penetrationMm() const { return depthMm < alongMm ? depthMm : alongMm; }
    };
    Cut cut(Sweep& s, double dz, double dr);

    double areaMm2() const;
    double zMin() const { return z0_; }
    double zMax() const { return z0_ + dz_ * static_cast<double>(n_); }
    double resolutionMm() const { return dz_; }
    std::size_t columns() const { return n_; }
    // The material of column i: [inner, outer] radius, empty when inner >= outer.
    double inner(std::size_t i) const { return in_[i]; }
    double outer(std::size_t i) const { return out_[i]; }
    double columnZ(std::size_t i) const { return z0_ + dz_ * (static_cast<double>(i) + 0.5); }
    // The outer diameter of the blank (for the chuck's jaws).
    double blankDiameterMm() const { return blankDiameter_; }

    static constexpr double kEpsMm = 1e-4;

private:
    static constexpr std::size_t kBlock = 64;
    // The columns whose centre lies in [za, zb]: [first, last), clipped.
    void span(double za, double zb, std::size_t& first, std::size_t& last) const;
    void refreshBlock(std::size_t b);
    // Calls f(i, u0, u1) for every column i the sweep covers that is not
    // empty and that a block's bounds do not rule out, in order of Z, with
    // [u0, u1] the radii the sweep reaches there; f returns false to stop.
    // Returns false if f stopped it.
    template <class F> bool visit(const Sweep& s, F&& f) const;

    double z0_ = 0, dz_ = 0.01;
    std::size_t n_ = 0;
    std::vector<double> in_, out_;
    std::vector<double> blockMinIn_, blockMaxOut_; // over the non-empty columns
    double blankDiameter_ = 0;
    double maxOuter_ = 0; // the largest outer radius (a cut never raises it)
};

} // namespace k528::proveout
