// The backplot scene rendered offscreen (needs X: Debian's VTK is GLX only):
// a rapid and a feed segment at known places have their colours, the rapid
// is dashed, the limit rectangle is where the constants put it, a segment
// beyond the limits is highlighted, and picking through our own index names
// the frame. Plus the level of detail and the pick index headless.
#include "backplot/backplot_scene.h"
#include "backplot/offscreen.h"
#include "cli_runner.h"
#include "profile/builtin.h"
#include "program/parser.h"
#include "proveout/proveout.h"
#include "stock/stock.h"
#include "toolpath/actual_path.h"
#include "engine/run.h"

#include <QTemporaryDir>
#include <QtTest>

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>

#include <cmath>
#include <cstdio>

using namespace k528;
using backplot::Rgb;

namespace {

constexpr int kW = 800, kH = 500;

toolpath::ProgrammedPath pathOf(const char* text, profile::MachineProfile prof) {
    const program::ParseResult parsed = program::parse(text);
    if (parsed.hasErrors())
        qFatal("program does not parse");
    return toolpath::programmedPath(prof, parsed.store, 1);
}

// The pixel column (Z) or row (X) of a coordinate in the scene's XZ view at kW × kH.
enum class Axis { Z, X };
struct PixelOf {
    PixelOf(const backplot::BackplotScene& scene, Axis a) : w(scene.window(kW, kH)), axis(a) {}
    double operator()(double v) const { return (v - (axis == Axis::Z ? w.x0 : w.y0)) / w.worldPerPixel; }
    backplot::ViewWindow w;
    Axis axis;
};

struct Image {
    std::vector<unsigned char> rgb;
    Rgb at(int x, int y) const { // y from the bottom
        const std::size_t i = (static_cast<std::size_t>(y) * kW + x) * 3;
        return {rgb[i] / 255.0, rgb[i + 1] / 255.0, rgb[i + 2] / 255.0};
    }
};

bool near(Rgb a, Rgb b) {
    return std::fabs(a.r - b.r) < 0.08 && std::fabs(a.g - b.g) < 0.08 && std::fabs(a.b - b.b) < 0.08;
}

// Whether a pixel within `r` of (x, y) has colour c.
bool around(const Image& img, double x, double y, Rgb c, int r = 2) {
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            const int px = static_cast<int>(std::floor(x)) + dx, py = static_cast<int>(std::floor(y)) + dy;
            if (px >= 0 && py >= 0 && px < kW && py < kH && near(img.at(px, py), c))
                return true;
        }
    return false;
}

// A lit surface of colour c: the pixel is c scaled by one factor (ambient + diffuse).
bool litAs(Rgb px, Rgb c) {
    const double k = px.r / c.r;
    return k > 0.3 && std::fabs(px.g - k * c.g) < 0.06 && std::fabs(px.b - k * c.b) < 0.06;
}

// World point -> pixel (origin bottom-left) through the scene's camera.
std::pair<double, double> project(const backplot::BackplotScene& scene, double x, double y, double z) {
    vtkCamera* cam = scene.renderer()->GetActiveCamera();
    vtkMatrix4x4* m = cam->GetCompositeProjectionTransformMatrix(double(kW) / kH, -1, 1);
    const double in[4] = {x, y, z, 1};
    double out[4];
    m->MultiplyPoint(in, out);
    return {(out[0] / out[3] + 1) / 2 * kW, (out[1] / out[3] + 1) / 2 * kH};
}

// A rendered picture of any size; y from the bottom.
struct Picture {
    int w = 0, h = 0;
    std::vector<unsigned char> rgb;
    Rgb at(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 3;
        return {rgb[i] / 255.0, rgb[i + 1] / 255.0, rgb[i + 2] / 255.0};
    }
};

Picture render(backplot::BackplotScene& scene, int w, int h) {
    Picture p;
    p.w = w, p.h = h;
    std::string error;
    if (!backplot::renderOffscreen(scene, w, h, "", &p.rgb, error))
        qFatal("%s", error.c_str());
    return p;
}

// The rows (from the bottom) and columns where `match` holds inside [x0, x1) × [y0, y1).
struct Box {
    int x0 = 1 << 30, x1 = -1, y0 = 1 << 30, y1 = -1, count = 0;
    bool empty() const { return count == 0; }
    int height() const { return empty() ? 0 : y1 - y0 + 1; }
    int width() const { return empty() ? 0 : x1 - x0 + 1; }
};
template <class F>
Box boxOf(const Picture& p, int x0, int x1, int y0, int y1, F match) {
    Box b;
    for (int y = std::max(0, y0); y < std::min(p.h, y1); ++y)
        for (int x = std::max(0, x0); x < std::min(p.w, x1); ++x)
            if (match(p.at(x, y))) {
                b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x);
                b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y);
                ++b.count;
            }
    return b;
}

// A colour of the µm scale (blue .. red: saturated, not the path's colours).
bool lutColour(Rgb c) {
    const double hi = std::max({c.r, c.g, c.b}), lo = std::min({c.r, c.g, c.b});
    return hi > 0.6 && hi - lo > 0.5;
}

} // namespace

class TestBackplotRender : public QObject {
    Q_OBJECT
private slots:
    void coloursAndLimits() {
        profile::MachineProfile prof = profile::builtin("training-lathe");
        // A rapid up X at Z0, then a feed along Z at X200.
        const toolpath::ProgrammedPath path =
            pathOf("%L1\nN1 G0 X200\nN2 G1 Z-100 FZ500\n", prof);
        backplot::BackplotScene scene;
        scene.setPath(path);
        Image img;
        std::string error;
        QVERIFY2(backplot::renderOffscreen(scene, kW, kH, "", &img.rgb, error), error.c_str());
        QCOMPARE(img.rgb.size(), std::size_t(kW * kH * 3));
        const PixelOf px(scene, Axis::Z), py(scene, Axis::X);
        // The feed at X200, Z-50.
        QVERIFY(around(img, px(-50), py(200), backplot::kFeedColour));
        QVERIFY(!around(img, px(-50), py(200), backplot::kRapidColour));
        // The rapid at Z0, X50..150: rapid colour, with gaps (dashed).
        int lit = 0, dark = 0;
        for (double x = 50; x <= 150; x += py.w.worldPerPixel) {
            if (around(img, px(0), py(x), backplot::kRapidColour, 1))
                ++lit;
            else
                ++dark;
        }
        QVERIFY2(lit > 10 && dark > 5, qPrintable(QString("lit %1 dark %2").arg(lit).arg(dark)));
        QVERIFY(!around(img, px(0), py(100), backplot::kFeedColour));
        // The limit rectangle: C98 = -115 mm (left edge), C47 = 272 mm (top edge, diameter).
        QVERIFY(around(img, px(-115), py(100), backplot::kLimitColour));
        QVERIFY(around(img, px(100), py(272), backplot::kLimitColour));
        QVERIFY(!around(img, px(-95), py(100), backplot::kLimitColour, 3));
        QVERIFY(near(img.at(static_cast<int>(px(-60)), static_cast<int>(py(100))), backplot::kBackground));
        // Picking through the index: the feed segment is frame N2, line 3.
        const long seg = scene.pick(px(-50), py(200), kW, kH);
        QCOMPARE(seg, 1L);
        QCOMPARE(path.segments[1].n, 2);
        QCOMPARE(path.segments[1].line, 3);
        QCOMPARE(scene.pick(px(-60), py(100), kW, kH), -1L);
    }
    // The prove-out's finding of a facing whose return rapid cuts through
    // the Ø40 bar: a red disc at its place on the path, gone when the
    // finding is; a finding of another line (another text of the program)
    // is not drawn; the safe program has none.
    void findingsAreRedMarkersAtTheirPlaces() {
        const profile::MachineProfile prof = profile::builtin("training-lathe");
        const char* bad = "%L1\nN1 G90 G0 M3 X44 Z2\nN2 Z-1\nN3 G1 X-1 FX150\nN4 G0 X44 Z-20\nN5 M30\n";
        const char* safe = "%L1\nN1 G90 G0 M3 X44 Z2\nN2 Z-1\nN3 G1 X-1 FX150\nN4 G0 Z2\nN5 X44\nN6 M30\n";
        const std::optional<stock::Blank> blank = stock::parseUcg("UCG,2,Z-80Z0,X40X0,S0S0,0,-5");
        QVERIFY(blank);
        engine::PreviewOptions po;
        po.fromReferencePoint = true; // as the prove-out pane and `k528 check --profile`
        const auto prove = [&](const char* text) {
            return proveout::proveProgram(prof, program::parse(text).store, 1, po, blank).result.findings;
        };
        QVERIFY(prove(safe).empty());
        const std::vector<proveout::Finding> found = prove(bad);
        QCOMPARE(found.size(), std::size_t(1));
        const proveout::Finding& f = found[0];
        QCOMPARE(f.line, 5);
        QVERIFY2(f.at.x >= -1 && f.at.x < 40 && f.at.z < 0, qPrintable(QString("X%1 Z%2").arg(f.at.x).arg(f.at.z))); // in the bar
        backplot::BackplotScene scene;
        scene.setPath(pathOf(bad, prof)); // the backplot's own preview of the same text
        scene.setStock(blank);
        scene.setFindings({{f.program, f.line, f.at.z, f.at.x}});
        QCOMPARE(scene.findingsShown().size(), std::size_t(1));
        Image img;
        std::string error;
        QVERIFY2(backplot::renderOffscreen(scene, kW, kH, "", &img.rgb, error), error.c_str());
        const backplot::ViewWindow w = scene.window(kW, kH);
        const double px = (f.at.z - w.x0) / w.worldPerPixel, py = (f.at.x - w.y0) / w.worldPerPixel;
        QVERIFY2(near(img.at(int(px), int(py)), backplot::kFindingColour),
                 qPrintable(QString("at %1,%2").arg(px).arg(py)));
        // A disc: red all round its centre, the background beyond its ring.
        for (int d : {-3, 3})
            QVERIFY(near(img.at(int(px) + d, int(py)), backplot::kFindingColour) &&
                    near(img.at(int(px), int(py) + d), backplot::kFindingColour));
        // Nothing red elsewhere: 30 px to the right at the same X is not a marker.
        QVERIFY(!around(img, px + 30, py, backplot::kFindingColour, 3));

        // Gone with the finding.
        scene.setFindings({});
        QVERIFY(scene.findingsShown().empty());
        QVERIFY2(backplot::renderOffscreen(scene, kW, kH, "", &img.rgb, error), error.c_str());
        QVERIFY(!around(img, px, py, backplot::kFindingColour, 3));
        // Not this path's: the same place on another line, or off the line's legs.
        scene.setFindings({{f.program, f.line - 2, f.at.z, f.at.x}, {f.program, f.line, f.at.z + 5, f.at.x + 30}});
        QVERIFY(scene.findingsShown().empty());
        QVERIFY2(backplot::renderOffscreen(scene, kW, kH, "", &img.rgb, error), error.c_str());
        QVERIFY(!around(img, px, py, backplot::kFindingColour, 3));
    }

    void outsideIsHighlightedAndTheRectangleFollowsTheConstants() {
        profile::MachineProfile prof = profile::builtin("training-lathe");
        prof.setC(98, -50000); // -ОГРАНИЧЕН Z = -50 mm
        const toolpath::ProgrammedPath path =
            pathOf("%L1\nN1 G0 X200\nN2 G1 Z-100 FZ500\n", prof);
        QVERIFY(path.segments[1].outside);
        backplot::BackplotScene scene;
        scene.setPath(path);
        Image img;
        std::string error;
        QVERIFY2(backplot::renderOffscreen(scene, kW, kH, "", &img.rgb, error), error.c_str());
        const PixelOf px(scene, Axis::Z), py(scene, Axis::X);
        QVERIFY(around(img, px(-50), py(100), backplot::kLimitColour));
        QVERIFY(around(img, px(-80), py(200), backplot::kOutsideColour));
        QVERIFY(!around(img, px(-80), py(200), backplot::kFeedColour));
    }
    void plotCommandWritesAPng() {
        QTemporaryDir dir;
        QFile f(dir.filePath("p.k528"));
        f.open(QIODevice::WriteOnly);
        f.write("; UCG,2,Z-100Z0,X100X0,S0S0,0,-5\n%L1\nN1 G0 X300\nN2 G1 Z-50 FZ200\n");
        f.close();
        const QString png = dir.filePath("p.png");
        const CliResult r = runK528({"plot", "--size", "320x200", "--out", png, f.fileName()});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.err.contains(QString::fromUtf8("L1 N1 line 3: ВНЕ ГРАНИЦ")));
        QFile out(png);
        QVERIFY(out.open(QIODevice::ReadOnly));
        QCOMPARE(out.read(8), QByteArray("\x89PNG\r\n\x1a\n", 8));
        const CliResult bad = runK528({"plot", "--size", "3x2", "--out", png, f.fileName()});
        QCOMPARE(bad.exitCode, 2);
    }
    void wheelIsACylinderOfR207() {
        // grinder-205: X on the diameter, R207 = 18.5 mm; the program dresses it to 12 mm.
        profile::MachineProfile prof = profile::builtin("grinder-205");
        const toolpath::ProgrammedPath path = pathOf(
            "%L1\nN1 G0 X40 Z150\nN2 G1 X30 FX100\nN3 R207=12000\nN4 G1 X20 FX100\n", prof);
        QCOMPARE(path.segments.size(), std::size_t(3));
        QCOMPARE(path.wheel.size(), std::size_t(2));
        QCOMPARE(path.wheel[0].segment, 0u);
        QCOMPARE(path.wheel[0].diameterMm, 18.5);
        QCOMPARE(path.wheel[1].segment, 2u); // N4: after the dressing
        QCOMPARE(path.wheel[1].diameterMm, 12.0);
        backplot::BackplotScene scene;
        scene.setPath(path);
        Image img;
        std::string error;
        QVERIFY2(backplot::renderOffscreen(scene, kW, kH, "", &img.rgb, error), error.c_str());
        // XZ: the wheel at the end (X20 Z150): Z 150..160, X 20 - 2·12 .. 20 (a diameter axis).
        const backplot::BackplotScene::WheelBox box = scene.wheelBox();
        QVERIFY(box.shown);
        QCOMPARE(box.diameterMm, 12.0);
        QCOMPARE(box.z0, 150.0);
        QCOMPARE(box.z1, 160.0);
        QCOMPARE(box.x0, -4.0);
        QCOMPARE(box.x1, 20.0);
        const PixelOf px(scene, Axis::Z), py(scene, Axis::X);
        QVERIFY(around(img, px(155), py(-4), backplot::kWheelColour));  // the edge towards the axis
        QVERIFY(around(img, px(160), py(2), backplot::kWheelColour));   // the +Z face
        QVERIFY(around(img, px(157), py(20), backplot::kWheelColour));  // the working edge
        QVERIFY(around(img, px(157), py(8), backplot::kWheelColour));   // its axis
        QVERIFY(!around(img, px(157), py(14), backplot::kWheelColour, 3)); // inside: not filled
        QVERIFY(!around(img, px(157), py(-9), backplot::kWheelColour, 3)); // beyond its diameter
        // Before the dressing (the end of N2, X30) the wheel is 18.5 mm.
        scene.setPlayhead(scene.segmentStart(1) + path.segments[1].durationS);
        QVERIFY2(backplot::renderOffscreen(scene, kW, kH, "", &img.rgb, error), error.c_str());
        QCOMPARE(scene.wheelBox().diameterMm, 18.5);
        QCOMPARE(scene.wheelBox().x1, 30.0);
        QCOMPARE(scene.wheelBox().x0, 30.0 - 37.0);
        const backplot::ViewWindow w2 = scene.window(kW, kH);
        QVERIFY(around(img, (155 - w2.x0) / w2.worldPerPixel, (-7 - w2.y0) / w2.worldPerPixel,
                       backplot::kWheelColour));
        // 3D at the end: a lit cylinder of radius 6 about the axis at radius 10 - 6 = 4.
        scene.setPlayhead(-1);
        scene.setViewMode(backplot::ViewMode::Solid3D);
        QVERIFY2(backplot::renderOffscreen(scene, kW, kH, "", &img.rgb, error), error.c_str());
        QVERIFY(scene.wheelBox().shown);
        const auto front = project(scene, 155, 4, 6); // the point nearest the camera's side
        QVERIFY2(litAs(img.at(int(front.first), int(front.second)), backplot::kWheelColour),
                 qPrintable(QString("%1 %2 %3").arg(img.at(int(front.first), int(front.second)).r)
                                .arg(img.at(int(front.first), int(front.second)).g)
                                .arg(img.at(int(front.first), int(front.second)).b)));
        const auto above = project(scene, 155, 4 + 6 + 3, 0);
        QVERIFY(!litAs(img.at(int(above.first), int(above.second)), backplot::kWheelColour));
        // A lathe (R207 = 0) has no wheel.
        backplot::BackplotScene lathe;
        lathe.setPath(pathOf("%L1\nN1 G0 X200\nN2 G1 Z-100 FZ500\n", profile::builtin("training-lathe")));
        QVERIFY(lathe.path().wheel.empty());
        QVERIFY2(backplot::renderOffscreen(lathe, kW, kH, "", &img.rgb, error), error.c_str());
        QVERIFY(!lathe.wheelBox().shown);
    }
    void oscillationStrokes() {
        profile::MachineProfile prof = profile::builtin("grinder-205");
        const toolpath::ProgrammedPath path =
            pathOf("%L1\nN1 G0 X40 Z150\nN2 G281 Z-8 FZ2000\nN3 G1 X30 FX100\nN4 G280\n", prof);
        QCOMPARE(path.segments[1].kind, toolpath::SegmentKind::Oscillation);
        backplot::BackplotScene scene;
        scene.setPath(path);
        Image img;
        std::string error;
        QVERIFY2(backplot::renderOffscreen(scene, kW, kH, "", &img.rgb, error), error.c_str());
        const PixelOf px(scene, Axis::Z), py(scene, Axis::X);
        // The stroke along Z at X40 from Z150 to the far reverse point Z142, in its colour.
        QVERIFY(around(img, px(146), py(40), backplot::kOscillationColour));
        QVERIFY(!around(img, px(146), py(40), backplot::kFeedColour, 0));
        // A tick across each reverse point, none between them.
        QVERIFY(around(img, px(142), py(40) + 4, backplot::kOscillationColour, 1));
        QVERIFY(!around(img, px(146), py(40) + 4, backplot::kOscillationColour, 1));
        // 3D: the wheel's swept band over the stroke, translucent, from Z142 (beside the wheel at Z150..160).
        scene.setViewMode(backplot::ViewMode::Solid3D);
        QVERIFY2(backplot::renderOffscreen(scene, kW, kH, "", &img.rgb, error), error.c_str());
        const double rc = 20 - 18.5 / 2; // the edge at radius 20, the wheel inside
        const auto band = project(scene, 145, rc, 18.5 / 2);
        const Rgb b = img.at(int(band.first), int(band.second));
        QVERIFY2(b.g > backplot::kBackground.g + 0.08 && b.b > backplot::kBackground.b + 0.08 &&
                     b.r < b.g,
                 qPrintable(QString("%1 %2 %3").arg(b.r).arg(b.g).arg(b.b)));
        const auto outside = project(scene, 135, rc, 18.5 / 2); // before the stroke's far point
        QVERIFY(near(img.at(int(outside.first), int(outside.second)), backplot::kBackground));
    }
    // The title, «ВНЕ ГРАНИЦ» and the rulers' labels are there from the first
    // frame, of a readable size, on lines of their own, and the path keeps
    // clear of them (issue: 5 px tall, shown only after a zoom, drawn over).
    void overlayIsReadableFromTheFirstFrame() {
        profile::MachineProfile prof = profile::builtin("training-lathe");
        const toolpath::ProgrammedPath path = pathOf(
            "%L1\nN1 G90 G54 G55\nN2 G0 X100 Z2\nN3 G1 Z-200 FZ500\nN4 G0 X320\nN5 Z2\nM30\n", prof);
        backplot::BackplotScene scene;
        scene.setPath(path);
        for (const auto& [w, h] : {std::pair{420, 360}, std::pair{1400, 400}}) {
            const Picture p = render(scene, w, h);
            const auto grey = [](Rgb c) { return near(c, backplot::kTitleColour); };
            const auto red = [](Rgb c) { return c.r > 0.6 && c.g < 0.35 && c.b < 0.35; };
            // The top band: the title's line, then «ВНЕ ГРАНИЦ».
            const int band = backplot::kTopBandPx;
            // (right of the left ruler, whose top label reaches into the band)
            const Box title = boxOf(p, backplot::kLeftBandPx, w, h - band, h, grey);
            const Box warning = boxOf(p, backplot::kLeftBandPx, w, h - band, h, red);
            QVERIFY2(title.height() >= 9 && title.height() <= 20,
                     qPrintable(QString("title %1 px tall at %2x%3").arg(title.height()).arg(w).arg(h)));
            QVERIFY2(warning.height() >= 9 && warning.height() <= 20, qPrintable(QString::number(warning.height())));
            QVERIFY2(warning.y1 < title.y0, qPrintable(QString("title rows %1..%2, warning %3..%4")
                                                           .arg(title.y0).arg(title.y1).arg(warning.y0).arg(warning.y1)));
            QVERIFY(title.width() > 120);
            QCOMPARE(scene.titleText(), std::string("L1  4 segments  X \xE2\x8C\x80 diameter"));
            QCOMPARE(scene.deviationBarTitle(), std::string("\xC2\xB5m"));
            // Nothing of the path in the band: the red there is the warning's text only.
            const Box pathRed = boxOf(p, boxOf(p, 0, w, title.y0 - 14, title.y0, red).x1 + 6, w, h - band, h, red);
            QVERIFY2(pathRed.empty(), qPrintable(QString("path in the top band at x %1").arg(pathRed.x0)));
            // The left ruler's labels (grey 0.8) are as tall as text.
            const auto label = [](Rgb c) { return c.r > 0.4 && std::fabs(c.r - c.g) < 0.1 && std::fabs(c.r - c.b) < 0.1; };
            // The tallest run of rows with label pixels left of the ruler.
            int run = 0, tallest = 0;
            for (int y = backplot::kBottomBandPx; y < h - band; ++y) {
                run = boxOf(p, 0, backplot::kLeftBandPx - 14, y, y + 1, label).empty() ? 0 : run + 1;
                tallest = std::max(tallest, run);
            }
            QVERIFY2(tallest >= 8 && tallest <= 16, qPrintable(QString("ruler label %1 px tall").arg(tallest)));
            // Our scale: a round length, its bar as long as that length in pixels.
            const double mm = scene.scaleBarMm();
            const double mag = std::pow(10.0, std::floor(std::log10(mm)));
            QVERIFY(std::fabs(mm / mag - 1) < 1e-9 || std::fabs(mm / mag - 2) < 1e-9 || std::fabs(mm / mag - 5) < 1e-9);
            const backplot::ViewWindow vw = scene.window(w, h);
            const Box bar = boxOf(p, w / 2, w, 10, 14, grey);
            QVERIFY2(std::abs(bar.width() - mm / vw.worldPerPixel) <= 3,
                     qPrintable(QString("bar %1 px for %2 mm").arg(bar.width()).arg(mm)));
        }
    }
    // The µm bar keeps its coloured strip in a wide view (it used to shrink
    // to its labels), at a fixed width at the right.
    void colourBarKeepsItsStripInAWideView() {
        profile::MachineProfile prof = profile::builtin("training-lathe");
        prof.setC(8, 1);
        prof.setC(60, 1);
        const program::ParseResult parsed = program::parse("%L1\nN1 G1 X60 FX3000\nN2 G1 Z-40 FZ3000\nM30\n");
        QVERIFY(!parsed.hasErrors());
        engine::RunOptions ro;
        ro.home = false;
        const toolpath::ActualPath actual = toolpath::actualPath(prof, parsed.store, 1, ro, 1.0);
        QVERIFY(actual.samples.size() > 10);
        backplot::BackplotScene scene;
        scene.setPath(toolpath::programmedPath(prof, parsed.store, 1));
        scene.setActual(&actual);
        for (const auto& [w, h] : {std::pair{1600, 400}, std::pair{420, 360}, std::pair{2400, 300}}) {
            const Picture p = render(scene, w, h);
            const Box strip = boxOf(p, w - backplot::kRightBarBandPx, w, 0, h, lutColour);
            QVERIFY2(strip.width() >= 15 && strip.height() >= 60,
                     qPrintable(QString("strip %1 x %2 px at %3x%4").arg(strip.width()).arg(strip.height()).arg(w).arg(h)));
        }
    }
    // The bar's labels are numbers as a reader writes them («394», «12.5»,
    // «0.25», never VTK's «394.»), its title in the caller's words.
    void deviationBarSpeaksTheCallersLanguage() {
        const auto label = [](double v) {
            char b[32];
            std::snprintf(b, sizeof b, backplot::kDeviationLabelFormat, v);
            return std::string(b);
        };
        QCOMPARE(label(394), std::string("394"));
        QCOMPARE(label(12.5), std::string("12.5"));
        QCOMPARE(label(0.25), std::string("0.25"));
        QCOMPARE(label(0), std::string("0"));
        QCOMPARE(label(231.27), std::string("231.3"));
        backplot::BackplotScene scene;
        backplot::OverlayTexts ru;
        ru.micrometres = "мкм";
        scene.setTexts(ru);
        QCOMPARE(scene.deviationBarTitle(), std::string("мкм"));
    }
    // The wheel zooms about the cursor: the world point under it stays there.
    void zoomKeepsThePointUnderTheCursor() {
        backplot::BackplotScene scene;
        scene.setPath(pathOf("%L1\nN1 G0 X200\nN2 G1 Z-100 FZ500\n", profile::builtin("training-lathe")));
        const int w = 600, h = 400;
        scene.fit(w, h);
        const backplot::ViewWindow a = scene.window(w, h);
        const double cx = 120, cy = 300; // display pixel, from the bottom-left
        const double wx = a.x0 + cx * a.worldPerPixel, wy = a.y0 + cy * a.worldPerPixel;
        scene.zoomAt(cx, cy, 2.0, w, h);
        const backplot::ViewWindow b = scene.window(w, h);
        QVERIFY(std::fabs(b.worldPerPixel - a.worldPerPixel / 2) < 1e-9 * a.worldPerPixel);
        QVERIFY(std::fabs(b.x0 + cx * b.worldPerPixel - wx) < 1e-6);
        QVERIFY(std::fabs(b.y0 + cy * b.worldPerPixel - wy) < 1e-6);
        // And back out: the same place again.
        scene.zoomAt(cx, cy, 0.5, w, h);
        const backplot::ViewWindow c = scene.window(w, h);
        QVERIFY(std::fabs(c.x0 - a.x0) < 1e-6 && std::fabs(c.y0 - a.y0) < 1e-6);
    }
    void levelOfDetailKeepsCornersAndBoundsTheSize() {
        // 20,000 zig-zag passes: the full view collapses them, a zoom shows every corner.
        toolpath::ProgrammedPath p;
        p.segments.reserve(20000);
        double z = 0;
        for (int i = 0; i < 20000; ++i) {
            toolpath::Segment s;
            s.kind = toolpath::SegmentKind::Feed;
            s.firstPoint = static_cast<std::uint32_t>(p.points.size());
            s.pointCount = 2;
            p.points.push_back({i % 2 ? 10.0 : 0.0, z});
            z -= 0.001;
            p.points.push_back({i % 2 ? 0.0 : 10.0, z});
            p.segments.push_back(s);
        }
        backplot::PathGeometry g;
        g.build(p);
        backplot::ViewWindow full{-21, -1, 1, 11, 0.03};
        const backplot::LodLines all = g.simplify(full, p.segments.size());
        QVERIFY2(all.feed.size() / 4 < 20000 / 3, qPrintable(QString::number(all.feed.size() / 4)));
        // Zoomed so that 1 µm is 4 pixels: the corners near Z = -10 are all there.
        backplot::ViewWindow zoom{-10.01, 4.99, -9.99, 5.01, 0.00025};
        const backplot::LodLines z1 = g.simplify(zoom, p.segments.size());
        QVERIFY(z1.legsConsidered >= 35);
        QVERIFY(z1.feed.size() / 4 >= 35); // each its own: none merged
        // The pick index finds the segment through a point of it.
        QCOMPARE(g.pick(-12.3455, 5.0, 0.0002), 12345L); // (Z, X): the middle of segment 12345
        QCOMPARE(g.pick(-30, 5.0, 0.1), -1L);
    }
};

QTEST_APPLESS_MAIN(TestBackplotRender)
#include "test_backplot_render.moc"
