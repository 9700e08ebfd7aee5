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

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

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
        const backplot::ViewWindow w = scene.window(kW, kH);
        const auto px = [&](double z) { return (z - w.x0) / w.worldPerPixel; };
        const auto py = [&](double x) { return (x - w.y0) / w.worldPerPixel; };
        // The feed at X200, Z-50.
        QVERIFY(around(img, px(-50), py(200), backplot::kFeedColour));
        QVERIFY(!around(img, px(-50), py(200), backplot::kRapidColour));
        // The rapid at Z0, X50..150: rapid colour, with gaps (dashed).
        int lit = 0, dark = 0;
        for (double x = 50; x <= 150; x += w.worldPerPixel) {
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
        const backplot::ViewWindow w = scene.window(kW, kH);
        const auto px = [&](double z) { return (z - w.x0) / w.worldPerPixel; };
        const auto py = [&](double x) { return (x - w.y0) / w.worldPerPixel; };
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
