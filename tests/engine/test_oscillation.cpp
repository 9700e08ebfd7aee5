// Oscillation (Gx81/Gx80) with the presets of screen УСТ 7 (R192..R199 for Z):
// strokes while the program goes on, reverse delay, exact reverse, spark-out
// strokes after Gx80, end point, preset reverse points.
#include "rig/engine_rig.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;

namespace {

// Watches the Z setpoint: reverse points reached (the setpoint at rest at a
// target), and how long it rests there.
struct Watch {
    struct Stop {
        double at = 0;       // internal units
        std::int64_t ms = 0; // time at rest
        double error = 0;    // following error when it left
    };
    std::vector<Stop> stops;
    bool resting = false;
    void step(EngineRig& r) {
        const auto& s = r.ctl->servo(Z);
        const bool rest = s.commandVelocity() == 0.0;
        if (rest && !resting)
            stops.push_back({s.setpoint(), 0, 0});
        if (rest && !stops.empty())
            stops.back().ms += 1;
        if (!rest && resting && !stops.empty())
            stops.back().error = s.followingError();
        resting = rest;
    }
    void run(EngineRig& r, std::int64_t ms) {
        for (std::int64_t i = 0; i < ms; ++i) {
            r.tick();
            step(r);
        }
    }
};

} // namespace

class TestOscillation : public QObject {
    Q_OBJECT
private slots:
    // «G281 Z=-30.5 Fz=100 ... осциллирующее перемещение по оси Z ... между
    // точкой текущего положения и точкой с координатой на 30.5 мм меньше»;
    // the program goes on; G280 stops it and waits.
    void strokesWhileProgramGoesOn() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G281 Z-10 FZ3000\nN2 G1 X5 FX100\nN3 G280\nN4 R1=1\n");
        r.start(1);
        Watch w;
        w.run(r, 2000);
        QVERIFY(r.ctl->oscillating(Z));
        QCOMPARE(r.ctl->programView().frameNumber, 2); // X moves meanwhile
        QVERIFY(r.x().moving);
        QVERIFY(w.stops.size() >= 4);
        for (std::size_t i = 1; i < w.stops.size(); ++i) {
            const double at = w.stops[i].at;
            QVERIFY2(at == -20000.0 || at == 0.0, qPrintable(QString::number(at)));
            QVERIFY(w.stops[i].at != w.stops[i - 1].at); // alternate ends
        }
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->r(1), 1);
        QVERIFY(!r.ctl->oscillating(Z));
        QVERIFY(std::llabs(r.current(X) - 5000) <= kRestTol);
        const std::int64_t zEnd = r.current(Z);
        QVERIFY(std::llabs(zEnd) <= kRestTol || std::llabs(zEnd + 10000) <= kRestTol);
    }
    // ХОДЫ ВЫХАЖИВАНИЯ: after G280 the stroke in progress ends, then R199 full
    // strokes, then the axis stops; the G280 frame waits for it.
    void sparkOut() {
        for (int spark : {0, 2, 3}) {
            EngineRig r("training-lathe", noHoming);
            QVERIFY(r.ctl->setR(199, spark).ok());
            r.load("%L1\nN1 G281 Z-10 FZ3000\nN2 G4 X1.1\nN3 G280\nN4 R1=1\n");
            r.start(1);
            QVERIFY(r.until([&] { return r.ctl->programView().frameNumber == 3; }, 5000));
            Watch w;
            w.resting = r.ctl->servo(Z).commandVelocity() == 0.0;
            std::int64_t waited = 0;
            while (r.ctl->r(1) == 0 && waited < 20000) {
                w.run(r, 1);
                ++waited;
                if (r.ctl->oscillating(Z))
                    QCOMPARE(r.ctl->r(1), 0);
            }
            QCOMPARE(r.ctl->r(1), 1);
            // Reverse points after G280: the partial stroke's end + `spark` full strokes.
            QCOMPARE(int(w.stops.size()), 1 + spark);
        }
    }
    // ТОЧКА ЗАВЕРШЕНИЯ R198: 1 = the "-" point, 2 = the "+" point.
    void endPoint() {
        for (int end : {1, 2}) {
            for (double dwellS : {0.3, 0.9}) { // G280 while going towards either end
                EngineRig r("training-lathe", noHoming);
                QVERIFY(r.ctl->setR(198, end).ok());
                r.load("%L1\nN1 G281 Z-10 FZ3000\nN2 G4 X" + std::to_string(dwellS) +
                       "\nN3 G280\n");
                r.start(1);
                QVERIFY(r.runToEnd());
                QCOMPARE(r.ctl->state(), ProgramState::Ended);
                const double expected = end == 1 ? -20000.0 : 0.0;
                QCOMPARE(r.ctl->servo(Z).setpoint(), expected);
            }
        }
    }
    // ЗАДЕРЖКА РЕВЕРСА R195 (ms): the axis waits at each reverse point.
    void reverseDelay() {
        EngineRig r("training-lathe", noHoming);
        QVERIFY(r.ctl->setR(195, 250).ok());
        r.load("%L1\nN1 G281 Z-5 FZ3000\nN2 G4 X3\n");
        r.start(1);
        Watch w;
        w.run(r, 2500);
        QVERIFY(w.stops.size() >= 3);
        for (std::size_t i = 1; i + 1 < w.stops.size(); ++i)
            QVERIFY2(w.stops[i].ms >= 249 && w.stops[i].ms <= 252,
                     qPrintable(QString::number(w.stops[i].ms)));
    }
    // -/+РЕВЕРС ТОЧНО: reverse only inside ДОПУСК ПОЗ at that point.
    void exactReverse() {
        EngineRig r("training-lathe", noHoming);
        QVERIFY(r.ctl->setR(196, 1).ok());
        QVERIFY(r.ctl->setR(197, 1).ok());
        r.load("%L1\nN1 G281 Z-10 FZ6000\nN2 G4 X4\n");
        r.start(1);
        Watch w;
        w.run(r, 3500);
        QVERIFY(w.stops.size() >= 3);
        for (std::size_t i = 1; i + 1 < w.stops.size(); ++i) {
            QVERIFY2(std::fabs(w.stops[i].error) <= 12.0,
                     qPrintable(QString::number(w.stops[i].error)));
            QVERIFY(w.stops[i].ms > 20); // it waited for the lag to settle
        }
        // Without: it turns as soon as the setpoint arrives.
        EngineRig q("training-lathe", noHoming);
        q.load("%L1\nN1 G281 Z-10 FZ6000\nN2 G4 X4\n");
        q.start(1);
        Watch v;
        v.run(q, 3500);
        for (std::size_t i = 1; i + 1 < v.stops.size(); ++i)
            QVERIFY(v.stops[i].ms <= 2);
    }
    // No stroke in the frame: the preset reverse points -MZ / +MZ (R192/R193)
    // at СКОРОСТЬ ОСЦИЛЛЯЦИИ R194.
    void presetPoints() {
        EngineRig r("training-lathe", noHoming);
        QVERIFY(r.ctl->setR(192, -8000).ok());
        QVERIFY(r.ctl->setR(193, -3000).ok());
        QVERIFY(r.ctl->setR(194, 2000000).ok());
        r.load("%L1\nN1 G281\nN2 G4 X3\n");
        r.start(1);
        Watch w;
        w.run(r, 2500);
        QVERIFY(w.stops.size() >= 3);
        QCOMPARE(w.stops[0].at, -16000.0); // the farther point first
        QCOMPARE(w.stops[1].at, -6000.0);
        QCOMPARE(w.stops[2].at, -16000.0);
        QVERIFY(std::fabs(r.ctl->servo(Z).commandVelocity()) <= 2000000.0 * 2 / 60000.0 + 1e-9);
    }
    // X has its own presets (screen УСТ 7, R184..R191): G181 without a
    // stroke oscillates X between -MX (R184) and +MX (R185) — diameter
    // values on the lathe — at R186, and G180 ends after R191 spark-out
    // strokes at the end point R190.
    void xAxisPresets() {
        EngineRig r("training-lathe", noHoming);
        QVERIFY(r.ctl->setR(184, 10000).ok()); // -MX: X10 (diameter)
        QVERIFY(r.ctl->setR(185, 30000).ok()); // +MX: X30
        QVERIFY(r.ctl->setR(186, 2000000).ok());
        QVERIFY(r.ctl->setR(190, 1).ok()); // end at -MX
        QVERIFY(r.ctl->setR(191, 2).ok()); // two spark-out strokes
        r.load("%L1\nN1 G181\nN2 G4 X3\nN3 G180\nN4 R1=1\n");
        r.start(1);
        // The X setpoint at each reverse point (internal units: one per
        // display discrete on the lathe's diameter axis).
        std::vector<double> stops, afterG180;
        bool resting = true;
        for (int t = 0; t < 30000 && r.ctl->r(1) == 0; ++t) {
            r.tick();
            const bool rest = r.ctl->servo(X).commandVelocity() == 0.0;
            if (rest && !resting)
                (r.ctl->programView().frameNumber == 3 ? afterG180 : stops)
                    .push_back(r.ctl->servo(X).setpoint());
            resting = rest;
            QVERIFY(!r.ctl->oscillating(Z));
        }
        QCOMPARE(r.ctl->r(1), 1);
        QVERIFY2(stops.size() >= 3, qPrintable(QString::number(stops.size())));
        for (std::size_t i = 0; i < stops.size(); ++i) {
            const double want = i % 2 == 0 ? 30000 : 10000; // the farther point first
            QVERIFY2(std::fabs(stops[i] - want) <= 1.0,
                     qPrintable(QString("%1: %2").arg(i).arg(stops[i])));
        }
        // After G180: the stroke in progress ends, two full strokes, and the
        // axis stands at -MX.
        QCOMPARE(int(afterG180.size()), 1 + 2);
        QVERIFY(std::fabs(afterG180.back() - 10000) <= 1.0);
        QVERIFY(std::llabs(r.current(X) - 10000) <= kRestTol);
    }
    // A mode change stops the oscillation; «Пуск» back in АВТОМАТ resumes it.
    void modeChangePauses() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G281 Z-10 FZ3000\nN2 G4 X5\nN3 G280\n");
        r.start(1);
        r.advance(700);
        r.m->setModeCode(2);
        r.advance(400);
        QVERIFY(!r.z().moving);
        const std::int64_t held = r.current(Z);
        r.advance(500);
        QCOMPARE(r.current(Z), held);
        r.m->setModeCode(1);
        r.advance(20);
        r.m->pressStart();
        r.advance(500);
        QVERIFY(r.z().moving);
        QVERIFY(r.ctl->oscillating(Z));
        QVERIFY(r.runToEnd());
        QCOMPARE(r.ctl->state(), ProgramState::Ended);
    }
    // «Сброс» ends the oscillation; so does the end of the program.
    void resetStops() {
        EngineRig r("training-lathe", noHoming);
        r.load("%L1\nN1 G281 Z-10 FZ3000\nN2 G4 X5\n");
        r.start(1);
        r.advance(700);
        QVERIFY(r.ctl->oscillating(Z));
        r.m->pressReset();
        r.advance(500);
        QVERIFY(!r.ctl->oscillating(Z));
        QVERIFY(!r.z().moving);
    }
};

QTEST_APPLESS_MAIN(TestOscillation)
#include "test_oscillation.moc"
