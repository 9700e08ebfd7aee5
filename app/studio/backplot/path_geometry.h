// The path as the view draws it (no VTK, no Qt: tested and benchmarked
// headless): every straight leg of every segment in view coordinates
// (horizontal = Z, vertical = X as the machine shows it), its colour class
// and its segment; a uniform 2D grid over the legs for picking (VTK's
// pickers take 0.1–1.3 s over a million cells; this takes microseconds);
// and the screen-space level of detail. Axis-parallel legs are indexed
// apart, sorted by their constant coordinate (a grid over a million long
// overlapping passes would hold each pass in hundreds of cells).
//
// Level of detail: for a view window and its size of a pixel, the legs that
// touch the window (with a margin of half a window) are snapped to a grid of
// half a pixel, legs that collapse to a point are dropped and legs that
// snap to the same pair of grid points (and class) are drawn once. A corner
// therefore moves by at most a quarter pixel (half a grid step) and every
// corner that a pixel can show stays. The result is bounded by what the window can show, not by
// the size of the program.
#pragma once

#include "toolpath/programmed_path.h"

#include <cstdint>
#include <vector>

namespace k528::backplot {

enum class LineClass : std::uint8_t { Feed, Rapid, Outside, Oscillation };

struct ViewWindow {
    double x0 = 0, y0 = 0, x1 = 1, y1 = 1; // world (Z, X)
    double worldPerPixel = 1;
};

struct LodLines {
    std::vector<float> feed, rapid, outside, oscillation; // 4 floats a leg: x0 y0 x1 y1
    std::vector<float> points;               // programmed points (diamonds): x y
    std::size_t legsConsidered = 0;
};

class PathGeometry {
public:
    void build(const toolpath::ProgrammedPath& path);
    std::size_t legs() const { return seg_.size(); }
    std::size_t segments() const { return segCount_; }
    // Bounds of all legs: x0, x1, y0, y1.
    const double* bounds() const { return bounds_; }
    // Legs of segments [0, segmentLimit) simplified for `w`; diamonds only
    // when at most `maxPoints` distinct programmed points are visible.
    LodLines simplify(const ViewWindow& w, std::size_t segmentLimit,
                      std::size_t maxPoints = 4000) const;
    // The segment whose leg passes nearest to (x, y) within `radius`, -1 if none.
    long pick(double x, double y, double radius) const;

private:
    std::vector<float> x0_, y0_, x1_, y1_;
    std::vector<std::uint32_t> seg_;
    std::vector<LineClass> cls_;
    std::size_t segCount_ = 0;
    double bounds_[4] = {0, 1, 0, 1};
    // Pick index: axis-parallel legs (most of a positioner's) sorted by their
    // constant coordinate; the others in a uniform grid (CSR), cells of gridW_ × gridH_.
    std::vector<std::uint32_t> horizontal_, vertical_; // leg indices sorted by y / by x
    std::vector<float> hKey_, vKey_;
    int gridW_ = 1, gridH_ = 1;
    double cellW_ = 1, cellH_ = 1;
    std::vector<std::uint32_t> cellStart_, cellLegs_;
};

} // namespace k528::backplot
