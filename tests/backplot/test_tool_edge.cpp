// The active tool's edge in the backplot (backplot/tool_edge.h): the
// outline of each tool of the training lathe with its tip's corner at the
// tool's point and its body where the orientation says, the nose radius
// rounding the corner by the right amount, X doubled on a diameter axis;
// in the scene the tool of the station in use at the playhead (M62 changes
// it), lines rebuilt only when the tool or its point changed, none in 3D,
// and rendered (needs X) in the tool's colour.
#include "backplot/backplot_scene.h"
#include "backplot/offscreen.h"
#include "backplot/tool_edge.h"
#include "profile/builtin.h"
#include "program/parser.h"

#include <QtTest>

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>

#include <cmath>
#include <numbers>

using namespace k528;

namespace {

constexpr int kW = 800, kH = 500;

struct Pt {
    double z, x;
};
std::vector<Pt> points(const std::vector<float>& lines) {
    std::vector<Pt> p;
    for (std::size_t i = 0; i + 1 < lines.size(); i += 2)
        p.push_back({lines[i], lines[i + 1]});
    return p;
}
double nearestTo(const std::vector<Pt>& ps, double z, double x) {
    double d = 1e9;
    for (const Pt& p : ps)
        d = std::min(d, std::hypot(p.z - z, p.x - x));
    return d;
}

const char* kProgram = "%L1\nN1 G0 X60 Z5\nN2 G1 Z-20 FZ100\nN3 G0 X80\nN4 M62\nN5 G0 Z-23\nN6 G1 X50 FX40\nN7 G0 X80\nN8 M30\n";

} // namespace

class TestToolEdge : public QObject {
    Q_OBJECT
    profile::MachineProfile lathe_ = profile::builtin("training-lathe");

private slots:
    void outlineStartsAtTheTipAndLiesOnTheBodysSide() {
        const std::vector<profile::Tool> tools = profile::tools(lathe_);
        QCOMPARE(tools.size(), std::size_t(4));
        for (const profile::Tool& t : tools) {
            const std::vector<Pt> ps = points(backplot::toolEdgeLines(t, -10, 40, 2));
            QVERIFY2(!ps.empty(), t.name.c_str());
            for (const Pt& p : ps) {
                QVERIFY2((p.z + 10) * t.zDirection >= -1e-4, t.name.c_str()); // the body's Z side of the tip
                if (t.kind != profile::ToolKind::Drill)                       // a drill is centred on its tip
                    QVERIFY2((p.x - 40) * t.xDirection >= -1e-4, t.name.c_str());
            }
            // Sharp, the outline goes through the tip's corner.
            profile::Tool sharp = t;
            sharp.tipRadiusMm = 0;
            QVERIFY2(nearestTo(points(backplot::toolEdgeLines(sharp, -10, 40, 2)), -10, 40) < 1e-4, t.name.c_str());
        }
        // The nose radius rounds the 80° corner: its arc passes r/sin 40° − r from the corner (radius view).
        profile::Tool turning = *profile::toolAt(tools, 1);
        QCOMPARE(turning.tipRadiusMm, 0.8);
        const double expect = 0.8 / std::sin(40 * std::numbers::pi / 180) - 0.8;
        QVERIFY(std::fabs(nearestTo(points(backplot::toolEdgeLines(turning, 0, 0, 1)), 0, 0) - expect) < 1e-3);
        // The grooving blade is as wide as the tool; its height shows doubled on a diameter axis.
        const profile::Tool groove = *profile::toolAt(tools, 2);
        const std::vector<Pt> g1 = points(backplot::toolEdgeLines(groove, 0, 0, 1));
        const std::vector<Pt> g2 = points(backplot::toolEdgeLines(groove, 0, 0, 2));
        double zMax = 0, x1 = 0, x2 = 0;
        for (const Pt& p : g1)
            zMax = std::max(zMax, p.z), x1 = std::max(x1, p.x);
        for (const Pt& p : g2)
            x2 = std::max(x2, p.x);
        QVERIFY(std::fabs(zMax - groove.widthMm) < 1e-4);
        QVERIFY(std::fabs(x2 - 2 * x1) < 1e-3);
        // The boring bar lies towards the axis (+z−x).
        const profile::Tool boring = *profile::toolAt(tools, 3);
        QCOMPARE(boring.xDirection, -1);
    }

    void theStationAtThePlayheadAndRebuildsOnlyOnChange() {
        const program::ParseResult parsed = program::parse(kProgram);
        QVERIFY(!parsed.hasErrors());
        const toolpath::ProgrammedPath path = toolpath::programmedPath(lathe_, parsed.store, 1);
        backplot::BackplotScene scene;
        scene.setPath(path);
        scene.setToolsInUse(backplot::toolsInUse(lathe_, path));
        scene.fit(kW, kH);
        scene.refresh(kW, kH);
        // All shown: the tool at the end is M62's, the grooving tool.
        QVERIFY(scene.toolEdge().shown());
        const int first = scene.toolEdge().rebuilds();
        QCOMPARE(first, 1);
        scene.refreshTool(kW, kH); // nothing changed: the same lines
        scene.refreshTool(kW, kH);
        QCOMPARE(scene.toolEdge().rebuilds(), first);
        // At N2 (tool 1) the edge is the turning tool's, moving with the playhead.
        std::size_t n2 = 0;
        while (path.segments[n2].n != 2)
            ++n2;
        scene.setPlayhead(scene.segmentStart(n2) + path.segments[n2].durationS / 2);
        scene.refreshTool(kW, kH);
        QCOMPARE(scene.toolEdge().rebuilds(), first + 1);
        scene.setPlayhead(scene.segmentStart(n2) + path.segments[n2].durationS * 0.75);
        scene.refreshTool(kW, kH);
        QCOMPARE(scene.toolEdge().rebuilds(), first + 2);
        // The 3D view draws none; a machine without tools draws none.
        scene.setViewMode(backplot::ViewMode::Solid3D);
        QVERIFY(!scene.toolEdge().shown());
        scene.setViewMode(backplot::ViewMode::XZ);
        scene.setToolsInUse({});
        scene.refreshTool(kW, kH);
        QVERIFY(!scene.toolEdge().shown());
        // Live: the turret's station; indexing (0) or unknown (-1): none.
        scene.setToolsInUse(backplot::toolsInUse(lathe_, path));
        for (const auto& [station, shown] : std::vector<std::pair<int, bool>>{{3, true}, {0, false}, {-1, false}}) {
            backplot::BackplotScene::LiveTool live;
            live.z = -5, live.x = 30, live.station = station;
            scene.setLiveTool(live);
            scene.refreshTool(kW, kH);
            QCOMPARE(scene.toolEdge().shown(), shown);
        }
    }

    void renderedInTheToolsColour() {
        if (qgetenv("DISPLAY").isEmpty())
            QSKIP("VTK renders through GLX: run under xvfb-run");
        const program::ParseResult parsed = program::parse(kProgram);
        const toolpath::ProgrammedPath path = toolpath::programmedPath(lathe_, parsed.store, 1);
        backplot::BackplotScene scene;
        scene.setPath(path);
        const backplot::ToolsInUse tools = backplot::toolsInUse(lathe_, path);
        // The grooving tool at the end (X80 Z-23): its blade's far corner, 3 mm along +Z and 12 mm up (×2 shown).
        const double cz = path.end.z + 3, cx = path.end.x + 2 * 12;
        for (const bool withTools : {true, false}) {
            scene.setToolsInUse(withTools ? tools : backplot::ToolsInUse{});
            std::vector<unsigned char> rgb;
            std::string error;
            QVERIFY2(backplot::renderOffscreen(scene, kW, kH, "", &rgb, error), error.c_str());
            vtkCamera* cam = scene.renderer()->GetActiveCamera();
            vtkMatrix4x4* m = cam->GetCompositeProjectionTransformMatrix(double(kW) / kH, -1, 1);
            const double in[4] = {cz, cx, 0, 1};
            double out[4];
            m->MultiplyPoint(in, out);
            const double px = (out[0] / out[3] + 1) / 2 * kW, py = (out[1] / out[3] + 1) / 2 * kH;
            bool found = false;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const int x = static_cast<int>(px) + dx, y = static_cast<int>(py) + dy;
                    if (x < 0 || y < 0 || x >= kW || y >= kH)
                        continue;
                    const std::size_t i = (static_cast<std::size_t>(y) * kW + x) * 3;
                    const backplot::Rgb c{rgb[i] / 255.0, rgb[i + 1] / 255.0, rgb[i + 2] / 255.0};
                    found |= std::fabs(c.r - backplot::kToolColour.r) < 0.08 &&
                             std::fabs(c.g - backplot::kToolColour.g) < 0.08 &&
                             std::fabs(c.b - backplot::kToolColour.b) < 0.08;
                }
            QVERIFY2(found == withTools, withTools ? "no edge at the blade's corner" : "an edge without tools");
        }
    }
};

QTEST_MAIN(TestToolEdge)
#include "test_tool_edge.moc"
