#include "backplot/tool_edge.h"

#include "backplot/backplot_scene.h"
#include "backplot/line_cells.h"
#include "proveout/tool_change.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <cmath>
#include <numbers>

namespace k528::backplot {

namespace {

constexpr double kDeg = std::numbers::pi / 180;

struct P {
    double u, v; // mm from the tip: u along the body's Z side, v radially towards its X side
};

// A polygon (closed) whose corners `rounded` get the nose radius `r`: each
// such corner is replaced by an arc tangent to its two edges.
std::vector<P> rounded(const std::vector<P>& poly, const std::vector<bool>& round, double r, int steps) {
    if (r <= 0)
        return poly;
    std::vector<P> out;
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
        const P c = poly[i];
        if (!round[i]) {
            out.push_back(c);
            continue;
        }
        const P a = poly[(i + n - 1) % n], b = poly[(i + 1) % n];
        double e1u = a.u - c.u, e1v = a.v - c.v, e2u = b.u - c.u, e2v = b.v - c.v;
        const double l1 = std::hypot(e1u, e1v), l2 = std::hypot(e2u, e2v);
        e1u /= l1, e1v /= l1, e2u /= l2, e2v /= l2;
        const double theta = std::acos(std::clamp(e1u * e2u + e1v * e2v, -1.0, 1.0));
        const double d = std::min({r / std::tan(theta / 2), l1 / 2, l2 / 2}); // corner -> tangent points
        const double rr = d * std::tan(theta / 2);
        double bu = e1u + e2u, bv = e1v + e2v;
        const double bl = std::hypot(bu, bv);
        bu /= bl, bv /= bl;
        const P centre{c.u + bu * rr / std::sin(theta / 2), c.v + bv * rr / std::sin(theta / 2)};
        const P t1{c.u + e1u * d, c.v + e1v * d}, t2{c.u + e2u * d, c.v + e2v * d};
        double a1 = std::atan2(t1.v - centre.v, t1.u - centre.u), a2 = std::atan2(t2.v - centre.v, t2.u - centre.u);
        // The short way round (the arc bulges towards the corner).
        if (a2 - a1 > std::numbers::pi)
            a2 -= 2 * std::numbers::pi;
        else if (a1 - a2 > std::numbers::pi)
            a2 += 2 * std::numbers::pi;
        for (int k = 0; k <= steps; ++k) {
            const double t = a1 + (a2 - a1) * k / steps;
            out.push_back({centre.u + rr * std::cos(t), centre.v + rr * std::sin(t)});
        }
    }
    return out;
}

// A rhombic insert with its `angle` corner at the tip, its first edge `lead`
// degrees off the Z side.
std::vector<P> insert(double angle, double lead) {
    const double L = kInsertEdgeMm;
    const P a{L * std::cos(lead * kDeg), L * std::sin(lead * kDeg)};
    const P b{L * std::cos((lead + angle) * kDeg), L * std::sin((lead + angle) * kDeg)};
    return {{0, 0}, a, {a.u + b.u, a.v + b.v}, b};
}

void addClosed(std::vector<std::vector<P>>& out, std::vector<P> poly) {
    poly.push_back(poly.front());
    out.push_back(std::move(poly));
}

} // namespace

ToolsInUse toolsInUse(const profile::MachineProfile& profile, const toolpath::ProgrammedPath& path) {
    ToolsInUse t;
    try {
        t.tools = profile::tools(profile);
        if (!t.tools.empty())
            t.stations = proveout::stationsAlong(path, proveout::geometryOf(profile));
    } catch (const std::exception&) {
        return {};
    }
    return t;
}

std::optional<profile::Tool> ToolsInUse::atStation(int station) const {
    return station > 0 ? profile::toolAt(tools, station) : std::nullopt;
}

std::optional<profile::Tool> ToolsInUse::atSegment(std::size_t i) const {
    if (stations.empty())
        return std::nullopt;
    return atStation(stations[std::min(i, stations.size() - 1)]);
}

std::vector<float> toolEdgeLines(const profile::Tool& t, double tipZ, double tipX, double shownPerMm, int steps) {
    std::vector<std::vector<P>> polylines; // in (u, v) from the tip
    const double r = t.tipRadiusMm;
    switch (t.kind) {
    case profile::ToolKind::Turning:
    case profile::ToolKind::Facing:
        addClosed(polylines, rounded(insert(80, 5), {true, false, false, false}, r, steps));
        break;
    case profile::ToolKind::Boring: {
        addClosed(polylines, rounded(insert(55, 10), {true, false, false, false}, r, steps));
        // The bar behind the insert: as long as the tool's body, as thick as its height.
        const double h = std::min(t.heightMm, 60.0), u0 = kInsertEdgeMm * 0.6, v0 = kInsertEdgeMm * 0.3;
        addClosed(polylines, {{u0, v0}, {t.widthMm, v0}, {t.widthMm, v0 + h}, {u0, v0 + h}});
        break;
    }
    case profile::ToolKind::Grooving: {
        const double w = t.widthMm > 0 ? t.widthMm : 3;
        addClosed(polylines, rounded({{0, 0}, {w, 0}, {w, 4 * w}, {0, 4 * w}}, {true, true, false, false}, r, steps));
        break;
    }
    case profile::ToolKind::Threading: {
        const double h = 4;
        addClosed(polylines, rounded({{0, 0}, {h * std::tan(30 * kDeg), h}, {-h * std::tan(30 * kDeg), h}},
                                     {true, false, false}, r, steps));
        break;
    }
    case profile::ToolKind::Drill: {
        // Centred on its tip: a diameter of the body's height, the 118° point, the body's length.
        const double rad = (t.heightMm > 0 && t.heightMm < 1000 ? t.heightMm : 10) / 2;
        const double cone = rad / std::tan(59 * kDeg), len = std::max(t.widthMm, cone + 1);
        polylines.push_back({{len, rad}, {cone, rad}, {0, 0}, {cone, -rad}, {len, -rad}, {len, rad}});
        break;
    }
    }
    std::vector<float> lines;
    for (const std::vector<P>& pl : polylines)
        for (std::size_t i = 1; i < pl.size(); ++i)
            for (const P& p : {pl[i - 1], pl[i]}) {
                lines.push_back(static_cast<float>(tipZ + t.zDirection * p.u));
                lines.push_back(static_cast<float>(tipX + t.xDirection * p.v * shownPerMm));
            }
    return lines;
}

struct ToolEdge::Vtk {
    vtkNew<vtkPolyData> data;
    vtkNew<vtkPolyDataMapper> mapper;
    vtkNew<vtkActor> actor;
};

ToolEdge::ToolEdge(vtkRenderer* renderer) : v_(std::make_unique<Vtk>()) {
    v_->mapper->SetInputData(v_->data);
    v_->mapper->ScalarVisibilityOff();
    v_->actor->SetMapper(v_->mapper);
    v_->actor->GetProperty()->SetColor(kToolColour.r, kToolColour.g, kToolColour.b); // the tool's colour
    v_->actor->GetProperty()->SetLineWidth(2);
    v_->actor->GetProperty()->SetLighting(false);
    v_->actor->VisibilityOff();
    renderer->AddActor(v_->actor);
}

ToolEdge::~ToolEdge() = default;

void ToolEdge::show(const std::optional<profile::Tool>& tool, double z, double x, double shownPerMm, bool visible) {
    const bool want = visible && tool.has_value();
    if (!want) {
        if (shown_)
            v_->actor->VisibilityOff();
        shown_ = false;
        return;
    }
    const bool same = shown_ && tool_ == tool && z_ == z && x_ == x && shownPerMm_ == shownPerMm;
    if (same)
        return;
    tool_ = tool, z_ = z, x_ = x, shownPerMm_ = shownPerMm;
    const std::vector<float> v = toolEdgeLines(*tool, z, x, shownPerMm);
    setCells(v_->data, v, 2, 0.32); // just above the tool's cross (0.3)
    v_->actor->VisibilityOn();
    shown_ = true;
    ++rebuilds_;
}

} // namespace k528::backplot
