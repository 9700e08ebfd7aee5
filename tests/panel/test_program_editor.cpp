// РЕДАКТИРОВАНИЕ УП (2.6.7) on the engine's program store: a frame typed on
// the panel is in the store as the model the parser builds from its
// canonical text; INS, ACK, DEL, ESC, `!`, SHIFT+▲▼; the catalog; a
// corrupt program area; no editing while a program is under way.
#include "rig/panel_rig.h"
#include "program/formatter.h"

#include <QtTest>

using namespace k528;
using namespace k528::testrig;

namespace {

constexpr const char* kOpen = "F6 1 1 1 1 ENTER UP"; // РЕДАКТИРОВАНИЕ УП, marker on ПРОГРАММА

// The program's text as the canonical formatter writes it alone.
std::string programText(const engine::Positioner& c, int number) {
    program::ProgramStore s;
    if (const program::Program* p = c.programs().find(number))
        s.insert(*p);
    return program::format(s);
}

// The store's program equals what the parser builds from `text`.
bool sameAsParsed(const engine::Positioner& c, int number, const std::string& text) {
    const program::ParseResult r = program::parse(text);
    const program::Program* a = c.programs().find(number);
    const program::Program* b = r.store.find(number);
    return !r.hasErrors() && a && b && program::sameContent(*a, *b);
}

} // namespace

class TestProgramEditor : public QObject {
    Q_OBJECT
private slots:
    // The four frames of 2.6.7 typed into a new program.
    void typedFramesAreTheParsersModel_data() {
        QTest::addColumn<QString>("keys");
        QTest::addColumn<QString>("text");
        QTest::newRow("ISO")
            << "1 2 DOWN DOWN 5 . 3 4 2 RIGHT 5 0 RIGHT - 1 2 3 4 . 6 7 8 RIGHT 1 0 0 0 ENTER"
            << "%L5\nN12 X5.342 FX50 Z-1234.678 FZ1000\n";
        QTest::newRow("ISO words")
            << "1 RIGHT 1 RIGHT 9 0 RIGHT RIGHT RIGHT 3 RIGHT 8 RIGHT RIGHT 2 RIGHT % 1 2 ENTER"
            << "%L5\nN1 G1 G90 M3 M8 L2 X=R12\n";
        QTest::newRow("computational") << "ACK 1 1 2 RIGHT 1 2 3 = % 1 + 1 2 ENTER"
                                       << "%L5\nN12 R123=R1+12\n";
        QTest::newRow("computational 2*R99") << "ACK 1 1 2 RIGHT 7 5 = 2 * % 9 9 ENTER"
                                             << "%L5\nN12 R75=2*R99\n";
        QTest::newRow("computational no op") << "ACK 1 RIGHT 4 = - 5 ENTER"
                                             << "%L5\nR4=-5\n";
        QTest::newRow("conditional") << "ACK 2 2 0 2 RIGHT 1 DOWN 3 0 1 ENTER"
                                     << "%L5\nN202 IF R1>0 GOTO 301\n";
        QTest::newRow("unconditional skipped") << "ACK 3 2 0 7 RIGHT 3 3 ENTER !"
                                               << "%L5\n/N207 GOTO 33\n";
        QTest::newRow("two frames") << "1 DOWN DOWN 1 0 ENTER INS 2 ENTER ACK 3 3 RIGHT 1 ENTER"
                                    << "%L5\nN1 X10\nN2\nN3 GOTO 1\n";
        QTest::newRow("F on X only") << "DOWN DOWN RIGHT 0 . 0 0 1 ENTER"
                                     << "%L5\nFX0.001\n";
        QTest::newRow("F 10000") << "DOWN DOWN RIGHT 1 0 0 0 0 ENTER" << "%L5\nFX10000\n";
    }
    void typedFramesAreTheParsersModel() {
        QFETCH(QString, keys);
        QFETCH(QString, text);
        PanelRig r;
        QVERIFY(!r.c().programs().contains(5));
        r.keys(kOpen);
        r.keys("5 ENTER");
        QVERIFY(r.c().programs().contains(5)); // «открытие УП по номеру (и новой)»
        r.keys(keys.toStdString());
        QCOMPARE(QString::fromStdString(programText(r.c(), 5)), text);
        QVERIFY(sameAsParsed(r.c(), 5, text.toStdString()));
        QVERIFY(!r.lines().contains("ОШИБКА ВВОДА"));
    }

    // F= has 7 cells: the largest feed, 10000, is shown with one decimal
    // «10000.0», so that nothing is cut.
    void largestFeedFitsItsField() {
        PanelRig r;
        r.keys(kOpen);
        r.keys("5 ENTER DOWN DOWN RIGHT 1 0 0 0 0 ENTER DOWN 9 9 9 9 . 5 ENTER");
        QCOMPARE(r.line(2), QString("X          F=10000.0"));
        QCOMPARE(r.line(3), QString("Z          F=9999.50"));
    }

    // INS in the middle of a program; DEL of the frame; the rest stays.
    void insertAndDeleteFrames() {
        PanelRig r;
        const std::string before = programText(r.c(), 1);
        r.keys(kOpen);
        r.keys("ENTER SHIFT+DOWN"); // program 1, frame N2
        QCOMPARE(r.p->programScreens().editor().frameIndex(), 1);
        r.keys("INS 1 0 0 DOWN 5 ENTER");
        const program::Program* p = r.c().programs().find(1);
        QCOMPARE(p->frames.size(), std::size_t(19));
        QCOMPARE(p->frames[2].number(), 100);
        QVERIFY(p->frames[2].iso().value().hasM(5));
        QCOMPARE(p->frames[3].number(), 3);
        QCOMPARE(r.lines(), expect({" N100G   G   G   #", " M5  M   M       L",
                                    "X          F=", "Z          F="}));
        // DEL with N blinking: the frame goes, the next one is shown.
        r.keys("UP DEL");
        QCOMPARE(r.c().programs().find(1)->frames.size(), std::size_t(18));
        QCOMPARE(QString::fromStdString(programText(r.c(), 1)), QString::fromStdString(before));
        QCOMPARE(r.line(0), QString(" N3  G   G   G   #"));
    }

    // DEL with a field blinking empties the field; the frame's comments stay.
    void deleteField() {
        PanelRig r;
        r.keys(kOpen);
        r.keys("ENTER RIGHT RIGHT RIGHT RIGHT");   // N1 .. #1
        QCOMPARE(r.display().lcd.blinkColumn, 17); // «#», column 18
        r.keys("DEL");
        const program::Frame& f = r.c().programs().find(1)->frames[0];
        QVERIFY(!f.iso().value().message.has_value());
        QVERIFY(!f.leading.empty()); // the comment lines above N1 in the text
        QCOMPARE(r.line(0), QString(" N1  G90 G0  G   #"));
    }

    // ESC gives the field its value back (and does not reset the machine);
    // leaving the field takes the value shown.
    void escRestoresAndLeavingTakes() {
        PanelRig r;
        r.keys(kOpen);
        r.keys("ENTER RIGHT 9 1");
        QCOMPARE(r.line(0), QString(" N1  G91 G0  G   #1"));
        QCOMPARE(r.display().lcd.blinkColumn, 8); // the input position
        r.keys("ESC");
        QCOMPARE(r.line(0), QString(" N1  G90 G0  G   #1"));
        QCOMPARE(r.display().lcd.blinkColumn, 5); // the name «G» blinks again
        QCOMPARE(r.display().lcd.blinkLength, 1);
        QVERIFY(r.c().programs().find(1)->frames[0].iso().value().hasG(90));
        r.keys("9 1 RIGHT");
        QVERIFY(r.c().programs().find(1)->frames[0].iso().value().hasG(91));
        QVERIFY(!r.c().programs().find(1)->frames[0].iso().value().hasG(90));
    }

    void outOfRange_data() {
        QTest::addColumn<QString>("keys");
        QTest::newRow("G 300") << "RIGHT 3 0 0 RIGHT";
        QTest::newRow("duplicate N") << "2 RIGHT";
        QTest::newRow("# 0") << "RIGHT RIGHT RIGHT RIGHT 0 ENTER";
        QTest::newRow("L 0") << "DOWN RIGHT RIGHT RIGHT 0 ENTER";
        QTest::newRow("X 10000") << "DOWN DOWN 1 0 0 0 0 ENTER";
        QTest::newRow("F 0") << "DOWN DOWN RIGHT 0 ENTER";
        QTest::newRow("F above 10000") << "DOWN DOWN RIGHT 1 0 0 0 0 . 1 ENTER";
        QTest::newRow("R 300") << "DOWN DOWN % 3 0 0 ENTER";
    }
    void outOfRange() {
        QFETCH(QString, keys);
        PanelRig r;
        const std::string before = programText(r.c(), 1);
        r.keys(kOpen);
        r.keys("ENTER");
        r.keys(keys.toStdString());
        QCOMPARE(r.line(1), QString("ОШИБКА ВВОДА"));
        QCOMPARE(programText(r.c(), 1), before);
    }

    void readOnlyTargetRefused() {
        PanelRig r;
        r.keys(kOpen);
        r.keys("5 ENTER ACK 1 RIGHT 2 4 0 ENTER");
        QCOMPARE(r.line(1), QString("ОШИБКА ВВОДА"));
        r.keys("2 2 9 ENTER = 5 ENTER"); // R229 (zero offset Z) may be written
        QCOMPARE(QString::fromStdString(programText(r.c(), 5)), QString("%L5\nR229=5\n"));
    }

    // A new frame left incomplete is not stored and goes when left.
    void incompleteFrameDropped() {
        PanelRig r;
        r.keys(kOpen);
        r.keys("ENTER ACK 1 5 0 ENTER"); // after N1: a computational frame N50 without R=
        QCOMPARE(r.c().programs().find(1)->frames.size(), std::size_t(18));
        QCOMPARE(r.lines(), expect({" N50 R", "     =", "", ""}));
        r.keys("SHIFT+UP");
        QCOMPARE(r.line(0), QString(" N1  G90 G0  G   #1"));
        r.keys("SHIFT+DOWN");
        QCOMPARE(r.line(0), QString(" N2  G1  G   G   #2"));
        QCOMPARE(r.c().programs().find(1)->frames.size(), std::size_t(18));
    }

    // An existing frame whose required field is deleted keeps its stored form.
    void requiredFieldDeleted() {
        PanelRig r;
        r.keys(kOpen);
        r.keys("ENTER SHIFT+DOWN SHIFT+DOWN SHIFT+DOWN SHIFT+DOWN SHIFT+DOWN"); // N6 R1=R10-R12
        QCOMPARE(r.line(0), QString(" N6  R1"));
        r.keys("DOWN DEL");
        QCOMPARE(r.lines(), expect({" N6  R1", "     =", "     -R12", ""}));
        QVERIFY(r.c().programs().find(1)->frames[5].compute().value().a.isR());
        r.keys("SHIFT+DOWN SHIFT+UP");
        QCOMPARE(r.lines(), expect({" N6  R1", "     =R10", "     -R12", ""}));
    }

    void skipToggle() {
        PanelRig r;
        r.keys(kOpen);
        r.keys("ENTER !");
        QVERIFY(r.c().programs().find(1)->frames[0].skip);
        QCOMPARE(r.line(0), QString("/N1  G90 G0  G   #1"));
        r.keys("!");
        QVERIFY(!r.c().programs().find(1)->frames[0].skip);
    }

    void fieldNavigation() {
        PanelRig r;
        r.keys(kOpen);
        r.keys("5 ENTER");
        // ▼ goes to the field below, nearest in column; ◀► through all.
        const struct {
            const char* key;
            int row, column, length; // blink, 0-based column
        } steps[] = {{"DOWN", 1, 1, 1},  {"DOWN", 2, 0, 1},  {"RIGHT", 2, 11, 2},
                     {"DOWN", 3, 11, 2}, {"RIGHT", 0, 1, 1}, {"LEFT", 3, 11, 2},
                     {"UP", 2, 11, 2},   {"UP", 1, 9, 1}};
        for (const auto& s : steps) {
            r.keys(s.key);
            const panel::Lcd l = r.display().lcd;
            QCOMPARE(l.blinkRow, s.row);
            QCOMPARE(l.blinkColumn, s.column);
            QCOMPARE(l.blinkLength, s.length);
        }
    }

    // Not while a program is under way (the engine gives no store to edit).
    void noEditingWhileAProgramIsActive() {
        PanelRig r(noHoming);
        r.load("%L7\nN1 G4 X20\nN2 M30\n");
        r.keys("F1 ACK 7 ENTER");
        r.m->pressStart();
        r.m->advance(100);
        r.keys(kOpen);
        r.keys("ENTER 9 9 ENTER");
        QCOMPARE(r.line(1), QString("ОШИБКА ВВОДА"));
        QCOMPARE(r.c().programs().find(1)->frames[0].number(), 1);
        r.keys("ESC"); // «Сброс» (C123): the program ends
        r.keys("9 9 ENTER");
        QCOMPARE(r.c().programs().find(1)->frames[0].number(), 99);
    }

    void corruptProgramArea() {
        PanelRig r([](profile::MachineProfile& p) { p.programs[3] = "%L3\nN1 Q5\n"; });
        QVERIFY(r.c().alarmRegistry().active(31));
        r.keys("F6 1 1 1 1 ENTER ENTER");
        QCOMPARE(r.lines(), expect({"РЕДАКТИРОВАНИЕ УП  ?", "    УП ЗАПОРЧЕНА", "", ""}));
        r.keys("ENTER");
        QCOMPARE(r.line(2), QString(">КАТАЛОГ"));
        r.keys("UP 1 ENTER");
        QCOMPARE(r.line(1), QString("    УП ЗАПОРЧЕНА"));
        r.keys("ESC DOWN DOWN ENTER ENTER"); // ОЧИСТИТЬ УП
        QVERIFY(!r.c().alarmRegistry().active(31));
        QVERIFY(r.c().programs().empty());
        r.keys("UP ENTER");
        QCOMPARE(r.lines(),
                 expect({"РЕДАКТИРОВАНИЕ УП  ?", "", "", ""})); // 31 stays latched until ESC
        r.keys("ESC ESC");
        QCOMPARE(r.line(0), QString("РЕДАКТИРОВАНИЕ УП"));
    }

    void deleteProgramFromTheMenu() {
        PanelRig r;
        r.keys(kOpen);
        r.keys("9 9");
        QCOMPARE(r.line(1), QString(">ПРОГРАММА 99"));
        r.keys("DEL"); // the number typed: there is no program 99
        QCOMPARE(r.line(1), QString("ОШИБКА ВВОДА"));
        r.keys("DEL"); // the number shown: the first of the catalog
        QCOMPARE(r.lines(), expect({"РЕДАКТИРОВАНИЕ УП", "УДАЛИТЬ L1?", "", "ENTER-ДА  ESC-НЕТ"}));
        r.keys("ENTER");
        QVERIFY(!r.c().programs().contains(1));
        QCOMPARE(r.line(1), QString(">ПРОГРАММА 90")); // the first of the catalog now
        r.keys("9 1 DEL ENTER");
        QVERIFY(!r.c().programs().contains(91));
    }

    // The frame shown follows the store (it is read from it, not copied).
    void followsTheStore() {
        PanelRig r;
        r.keys(kOpen);
        r.keys("ENTER");
        program::ProgramStore* s = r.c().editablePrograms();
        s->find(1)->frames[0] = program::parse("%L1\nN1 M30\n").store.find(1)->frames[0];
        QVERIFY(r.c().programsEdited().ok());
        QCOMPARE(r.lines(), expect({" N1  G   G   G   #", " M30 M   M       L",
                                    "X          F=", "Z          F="}));
    }
};

QTEST_APPLESS_MAIN(TestProgramEditor)
#include "test_program_editor.moc"
