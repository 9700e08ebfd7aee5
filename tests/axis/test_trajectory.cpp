#include <QtTest>

#include <cmath>

#include "axis/constants.h"
#include "axis/trajectory.h"
#include "rig/axis_loop.h"

using namespace k528::axis;
namespace testrig = k528::testrig;
using testrig::AxisLoop;

class TestTrajectory : public QObject {
    Q_OBJECT
private slots:
    // 100 mm at 1000 mm/min with УСКОРЕНИЕ 1 = 2000 takes 6.21 s
    // (trapezoid: L/v + v/a = 6 s + 0.2133 s).
    void trapezoidTimeMatchesFormula() {
        const Constants k = testrig::grinderZ();
        const double a = k.accelToInternalPerMs2(2000);
        const double v = k.mmPerMinToInternalPerMs(1000);
        Trajectory t;
        t.reset(0);
        t.moveTo(AxisLoop::mm(100), v, a);
        int ms = 0;
        double maxV = 0, maxA = 0, prevV = 0, maxPos = 0, lastDv = 0;
        while (!t.atTarget() && ms < 20000) {
            t.tick(1.0);
            ++ms;
            maxV = std::max(maxV, std::fabs(t.velocity()));
            maxA = std::max(maxA, lastDv);
            lastDv = std::fabs(t.velocity() - prevV); // the final snap is checked apart
            maxPos = std::max(maxPos, t.position());
            prevV = t.velocity();
        }
        const double expectedS = 100.0 / (1000.0 / 60.0) + (1000.0 / 60.0) / 78.125;
        QCOMPARE(std::round(expectedS * 100) / 100, 6.21);
        QVERIFY2(std::fabs(ms / 1000.0 - expectedS) <= 0.002, qPrintable(QString::number(ms)));
        QVERIFY(maxV <= v * (1 + 1e-12));
        QVERIFY(maxA <= a * (1 + 1e-9));
        QVERIFY(lastDv <= 2 * a);
        QCOMPARE(maxPos, AxisLoop::mm(100)); // no overshoot
        QCOMPARE(t.position(), AxisLoop::mm(100));
    }

    void triangularProfileForShortMoves() {
        Trajectory t;
        t.reset(0);
        const double a = 0.01; // internal/ms²
        t.moveTo(1000, 100, a);  // never reaches 100/ms: peak sqrt(a·L) = 3.16
        int ms = 0;
        double peak = 0;
        while (!t.atTarget() && ms < 100000) {
            t.tick(1.0);
            ++ms;
            peak = std::max(peak, t.velocity());
        }
        QVERIFY(std::fabs(peak - std::sqrt(a * 1000)) < 0.02);
        QVERIFY(std::fabs(ms - 2 * std::sqrt(1000 / a)) <= 3); // 2·sqrt(L/a)
    }

    void stopBrakesOverTheBrakingDistance() {
        Trajectory t;
        t.reset(0);
        t.moveTo(1e9, 10, 0.05);
        while (t.velocity() < 10)
            t.tick(1.0);
        const double x0 = t.position();
        t.stop(0.05);
        while (!t.atRest())
            t.tick(1.0);
        QVERIFY(std::fabs((t.position() - x0) - 10.0 * 10.0 / (2 * 0.05)) < 10.0);
        QCOMPARE(t.target(), t.position());
    }

    void scaleZeroHoldsAndResumes() {
        Trajectory t;
        t.reset(0);
        t.moveTo(100000, 10, 0.05);
        for (int i = 0; i < 1000; ++i)
            t.tick(1.0);
        t.setScale(0);
        for (int i = 0; i < 1000; ++i)
            t.tick(1.0);
        QVERIFY(t.atRest());
        QVERIFY(!t.atTarget());
        const double held = t.position();
        for (int i = 0; i < 500; ++i)
            t.tick(1.0);
        QCOMPARE(t.position(), held);
        t.setScale(0.5);
        int ms = 0;
        double maxV = 0;
        while (!t.atTarget() && ms < 100000) {
            t.tick(1.0);
            ++ms;
            maxV = std::max(maxV, t.velocity());
        }
        QVERIFY(t.atTarget());
        QVERIFY(maxV <= 5.0 + 1e-12);
    }

    void targetBehindReversesWithoutJump() {
        Trajectory t;
        t.reset(0);
        t.moveTo(100000, 10, 0.05);
        for (int i = 0; i < 1000; ++i)
            t.tick(1.0);
        t.setTarget(0);
        double prevV = t.velocity(), maxDv = 0, maxPos = 0;
        int ms = 0;
        while (!t.atTarget() && ms < 100000) {
            t.tick(1.0);
            ++ms;
            maxDv = std::max(maxDv, std::fabs(t.velocity() - prevV));
            prevV = t.velocity();
            maxPos = std::max(maxPos, t.position());
        }
        QVERIFY(t.atTarget());
        QCOMPARE(t.position(), 0.0);
        QVERIFY(maxDv <= 0.05 * 2.0 + 1e-9); // at most the final snap of one step
        QVERIFY(maxPos > 1000);              // it had to brake first
    }

    void deterministic() {
        const auto run = [] {
            Trajectory t;
            t.reset(3.5);
            t.moveTo(123456.75, 7.25, 0.0125);
            double sum = 0;
            for (int i = 0; i < 20000; ++i) {
                t.tick(1.0);
                sum += t.position() * 1e-3 + t.velocity();
            }
            return sum;
        };
        QCOMPARE(run(), run());
    }
};

QTEST_APPLESS_MAIN(TestTrajectory)
#include "test_trajectory.moc"
