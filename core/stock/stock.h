// The lathe blank and material removal (NC-200 manual 23.2.4).
//
// The blank is a body of revolution defined as NC-200's UCG defines it:
//   UCG,N,Z<outer length>Z<bore length>,X<outer diameter>X<bore diameter>,
//       S<outer cone angle>S<bore cone angle>,<direction>,<detail>
// The outer length is measured from the part zero (its sign gives the side);
// the bore is measured from the right face leftwards with the same sign; the
// outer generatrix leaves the point where the left face meets the outer
// diameter at the outer angle (degrees, + counter-clockwise from +Z), the
// bore's leaves the point where its bottom meets the bore diameter at the
// bore angle. A program file keeps its blank in a comment holding
// `UCG,...` (e.g. `; UCG,2,Z-100Z0,X200X0,S0S0,0,-5`).
//
// Geometry is the half profile in the (z, r) plane, r = radius ≥ 0 (X / 2
// on a diameter axis), as Boost.Geometry polygons. The tool is a rectangle
// whose cutting corner is the programmed point: it extends `widthMm` towards
// +Z and `heightMm` outwards (+r) from it (an outside turning tool held from
// above; a facing or turning cut leaves sharp steps where the tip stopped).
// A straight move sweeps the convex hull of the rectangle at both ends;
// material removal is the polygon difference. Each leg of a dogleg is swept
// on its own.
#pragma once

#include "toolpath/programmed_path.h"
#include "util/text_catalog.h"

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace k528::stock {

struct Blank {
    double outerLengthMm = -100; // signed, from the part zero
    double boreLengthMm = 0;     // from the right face leftwards, same sign
    double outerDiameterMm = 100;
    double boreDiameterMm = 0;
    double outerAngleDeg = 0, boreAngleDeg = 0;
    int direction = 0; // 0: Z horizontal
    int detail = -5;
};

// Parses "UCG,2,Z-100Z0,X200X0,S0S0,0,-5" (spaces allowed); nullopt with
// `error` set when malformed (ucgErrorText in English) and `errorId` to its
// id, which a display says in its language.
std::optional<Blank> parseUcg(std::string_view text, std::string* error = nullptr,
                              std::string* errorId = nullptr);
// The first `UCG,` of a program file's text (in a comment), if any; without
// one, the error's id is kNoUcg.
std::optional<Blank> findUcg(std::string_view fileText, std::string* error = nullptr,
                             std::string* errorId = nullptr);
inline constexpr std::string_view kNoUcg = "none";
// What can be wrong with a UCG line: its ids (errorId) with their Russian
// and English (the desktop says the same ids through its translators).
util::TextCatalog ucgTexts();
// A UCG line's error as everyone says it (`k528 prove`, the prove-out, an
// exercise's blank): the text of its id after the "UCG: " that says which
// line is wrong. `said` is the text in a display's own words (its translation).
std::string ucgErrorText(std::string_view said);
std::string ucgErrorText(std::string_view id, std::span<const std::string> args, bool russian);
std::string formatUcg(const Blank& b);

struct PointZR {
    double z = 0, r = 0;
};
using Ring = std::vector<PointZR>; // closed implicitly; outer rings clockwise (Boost.Geometry default)

struct Tool {
    double widthMm = 3;     // along +Z from the tip
    double heightMm = 1000; // along +r from the tip
};

// The region the tool sweeps moving from `a` to `b` (z, r of the tip): the
// convex hull of the tool's rectangle at both ends, clockwise.
Ring toolSweep(PointZR a, PointZR b, const Tool& tool);

// The material as plain rings: each polygon's outer ring and its holes.
struct Shape {
    struct Polygon {
        Ring outer;
        std::vector<Ring> holes;
    };
    std::vector<Polygon> polygons;
};

// Called while a path is cut with the legs done and their total; false
// stops the cut there (the stock then holds the legs cut so far).
using CutProgress = std::function<bool(std::size_t done, std::size_t total)>;

// The material: a set of polygons (outer ring + holes) in (z, r).
class Stock {
public:
    explicit Stock(const Blank& b);
    // Removes what the tool sweeps moving from `a` to `b` (z, r of the tip).
    void cut(PointZR a, PointZR b, const Tool& tool);
    // Cuts along a whole programmed path (every segment's legs). A leg the
    // path repeats exactly (an endless loop's second pass) is cut once: the
    // material it sweeps is gone after the first. Returns false when
    // `progress` stopped it.
    bool cutPath(const toolpath::ProgrammedPath& path, const Tool& tool,
                 const CutProgress& progress = {});

    double areaMm2() const; // of the half profile
    // Outer rings and holes: polygon i has outer(i) and holes(i).
    std::size_t polygons() const;
    Ring outer(std::size_t i) const;
    std::vector<Ring> holes(std::size_t i) const;
    Shape shape() const;
    std::size_t moves() const { return moves_; }
    const Blank& blank() const { return blank_; }

private:
    struct Impl;
    std::shared_ptr<Impl> d_;
    Blank blank_;
    std::size_t moves_ = 0;
};

} // namespace k528::stock
