// The engine's small parts on their own: 32-bit arithmetic of computational
// frames, the message registry, the M hand-over protocol, the fast-input map.
#include "engine/alarms.h"
#include "engine/fast_inputs.h"
#include "engine/m_handshake.h"
#include "engine/rparams.h"

#include <QtTest>

using namespace k528::engine;
using k528::program::ArithOp;

class TestEngineParts : public QObject {
    Q_OBJECT
private slots:
    void arithmetic() {
        QCOMPARE(arith(7, ArithOp::Div, 2).value, 3);
        QCOMPARE(arith(-7, ArithOp::Div, 2).value, -3); // toward zero
        QCOMPARE(arith(-7, ArithOp::Div, -2).value, 3);
        QCOMPARE(arith(2147483647, ArithOp::Add, 0).value, 2147483647);
        QVERIFY(!arith(2147483647, ArithOp::Add, 1).ok);
        QVERIFY(!arith(-2147483647 - 1, ArithOp::Sub, 1).ok);
        QVERIFY(arith(-2147483647 - 1, ArithOp::Add, 0).ok);
        QVERIFY(!arith(-2147483647 - 1, ArithOp::Div, -1).ok);
        QVERIFY(!arith(46341, ArithOp::Mul, 46341).ok);
        QCOMPARE(arith(46340, ArithOp::Mul, 46340).value, 2147395600);
        const ArithResult d = arith(1, ArithOp::Div, 0);
        QVERIFY(!d.ok && d.divisionByZero);
        QCOMPARE(arith(5, ArithOp::None, 0).value, 5);
        RStore r;
        r.set(1, 2147483640);
        QVERIFY(r.add(1, 7));
        QVERIFY(!r.add(1, 1));
        QCOMPARE(r[1], 2147483647);
        QVERIFY(rReadOnly(232) && rReadOnly(262) && !rReadOnly(231) && !rReadOnly(263));
    }
    void registry() {
        AlarmRegistry a;
        QVERIFY(a.raise(46, false, 3, 12));
        QVERIFY(!a.raise(46));
        QCOMPARE(a.entry(46).line, 12);
        a.raise(9, true);
        a.acknowledge(AlarmCategory::Fault);
        QVERIFY(a.latched(9)); // still active
        a.clear(9);
        a.acknowledge(AlarmCategory::Fault);
        QVERIFY(!a.latched(9));
        QVERIFY(a.latched(46));
        a.raise(31, true);
        QCOMPARE(a.latchedList(), (std::vector<int>{46, 31}));
        QVERIFY(a.anyActive(AlarmCategory::System));
        a.acknowledge(AlarmCategory::Program);
        QCOMPARE(a.latchedList(), (std::vector<int>{31}));
        QCOMPARE(alarmCategory(42), AlarmCategory::Program);
        QCOMPARE(alarmCategory(55), AlarmCategory::System);
        QCOMPARE(alarmCategory(57), AlarmCategory::Fault);
        QCOMPARE(alarmAxis(23), 1);
        QCOMPARE(alarmAxis(33), 0);
        QCOMPARE(alarmAxis(46), -1);
    }
    void handshake() {
        InterfaceWords w;
        MHandshake h;
        h.setLeadMs(20);
        const int codes[] = {3, 8};
        h.begin(codes, 2, 0);
        QVERIFY(!h.tick(w, 0));
        QCOMPARE(w.field(2001, 0, 7), 3u);
        QVERIFY(!w.bit(z::MStrobe));
        QVERIFY(!h.tick(w, 19));
        QVERIFY(!w.bit(z::MStrobe));
        QVERIFY(!h.tick(w, 20));
        QVERIFY(w.bit(z::MStrobe));
        w.setBit(z::MAcknowledge, true);
        QVERIFY(!h.tick(w, 21));
        QVERIFY(!w.bit(z::MStrobe));
        QVERIFY(!h.tick(w, 22)); // waits for the acknowledgement to drop
        w.setBit(z::MAcknowledge, false);
        QVERIFY(!h.tick(w, 23));
        QCOMPARE(w.field(2001, 0, 7), 8u);
        QVERIFY(!h.tick(w, 43));
        QVERIFY(w.bit(z::MStrobe));
        w.setBit(z::MAcknowledge, true);
        h.tick(w, 44);
        w.setBit(z::MAcknowledge, false);
        QVERIFY(h.tick(w, 45));
        QVERIFY(!h.busy());
        QCOMPARE(w.field(2001, 0, 7), 8u);
        h.begin(codes, 1, 50);
        h.tick(w, 50);
        h.cancel(w);
        QCOMPARE(w.field(2001, 0, 7), 0u);
    }
    void fastInputs() {
        std::array<std::int64_t, 153> c{};
        c[107] = 3; // X1: drive ready
        c[108] = 4; // X2: limit +
        c[111] = 7; // X5: touch (X: active at 0)
        c[115] = 7; // Z1: erase 1 (Z: active at 1)
        FastInputMap m;
        m.configure(c);
        QCOMPARE(m.inputOf(0, FastFunction::LimitPlus), 1);
        QVERIFY(!m.wired(0, FastFunction::DecelCam));
        QVERIFY(m.active(0, FastFunction::DriveReady, 0b00000001));
        QVERIFY(!m.active(0, FastFunction::DriveReady, 0));
        QVERIFY(m.active(0, FastFunction::LimitPlus, 0)); // opened contact
        QVERIFY(!m.active(0, FastFunction::LimitPlus, 0b10));
        QVERIFY(m.active(0, FastFunction::Erase1, 0));
        QVERIFY(!m.active(1, FastFunction::Erase1, 0));
        QVERIFY(m.active(1, FastFunction::Erase1, 1));
        QVERIFY(!m.active(0, FastFunction::DecelCam, 0)); // not wired: never active
    }
};

QTEST_APPLESS_MAIN(TestEngineParts)
#include "test_units_engine.moc"
