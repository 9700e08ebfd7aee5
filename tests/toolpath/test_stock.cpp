// core/stock: the NC-200 UCG blank and material removal of a
// facing and a turning program — areas and vertices within 1 µm.
#include "profile/builtin.h"
#include "program/parser.h"
#include "stock/stock.h"
#include "toolpath/programmed_path.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace k528;

namespace {

stock::Stock cutBy(const char* program, const char* ucg) {
    const program::ParseResult parsed = program::parse(program);
    if (parsed.hasErrors())
        qFatal("program does not parse");
    const toolpath::ProgrammedPath p =
        toolpath::programmedPath(profile::builtin("training-lathe"), parsed.store, 1);
    std::string error;
    const std::optional<stock::Blank> b = stock::parseUcg(ucg, &error);
    if (!b)
        qFatal("%s", error.c_str());
    stock::Stock s(*b);
    s.cutPath(p, stock::Tool{});
    return s;
}

// Every expected vertex has an actual one within 1 µm and the counts agree.
bool sameVertices(const stock::Ring& actual, const std::vector<stock::PointZR>& expected) {
    if (actual.size() != expected.size()) {
        for (const auto& p : actual)
            qWarning("vertex %.6f %.6f", p.z, p.r);
        return false;
    }
    for (const stock::PointZR& e : expected) {
        bool found = false;
        for (const stock::PointZR& a : actual)
            found = found || (std::fabs(a.z - e.z) <= 1e-3 && std::fabs(a.r - e.r) <= 1e-3);
        if (!found) {
            qWarning("missing vertex %.6f %.6f", e.z, e.r);
            return false;
        }
    }
    return true;
}

} // namespace

class TestStock : public QObject {
    Q_OBJECT
private slots:
    void ucg() {
        std::string error;
        const auto b = stock::parseUcg("UCG,2,Z-100Z-15,X200X20,S-15S75,0,-5", &error);
        QVERIFY2(b, error.c_str());
        QCOMPARE(b->outerLengthMm, -100.0);
        QCOMPARE(b->boreLengthMm, -15.0);
        QCOMPARE(b->outerDiameterMm, 200.0);
        QCOMPARE(b->boreDiameterMm, 20.0);
        QCOMPARE(b->outerAngleDeg, -15.0);
        QCOMPARE(b->boreAngleDeg, 75.0);
        std::string id;
        QVERIFY(!stock::parseUcg("UCG,2,Z-100Z10,X200X0,S0S0", &error, &id));
        QCOMPARE(id, std::string("bore-sign"));
        QVERIFY(!stock::parseUcg("UCG,2,X200X0", &error, &id));
        QCOMPARE(id, std::string("z"));
        QVERIFY(stock::findUcg("%L1 (shaft)\n; UCG,2,Z-100Z0,X100X0,S0S0,0,-5\nN1 G0 X0\n"));
        // Every error of a UCG line is said after the "UCG: " that names the
        // line, the file's missing one too, in both languages.
        QCOMPARE(error, std::string("UCG: expected Z<outer length>Z<bore length>"));
        QVERIFY(!stock::findUcg("%L1 (shaft)\nN1 G0 X0 ; UCG\n", &error, &id));
        QCOMPARE(id, std::string(stock::kNoUcg));
        QCOMPARE(error, std::string("UCG: no UCG in the file"));
        QCOMPARE(stock::ucgErrorText("cone", {}, true), std::string("UCG: углы конусов в пределах ±90°"));
        QCOMPARE(stock::ucgErrorText("отверстие длиннее заготовки"), std::string("UCG: отверстие длиннее заготовки"));
        // A plain cylinder Ø100 × 100: half profile 50 × 100.
        const stock::Stock s(*stock::parseUcg("UCG,2,Z-100Z0,X100X0,S0S0,0,-5"));
        QVERIFY(std::fabs(s.areaMm2() - 5000) < 1e-6);
        // A bore Ø20 × 30 from the right face: 5000 − 10 × 30.
        const stock::Stock t(*stock::parseUcg("UCG,2,Z-100Z-30,X100X20,S0S0,0,-5"));
        QVERIFY(std::fabs(t.areaMm2() - 4700) < 1e-6);
        QVERIFY(sameVertices(t.outer(0), {{-100, 0}, {-100, 50}, {0, 50}, {0, 10}, {-30, 10}, {-30, 0}}));
    }
    void turning() {
        const stock::Stock s = cutBy("%L1\nN1 G192 X200\nN2 G292 Z50\nN3 G0 X60 Z2\n"
                                     "N4 G1 Z-50 FZ100\nN5 G0 X110\nN6 G0 Z2\n",
                                     "UCG,2,Z-100Z0,X100X0,S0S0,0,-5");
        QCOMPARE(s.polygons(), std::size_t(1));
        QVERIFY2(std::fabs(s.areaMm2() - 4000) < 1e-3, qPrintable(QString::number(s.areaMm2())));
        QVERIFY(sameVertices(s.outer(0),
                             {{-100, 0}, {-100, 50}, {-50, 50}, {-50, 30}, {0, 30}, {0, 0}}));
    }
    void facing() {
        const stock::Stock s = cutBy("%L1\nN1 G192 X200\nN2 G292 Z50\nN3 G0 X110 Z-2\n"
                                     "N4 G1 X-1 FX100\nN5 G0 Z10\n",
                                     "UCG,2,Z-100Z0,X100X0,S0S0,0,-5");
        QVERIFY2(std::fabs(s.areaMm2() - 4900) < 1e-3, qPrintable(QString::number(s.areaMm2())));
        QVERIFY(sameVertices(s.outer(0), {{-100, 0}, {-100, 50}, {-2, 50}, {-2, 0}}));
    }
    // An endless loop (GOTO back) drawn up to a frame limit: its legs
    // repeat exactly, and each is cut once — the stock is the one pass's,
    // at the cost of one pass.
    void anEndlessLoopIsCutOnce() {
        const char* ucg = "UCG,2,Z-100Z0,X100X0,S0S0,0,-5";
        const char* pass = "%L1\nN1 G192 X200\nN2 G292 Z50\nN3 G0 X60 Z2\n"
                           "N4 G1 Z-50 FZ100\nN5 G0 X110\nN6 G0 Z2\n";
        const program::ParseResult endless = program::parse(
            "%L1\nN1 G192 X200\nN2 G292 Z50\nN3 G0 X60 Z2\n"
            "N4 G1 Z-50 FZ100\nN5 G0 X110\nN6 G0 Z2\nN7 GOTO 3\n");
        QVERIFY(!endless.hasErrors());
        toolpath::PathOptions o;
        o.preview.maxFrames = 5000;
        const toolpath::ProgrammedPath p =
            toolpath::programmedPath(profile::builtin("training-lathe"), endless.store, 1, o);
        QCOMPARE(p.run.status, engine::PreviewStatus::Limit);
        QVERIFY(p.segments.size() > 1000);
        stock::Stock s(*stock::parseUcg(ucg));
        QVERIFY(s.cutPath(p, stock::Tool{}));
        const stock::Stock once = cutBy(pass, ucg);
        QVERIFY2(std::fabs(s.areaMm2() - once.areaMm2()) < 1e-6,
                 qPrintable(QString("%1 vs %2").arg(s.areaMm2()).arg(once.areaMm2())));
        QVERIFY2(s.moves() <= once.moves() + 2, qPrintable(QString("%1 legs cut").arg(s.moves())));
    }
    // Progress: legs done of the total, rising, the last call (total,
    // total); false stops the cut there.
    void cutProgressAndStop() {
        const program::ParseResult endless = program::parse(
            "%L1\nN1 G192 X200\nN2 G292 Z50\nN3 G0 X60 Z2\n"
            "N4 G1 Z-50 FZ100\nN5 G0 X110\nN6 G0 Z2\nN7 GOTO 3\n");
        toolpath::PathOptions o;
        o.preview.maxFrames = 2000;
        const toolpath::ProgrammedPath p =
            toolpath::programmedPath(profile::builtin("training-lathe"), endless.store, 1, o);
        const stock::Blank blank = *stock::parseUcg("UCG,2,Z-100Z0,X100X0,S0S0,0,-5");
        std::vector<std::size_t> seen;
        stock::Stock all(blank);
        QVERIFY(all.cutPath(p, stock::Tool{}, [&](std::size_t done, std::size_t total) {
            if (total != p.segments.size())
                qFatal("total %zu", total);
            seen.push_back(done);
            return true;
        }));
        QVERIFY(seen.size() >= 2);
        QVERIFY(std::is_sorted(seen.begin(), seen.end()));
        QCOMPARE(seen.back(), p.segments.size());
        stock::Stock stopped(blank);
        QVERIFY(!stopped.cutPath(p, stock::Tool{}, [](std::size_t, std::size_t) { return false; }));
        QCOMPARE(stopped.moves(), std::size_t(0));
        QVERIFY(std::fabs(stopped.areaMm2() - 5000) < 1e-6); // the blank, uncut
    }
    // The preview asks keepGoing every PreviewOptions::kKeepGoingFrames
    // frames with the count so far; false ends it as cancelled there.
    void previewCancelledByKeepGoing() {
        const program::ParseResult endless = program::parse("%L1\nN1 G91 G1 Z1 FZ1000\nN2 GOTO 1\n");
        std::vector<std::int64_t> asked;
        toolpath::PathOptions o;
        o.preview.keepGoing = [&](std::int64_t frames) {
            asked.push_back(frames);
            return asked.size() < 3;
        };
        const toolpath::ProgrammedPath p =
            toolpath::programmedPath(profile::builtin("training-lathe"), endless.store, 1, o);
        QCOMPARE(p.run.status, engine::PreviewStatus::Cancelled);
        QCOMPARE(asked.size(), std::size_t(3));
        for (std::size_t i = 0; i < asked.size(); ++i)
            QVERIFY(asked[i] >= static_cast<std::int64_t>(i + 1) * engine::PreviewOptions::kKeepGoingFrames);
        QCOMPARE(p.run.frames, asked.back());
        QVERIFY(p.run.frames < 4 * engine::PreviewOptions::kKeepGoingFrames);
    }
};

QTEST_APPLESS_MAIN(TestStock)
#include "test_stock.moc"
