#include "training/drawing.h"

#include "training/geometry.h"

#include <cmath>

namespace k528::training {

namespace {
using namespace geo;

// The contour with every element moved by `dev(i)` mm along its outward
// normal: the polygon closed along the axis.
Multi offsetContour(const std::vector<ContourPoint>& c, const std::vector<double>& off) {
    const std::size_t n = c.size();
    // Points (z, r) and, per element i (from point i-1 to i), its line moved
    // by off[i]: a point on it and its direction.
    struct L {
        double pz, pr, dz, dr;
    };
    std::vector<L> lines(n);
    for (std::size_t i = 1; i < n; ++i) {
        const double z0 = c[i - 1].zMm, r0 = c[i - 1].dMm / 2, z1 = c[i].zMm, r1 = c[i].dMm / 2;
        const double dz = z1 - z0, dr = r1 - r0, len = std::hypot(dz, dr);
        const double nz = dr / len, nr = -dz / len; // the outward normal
        lines[i] = {z0 + nz * off[i], r0 + nr * off[i], dz / len, dr / len};
    }
    const auto meet = [&](const L& a, const L& b, double fz, double fr, P& out) {
        const double den = a.dz * b.dr - a.dr * b.dz;
        if (std::fabs(den) < 1e-12) {
            out = P(fz, fr);
            return false;
        }
        const double t = ((b.pz - a.pz) * b.dr - (b.pr - a.pr) * b.dz) / den;
        out = P(a.pz + a.dz * t, a.pr + a.dr * t);
        return true;
    };
    Poly poly;
    const L axis{0, 0, 1, 0};
    P q;
    // The first point: where the first element meets the axis.
    if (!meet(axis, lines[1], lines[1].pz, 0, q))
        q = P(lines[1].pz, 0);
    bg::append(poly.outer(), q);
    for (std::size_t i = 1; i + 1 < n; ++i) {
        if (meet(lines[i], lines[i + 1], 0, 0, q)) {
            bg::append(poly.outer(), q);
        } else {
            // Parallel neighbours: each keeps its own offset at the shared point.
            const double z = c[i].zMm, r = c[i].dMm / 2;
            bg::append(poly.outer(), P(lines[i].pz + (z - c[i - 1].zMm), lines[i].pr + (r - c[i - 1].dMm / 2)));
            bg::append(poly.outer(), P(lines[i + 1].pz, lines[i + 1].pr));
        }
    }
    if (!meet(lines[n - 1], axis, lines[n - 1].pz, 0, q))
        q = P(lines[n - 1].pz, 0);
    bg::append(poly.outer(), q);
    bg::correct(poly);
    Multi m;
    if (!bg::is_valid(poly)) {
        // A self-touching offset (a tolerance larger than an element): let
        // Boost split it.
        Multi fixed;
        bg::union_(poly, Poly(), fixed);
        return fixed;
    }
    m.push_back(poly);
    return m;
}

// The deviation of element i toward more material (`upper`) or less, in
// mm along its normal.
double deviation(const ContourPoint& a, const ContourPoint& b, const Tolerance& t, bool most) {
    const double dev = most ? t.upperMm : t.lowerMm;
    const bool cylinder = a.dMm == b.dMm && a.zMm != b.zMm;
    return cylinder ? dev / 2 : dev;
}

} // namespace

DrawingShapes drawingShapes(const Exercise& e) {
    DrawingShapes d;
    const Drawing& dr = e.drawing;
    if (dr.kind == Drawing::Kind::Contour) {
        const std::size_t n = dr.contour.size();
        std::vector<double> zero(n, 0.0), most(n, 0.0), least(n, 0.0);
        for (std::size_t i = 1; i < n; ++i) {
            const Tolerance t = dr.contour[i].tol.value_or(dr.tolerance);
            most[i] = deviation(dr.contour[i - 1], dr.contour[i], t, true);
            least[i] = deviation(dr.contour[i - 1], dr.contour[i], t, false);
        }
        d.present = true;
        d.nominal = shapesOf(offsetContour(dr.contour, zero));
        d.most = shapesOf(offsetContour(dr.contour, most));
        d.least = shapesOf(offsetContour(dr.contour, least));
    } else if (dr.kind == Drawing::Kind::Bore && e.ring) {
        const Ring& r = *e.ring;
        const auto ring = [&](double boreMm) {
            Multi m;
            m.push_back(rect(r.zMinMm, r.zMaxMm, boreMm / 2, r.outerMm / 2));
            return shapesOf(m);
        };
        d.present = true;
        d.nominal = ring(dr.boreMm);
        d.most = ring(dr.boreMm + dr.boreTol.lowerMm); // a smaller bore holds more material
        d.least = ring(dr.boreMm + dr.boreTol.upperMm);
    }
    return d;
}

DrawingShapes drawingFromPart(const std::vector<Shape>& part, const Tolerance& t) {
    DrawingShapes d;
    const Multi m = multiOf(part);
    const auto grown = [&](double by) {
        if (by == 0)
            return m;
        namespace st = bg::strategy::buffer;
        Multi out;
        bg::buffer(m, out, st::distance_symmetric<double>(by), st::side_straight(),
                   st::join_miter(), st::end_flat(), st::point_square());
        return out;
    };
    d.present = true;
    d.nominal = part;
    d.most = shapesOf(grown(t.upperMm));
    d.least = shapesOf(grown(t.lowerMm));
    return d;
}

} // namespace k528::training
