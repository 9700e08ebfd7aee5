// Boost.Geometry types of the half profile (z, r): the material along an
// actual path (actual.h) and the grade's comparison with the drawing
// (core/training). Not part of the modules' interfaces: their headers speak
// in stock::Ring and Shape. Polygons clockwise and closed, Boost.Geometry's
// defaults.
#pragma once

#include "proveout/actual.h"
#include "stock/stock.h"

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>

#include <vector>

namespace k528::proveout::geo {

namespace bg = boost::geometry;
using P = bg::model::d2::point_xy<double>; // x = z, y = r
using Poly = bg::model::polygon<P>;
using Multi = bg::model::multi_polygon<Poly>;
using Box = bg::model::box<P>;
using Line = bg::model::linestring<P>;

inline Poly rect(double z0, double z1, double r0, double r1) {
    Poly p;
    bg::append(p.outer(), P(z0, r0));
    bg::append(p.outer(), P(z0, r1));
    bg::append(p.outer(), P(z1, r1));
    bg::append(p.outer(), P(z1, r0));
    bg::correct(p);
    return p;
}

// A polygon from its outer ring and its holes (any orientation).
inline Poly polygonOf(const stock::Ring& outer, const std::vector<stock::Ring>& holes) {
    Poly p;
    for (const stock::PointZR& q : outer)
        bg::append(p.outer(), P(q.z, q.r));
    for (const stock::Ring& h : holes) {
        p.inners().emplace_back();
        for (const stock::PointZR& q : h)
            bg::append(p.inners().back(), P(q.z, q.r));
    }
    bg::correct(p);
    return p;
}
inline Poly polygonOf(const stock::Ring& ring) {
    return polygonOf(ring, {});
}

// The stock's material as Boost polygons.
inline Multi multiOf(const stock::Stock& s) {
    Multi m;
    for (std::size_t i = 0; i < s.polygons(); ++i)
        m.push_back(polygonOf(s.outer(i), s.holes(i)));
    return m;
}

// The interface's shapes as Boost polygons.
inline Multi multiOf(const std::vector<Shape>& shapes) {
    Multi m;
    for (const Shape& s : shapes)
        m.push_back(polygonOf(s.outer, s.holes));
    return m;
}

inline Multi translated(const Multi& m, double dz) {
    Multi out = m;
    for (Poly& p : out) {
        for (P& q : p.outer())
            q.x(q.x() + dz);
        for (auto& h : p.inners())
            for (P& q : h)
                q.x(q.x() + dz);
    }
    return out;
}

// A multi-polygon for the interface: each polygon's outer ring and its holes.
inline std::vector<Shape> shapesOf(const Multi& m) {
    std::vector<Shape> out;
    for (const Poly& p : m) {
        Shape s;
        for (std::size_t k = 0; k + 1 < p.outer().size(); ++k)
            s.outer.push_back({p.outer()[k].x(), p.outer()[k].y()});
        for (const auto& h : p.inners()) {
            s.holes.emplace_back();
            for (std::size_t k = 0; k + 1 < h.size(); ++k)
                s.holes.back().push_back({h[k].x(), h[k].y()});
        }
        out.push_back(std::move(s));
    }
    return out;
}

} // namespace k528::proveout::geo
