// The PLC's scan on a small description and a hand-driven positioner side:
// debounce, timers, latches and edges, the keys of Z1300, the LEDs, the
// message bits, module failures, interlocks, the M hand-over with GOST
// timing, and that skipping idle scans changes nothing.
#include "engine/interface_words.h"
#include "plc/plc.h"

#include <QtTest>
#include <array>
#include <string>

using namespace k528;
namespace z = engine::z;

namespace {

const char* kDescription = R"json({
 "format": 1, "name": "test",
 "plc": {"debounce_ms": 8, "pulse_ms": 20, "m_timing_ms": {"t1": 20, "t2": 20, "t3": 40, "t4": 80}},
 "modules": [{"place": 0, "title": "in"}, {"place": 1, "title": "out"}],
 "inputs": [
   {"name": "btn", "signal": "s.btn", "module": 0},
   {"name": "nc_in", "signal": "s.nc", "contact": "nc", "module": 0},
   {"name": "fast", "signal": "s.fast", "module": 0, "debounce_ms": 0},
   {"name": "other", "signal": "s.other", "module": 1}
 ],
 "outputs": [
   {"name": "lamp", "signal": "lamp.x", "module": 1},
   {"name": "motor", "signal": "m.fwd", "module": 0}
 ],
 "flags": ["f", "latched"],
 "logic": [
   {"timer": "ton", "on_delay_ms": 100, "when": "btn"},
   {"timer": "tof", "off_delay_ms": 50, "when": "btn"},
   {"timer": "tp", "pulse_ms": 30, "when": "btn"},
   {"out": "lamp", "when": "ton"},
   {"set": "latched", "when": "rise(btn)"},
   {"reset": "latched", "when": "other"},
   {"out": "motor", "when": "f"}
 ],
 "m_functions": [
   {"m": 3, "set": ["f"], "done": "other", "wait_work": 2, "timeout_ms": 1000, "timeout_alarm": 5},
   {"m": 9, "reset": ["f"]},
   {"m": 60, "pulse": ["Z1007.0"]}
 ],
 "unknown_m": {"alarm": 7},
 "interlocks": [
   {"name": "il", "when": "other & btn", "feed_hold": true, "start_inhibit": true, "stop_program": true,
    "alarm": 3, "work": 4, "off": ["f"]},
   {"name": "il2", "when": "fast", "latch": true, "estop": true, "data_hold": true, "override_max": 10, "alarm": 30}
 ],
 "keys": [{"key": 1, "toggle": "f"}, {"key": 7, "when": "other", "pulse": "Z1001.0"}],
 "leds": [{"key": 1, "green": "f", "red": "!f"}, {"key": 7, "green": "other"}],
 "alarms": [{"k": 17, "when": "btn"}],
 "work": [{"k": 32, "when": "latched"}],
 "positioner": {
   "estop_ok": "true", "feed_enable": "true", "start_enable": "true", "start": "btn", "stop": "false",
   "data_hold": "false", "acknowledge": "other", "r150": "latched",
   "mode": [{"code": 2, "when": "fast & other"}],
   "override": {"from_plc": "true", "code": ["btn", "other", "fast", "nc_in"]},
   "x": {"jog_plus": "btn", "regulator": "true"}
 }
})json";

struct P {
    plc::Plc plc;
    engine::InterfaceWords pos; // the positioner's side
    std::int64_t now = 0;
    bool everyTick = false;

    P() : plc(plc::readDescription(kDescription, "test.json")) {}
    int in(std::string_view n) { return *plc.inputIndex(n); }
    int out(std::string_view n) { return *plc.outputIndex(n); }
    void set(std::string_view n, bool v) { plc.setInput(in(n), v); }
    bool sig(std::string_view n) { return *plc.signal(n); }
    bool zb(engine::ZBit b) { return pos.bit(b); }
    void tick() {
        plc.readPositioner(pos);
        if (everyTick || plc.scanDue(now)) {
            plc.scan(now);
            plc.writePositioner(pos);
        }
        ++now;
    }
    void run(int ms) {
        for (int i = 0; i < ms; ++i)
            tick();
    }
};

} // namespace

class TestPlc : public QObject {
    Q_OBJECT
private slots:
    // GOST 26642 6.1.7: insensitive to bounce for 5..10 ms.
    void debounce() {
        P p;
        p.run(5);
        QVERIFY(!p.sig("btn"));
        p.set("btn", true);
        p.run(7);
        QVERIFY(!p.sig("btn"));
        p.run(2);
        QVERIFY(p.sig("btn"));
        // A glitch shorter than the debounce time is not seen.
        p.set("btn", false);
        p.run(5);
        p.set("btn", true);
        p.run(20);
        QVERIFY(p.sig("btn"));
        // A bouncing contact: counted from its last change.
        p.set("btn", false);
        p.tick();
        p.set("btn", true);
        p.tick();
        p.set("btn", false);
        p.tick();
        p.set("btn", true);
        p.tick();
        p.set("btn", false);
        const std::int64_t settled = p.now;
        for (int i = 0; i < 30 && p.sig("btn"); ++i)
            p.tick();
        QVERIFY(!p.sig("btn"));
        QVERIFY(p.now - settled >= 8 && p.now - settled <= 9);
        // An input without debounce follows at once.
        p.set("fast", true);
        p.tick();
        QVERIFY(p.sig("fast"));
    }

    // The levels at power-on are taken as they are (the filter starts settled).
    void levelsAtPowerOn() {
        P p;
        p.set("nc_in", true);
        p.tick();
        QVERIFY(p.sig("nc_in"));
    }

    void timersLatchesEdges() {
        P p;
        p.run(3);
        p.set("btn", true);
        p.run(9); // debounced at 8
        QVERIFY(p.sig("btn"));
        QVERIFY(p.sig("tof") && p.sig("tp") && !p.sig("ton"));
        QVERIFY(p.sig("latched"));
        QVERIFY(p.zb(z::R150Bit));
        p.run(30);
        QVERIFY(!p.sig("tp")); // 30 ms pulse
        p.run(70);
        QVERIFY(p.sig("ton") && p.plc.output(p.out("lamp")));
        p.set("btn", false);
        p.run(9);
        QVERIFY(!p.sig("ton") && p.sig("tof"));
        p.run(50);
        QVERIFY(!p.sig("tof"));
        QVERIFY(p.sig("latched")); // set on the edge only, reset by `other`
        p.set("other", true);
        p.run(9);
        QVERIFY(!p.sig("latched"));
        QVERIFY(!p.zb(z::R150Bit));
    }

    // Keys of Z1300 (table 4): K1 is bit 0, K7 bit 8; the PLC clears them.
    void keysAndLeds() {
        P p;
        p.run(2);
        QVERIFY(p.zb({1907, 0}) && !p.zb({1906, 0})); // K1 red: f off
        p.pos.setBit({1300, 0}, true);
        p.run(2);
        QVERIFY(!p.pos.bit({1300, 0}));
        QVERIFY(p.sig("f") && p.plc.output(p.out("motor")));
        QVERIFY(p.zb({1906, 0}) && !p.zb({1907, 0}));
        // K7: bit 8; its condition `other` is false: taken but no action.
        p.pos.setBit({1300, 8}, true);
        p.run(2);
        QVERIFY(!p.pos.bit({1300, 8}));
        QVERIFY(!p.zb(z::startCycle(1)));
        p.set("other", true);
        p.run(9);
        QVERIFY(p.zb({1906, 8}));
        p.pos.setBit({1300, 8}, true);
        p.run(2);
        QVERIFY(p.zb(z::startCycle(1))); // a pulse of pulse_ms
        p.run(20);
        QVERIFY(!p.zb(z::startCycle(1)));
        // K1 again toggles f off.
        p.pos.setBit({1300, 0}, true);
        p.run(2);
        QVERIFY(!p.sig("f"));
    }

    // Message bits: alarm k on Z1900/Z1901 bit k-1, work k on Z1902/Z1903.
    void messageBits() {
        P p;
        p.set("btn", true);
        p.run(10);
        QVERIFY(p.zb({1901, 0}));  // alarm 17
        QVERIFY(p.zb({1903, 15})); // work 32 (latched)
        p.set("btn", false);
        p.run(10);
        QVERIFY(!p.zb({1901, 0}));
    }

    // A failed module: its inputs read 0, its outputs drop, Z1307.place.
    void moduleFailure() {
        P p;
        p.set("other", true);
        p.set("btn", true);
        p.run(120);
        QVERIFY(p.plc.output(p.out("lamp")));
        p.plc.setModuleFailed(1, true);
        QVERIFY(!p.plc.output(p.out("lamp"))); // at once
        p.run(10);
        QVERIFY(p.zb({1307, 1}));
        QVERIFY(!p.sig("other"));
        QVERIFY(p.sig("btn"));
        p.plc.setModuleFailed(1, false);
        p.run(10);
        QVERIFY(!p.zb({1307, 1}));
        QVERIFY(p.sig("other"));
    }

    void interlocks() {
        P p;
        p.run(2);
        QVERIFY(p.zb(z::FeedEnable) && p.zb(z::StartEnable) && p.zb(z::EmergencyStopOk));
        p.pos.setBit({1300, 0}, true); // K1: f on
        p.run(2);
        QVERIFY(p.sig("f"));
        p.set("other", true);
        p.set("btn", true);
        p.run(9);
        QVERIFY(*p.plc.signal("il"));
        QVERIFY(!p.zb(z::FeedEnable) && !p.zb(z::StartEnable));
        QVERIFY(p.zb(z::Stop)); // «Стоп» pulse when it trips
        QVERIFY(p.zb({1900, 2}) && p.zb({1902, 3}));
        QVERIFY(!p.sig("f")); // forced off
        p.run(25);
        QVERIFY(!p.zb(z::Stop));
        p.set("btn", false);
        p.run(10);
        QVERIFY(p.zb(z::FeedEnable) && !p.zb({1900, 2}));
        // il2: latched until acknowledged (Z1000.7 = `other`) once the cause is gone.
        p.set("other", false);
        p.run(10);
        p.set("fast", true);
        p.run(2);
        QVERIFY(!p.zb(z::EmergencyStopOk) && p.zb(z::DataHold));
        QVERIFY(p.zb({1901, 13})); // alarm 30
        // override capped at 10 % (code 4) with the code from the PLC.
        QVERIFY(p.zb(z::OverrideFromPlc));
        QCOMPARE(p.pos.field(1001, 12, 4), 4u); // code bits: fast = 4
        p.set("nc_in", true);
        p.set("btn", true);
        p.run(10);
        QCOMPARE(p.pos.field(1001, 12, 4), 4u); // 13 -> 10 % cap (code 4)
        p.set("nc_in", false);
        p.set("btn", false);
        p.set("fast", false);
        p.run(5);
        QVERIFY(!p.zb(z::EmergencyStopOk)); // still latched
        p.set("other", true);
        p.run(10);
        QVERIFY(p.zb(z::EmergencyStopOk));
        QVERIFY(!*p.plc.signal("il2"));
    }

    void modeCode() {
        P p;
        p.set("other", true);
        p.set("fast", true);
        p.run(10);
        QCOMPARE(p.pos.field(z::ModeCodeWord, z::ModeCodeFirst, z::ModeCodeWidth), 2u);
        p.set("fast", false);
        p.run(3);
        QCOMPARE(p.pos.field(z::ModeCodeWord, z::ModeCodeFirst, z::ModeCodeWidth), 0u);
    }

    // GOST 26642 §6.4 as the PLC plays it: the code is read at the strobe,
    // acknowledged when done and no earlier than T3, dropped with the strobe;
    // M pulses last T4.
    void mFunctionHandshake() {
        P p;
        p.run(5);
        p.pos.setField(z::MCodeWord, z::MCodeFirst, z::MCodeWidth, 3);
        p.run(20);
        QVERIFY(!p.sig("f")); // no strobe: nothing happens
        p.pos.setBit(z::MStrobe, true);
        p.run(1);
        QVERIFY(p.sig("f"));
        QVERIFY(p.plc.mBusy());
        p.run(100);
        QVERIFY(!p.zb(z::MAcknowledge)); // `other` not yet
        QVERIFY(p.zb({1902, 1}));        // work 2 while waiting
        p.set("other", true);
        p.run(7);
        QVERIFY(!p.zb(z::MAcknowledge));
        p.run(3);
        QVERIFY(p.zb(z::MAcknowledge));
        QVERIFY(!p.zb({1902, 1}));
        p.pos.setBit(z::MStrobe, false);
        p.run(1);
        QVERIFY(!p.zb(z::MAcknowledge));
        const plc::MEvent e = p.plc.mLog().back();
        QCOMPARE(e.code, 3);
        QCOMPARE(e.strobeMs - e.codeMs, 20);
        QVERIFY(e.ackMs > e.strobeMs + 100);
        QVERIFY(e.dropMs > e.ackMs);

        // A function done at once is still acknowledged only after T3.
        p.pos.setField(z::MCodeWord, z::MCodeFirst, z::MCodeWidth, 9);
        p.run(20);
        p.pos.setBit(z::MStrobe, true);
        const std::int64_t t0 = p.now;
        while (!p.zb(z::MAcknowledge) && p.now < t0 + 200)
            p.tick();
        QCOMPARE(p.now - 1 - t0, 40);
        QVERIFY(!p.sig("f"));
        p.pos.setBit(z::MStrobe, false);
        p.run(2);

        // M60: a pulse on Z1007.0 of T4.
        p.pos.setField(z::MCodeWord, z::MCodeFirst, z::MCodeWidth, 60);
        p.run(20);
        p.pos.setBit(z::MStrobe, true);
        p.run(1);
        QVERIFY(p.zb(z::roughDressComp(axis::AxisId::X)));
        p.run(78);
        QVERIFY(p.zb(z::roughDressComp(axis::AxisId::X)));
        p.run(2);
        QVERIFY(!p.zb(z::roughDressComp(axis::AxisId::X)));
        p.pos.setBit(z::MStrobe, false);
        p.run(2);

        // Time-out: the alarm while the function waits.
        p.set("other", false);
        p.run(10);
        p.pos.setField(z::MCodeWord, z::MCodeFirst, z::MCodeWidth, 3);
        p.run(20);
        p.pos.setBit(z::MStrobe, true);
        p.run(990);
        QVERIFY(!p.zb({1900, 4}));
        p.run(20);
        QVERIFY(p.zb({1900, 4}));
        QVERIFY(p.plc.mLog().back().timedOut);
        // «Сброс»: the positioner drops the strobe; the alarm bit goes.
        p.pos.setBit(z::MStrobe, false);
        p.run(2);
        QVERIFY(!p.zb({1900, 4}));

        // An unknown M: alarm 7 and no acknowledgement.
        p.pos.setField(z::MCodeWord, z::MCodeFirst, z::MCodeWidth, 42);
        p.run(20);
        p.pos.setBit(z::MStrobe, true);
        p.run(300);
        QVERIFY(!p.zb(z::MAcknowledge));
        QVERIFY(p.zb({1900, 6}));
        QVERIFY(!p.plc.mLog().back().described);
    }

    // The link to the positioner lost: link_ok = 0, Z2000..Z2008 read 0.
    void lostLink() {
        P p;
        p.pos.setBit(z::Ready, true);
        p.run(3);
        QCOMPARE(p.plc.signal("Z2000.0"), std::optional<bool>(true));
        QCOMPARE(p.plc.signal("link_ok"), std::optional<bool>(true));
        p.plc.setLinkOk(false);
        p.run(3);
        QCOMPARE(p.plc.signal("Z2000.0"), std::optional<bool>(false));
        QCOMPARE(p.plc.signal("link_ok"), std::optional<bool>(false));
        p.plc.setLinkOk(true);
        p.run(3);
        QCOMPARE(p.plc.signal("Z2000.0"), std::optional<bool>(true));
    }

    // The words bit for bit: every bit of Z2000..Z2008 is its signal
    // Z<word>.<bit> after a scan (the scan unpacks eight at a time), and the
    // PLC's own image of the words holds them; the messages it packs into
    // Z1900.. read back as the signals.
    void wordsBitForBit() {
        P p;
        p.run(3);
        std::uint32_t seed = 77;
        const auto rnd = [&] {
            seed = seed * 1103515245u + 12345u;
            return static_cast<std::uint16_t>(seed >> 8);
        };
        for (int round = 0; round < 50; ++round) {
            std::array<std::uint16_t, 9> v{};
            for (int a = 2000; a <= 2008; ++a) {
                v[static_cast<std::size_t>(a - 2000)] = round == 0 ? 0xFFFF : round == 1 ? 0 : rnd();
                p.pos.setWord(a, v[static_cast<std::size_t>(a - 2000)]);
            }
            p.tick();
            for (int a = 2000; a <= 2008; ++a) {
                QCOMPARE(p.plc.words().word(a), v[static_cast<std::size_t>(a - 2000)]);
                for (int b = 0; b < 16; ++b)
                    QCOMPARE(p.sig("Z" + std::to_string(a) + "." + std::to_string(b)),
                             ((v[static_cast<std::size_t>(a - 2000)] >> b) & 1u) != 0);
            }
        }
        p.set("btn", true); // alarm 17 (Z1901.0), interlock-free
        p.run(20);
        for (int a : {1900, 1901, 1902, 1903}) {
            std::uint16_t packed = 0;
            for (int b = 0; b < 16; ++b)
                packed = static_cast<std::uint16_t>(
                    packed | (p.sig("Z" + std::to_string(a) + "." + std::to_string(b)) ? 1u << b : 0u));
            QCOMPARE(p.pos.word(a), packed);
        }
        QVERIFY((p.pos.word(1901) & 1u) != 0);
    }

    // Skipping scans that could change nothing is exact: the same inputs
    // give the same words and outputs every tick as scanning every tick.
    void skippingIsExact() {
        P a, b;
        b.everyTick = true;
        std::uint32_t seed = 12345;
        const auto rnd = [&] {
            seed = seed * 1103515245u + 12345u;
            return (seed >> 16) & 0x7FFF;
        };
        const char* names[] = {"btn", "nc_in", "fast", "other"};
        for (int t = 0; t < 20000; ++t) {
            const unsigned r = rnd();
            if (r % 97 == 0) {
                const char* n = names[r % 4];
                const bool v = (r >> 8) & 1u;
                a.set(n, v);
                b.set(n, v);
            }
            if (r % 499 == 0) {
                const int key = 1 + static_cast<int>(r % 12);
                a.pos.setBit({1300, z::keyBit(key)}, true);
                b.pos.setBit({1300, z::keyBit(key)}, true);
            }
            if (r % 877 == 0) {
                const unsigned code = (r >> 4) % 100;
                for (P* p : {&a, &b}) {
                    p->pos.setField(z::MCodeWord, z::MCodeFirst, z::MCodeWidth, code);
                }
            }
            if (r % 311 == 0) {
                const bool s = (r >> 5) & 1u;
                a.pos.setBit(z::MStrobe, s);
                b.pos.setBit(z::MStrobe, s);
            }
            a.tick();
            b.tick();
            QVERIFY2(a.pos == b.pos, qPrintable(QString("tick %1").arg(t)));
            for (int o = 0; o < a.plc.outputCount(); ++o)
                QCOMPARE(a.plc.output(o), b.plc.output(o));
        }
        QVERIFY(a.plc.scans() < b.plc.scans() / 4);
    }
};

QTEST_APPLESS_MAIN(TestPlc)
#include "test_plc.moc"
