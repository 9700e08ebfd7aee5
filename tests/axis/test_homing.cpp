#include <QtTest>

#include <cmath>

#include "axis/homing.h"
#include "rig/axis_loop.h"

using namespace k528::axis;
namespace testrig = k528::testrig;
using testrig::AxisLoop;

namespace {

// A grinder Z with the deceleration cam under the slide between cam0 and cam1
// (mm of slide travel) and zero marks at motor positions phase + k·5 mm.
struct HomingRig {
    AxisLoop r;
    HomingCycle cycle;
    double cam0, cam1;

    HomingRig(const Constants& k, double phaseMm, double camFrom, double camTo, double startMm = 100)
        : r(k, [&] {
              auto m = testrig::grinderZMechanics();
              m.zeroMarkPhaseMm = phaseMm;
              m.startSlideMm = startMm;
              return m;
          }()),
          cam0(camFrom), cam1(camTo) {}

    bool cam() const { return r.mech.slideMm() >= cam0 && r.mech.slideMm() <= cam1; }
    bool run(std::int64_t limitMs = 600000) {
        if (!cycle.start(r.servo, cam()))
            return false;
        for (std::int64_t i = 0; i < limitMs && cycle.running(); ++i) {
            r.step();
            cycle.tick(r.servo, cam());
        }
        return !cycle.running();
    }
};

Constants grinder(const std::function<void(Constants&)>& f = {}) {
    Constants k = testrig::grinderZ();
    if (f)
        f(k);
    return k;
}

} // namespace

class TestHoming : public QObject {
    Q_OBJECT
private slots:
    // Appendix Ж, Z: towards + at F СТАРТ БТ (50 mm/min) onto the cam, off it
    // at F ОТКЛ.БТ (5 mm/min), first zero mark, ЗНАЧЕНИЕ БТ = 190.000 mm.
    void grinderZReferencesOnTheFirstMarkAfterTheCam() {
        HomingRig h(grinder(), 0.7, 180.0, 185.0);
        QVERIFY(h.run());
        QVERIFY(h.cycle.done());
        QCOMPARE(h.cycle.alarm(), 0);
        QVERIFY(std::fabs(h.r.servo.actual() - AxisLoop::mm(190.0)) <= 10);
        QVERIFY(std::fabs(h.r.mech.slideMm() - 185.7) < 0.01);
        // R247: from leaving the cam (185.0) to the mark (185.7).
        QVERIFY(std::abs(h.cycle.distanceDisc() - 700) <= 1);
        QCOMPARE(h.r.servo.fault(), Fault::None);
    }

    void speedsFollowTheCam() {
        HomingRig h(grinder(), 0.7, 180.0, 185.0);
        QVERIFY(h.cycle.start(h.r.servo, h.cam()));
        h.r.run(3000);
        const double s0 = h.r.mech.slideMm();
        h.r.run(2000);
        const double startMmPerMin = (h.r.mech.slideMm() - s0) * 30.0;
        QVERIFY2(std::fabs(startMmPerMin - 50.0) < 0.5, qPrintable(QString::number(startMmPerMin))); // F СТАРТ БТ
        while (!h.cam()) {
            h.r.step();
            h.cycle.tick(h.r.servo, h.cam());
        }
        for (int i = 0; i < 3000; ++i) {
            h.r.step();
            h.cycle.tick(h.r.servo, h.cam());
        }
        QCOMPARE(h.cycle.phase(), HomingCycle::Phase::OnCam);
        // F ОТКЛ.БТ = 5 mm/min is half a DAC unit of feed-forward: the loop
        // dithers between codes, so measure the mean speed over 2 s.
        const double x0 = h.r.mech.slideMm();
        for (int i = 0; i < 2000; ++i) {
            h.r.step();
            h.cycle.tick(h.r.servo, h.cam());
        }
        const double meanMmPerMin = (h.r.mech.slideMm() - x0) * 30.0;
        QVERIFY2(std::fabs(meanMmPerMin - 5.0) < 0.1, qPrintable(QString::number(meanMmPerMin)));
    }

    void startingOnTheCamGoesSlowFromTheStart() {
        HomingRig h(grinder(), 0.7, 95.0, 102.0, 100.0);
        QVERIFY(h.cycle.start(h.r.servo, h.cam()));
        QCOMPARE(h.cycle.phase(), HomingCycle::Phase::OnCam);
        QVERIFY(h.run());
        QVERIFY(std::fabs(h.r.mech.slideMm() - 105.7) < 0.01); // first mark after 102
    }

    void offsetAndBeforeSearchDistance() {
        // S до поиска 0-метки = 1 mm skips the mark at 185.7; СМЕЩЕНИЕ БТ = -0.5 mm.
        HomingRig h(grinder([](Constants& k) {
                        k.beforeZeroSearchDisc = 1000;
                        k.homeOffsetDisc = -500;
                    }),
                    0.7, 180.0, 185.0);
        QVERIFY(h.run());
        QVERIFY(h.cycle.done());
        QVERIFY(std::fabs(h.r.mech.slideMm() - 190.2) < 0.01);    // mark 190.7, then -0.5
        QVERIFY(std::fabs(h.r.servo.actual() - AxisLoop::mm(190.0)) <= 10);
        QVERIFY(std::abs(h.cycle.distanceDisc() - 5700) <= 1);
    }

    void negativeDirection() {
        // ПБТ В "-" = 1: the cam lies below the start.
        HomingRig h(grinder([](Constants& k) { k.homeNegative = true; }), 0.7, 40.0, 45.0);
        QVERIFY(h.run());
        QVERIFY(h.cycle.done());
        QVERIFY(std::fabs(h.r.mech.slideMm() - 35.7) < 0.01); // first mark below 40.0
    }

    void alarm41WhenTheSearchEndsWithoutMark() {
        // The mark lies 3 mm after the cam; S поиска 0-метки = 1 mm.
        HomingRig h(grinder([](Constants& k) { k.zeroSearchDisc = 1000; }), 3.0, 180.0, 185.0);
        QVERIFY(h.run());
        QCOMPARE(h.cycle.phase(), HomingCycle::Phase::Failed);
        QCOMPARE(h.cycle.alarm(), 41);
        QVERIFY(h.r.mech.slideMm() < 186.1);
        // Near miss: 3.5 mm of search finds it.
        HomingRig ok(grinder([](Constants& k) { k.zeroSearchDisc = 3500; }), 3.0, 180.0, 185.0);
        QVERIFY(ok.run());
        QVERIFY(ok.cycle.done());
    }

    void alarm40WhenTheCamIsNotLeft() {
        // S конечника БТ = 2 mm on a 5 mm cam.
        HomingRig h(grinder([](Constants& k) { k.decelCamDisc = 2000; }), 0.7, 180.0, 185.0);
        QVERIFY(h.run());
        QCOMPARE(h.cycle.alarm(), 40);
        HomingRig ok(grinder([](Constants& k) { k.decelCamDisc = 6000; }), 0.7, 180.0, 185.0);
        QVERIFY(ok.run());
        QVERIFY(ok.cycle.done());
    }

    void cancelStopsTheAxis() {
        HomingRig h(grinder(), 0.7, 180.0, 185.0);
        QVERIFY(h.cycle.start(h.r.servo, h.cam()));
        h.r.run(3000);
        h.cycle.cancel(h.r.servo);
        h.r.run(2000);
        QCOMPARE(h.cycle.phase(), HomingCycle::Phase::Idle);
        QCOMPARE(h.r.mech.motorSpeedMmPerMin(), 0.0);
    }
};

QTEST_APPLESS_MAIN(TestHoming)
#include "test_homing.moc"
