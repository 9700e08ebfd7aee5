// core/stock (issue 12): the NC-200 UCG blank and material removal of a
// facing and a turning program — areas and vertices within 1 µm.
#include "profile/builtin.h"
#include "program/parser.h"
#include "stock/stock.h"
#include "toolpath/programmed_path.h"

#include <QtTest>

#include <cmath>

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
        QVERIFY(!stock::parseUcg("UCG,2,Z-100Z10,X200X0,S0S0", &error));
        QVERIFY(!stock::parseUcg("UCG,2,X200X0", &error));
        QVERIFY(stock::findUcg("%L1 (shaft)\n; UCG,2,Z-100Z0,X100X0,S0S0,0,-5\nN1 G0 X0\n"));
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
};

QTEST_APPLESS_MAIN(TestStock)
#include "test_stock.moc"
