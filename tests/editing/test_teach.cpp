// Teach-in (editing/teach.h): the controller's position as a frame, and the
// preset R-parameters whose hint names a coordinate.
#include "editing/teach.h"
#include "program/parser.h"

#include <QtTest>

using namespace k528;
using namespace k528::editing;

class TestTeach : public QObject {
    Q_OBJECT
private slots:
    void frames() {
        QCOMPARE(teachFrame(12, 40.5, -5.0), std::string("N12 X40.5 Z-5"));
        QCOMPARE(teachFrame(0, 40.0004, std::nullopt), std::string("X40"));
        QCOMPARE(teachFrame(0, std::nullopt, -0.0001), std::string("Z0"));
        QCOMPARE(teachFrame(3, 1234.5678, 0.001), std::string("N3 X1234.568 Z0.001"));
        QCOMPARE(teachFrame(1, std::nullopt, std::nullopt), std::string());
        QCOMPARE(teachRFrame(7, 220, 200000), std::string("N7 R220=200000"));
        QCOMPARE(teachRFrame(0, 221, -5), std::string("R221=-5"));
        QCOMPARE(nextFrameNumber(12), 13);
        QCOMPARE(nextFrameNumber(0), 0);
        // What is taught parses as a frame of the language.
        const auto parsed = program::parse("%L1\n" + teachFrame(1, 40.5, -5) + "\n" + teachRFrame(2, 220, 200000) +
                                               "\nN3 M30\n");
        QVERIFY(!parsed.hasErrors());
    }

    void targets() {
        const std::vector<TeachTarget> t = teachTargets();
        const auto find = [&](int r) -> const TeachTarget* {
            for (const TeachTarget& x : t)
                if (x.r == r)
                    return &x;
            return nullptr;
        };
        for (int r : {184, 185, 192, 193, 200, 201, 220, 221})
            QVERIFY2(find(r), qPrintable(QString::number(r)));
        QCOMPARE(find(220)->axis, catalog::Axis::X);
        QCOMPARE(find(221)->axis, catalog::Axis::Z);
        QVERIFY(find(220)->machineCoordinate); // «в системе станка»
        QVERIFY(!find(200)->machineCoordinate);
        QVERIFY(!find(10));                    // a user parameter has no hint
        for (const TeachTarget& x : t)
            QVERIFY(x.r < 232 || x.r > 262); // never a read-only one
    }
};

QTEST_GUILESS_MAIN(TestTeach)
#include "test_teach.moc"
