// The program editor (issue 11): a bad frame gets its squiggle on the
// exact columns and a Problems entry, fixing it clears both; typing is
// validated after the debounce on a worker; the machine's limits are
// checked too; colours come from core's tokens; unsaved changes survive a
// cancelled close; a screenshot of the editor with diagnostics.
#include "editor/editor_tab.h"
#include "editor/frame_master.h"
#include "editor/program_editor.h"
#include "program/tokens.h"
#include "profile/builtin.h"
#include "session/simulation_session.h"

#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>

using namespace k528;
using namespace k528::studio;

namespace {

bool indicatorAt(ProgramEditor& ed, int indicator, int pos) {
    return ed.SendScintilla(QsciScintilla::SCI_INDICATORVALUEAT, indicator, pos) != 0;
}

int styleAt(ProgramEditor& ed, int pos) {
    return static_cast<int>(ed.SendScintilla(QsciScintilla::SCI_GETSTYLEAT, pos));
}

QString write(const QTemporaryDir& dir, const QString& name, const QByteArray& text) {
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        return {};
    f.write(text);
    return path;
}

} // namespace

class TestEditor : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QCoreApplication::setOrganizationName("k528-test-editor"); }

    void squiggleOnTheExactColumnsAndProblemsEntry() {
        EditorTab tab(nullptr);
        tab.newFile();
        ProgramEditor* ed = tab.currentEditor();
        QVERIFY(ed);
        // Line 2: "N2 G1 X5..3": the value word X5..3 is columns 7..12.
        ed->setText("%L1\nN1 G1 X1\nN2 G1 X5..3\nM30\n");
        ed->validateNow();
        QCOMPARE(int(ed->diagnostics().size()), 1);
        const program::Diagnostic d = ed->diagnostics().front();
        QCOMPARE(d.line, 3);
        QCOMPARE(d.column, 7);
        QCOMPARE(d.endColumn, 12);
        const int lineStart = ed->positionFromLineIndex(2, 0);
        for (int c = 0; c < 14; ++c) {
            const bool inside = c >= 6 && c < 11;
            QCOMPARE(indicatorAt(*ed, ProgramEditor::kErrorIndicator, lineStart + c), inside);
        }
        QCOMPARE(tab.problems()->topLevelItemCount(), 1);
        QTreeWidgetItem* item = tab.problems()->topLevelItem(0);
        QCOMPARE(item->text(1), QString("L1"));
        QCOMPARE(item->text(2), QString("3"));
        QCOMPARE(item->text(3), QString("[M33]"));
        QVERIFY(!ed->hoverText(lineStart + 7).isEmpty());
        QVERIFY(ed->hoverText(lineStart + 7).startsWith("[M33] "));
        QVERIFY(ed->hoverText(lineStart + 1).isEmpty());
        QVERIFY(tab.problemCount()->text().contains('1'));
        // The Problems entry jumps to the place.
        emit tab.problems()->itemActivated(item, 0);
        int line = -1, index = -1;
        ed->getCursorPosition(&line, &index);
        QCOMPARE(line, 2);
        QCOMPARE(index, 6);
        // Fixing the frame clears both.
        ed->setText("%L1\nN1 G1 X1\nN2 G1 X5.3\nM30\n");
        ed->validateNow();
        QVERIFY(ed->diagnostics().empty());
        for (int c = 0; c < 12; ++c)
            QVERIFY(!indicatorAt(*ed, ProgramEditor::kErrorIndicator, lineStart + c));
        QCOMPARE(tab.problems()->topLevelItemCount(), 0);
    }

    void typingIsValidatedAfterTheDebounce() {
        ProgramEditor ed;
        ed.setText("%L1\nM30\n");
        ed.validateNow();
        QSignalSpy spy(&ed, &ProgramEditor::validated);
        ed.setCursorPosition(1, 0);
        QTest::keyClicks(&ed, "GOTO 77");
        QTest::keyClick(&ed, Qt::Key_Return);
        QVERIFY(spy.wait(3000));
        // The worker's result for the newest text.
        while (ed.diagnostics().empty() && spy.wait(1000)) {
        }
        bool jump = false;
        for (const auto& d : ed.diagnostics())
            jump |= d.rule == program::Rule::JumpTarget && d.line == 2;
        QVERIFY(jump);
    }

    void columnsCountCodePoints() {
        ProgramEditor ed;
        // A Cyrillic letter («Х») is an error; the squiggle is on it, two bytes.
        ed.setText("%L1\n(пример) G1 Х5\n");
        ed.validateNow();
        QVERIFY(!ed.diagnostics().empty());
        const program::Diagnostic& d = ed.diagnostics().front();
        const auto [b, e] = ed.spanPositions(d);
        const QByteArray all = ed.text().toUtf8();
        QCOMPARE(all.mid(b, 2), QByteArray("Х"));
        QVERIFY(e > b);
    }

    void machineLimitsAreCheckedToo() {
        SimulationSession session(profile::builtin("training-lathe"));
        EditorTab tab(&session);
        tab.newFile();
        ProgramEditor* ed = tab.currentEditor();
        ed->setText("%L1\nG1 X9999 FX50\nM30\n");
        ed->validateNow();
        bool limit = false;
        for (const auto& d : ed->diagnostics())
            limit |= d.rule == program::Rule::SoftLimit || d.rule == program::Rule::FeedAboveMax;
        QVERIFY(limit);
        tab.setCheckAgainstMachine(false);
        ed->validateNow();
        QVERIFY(ed->diagnostics().empty());
    }

    void coloursAreTheTokenKinds() {
        ProgramEditor ed;
        ed.resize(600, 300);
        ed.setText("%L1 (t)\nN1 G1 X5 FX50 ; c\nM30\n");
        ed.recolor();
        const int l2 = ed.positionFromLineIndex(1, 0);
        QCOMPARE(styleAt(ed, 0), int(program::TokenKind::Header));
        QCOMPARE(styleAt(ed, 5), int(program::TokenKind::Title));
        QCOMPARE(styleAt(ed, l2), int(program::TokenKind::FrameNumber));
        QCOMPARE(styleAt(ed, l2 + 3), int(program::TokenKind::GWord));
        QCOMPARE(styleAt(ed, l2 + 6), int(program::TokenKind::AxisValue));
        QCOMPARE(styleAt(ed, l2 + 9), int(program::TokenKind::Feed));
        QCOMPARE(styleAt(ed, l2 + 15), int(program::TokenKind::Comment));
        QCOMPARE(styleAt(ed, ed.positionFromLineIndex(2, 0)), int(program::TokenKind::MWord));
        // %L lines are fold points.
        const int level = static_cast<int>(ed.SendScintilla(QsciScintilla::SCI_GETFOLDLEVEL, 0));
        QVERIFY(level & QsciScintilla::SC_FOLDLEVELHEADERFLAG);
    }

    void unsavedChangesAreNotLostOnClose() {
        QTemporaryDir dir;
        const QString path = write(dir, "p.k528", "%L1\nM30\n");
        QMainWindow window;
        auto* tab = new EditorTab(nullptr, &window);
        window.setCentralWidget(tab);
        window.show();
        QVERIFY(tab->openFile(path));
        ProgramEditor* ed = tab->currentEditor();
        ed->setCursorPosition(1, 0);
        ed->insert("G1 X5\n");
        QVERIFY(ed->isModified());
        int asked = 0;
        tab->setCloseQuestion([&](const QString&) {
            ++asked;
            return EditorTab::CloseChoice::Cancel;
        });
        QVERIFY(!window.close());
        QCOMPARE(asked, 1);
        QCOMPARE(tab->documentCount(), 1);
        QCOMPARE(tab->currentEditor()->text(), QString("%L1\nG1 X5\nM30\n"));
        // «Save» writes the edits, then the window closes.
        tab->setCloseQuestion([&](const QString&) { return EditorTab::CloseChoice::Save; });
        QVERIFY(window.close());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("%L1\nG1 X5\nM30\n"));
    }

    void sendsThroughTheCheckThenLoadPath() {
        SimulationSession session(profile::builtin("training-lathe"));
        EditorTab tab(&session);
        tab.newFile();
        tab.currentEditor()->setText("%L42 (sent)\nG1 X1 FX50\nM30\n");
        QVERIFY(tab.sendToController());
        QVERIFY(session.controller().programs().contains(42));
        tab.currentEditor()->setText("%L43\nGOTO 5\nM30\n");
        QVERIFY(!tab.sendToController());
        QVERIFY(!session.controller().programs().contains(43));
    }

    void masterInsertsTheExpectedFrame() {
        EditorTab tab(nullptr);
        tab.newFile(); // "%L1\nM30\n"
        ProgramEditor* ed = tab.currentEditor();
        ed->setCursorPosition(0, 0);
        FrameMaster m;
        m.setKind(FrameMaster::Iso);
        QTest::keyClicks(m.field("N"), "12");
        QTest::keyClicks(m.field("G"), "1");
        QTest::keyClicks(m.field("X"), "5.3420");
        QTest::keyClicks(m.field("FX"), "50");
        QTest::keyClicks(m.field("Z"), "-1234.678");
        QTest::keyClicks(m.field("FZ"), "1000");
        QVERIFY(m.valid());
        QCOMPARE(m.text(), QString("N12 G1 X5.342 FX50 Z-1234.678 FZ1000"));
        tab.insertFromMaster(m.text(), false);
        QCOMPARE(ed->text(), QString("%L1\nN12 G1 X5.342 FX50 Z-1234.678 FZ1000\nM30\n"));
        // Validated as typed: G4 with Z is refused with its message number.
        FrameMaster bad;
        bad.setKind(FrameMaster::Iso);
        QTest::keyClicks(bad.field("G"), "4");
        QTest::keyClicks(bad.field("X"), "2");
        QVERIFY(bad.valid());
        QTest::keyClicks(bad.field("Z"), "1");
        QVERIFY(!bad.valid());
        QVERIFY(bad.problemsText().contains("[M63]"));
        QTest::keyClicks(bad.field("X"), ".");
        // Opened on an existing frame: its fields, edited, replace the line.
        ed->setCursorPosition(1, 3);
        FrameMaster edit;
        QVERIFY(edit.setFromLine(ed->text(1).trimmed()));
        QCOMPARE(edit.kind(), FrameMaster::Iso);
        QCOMPARE(edit.field("X")->text(), QString("5.342"));
        edit.field("X")->setText("7");
        QCOMPARE(edit.text(), QString("N12 G1 X7 FX50 Z-1234.678 FZ1000"));
        tab.insertFromMaster(edit.text(), true);
        QCOMPARE(ed->text(), QString("%L1\nN12 G1 X7 FX50 Z-1234.678 FZ1000\nM30\n"));
        // The other masters.
        FrameMaster j;
        QVERIFY(j.setFromLine("N3 IF R1>0 GOTO 12"));
        QCOMPARE(j.kind(), FrameMaster::IfGoto);
        QCOMPARE(j.text(), QString("N3 IF R1>0 GOTO 12"));
        QVERIFY(j.setFromLine("r75 = 2 * r99"));
        QCOMPARE(j.kind(), FrameMaster::Compute);
        QCOMPARE(j.text(), QString("R75=2*R99"));
        QVERIFY(j.setFromLine("G04 X20.500"));
        QCOMPARE(j.kind(), FrameMaster::Dwell);
        QCOMPARE(j.text(), QString("G4 X20.5"));
        QVERIFY(j.setFromLine("#3=ПРАВКА"));
        QCOMPARE(j.kind(), FrameMaster::Message);
        QCOMPARE(j.text(), QString("#3=ПРАВКА"));
        j.field("msgText")->setText("ПРАВКА КРУГА СЛИШКОМ ДЛИННО");
        QVERIFY(!j.valid());
    }

    void screenshotWithDiagnostics() {
        QMainWindow window;
        auto* tab = new EditorTab(nullptr, &window);
        window.setCentralWidget(tab);
        window.resize(1000, 640);
        window.show();
        tab->newFile();
        ProgramEditor* ed = tab->currentEditor();
        ed->setText("; RU: пример с ошибками\n%L1 (ring 205, rough)\nN10 G1 X5.342 FX50 Z-12.5 FZ100\n"
                    "N20 R75=2*R99\nN30 IF R1>0 GOTO 99\nN40 G4 X2 Z1\n/N50 M3 #2\nN60 L7\nM30\n\n"
                    "%L7 (dress)\nG281 Z-3 FZ200\nM17\n\n%MESSAGES\n#2=ПРАВКА КРУГА\n");
        ed->validateNow();
        ed->toggleBreakpoint(4);
        ed->setExecutingLine(2);
        QVERIFY(tab->problems()->topLevelItemCount() >= 2);
        QTest::qWait(50);
        const QImage img = window.grab().toImage();
        const QString out = QStringLiteral(K528_BINARY_DIR) + "/tests/studio/editor-screenshot.png";
        QVERIFY(img.save(out));
        qInfo("screenshot: %s", qPrintable(out));
    }
};

QTEST_MAIN(TestEditor)
#include "test_editor.moc"
