#include "stock/stock.h"

#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>

#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <set>

namespace bg = boost::geometry;

namespace k528::stock {

namespace {
using P = bg::model::d2::point_xy<double>;
using Poly = bg::model::polygon<P>; // clockwise, closed (Boost's defaults)
using Multi = bg::model::multi_polygon<Poly>;
using Box = bg::model::box<P>;
constexpr double kPi = 3.14159265358979323846;

// Reads a signed decimal number at `s[i]`; false if none.
bool number(std::string_view s, std::size_t& i, double& v) {
    while (i < s.size() && s[i] == ' ')
        ++i;
    std::size_t j = i;
    if (j < s.size() && (s[j] == '-' || s[j] == '+'))
        ++j;
    bool digits = false;
    while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || s[j] == '.')) {
        digits = digits || s[j] != '.';
        ++j;
    }
    if (!digits)
        return false;
    v = std::strtod(std::string(s.substr(i, j - i)).c_str(), nullptr);
    i = j;
    return true;
}

bool letterPair(std::string_view s, std::size_t& i, char letter, double& a, double& b) {
    while (i < s.size() && s[i] == ' ')
        ++i;
    if (i >= s.size() || std::toupper(static_cast<unsigned char>(s[i])) != letter)
        return false;
    ++i;
    if (!number(s, i, a))
        return false;
    while (i < s.size() && s[i] == ' ')
        ++i;
    if (i >= s.size() || std::toupper(static_cast<unsigned char>(s[i])) != letter)
        return false;
    ++i;
    return number(s, i, b);
}

bool comma(std::string_view s, std::size_t& i) {
    while (i < s.size() && s[i] == ' ')
        ++i;
    if (i < s.size() && s[i] == ',') {
        ++i;
        return true;
    }
    return false;
}

std::string fmt(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

constexpr util::CatalogText kUcgTexts[] = {
    {"expected", "ожидалось UCG", "expected UCG"},
    {"type", "после «UCG,» ожидался тип N", "expected the type N after UCG,"},
    {"z", "ожидалось Z<длина заготовки>Z<длина отверстия>", "expected Z<outer length>Z<bore length>"},
    {"x", "ожидалось X<наружный диаметр>X<диаметр отверстия>", "expected X<outer diameter>X<bore diameter>"},
    {"s", "ожидалось S<угол снаружи>S<угол отверстия>", "expected S<outer angle>S<bore angle>"},
    {"direction", "направление — 0 или 1", "the direction is 0 or 1"},
    {"detail", "детализация — от -1 до -5", "the detail is -1..-5"},
    {"small", "заготовка меньше 0,01 мм", "the blank is smaller than 0.01 mm"},
    {"bore-sign", "длина отверстия того же знака, что длина заготовки", "the bore length has the sign of the outer length"},
    {"bore-long", "отверстие длиннее заготовки", "the bore is longer than the blank"},
    {"bore-diameter", "диаметр отверстия — от 0 до наружного диаметра", "the bore diameter is 0..the outer diameter"},
    {"cone", "углы конусов в пределах ±90°", "cone angles are within ±90°"},
    {kNoUcg, "в файле нет UCG", "no UCG in the file"},
};

} // namespace

util::TextCatalog ucgTexts() { return util::TextCatalog(kUcgTexts); }

std::string ucgErrorText(std::string_view said) { return "UCG: " + std::string(said); }

std::string ucgErrorText(std::string_view id, std::span<const std::string> args, bool russian) {
    return ucgErrorText(ucgTexts().render(id, args, russian));
}

std::optional<Blank> parseUcg(std::string_view s, std::string* error, std::string* errorId) {
    const auto fail = [&](std::string_view id) -> std::optional<Blank> {
        if (error)
            *error = ucgErrorText(id, {}, false);
        if (errorId)
            *errorId = std::string(id);
        return std::nullopt;
    };
    std::size_t i = 0;
    while (i < s.size() && s[i] == ' ')
        ++i;
    if (s.substr(i, 3) != "UCG" && s.substr(i, 3) != "ucg")
        return fail("expected");
    i += 3;
    double n = 0;
    if (!comma(s, i) || !number(s, i, n))
        return fail("type");
    Blank b;
    if (!comma(s, i) || !letterPair(s, i, 'Z', b.outerLengthMm, b.boreLengthMm))
        return fail("z");
    if (!comma(s, i) || !letterPair(s, i, 'X', b.outerDiameterMm, b.boreDiameterMm))
        return fail("x");
    if (!comma(s, i) || !letterPair(s, i, 'S', b.outerAngleDeg, b.boreAngleDeg))
        return fail("s");
    double dir = 0, detail = -5;
    if (comma(s, i)) {
        if (!number(s, i, dir) || (dir != 0 && dir != 1))
            return fail("direction");
        if (comma(s, i) && (!number(s, i, detail) || detail > -1 || detail < -5))
            return fail("detail");
    }
    b.direction = static_cast<int>(dir);
    b.detail = static_cast<int>(detail);
    if (std::fabs(b.outerLengthMm) < 0.01 || b.outerDiameterMm < 0.01)
        return fail("small");
    if (b.boreLengthMm != 0 && (b.boreLengthMm > 0) != (b.outerLengthMm > 0))
        return fail("bore-sign");
    if (std::fabs(b.boreLengthMm) > std::fabs(b.outerLengthMm))
        return fail("bore-long");
    if (b.boreDiameterMm < 0 || b.boreDiameterMm >= b.outerDiameterMm)
        return fail("bore-diameter");
    if (std::fabs(b.outerAngleDeg) >= 90 || std::fabs(b.boreAngleDeg) >= 90)
        return fail("cone");
    return b;
}

std::optional<Blank> findUcg(std::string_view text, std::string* error, std::string* errorId) {
    for (std::size_t p = 0; (p = text.find("UCG", p)) != std::string_view::npos; ++p) {
        std::size_t end = text.find_first_of(")\n\r", p);
        const std::string_view candidate = text.substr(p, end == std::string_view::npos ? text.size() - p : end - p);
        if (candidate.size() > 3 && candidate.find(',') != std::string_view::npos)
            return parseUcg(candidate, error, errorId);
    }
    if (error)
        *error = ucgErrorText(kNoUcg, {}, false);
    if (errorId)
        *errorId = std::string(kNoUcg);
    return std::nullopt;
}

std::string formatUcg(const Blank& b) {
    return "UCG,2,Z" + fmt(b.outerLengthMm) + "Z" + fmt(b.boreLengthMm) + ",X" +
           fmt(b.outerDiameterMm) + "X" + fmt(b.boreDiameterMm) + ",S" + fmt(b.outerAngleDeg) +
           "S" + fmt(b.boreAngleDeg) + "," + std::to_string(b.direction) + "," +
           std::to_string(b.detail);
}

Ring toolSweep(PointZR a, PointZR b, const Tool& t) {
    bg::model::multi_point<P> pts;
    for (const PointZR& q : {a, b}) {
        bg::append(pts, P(q.z, q.r));
        bg::append(pts, P(q.z + t.widthMm, q.r));
        bg::append(pts, P(q.z + t.widthMm, q.r + t.heightMm));
        bg::append(pts, P(q.z, q.r + t.heightMm));
    }
    Poly hull;
    bg::convex_hull(pts, hull);
    Ring r;
    const auto& o = hull.outer();
    for (std::size_t k = 0; k + 1 < o.size(); ++k) // closed: drop the repeat
        r.push_back({o[k].x(), o[k].y()});
    return r;
}

struct Stock::Impl {
    Multi m;
};

Stock::Stock(const Blank& b) : d_(std::make_shared<Impl>()), blank_(b) {
    const double z0 = std::min(0.0, b.outerLengthMm), z1 = std::max(0.0, b.outerLengthMm);
    const double R = b.outerDiameterMm / 2;
    const double ta = std::tan(b.outerAngleDeg * kPi / 180);
    const double rRight = std::max(0.0, R + (z1 - z0) * ta);
    Poly p;
    auto& o = p.outer();
    o.push_back(P(z0, 0));
    o.push_back(P(z0, R));
    o.push_back(P(z1, rRight));
    const double rb = b.boreDiameterMm / 2;
    const double lb = std::fabs(b.boreLengthMm);
    if (rb > 0 && lb > 0) {
        const double zb = z1 - lb;
        const double tb = std::tan(b.boreAngleDeg * kPi / 180);
        o.push_back(P(z1, std::max(0.0, rb + lb * tb)));
        o.push_back(P(zb, rb));
        o.push_back(P(zb, 0));
    } else {
        o.push_back(P(z1, 0));
    }
    bg::correct(p);
    d_->m.push_back(p);
}

void Stock::cut(PointZR a, PointZR b, const Tool& t) {
    ++moves_;
    // The swept rectangle: convex hull of the tool at both ends.
    const double zl = std::min(a.z, b.z), zr = std::max(a.z, b.z) + t.widthMm;
    const double rl = std::min(a.r, b.r), rh = std::max(a.r, b.r) + t.heightMm;
    const Box env(P(zl, rl), P(zr, rh));
    Box sb;
    bg::envelope(d_->m, sb);
    if (!bg::intersects(env, sb))
        return;
    Poly sweep;
    for (const PointZR& q : toolSweep(a, b, t))
        bg::append(sweep.outer(), P(q.z, q.r));
    bg::correct(sweep);
    Multi out;
    bg::difference(d_->m, sweep, out);
    d_->m = std::move(out);
}

bool Stock::cutPath(const toolpath::ProgrammedPath& path, const Tool& tool, const CutProgress& progress) {
    const double toR = path.diameterX ? 0.5 : 1.0;
    // Legs already cut, by their ends (an ordered set: only membership is asked).
    std::set<std::array<double, 4>> done;
    const std::size_t total = path.segments.size();
    constexpr std::size_t kReportEvery = 256;
    for (std::size_t k = 0; k < total; ++k) {
        if (progress && k % kReportEvery == 0 && !progress(k, total))
            return false;
        const toolpath::Segment& s = path.segments[k];
        const toolpath::PointMm* p = path.pointsOf(s);
        for (int i = 1; i < s.pointCount; ++i) {
            const PointZR a{p[i - 1].z, p[i - 1].x * toR}, b{p[i].z, p[i].x * toR};
            if (done.insert({a.z, a.r, b.z, b.r}).second)
                cut(a, b, tool);
        }
    }
    if (progress)
        progress(total, total);
    return true;
}

double Stock::areaMm2() const {
    return bg::area(d_->m);
}
std::size_t Stock::polygons() const {
    return d_->m.size();
}
Ring Stock::outer(std::size_t i) const {
    Ring r;
    const auto& o = d_->m.at(i).outer();
    for (std::size_t k = 0; k + 1 < o.size(); ++k) // closed: drop the repeat
        r.push_back({o[k].x(), o[k].y()});
    return r;
}
std::vector<Ring> Stock::holes(std::size_t i) const {
    std::vector<Ring> out;
    for (const auto& h : d_->m.at(i).inners()) {
        Ring r;
        for (std::size_t k = 0; k + 1 < h.size(); ++k)
            r.push_back({h[k].x(), h[k].y()});
        out.push_back(r);
    }
    return out;
}

Shape Stock::shape() const {
    Shape s;
    s.polygons.reserve(polygons());
    for (std::size_t i = 0; i < polygons(); ++i)
        s.polygons.push_back({outer(i), holes(i)});
    return s;
}

} // namespace k528::stock
