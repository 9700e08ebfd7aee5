// The panel around the screens: modes through the engine (F keys, the
// password, a mode the PLC imposes), K keys and LEDs (table 4), L keys,
// SHIFT, ESC per C123..C125, the service marks and HELP lists, and the
// АВТ/РУЧ/ПБТ screens drawn from a machine that moves.
#include "engine/interface_words.h"
#include "rig/panel_rig.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;
namespace z = k528::engine::z;

class TestPanel : public QObject {
    Q_OBJECT
private slots:
    // --- modes and the password -----------------------------------------------------
    void functionKeysSelectModes() {
        PanelRig r;
        const Mode modes[] = {Mode::Auto, Mode::Manual, Mode::Reference, Mode::SetActual};
        for (int f = 1; f <= 4; ++f) {
            r.p->press(static_cast<Key>(static_cast<int>(Key::F1) + f - 1));
            QCOMPARE(r.c().mode(), modes[f - 1]);
            QCOMPARE(r.p->shownMode(), modes[f - 1]);
        }
    }

    void passwordRight() {
        for (const char* f : {"F5", "F6", "F7"}) {
            PanelRig r;
            r.keys(f);
            QVERIFY(r.p->passwordShown());
            QCOMPARE(r.c().mode(), Mode::Manual); // the mode changes after the password
            r.keys("1 1 1 1 ENTER");
            QVERIFY(!r.p->passwordShown());
            QCOMPARE(int(r.c().mode()), f[1] - '0');
            QCOMPARE(r.p->access(), panel::Access::Full);
        }
    }

    void passwordWrong() {
        {
            PanelRig r;
            r.keys("F5 1 1 1 2 ENTER");
            QCOMPARE(r.c().mode(), Mode::MachineData); // open for viewing
            QCOMPARE(r.p->access(), panel::Access::ViewOnly);
        }
        {
            PanelRig r; // the password has four digits: a fifth is not taken
            r.keys("F6 1 1 1 1 1");
            QCOMPARE(r.p->passwordScreen().typed(), std::string("1111"));
            r.keys("ENTER");
            QVERIFY(!r.p->passwordShown());
            QCOMPARE(r.c().mode(), Mode::ProgramEdit);
        }
        for (const char* f : {"F6", "F7"}) {
            PanelRig r;
            r.keys("F1");
            r.keys(f);
            r.keys("1 2 1 2 ENTER");
            QVERIFY(r.p->passwordShown());
            QVERIFY(r.p->passwordScreen().closed());
            QCOMPARE(r.c().mode(), Mode::Auto); // closed: the mode stays
            QCOMPARE(r.lines(), expect({"ПАРОЛЬ?", ">", "ДОСТУП ЗАКРЫТ", ""}));
            r.keys("ESC");
            QCOMPARE(r.line(0), QString("АВТ            100%"));
        }
    }

    // The password opens the mode for as long as it is shown.
    void passwordAskedOnEveryEntry() {
        PanelRig r;
        r.keys("F6 1 1 1 1 ENTER ENTER");
        QCOMPARE(r.p->programScreens().page(), panel::ProgramEditScreens::Page::Catalog);
        r.keys("F6"); // already open: its menu, no password
        QVERIFY(!r.p->passwordShown());
        QCOMPARE(r.p->programScreens().page(), panel::ProgramEditScreens::Page::Menu);
        r.keys("F7");
        QVERIFY(r.p->passwordShown());
        r.keys("1 1 1 1 ENTER F6");
        QVERIFY(r.p->passwordShown());
        r.keys("F2 F6");
        QVERIFY(r.p->passwordShown());
    }

    // Z1000.8-10 != 0: the PLC sets the mode, the F keys are refused.
    void modeImposedByThePlc() {
        PanelRig r;
        r.m->setModeCode(1);
        r.m->tick();
        QCOMPARE(r.c().mode(), Mode::Auto);
        QCOMPARE(r.line(0), QString("АВТ            100%"));
        r.keys("F2");
        QCOMPARE(r.c().mode(), Mode::Auto);
        QCOMPARE(r.lines(), expect({"АВТ            100%", "РЕЖИМ ЗАДАН ПЛК",
                                    " X    0.000    0.000", " Z    0.000    0.000"}));
        r.keys("MODE"); // the line goes with the next key
        QCOMPARE(r.lines(), expect({"АВТ            100%", "", " X    0.000 F=  0.00",
                                    " Z    0.000 F=  0.00"}));
        r.keys("F6");
        QVERIFY(!r.p->passwordShown());
        QCOMPARE(r.line(1), QString("РЕЖИМ ЗАДАН ПЛК"));
        r.keys("F1"); // the mode it is in: its first screen
        QCOMPARE(r.line(1), QString(""));
        QCOMPARE(r.line(2), QString(" X    0.000    0.000"));
        // The PLC lets go: the mode stays, the keys work again.
        r.m->setModeCode(0);
        r.m->tick();
        QCOMPARE(r.c().mode(), Mode::Auto);
        r.keys("F3");
        QCOMPARE(r.c().mode(), Mode::Reference);
    }

    // A protected mode set by the PLC: the panel asks the password there.
    void protectedModeImposed() {
        PanelRig r;
        r.keys("F4 3");
        r.m->setModeCode(6);
        r.m->tick();
        QCOMPARE(r.c().mode(), Mode::ProgramEdit);
        QCOMPARE(r.lines(), expect({"ПАРОЛЬ?", ">", "", ""}));
        r.keys("ESC"); // nothing to go back to
        QVERIFY(r.p->passwordShown());
        r.keys("4 4 4 4 ENTER");
        QCOMPARE(r.lines(), expect({"ПАРОЛЬ?", ">", "ДОСТУП ЗАКРЫТ", ""}));
        r.keys("1 1 1 1 ENTER");
        QCOMPARE(r.lines(),
                 expect({"РЕДАКТИРОВАНИЕ УП", " ПРОГРАММА 1", ">КАТАЛОГ", " ОЧИСТИТЬ УП"}));
        r.m->setModeCode(5);
        r.m->tick();
        r.keys("0 0 0 0 ENTER");
        QCOMPARE(r.p->access(), panel::Access::ViewOnly);
        QCOMPARE(r.line(0), QString("ПАРАМЕТРЫ СТАНКА"));
    }

    // --- K keys, LEDs, L keys, SHIFT ------------------------------------------------
    void kKeysSetZ1300() {
        PanelRig r;
        const int bits[] = {0, 1, 2, 3, 4, 5, 8, 9, 10, 11, 12, 13};
        for (int k = 1; k <= 12; ++k) {
            r.c().words().setWord(z::KeysWord, 0); // the PLC took the previous one
            r.p->press(static_cast<Key>(static_cast<int>(Key::K1) + k - 1));
            QCOMPARE(int(r.c().words().word(z::KeysWord)), 1 << bits[k - 1]);
        }
        // Pressed again before the PLC clears: the bits add up; the screen stays.
        r.c().words().setWord(z::KeysWord, 0);
        r.keys("F4 K1 K7");
        QCOMPARE(int(r.c().words().word(z::KeysWord)), (1 << 0) | (1 << 8));
        QCOMPARE(r.line(0), QString("УСТ ПРЕДУСТАНОВКИ"));
    }

    void ledsFollowZ1906Z1907() {
        PanelRig r;
        QCOMPARE(r.display().leds.green, std::uint16_t(0));
        r.c().words().setWord(z::GreenLedsWord, 0x0101); // K1 and K7
        r.c().words().setWord(z::RedLedsWord, 0x2020);   // K6 and K12
        const panel::Leds l = r.display().leds;
        QCOMPARE(l.green, std::uint16_t((1u << 0) | (1u << 6)));
        QCOMPARE(l.red, std::uint16_t((1u << 5) | (1u << 11)));
        QVERIFY(l.greenOn(1) && l.greenOn(7) && !l.greenOn(2));
        QVERIFY(l.redOn(6) && l.redOn(12) && !l.redOn(1));
        r.c().words().setWord(z::GreenLedsWord, 0x00C0); // bits 6, 7: no key
        QCOMPARE(r.display().leds.green, std::uint16_t(0));
    }

    // Table М.1: the K923's own messages, and what the hardware does then.
    void k923Health() {
        {
            PanelRig r; // no link to the PLC: screens work, K keys and their LEDs do not
            r.p->setHealth({.plcLink = false});
            r.c().words().setWord(z::GreenLedsWord, 0x0101);
            QCOMPARE(r.line(1), QString("НЕТ СВЯЗИ С ПЛК"));
            QCOMPARE(r.display().leds.green, std::uint16_t(0));
            QVERIFY(r.display().leds.overrideOn(4)); // the positioner's override
            r.keys("K1");
            QCOMPARE(int(r.c().words().word(z::KeysWord)), 0);
            r.keys("F1");
            QCOMPARE(r.c().mode(), Mode::Auto);
            QCOMPARE(r.line(0), QString("АВТ            100%"));
            QCOMPARE(r.line(1), QString("НЕТ СВЯЗИ С ПЛК"));
            r.p->setHealth({});
            QCOMPARE(r.line(1), QString());
            QCOMPARE(r.display().leds.green, std::uint16_t((1u << 0) | (1u << 6)));
        }
        {
            PanelRig r; // no link to the positioner: no screens, no modes; K keys still go
            r.p->setHealth({.positionerLink = false});
            QCOMPARE(r.lines(), expect({"НЕТ СВЯЗИ С БП", "", "", ""}));
            r.keys("F1");
            QCOMPARE(r.c().mode(), Mode::Manual);
            r.keys("K1");
            QCOMPARE(int(r.c().words().word(z::KeysWord)), 1);
        }
        for (const bool ram : {false, true}) {
            PanelRig r; // the K923 itself is down: its message and nothing else
            r.p->setHealth(ram ? panel::Health{.ramOk = false} : panel::Health{.residentOk = false});
            r.c().words().setWord(z::GreenLedsWord, 0x0101);
            QCOMPARE(r.lines(), expect({ram ? "НЕИСПРАВНО ОЗУ" : "НАРУШЕН РЕЗИДЕНТ", "", "", ""}));
            QCOMPARE(r.display().leds, panel::Leds{});
            r.keys("F1 K1");
            QCOMPARE(r.c().mode(), Mode::Manual);
            QCOMPARE(int(r.c().words().word(z::KeysWord)), 0);
        }
        {
            PanelRig r; // the PLC in debug stop: line 2, until a key's own message
            r.p->setHealth({.plcStopped = true});
            QCOMPARE(r.line(1), QString("Режим ПЛК СТОП !"));
            r.keys("F2 MODE MODE PAR 2 4 0 ENTER 5 ENTER"); // R240 is read only
            QCOMPARE(r.line(1), QString("ОШИБКА ВВОДА"));
            r.keys("DOWN"); // the next key takes it away
            QCOMPARE(r.line(1), QString("Режим ПЛК СТОП !"));
        }
    }

    void overrideKeys() {
        PanelRig r;
        // Power-on: 100 %, the code of L4 (C142 = 10).
        QCOMPARE(r.display().leds.override, std::uint8_t(1u << 3));
        r.keys("L2");
        QCOMPARE(r.c().programView().overridePercent, 20); // C140 = 5
        QCOMPARE(r.display().leds.override, std::uint8_t(1u << 1));
        QCOMPARE(r.line(0), QString("РУЧ             20%"));
        r.keys("L1");
        QCOMPARE(r.c().programView().overridePercent, 0);
        QCOMPARE(r.display().leds.override, std::uint8_t(1u << 0));
        // The PLC sets the override (Z1001.11): no L key is in effect.
        r.m->setOverrideCode(8);
        r.m->tick();
        QCOMPARE(r.line(0), QString("РУЧ             75%"));
        QCOMPARE(r.display().leds.override, std::uint8_t(0));
    }

    void shiftLatches() {
        PanelRig r;
        r.keys("F4 SHIFT");
        QVERIFY(r.display().leds.shift);
        r.keys("DOWN");
        QVERIFY(!r.display().leds.shift);
        QCOMPARE(r.p->presetScreens().menuMarker(), 3);
        r.keys("SHIFT SHIFT DOWN"); // SHIFT again cancels
        QCOMPARE(r.p->presetScreens().menuMarker(), 4);
    }

    // --- ESC (C123..C125) --------------------------------------------------------
    void escAcknowledgesMachineFaults() {
        for (const bool enabled : {true, false}) {
            PanelRig r([&](profile::MachineProfile& p) { p.setC(124, enabled ? 1 : 0); });
            r.m->setPlcAlarm(1, true);
            r.m->tick();
            r.m->setPlcAlarm(1, false);
            r.m->tick();
            QCOMPARE(r.c().plcMessages().alarms, 1u); // stays until acknowledged
            r.keys("F4 2 5");                         // typing: ESC only restores the field
            r.keys("ESC");
            QCOMPARE(r.c().plcMessages().alarms, 1u);
            QCOMPARE(r.line(2), QString(">R220=200.000"));
            r.keys("ESC");
            QCOMPARE(r.c().plcMessages().alarms, enabled ? 0u : 1u);
        }
    }

    void escAcknowledgesSystemMessages() {
        for (const bool enabled : {true, false}) {
            PanelRig r([&](profile::MachineProfile& p) { p.setC(125, enabled ? 1 : 0); });
            r.m->setPlcSystem(2, true);
            r.m->tick();
            r.m->setPlcSystem(2, false);
            r.m->tick();
            QCOMPARE(r.c().plcMessages().system, std::uint16_t(2));
            QVERIFY(r.c().alarmRegistry().latched(55));
            r.keys("ESC");
            QCOMPARE(r.c().plcMessages().system, std::uint16_t(enabled ? 0 : 2));
            QCOMPARE(r.c().alarmRegistry().latched(55), !enabled);
        }
    }

    void escResets() {
        for (const bool enabled : {true, false}) {
            PanelRig r([&](profile::MachineProfile& p) {
                noHoming(p);
                p.setC(123, enabled ? 1 : 0);
            });
            r.load("%L7\nN1 G4 X20\nN2 M30\n");
            r.keys("F1 ACK 7 ENTER");
            r.m->pressStart();
            r.m->advance(100);
            QCOMPARE(r.c().state(), engine::ProgramState::Dwell);
            r.keys("ESC");
            QCOMPARE(r.c().state(),
                     enabled ? engine::ProgramState::Idle : engine::ProgramState::Dwell);
        }
    }

    // --- service marks and HELP lists ------------------------------------------------
    void workMessages() {
        PanelRig r;
        r.m->setPlcWork(1, true);
        r.m->setPlcWork(3, true);
        r.m->tick();
        QCOMPARE(r.line(0), QString("РУЧ            100%*"));
        r.keys("HELP");
        QCOMPARE(r.line(0), QString(">1 - СООБЩЕНИЯ")); // no mark on the service screens
        r.keys("1");
        QCOMPARE(r.lines(), expect({"СООБЩЕНИЯ        1/2", "Закройте дверь", "", ""}));
        r.keys("DOWN");
        QCOMPARE(r.lines(), expect({"СООБЩЕНИЯ        2/2", "Шпиндель вращается", "", ""}));
        r.keys("DOWN"); // the empty screen between the last and the first
        QCOMPARE(r.lines(), expect({"СООБЩЕНИЯ", "", "", ""}));
        r.keys("DOWN");
        QCOMPARE(r.line(1), QString("Закройте дверь"));
        r.keys("UP");
        QCOMPARE(r.lines(), expect({"СООБЩЕНИЯ", "", "", ""}));
        r.keys("UP");
        QCOMPARE(r.line(1), QString("Шпиндель вращается"));
        // Work messages go when their bit goes (no acknowledgement).
        r.m->setPlcWork(3, false);
        r.m->tick();
        QCOMPARE(r.lines(), expect({"СООБЩЕНИЯ", "", "", ""}));
        r.keys("HELP");
        QCOMPARE(r.line(0), QString("РУЧ            100%*"));
    }

    // ПРЕДУСТАНОВКИ as 2.6.5 prints them: the «MX:» hint shows the machine
    // coordinate («MX: -123.456»), R167 ДОПУСК two decimals («R167 = 1.00»).
    void presetsHintAndTolerance() {
        PanelRig r;
        r.keys("F2");
        r.m->setJog(engine::AxisId::X, -1);
        r.m->advance(500);
        r.m->setJog(engine::AxisId::X, 0);
        r.m->advance(500);
        const engine::AxisView x = r.c().axisView(engine::AxisId::X);
        QVERIFY(x.machineDisc < -100);
        r.keys("F4 2");
        const QString hint = r.line(1).trimmed();
        QVERIFY2(hint.startsWith("MX: -"), qPrintable(hint));
        QCOMPARE(std::llround(hint.mid(4).toDouble() * 1000.0), static_cast<long long>(x.machineDisc));
        r.keys("DOWN");
        QCOMPARE(r.line(1).trimmed(), QString("MZ: 0.000"));
        r.c().setR(167, 1000);
        r.keys("F4 MODE 9 SHIFT+DOWN");
        QVERIFY2(r.lines().join("|").contains("R167=1.00|") || r.lines().join("|").endsWith("R167=1.00"),
                 qPrintable(r.lines().join("|")));
    }

    void faults() {
        PanelRig r;
        r.m->setEmergencyStop(true);
        r.m->setPlcAlarm(2, true);
        r.m->tick();
        QCOMPARE(r.line(0), QString("РУЧ            100%!"));
        r.keys("HELP 2");
        // 9 first (the positioner's, in the order they came), then the PLC's.
        QCOMPARE(r.lines(), expect({"НЕИСПРАВНОСТИ    1/2", "9.Аварийный «СТОП»", "от ПЛК", ""}));
        r.keys("DOWN");
        QCOMPARE(r.lines(), expect({"НЕИСПРАВНОСТИ    2/2", "Перегрев двигателя", "шпинделя", ""}));
        // Gone but not acknowledged: still listed.
        r.m->setEmergencyStop(false);
        r.m->setPlcAlarm(2, false);
        r.m->tick();
        QCOMPARE(r.line(0), QString("НЕИСПРАВНОСТИ    2/2"));
        r.keys("ESC"); // C124 = 1: acknowledged, the list is empty
        QCOMPARE(r.lines(), expect({"НЕИСПРАВНОСТИ", "", "", ""}));
        r.keys("HELP");
        QCOMPARE(r.line(0), QString("РУЧ            100%"));
    }

    void systemMessagesAndMarkOrder() {
        PanelRig r;
        r.m->setPlcWork(1, true);
        r.m->setPlcSystem(1, true);
        r.m->tick();
        QCOMPARE(r.line(0), QString("РУЧ            100%?")); // «?» before «*»
        r.keys("HELP 3");
        QCOMPARE(r.lines(),
                 expect({"СИСТЕМА          1/2", "55. Отказ модулей", "ввода/вывода в ПЛК", ""}));
        r.keys("DOWN");
        QCOMPARE(r.lines(), expect({"СИСТЕМА          2/2", "Отказ модуля ПЛК,", "место 0", ""}));
        r.m->setPlcAlarm(12, true);
        r.m->tick();
        r.keys("HELP");
        QCOMPARE(r.line(0), QString("РУЧ            100%!")); // «!» before «?»
        r.keys("F4 9");
        QCOMPARE(r.line(0), QString("УСТ9 ОСЕВ.ОРИЕНТАЦИ!")); // column 20 of every title line
    }

    // A PLC message without a text in the profile shows its address.
    void plcMessageWithoutText() {
        PanelRig r([](profile::MachineProfile& p) { p.plcAlarm.erase(30); });
        r.m->setPlcAlarm(30, true);
        r.m->tick();
        r.keys("HELP 2");
        QCOMPARE(r.line(1), QString("Z1901.13"));
    }

    // --- screens of a moving machine -------------------------------------------------
    // The manual's example coordinates, set with «установка фактического значения».
    void manualsCoordinates() {
        PanelRig r;
        r.keys("F4 1 2 3 4 . 5 6 7 ENTER RIGHT - 1 0 6 5 . 1 2 4 ENTER F1");
        QCOMPARE(r.lines(), expect({"АВТ            100%", "", " X  234.567    0.000",
                                    " Z-1065.124    0.000"}));
        r.keys("MODE");
        QCOMPARE(r.lines(), expect({"АВТ            100%", "", " X  234.567 F=  0.00",
                                    " Z-1065.124 F=  0.00"}));
        r.keys("F3");
        QCOMPARE(r.lines(),
                 expect({"ПБТ            100%", "", " X  234.567#0.000", " Z-1065.124#0.000"}));
    }

    void jogShowsMotion() {
        PanelRig r;
        r.keys("MODE"); // РУЧ screen 2
        r.m->setJog(X, 1);
        r.m->advance(2000);
        QVERIFY(r.c().axisView(X).moving);
        // F ОБЫЧНАЯ X = 150000 (10·discrete/min) = 1500 mm/min: 6 columns, one decimal.
        QVERIFY2(r.line(2).startsWith("*X") && r.line(2).endsWith(" F=1500.0"),
                 qPrintable(r.line(2)));
        QCOMPARE(r.line(3), QString(" Z    0.000 F=  0.00"));
        const QString cur = QString::fromStdString(
            units::formatDisc(r.c().axisView(X).currentDisc, r.c().axisView(X).scale));
        QCOMPARE(r.line(2), "*X" + cur.rightJustified(9) + " F=1500.0");
        // Screen 1: a jog without soft limits (not homed) has no end point:
        // the remaining path (R244) is 0.
        r.keys("MODE MODE");
        const engine::AxisView v = r.c().axisView(X);
        QCOMPARE(v.remainingDisc, std::int64_t(0));
        QCOMPARE(r.line(2), "*X" + QString::fromStdString(units::formatDisc(v.currentDisc, v.scale))
                                       .rightJustified(9) + "    0.000");
        r.m->setJog(X, 0);
        r.m->advance(3000);
        QVERIFY(r.line(2).startsWith(" X"));
    }

    void programMessageLine() {
        PanelRig r(noHoming);
        r.load("%L7\nN1 #3 G4 X5\nN2 #4 G4 X5\nN3 M30\n");
        r.keys("F1 ACK 7 ENTER");
        r.m->pressStart();
        r.m->advance(200);
        QCOMPARE(r.lines(), expect({"АВТ     7      100%", "ЧЕРНОВАЯ ОБТОЧКА",
                                    " X    0.000    0.000", " Z    0.000    0.000"}));
        r.m->advance(5000);
        QCOMPARE(r.line(1), QString("ЧИСТОВАЯ ОБТОЧКА"));
    }

    void homingFlags() {
        PanelRig r;
        QVERIFY(r.home());
        r.keys("F3");
        const engine::AxisView x = r.c().axisView(X), zv = r.c().axisView(Z);
        const auto f = [](std::int64_t d, const units::AxisScale& s) {
            return QString::fromStdString(units::formatDisc(d, s));
        };
        QCOMPARE(r.lines(), (QStringList{"ПБТ X Z        100%", "",
                                         " X" + f(x.currentDisc, x.scale).rightJustified(9) + "#" +
                                             f(x.homeDistanceDisc, x.scale),
                                         " Z" + f(zv.currentDisc, zv.scale).rightJustified(9) +
                                             "#" + f(zv.homeDistanceDisc, zv.scale)}));
        QVERIFY(std::llabs(x.homeDistanceDisc - 3000) <=
                2); // R246: 1.5 mm of slide on the diameter
    }

    void diagnosticsFollowTheServo() {
        PanelRig r;
        r.m->setJog(Z, -1);
        r.m->advance(1500);
        r.keys("HELP 4 RIGHT");
        const engine::AxisView v = r.c().axisView(Z);
        QVERIFY(v.dac != 0);
        QCOMPARE(r.lines(), (QStringList{"ABS_Z " + QString::fromStdString(units::formatDisc(
                                                        std::llround(v.absInternal), v.scale)),
                                         "ERR_Z " + QString::fromStdString(units::formatDisc(
                                                        std::llround(v.errorInternal), v.scale)),
                                         "DAC_Z " + QString::number(v.dac),
                                         "PLS_Z " + QString::number(v.pulsesPerTick)}));
        QVERIFY(r.line(2) != QString("DAC_Z 0"));
    }

    void pcLink() {
        PanelRig r;
        r.keys("F7 1 1 1 1 ENTER DOWN DOWN ENTER");
        QVERIFY(r.p->pcLinkReady());
        r.keys("HELP");
        QVERIFY(!r.p->pcLinkReady());
        r.keys("HELP");
        QVERIFY(r.p->pcLinkReady());
        r.keys("ESC");
        QVERIFY(!r.p->pcLinkReady());
        r.keys("ENTER F1");
        QVERIFY(!r.p->pcLinkReady());
    }

    void clearParameters() {
        PanelRig r;
        r.keys("F7 1 1 1 1 ENTER DOWN ENTER ESC");
        QCOMPARE(r.c().r(10), 40000); // ESC: not cleared
        r.keys("ENTER ENTER");
        QCOMPARE(r.c().r(10), 0);
        QCOMPARE(r.c().r(220), 0);
        r.keys("UP ENTER ENTER");
        QCOMPARE(r.c().c()[1], std::int64_t(0));
        QCOMPARE(r.c().c()[40], std::int64_t(0));
        QCOMPARE(r.line(0), QString("УПРАВЛЕНИЕ ДАННЫМИ !")); // the constants now fail the test
    }
};

QTEST_APPLESS_MAIN(TestPanel)
#include "test_panel.moc"
