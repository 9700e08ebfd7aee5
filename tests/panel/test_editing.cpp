// Values typed on the panel reach the engine: R-parameters on РУЧ screen 3
// and the preset groups (engine setR, setCurrentValue), C-parameters
// (engine setC), in the formats of docs/panel.md; «ОШИБКА ВВОДА» for what
// the engine or the format refuses.
#include "rig/panel_rig.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;

class TestEditing : public QObject {
    Q_OBJECT
private slots:
    // --- РУЧ screen 3 ---------------------------------------------------------
    void manualR_data() {
        QTest::addColumn<QString>("keys");
        QTest::addColumn<int>("number");
        QTest::addColumn<int>("value");
        QTest::addColumn<QString>("marked"); // the marked line afterwards
        QTest::newRow("plain") << "PAR 2 0 ENTER 1 2 3 4 5 ENTER" << 20 << 12345 << ">R20=12345";
        QTest::newRow("negative") << "PAR 9 9 ENTER - 1 2 3 4 5 ENTER" << 99 << -12345
                                  << ">R99=-12345";
        QTest::newRow("product") << "PAR 2 0 ENTER 1 2 * 3 ENTER" << 20 << 36 << ">R20=36";
        QTest::newRow("left to right") << "PAR 2 0 ENTER 2 + 3 * 4 ENTER" << 20 << 20 << ">R20=20";
        QTest::newRow("quotient rounded") << "PAR 2 0 ENTER 7 / 2 ENTER" << 20 << 4 << ">R20=4";
        QTest::newRow("minus after op") << "PAR 2 0 ENTER 5 * - 2 ENTER" << 20 << -10 << ">R20=-10";
        QTest::newRow("preset changed") << "PAR 1 0 ENTER 1 ENTER" << 10 << 1 << ">R10=1";
        QTest::newRow("system R") << "PAR 2 2 4 ENTER 7 ENTER" << 224 << 7 << ">R224=7";
        QTest::newRow("DEL takes a digit")
            << "PAR 2 0 ENTER 1 2 3 DEL ENTER" << 20 << 12 << ">R20=12";
        QTest::newRow("largest") << "PAR 2 0 ENTER 2 1 4 7 4 8 3 6 4 7 ENTER" << 20 << 2147483647
                                 << ">R20=2147483647";
    }
    void manualR() {
        QFETCH(QString, keys);
        QFETCH(int, number);
        QFETCH(int, value);
        QFETCH(QString, marked);
        PanelRig r;
        r.keys("F2 MODE MODE");
        r.keys(keys.toStdString());
        QCOMPARE(r.c().r(number), value);
        QVERIFY2(r.lines().contains(marked), qPrintable(r.lines().join('|')));
        QVERIFY(!r.lines().contains("ОШИБКА ВВОДА"));
    }

    void manualRRefused_data() {
        QTest::addColumn<QString>("keys");
        QTest::addColumn<int>("number");
        QTest::addColumn<int>("value");
        QTest::newRow("read only") << "PAR 2 4 0 ENTER 5 ENTER" << 240 << 0;
        QTest::newRow("decimal point") << "PAR 1 0 ENTER 1 . 5 ENTER" << 10 << 40000;
        QTest::newRow("beyond 32 bits") << "PAR 1 0 ENTER 2 1 4 7 4 8 3 6 4 8 ENTER" << 10 << 40000;
        QTest::newRow("division by zero") << "PAR 1 0 ENTER 5 / 0 ENTER" << 10 << 40000;
        QTest::newRow("malformed") << "PAR 1 0 ENTER 5 * ENTER" << 10 << 40000;
    }
    void manualRRefused() {
        QFETCH(QString, keys);
        QFETCH(int, number);
        QFETCH(int, value);
        PanelRig r;
        r.keys("F2 MODE MODE");
        r.keys(keys.toStdString());
        QCOMPARE(r.c().r(number), value);
        QCOMPARE(r.line(1), QString("ОШИБКА ВВОДА"));
        r.keys("DOWN"); // the next key takes the message away
        QVERIFY(r.line(1) != QString("ОШИБКА ВВОДА"));
    }

    void manualREqualsAssigns() {
        PanelRig r;
        r.keys("F2 MODE MODE PAR 2 0 ENTER 1 2 * 3 =");
        QCOMPARE(r.line(3), QString(">R20=36")); // «=» shows the result, nothing written yet
        QCOMPARE(r.c().r(20), 0);
        QCOMPARE(r.display().lcd.blinkRow, 3);
        QCOMPARE(r.display().lcd.blinkColumn, 7);
        r.keys("ENTER");
        QCOMPARE(r.c().r(20), 36);
        QCOMPARE(r.display().lcd.blinkLength, 0);
    }

    // A key that types nothing in a field does not start an entry: ESC then
    // is the machine's ESC again.
    void keysThatTypeNothing() {
        PanelRig r;
        r.keys("F4 2 + * % !");
        QVERIFY(!r.p->presetScreens().editing());
        QCOMPARE(r.line(2), QString(">R220=200.000"));
        r.keys("F2 MODE MODE % /");
        QCOMPARE(r.line(1), QString(">R0=0"));
        QCOMPARE(r.display().lcd.blinkLength, 0);
        r.keys("F5 1 1 1 1 ENTER + %");
        QVERIFY(!r.p->cparamScreen().editing());
    }

    void movingAwayDropsTheTypedValue() {
        PanelRig r;
        r.keys("F2 MODE MODE PAR 1 0 ENTER 5 DOWN");
        QCOMPARE(r.c().r(10), 40000);
        QCOMPARE(r.line(2), QString(" R10=40000"));
    }

    // A manual cycle executing in РУЧНОЙ: the engine refuses R-parameters
    // (setR), the panel says «ОШИБКА ВВОДА»; after it, they can be written.
    void notWhileACycleExecutes() {
        PanelRig r(noHoming);
        r.keys("MODE MODE PAR 2 0 ENTER");
        r.m->startCycle(6); // C148 = 91: «ПРОГРЕВ СТАНКА»
        r.m->advance(100);
        QCOMPARE(r.c().state(), engine::ProgramState::Running);
        r.keys("5 ENTER");
        QCOMPARE(r.line(1), QString("ОШИБКА ВВОДА"));
        QCOMPARE(r.c().r(20), 0);
        r.keys("ESC"); // C123 = 1: «Сброс»
        QCOMPARE(r.c().state(), engine::ProgramState::Idle);
        r.keys("5 ENTER");
        QCOMPARE(r.c().r(20), 5);
    }

    // --- ПРЕДУСТАНОВКИ --------------------------------------------------------
    void presets_data() {
        QTest::addColumn<QString>("keys");
        QTest::addColumn<int>("number");
        QTest::addColumn<int>("value");
        QTest::addColumn<QString>("marked");
        // The values of the manual's screens, typed as printed.
        QTest::newRow("R224 -12.356")
            << "1 DOWN - 1 2 . 3 5 6 ENTER" << 224 << -12356 << ">R224=-12.356";
        QTest::newRow("R226 1.234")
            << "1 DOWN DOWN 1 . 2 3 4 ENTER" << 226 << 1234 << ">R226=1.234";
        QTest::newRow("R229 Z") << "1 RIGHT DOWN DOWN DOWN - 1 0 4 3 . 0 3 8 ENTER" << 229
                                << -1043038 << ">R229=-1043.038";
        QTest::newRow("R220 whole mm") << "2 1 2 ENTER" << 220 << 12000 << ">R220=12.000";
        QTest::newRow("R220 sum") << "2 1 0 + 2 . 5 ENTER" << 220 << 12500 << ">R220=12.500";
        QTest::newRow("R218 discretes") << "3 1 2 ENTER" << 218 << 12 << ">R218=12";
        QTest::newRow("R219 discretes") << "3 DOWN 2 1 ENTER" << 219 << 21 << ">R219=21";
        QTest::newRow("R210 0.030") << "4 . 0 3 ENTER" << 210 << 30 << ">R210=0.030";
        QTest::newRow("R212 feed")
            << "4 DOWN DOWN 1 0 0 . 0 0 ENTER" << 212 << 100000 << ">R212=100.00";
        QTest::newRow("R216 feed X")
            << "4 RIGHT DOWN DOWN 6 0 ENTER" << 216 << 60000 << ">R216=60.00";
        QTest::newRow("R204 600.000") << "5 6 0 0 ENTER" << 204 << 600000 << ">R204=600.000";
        QTest::newRow("R202 100.00")
            << "6 DOWN DOWN 1 0 0 ENTER" << 202 << 100000 << ">R202=100.00";
        QTest::newRow("R186 100.00")
            << "7 DOWN DOWN 1 0 0 . 0 0 ENTER" << 186 << 100000 << ">R186=100.00";
        QTest::newRow("R187 1.000 s") << "7 DOWN DOWN DOWN 1 ENTER" << 187 << 1000 << ">R187=1.000";
        QTest::newRow("R195 Z 0.25 s")
            << "7 RIGHT DOWN DOWN DOWN . 2 5 ENTER" << 195 << 250 << ">R195=0.250";
        QTest::newRow("R191 2") << "7 SHIFT+DOWN SHIFT+DOWN SHIFT+DOWN 2 ENTER" << 191 << 2
                                << ">R191=2";
        QTest::newRow("R177 15.00")
            << "8 DOWN DOWN DOWN 1 5 ENTER" << 177 << 15000 << ">R177=15.00";
        QTest::newRow("R182 Z") << "8 LEFT DOWN DOWN DOWN 9 . 5 ENTER" << 182 << 9500
                                << ">R182=9.50";
        QTest::newRow("R165 -1") << "9 DOWN - 1 ENTER" << 165 << -1 << ">R165=-1";
        QTest::newRow("R164 123.030") << "9 1 2 3 . 0 3 ENTER" << 164 << 123030 << ">R164=123.030";
    }
    void presets() {
        QFETCH(QString, keys);
        QFETCH(int, number);
        QFETCH(int, value);
        QFETCH(QString, marked);
        PanelRig r;
        r.keys("F4");
        r.keys(keys.toStdString());
        QCOMPARE(r.c().r(number), value);
        QVERIFY2(r.lines().contains(marked), qPrintable(r.lines().join('|')));
    }

    void presetsRefused_data() {
        QTest::addColumn<QString>("keys");
        QTest::addColumn<int>("number");
        QTest::addColumn<int>("value");
        QTest::newRow("more decimals than X has") << "2 1 . 2 3 4 5 ENTER" << 220 << 200000;
        QTest::newRow("feed with 3 decimals") << "8 1 . 2 3 4 ENTER" << 174 << 0;
        QTest::newRow("seconds with 4 decimals")
            << "7 DOWN DOWN DOWN 1 . 0 0 0 1 ENTER" << 187 << 0;
        QTest::newRow("beyond 32 bits") << "2 3 0 0 0 0 0 0 ENTER" << 220 << 200000;
    }
    void presetsRefused() {
        QFETCH(QString, keys);
        QFETCH(int, number);
        QFETCH(int, value);
        PanelRig r;
        r.keys("F4");
        r.keys(keys.toStdString());
        QCOMPARE(r.c().r(number), value);
        QCOMPARE(r.line(1), QString("ОШИБКА ВВОДА"));
    }

    // «Установка фактического значения» (group 1, X=): the current
    // coordinate becomes the typed value, the zero offset follows.
    void currentValue() {
        PanelRig r;
        r.keys("F4 1 1 2 0 5 . 1 2 4 ENTER");
        QCOMPARE(r.c().axisView(X).currentDisc, std::int64_t(1205124));
        QCOMPARE(r.c().r(228), -1205124); // machine 0 − 1205.124
        QCOMPARE(r.lines(), expect({"УСТ1 КООРД.И СМЕЩ.X", "ТЕКУЩАЯ КООРДИНАТА", ">   X=1205.124",
                                    " R224=0.000"}));
        r.keys("DOWN DOWN DOWN");
        QCOMPARE(r.line(3), QString(">R228=-1205.124"));
        r.keys("RIGHT UP UP UP - 5 ENTER");
        QCOMPARE(r.c().axisView(Z).currentDisc, std::int64_t(-5000));
        QCOMPARE(r.line(2), QString(">   Z=-5.000"));
    }

    // The discrete of the axis sets the point: 0.01 mm on X.
    void otherDiscrete() {
        PanelRig r([](profile::MachineProfile& p) {
            p.setC(5, 0);
            p.setC(6, 1);
        });
        r.keys("F4 1 DOWN 1 . 2 3 ENTER");
        QCOMPARE(r.c().r(224), 123);
        QCOMPARE(r.line(3), QString(">R224=1.23"));
        r.keys("MODE 8 1 . 5 ENTER");
        QCOMPARE(r.c().r(174), 150); // 1.5 mm/min = 150 discretes of 0.01 mm per minute
        QCOMPARE(r.line(2), QString(">R174=1.50"));
        r.keys("MODE 1 DOWN 1 . 2 3 4 ENTER");
        QCOMPARE(r.line(1), QString("ОШИБКА ВВОДА"));
        QCOMPARE(r.c().r(224), 123);
    }

    // --- С-ПАРАМЕТРЫ -----------------------------------------------------------
    void cparams_data() {
        QTest::addColumn<QString>("keys");
        QTest::addColumn<int>("number");
        QTest::addColumn<qlonglong>("value");
        QTest::addColumn<QString>("line");
        QTest::addColumn<int>("row");
        QTest::newRow("T контроля ДОС X")
            << "PAR 2 1 ENTER 2 5 0 0 ENTER" << 21 << 2500LL << "N021>X=2500" << 2;
        QTest::newRow("Z of the pair")
            << "PAR 2 1 ENTER LEFT 1 5 0 0 ENTER" << 73 << 1500LL << "N073>Z=1500" << 3;
        QTest::newRow("F ОБЫЧНАЯ")
            << "PAR 4 0 ENTER 2 0 0 0 0 0 ENTER" << 40 << 200000LL << "N040>X=200000" << 2;
        QTest::newRow("signed") << "PAR 4 6 ENTER - 5 0 0 0 ENTER" << 46 << -5000LL
                                << "N046>X=-5000" << 2;
        QTest::newRow("common") << "PAR 1 4 0 ENTER 7 ENTER" << 140 << 7LL << "№140 7" << 2;
        QTest::newRow("calculated")
            << "PAR 4 1 ENTER 5 0 0 0 * 1 0 0 ENTER" << 41 << 500000LL << "N041>X=500000" << 2;
    }
    void cparams() {
        QFETCH(QString, keys);
        QFETCH(int, number);
        QFETCH(qlonglong, value);
        QFETCH(QString, line);
        QFETCH(int, row);
        PanelRig r;
        r.keys("F5 1 1 1 1 ENTER");
        r.keys(keys.toStdString());
        QCOMPARE(r.c().c()[static_cast<std::size_t>(number)], std::int64_t(value));
        QCOMPARE(r.line(row), line);
    }

    void cparamsRefused_data() {
        QTest::addColumn<QString>("keys");
        QTest::addColumn<int>("number");
        QTest::addColumn<qlonglong>("value");
        QTest::newRow("ДОПУСК ПОЗ. above 255") << "PAR 3 1 ENTER 3 0 0 ENTER" << 31 << 10LL;
        QTest::newRow("ДОПУСК ПОЗ. 0") << "PAR 3 1 ENTER 0 ENTER" << 31 << 10LL;
        QTest::newRow("flag 2") << "PAR 1 0 ENTER 2 ENTER" << 10 << 1LL;
        QTest::newRow("N ДОС 5") << "PAR 1 7 ENTER 5 ENTER" << 17 << 1LL;
        QTest::newRow("decimal point") << "PAR 2 1 ENTER 1 . 5 ENTER" << 21 << 1000LL;
        QTest::newRow("override code 11") << "PAR 1 3 9 ENTER 1 1 ENTER" << 139 << 0LL;
    }
    void cparamsRefused() {
        QFETCH(QString, keys);
        QFETCH(int, number);
        QFETCH(qlonglong, value);
        PanelRig r;
        r.keys("F5 1 1 1 1 ENTER");
        r.keys(keys.toStdString());
        QCOMPARE(r.c().c()[static_cast<std::size_t>(number)], std::int64_t(value));
        QCOMPARE(r.line(1), QString("ОШИБКА ВВОДА"));
    }

    void cparamsViewOnly() {
        PanelRig r;
        r.keys("F5 9 9 9 9 ENTER");
        QCOMPARE(r.p->access(), panel::Access::ViewOnly);
        QCOMPARE(r.c().mode(), Mode::MachineData);
        r.keys("PAR 2 1 ENTER 2 5 0 0 ENTER");
        QCOMPARE(r.c().c()[21], std::int64_t(1000));
        QCOMPARE(r.line(2), QString("N021>X=1000"));
        // F5 again asks for the password; the right one opens it.
        r.keys("F5");
        QVERIFY(r.p->passwordShown());
        r.keys("1 1 1 1 ENTER 2 5 0 0 ENTER");
        QCOMPARE(r.p->access(), panel::Access::Full);
        QCOMPARE(r.c().c()[21], std::int64_t(2500));
    }

    // A changed constant acts: the servo follows, the cross-checks give their message.
    void cparamsReachTheEngine() {
        PanelRig r;
        r.keys("F5 1 1 1 1 ENTER PAR 1 7 ENTER 3 ENTER"); // N ДОС X on the channel of Z's encoder
        QCOMPARE(r.c().c()[17], std::int64_t(3));
        QVERIFY(r.c().alarmRegistry().active(37)); // «Ошибка N ДОС»
        QCOMPARE(r.line(0), QString("ПАРАМЕТРЫ СТАНКА   !"));
    }
};

QTEST_APPLESS_MAIN(TestEditing)
#include "test_editing.moc"
