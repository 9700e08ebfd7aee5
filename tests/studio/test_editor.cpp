// The program editor: a bad frame gets its squiggle on the
// exact columns and a Problems entry, fixing it clears both; typing is
// validated after the debounce on a worker; the machine's limits are
// checked too; colours come from core's tokens; unsaved changes survive a
// cancelled close; a screenshot of the editor with diagnostics.
#include "db/database.h"
#include "rig/widgets.h"
#include "editor/cycle_time_label.h"
#include "editor/editor_tab.h"
#include "editor/refactor_actions.h"
#include "editor/listing_actions.h"
#include "editor/listing.h"
#include "editor/frame_master.h"
#include "editor/program_editor.h"
#include "editor/problems_model.h"
#include "program/tokens.h"
#include "profile/builtin.h"
#include "rig/studio_rig.h"

#include "test_util.h"

#include <QApplication>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
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

using testutil::writeBytes;

} // namespace

class TestEditor : public QObject {
    Q_OBJECT
    QTemporaryDir dbDir_;
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("k528-test-editor");
        // The machines' database of these tests: a new one, never the shop's.
        QVERIFY(dbDir_.isValid());
        qputenv("K528_DB", dbDir_.filePath("machines.sqlite").toUtf8());
    }

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
        QAbstractItemModel* problems = tab.problems()->model();
        QCOMPARE(problems->rowCount(), 1);
        QCOMPARE(problems->index(0, 1).data().toString(), QString("L1"));
        QCOMPARE(problems->index(0, 2).data().toString(), QString("3"));
        // The Code column: the controller's message and the rule's short name, its id in the tooltip.
        QCOMPARE(problems->index(0, 3).data().toString(), QString("[M33] bad number"));
        QCOMPARE(problems->index(0, 3).data(Qt::ToolTipRole).toString(), QString("bad-number"));
        // Its width fits the widest code of all rows, measured from the distinct codes.
        const QFontMetrics metrics = tab.problems()->fontMetrics();
        QVERIFY(tab.problems()->header()->sectionSize(3) > metrics.horizontalAdvance("[M33] bad number"));
        ed->setText("%L1\nN1 G1 X5..3\nN2 G1 X5..3\nN3 G77\nN4 G1 X1 F99999999\nM30\nGOTO\n");
        ed->validateNow();
        QVERIFY(problems->rowCount() >= 3);
        int widest = 0;
        for (int row = 0; row < problems->rowCount(); ++row)
            widest = std::max(widest, metrics.horizontalAdvance(problems->index(row, 3).data().toString()));
        QCOMPARE(static_cast<ProblemsModel*>(problems)->widestCode(metrics), widest);
        QVERIFY(tab.problems()->header()->sectionSize(3) > widest);
        ed->setText("%L1\nN1 G1 X1\nN2 G1 X5..3\nM30\n");
        ed->validateNow();
        QVERIFY(!ed->hoverText(lineStart + 7).isEmpty());
        QVERIFY(ed->hoverText(lineStart + 7).startsWith("[M33] "));
        QVERIFY(ed->hoverText(lineStart + 1).isEmpty());
        QVERIFY(tab.problemCount()->text().contains('1'));
        // The Problems entry jumps to the place.
        emit tab.problems()->activated(problems->index(0, 0));
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
        QCOMPARE(problems->rowCount(), 0);
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

    // The validation reads Scintilla's gap buffer in its two parts, where
    // they lie, into a buffer it reuses: the text validated is the text on
    // screen wherever the gap is (after an edit in the middle, at the start,
    // at the end, after a deletion that shortens it), and reading it does
    // not move the gap (which would move all the text after the caret).
    void validationReadsTheTextAroundTheGap() {
        ProgramEditor ed;
        QString text = "%L1\n";
        for (int n = 1; n <= 40; ++n)
            text += QStringLiteral("N%1 G1 X%1\n").arg(n);
        text += "M30\n";
        ed.setText(text);
        ed.validateNow();
        QVERIFY(ed.diagnostics().empty());
        QCOMPARE(int(ed.store().find(1)->frames.size()), 41);
        // An edit in the middle: the gap is there now.
        ed.setCursorPosition(20, 0);
        ed.insert("N99 G1 X5..3\n");
        const long gap = static_cast<long>(ed.SendScintilla(QsciScintilla::SCI_GETGAPPOSITION));
        QVERIFY(gap > 0 && gap < ed.length());
        ed.validateNow();
        QCOMPARE(static_cast<long>(ed.SendScintilla(QsciScintilla::SCI_GETGAPPOSITION)), gap);
        QCOMPARE(int(ed.diagnostics().size()), 1);
        QCOMPARE(ed.diagnostics().front().line, 21);
        QCOMPARE(int(ed.store().find(1)->frames.size()), 42);
        // Frames before and after the gap are read whole.
        QVERIFY(ed.store().find(1)->indexOfN(19) >= 0);
        QVERIFY(ed.store().find(1)->indexOfN(20) >= 0);
        QVERIFY(ed.store().find(1)->indexOfN(40) >= 0);
        // The text shortened (the buffer is reused, nothing of the longer text
        // is left at its end): the bad frame and the last ten lines deleted.
        ed.setSelection(20, 0, 21, 0);
        ed.removeSelectedText();
        ed.setSelection(31, 0, 41, 0);
        ed.removeSelectedText();
        ed.validateNow();
        QVERIFY(ed.diagnostics().empty());
        QCOMPARE(int(ed.store().find(1)->frames.size()), 31);
        // The gap at the start, then at the end.
        ed.setCursorPosition(0, 0);
        ed.insert("%L2\nN1 G1 Z1\nM30\n");
        ed.validateNow();
        QCOMPARE(int(ed.store().size()), 2);
        ed.append("%L3\nN1 G1 Z1\nM30\n");
        ed.validateNow();
        QCOMPARE(int(ed.store().size()), 3);
        QVERIFY(ed.diagnostics().empty());
        QCOMPARE(ed.store().firstWritten(), 2);
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
        testrig::SimulatedSeam lathe(profile::builtin("training-lathe"));
        EditorTab tab(&lathe.seam);
        tab.setPreviewBeforeSending(false);
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
        const QString path = writeBytes(dir, "p.k528", "%L1\nM30\n");
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
        QString named;
        tab->setCloseQuestion([&](const QString& name) {
            ++asked;
            named = name;
            return EditorTab::CloseChoice::Cancel;
        });
        QVERIFY(!window.close());
        QCOMPARE(asked, 1);
        QCOMPARE(named, QString("p.k528")); // the file's name, not the tab's «p.k528 *»
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
        testrig::SimulatedSeam lathe(profile::builtin("training-lathe"));
        EditorTab tab(&lathe.seam);
        tab.setPreviewBeforeSending(false);
        tab.newFile();
        tab.currentEditor()->setText("%L42 (sent)\nG1 X1 FX50\nM30\n");
        QVERIFY(tab.sendToController());
        QVERIFY(lathe.session.controller().programs().contains(42));
        tab.currentEditor()->setText("%L43\nGOTO 5\nM30\n");
        QVERIFY(!tab.sendToController());
        QVERIFY(!lathe.session.controller().programs().contains(43));
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
        // Its comments stay — "(…)" between the words and "; …" — and the
        // master says before OK which line it replaces and what stays.
        ed->setText("%L1\nN5 G1 X5 (rough) FX50 ; finish pass\nM30\n");
        ed->setCursorPosition(1, 4);
        QString said;
        QTimer::singleShot(0, &tab, [&] {
            if (auto* m = qobject_cast<FrameMaster*>(QApplication::activeModalWidget())) {
                said = m->placement();
                m->reject();
            }
        });
        tab.openMaster();
        QVERIFY2(said.contains("line 2") && said.contains("(rough) ; finish pass"), qPrintable(said));
        QCOMPARE(ed->text(), QString("%L1\nN5 G1 X5 (rough) FX50 ; finish pass\nM30\n")); // cancelled: unchanged
        QSignalSpy told(&tab, &EditorTab::statusMessage);
        tab.insertFromMaster("N5 G1 X7 FX50", true);
        QCOMPARE(ed->text(), QString("%L1\nN5 G1 X7 FX50 (rough) ; finish pass\nM30\n"));
        QVERIFY(!told.isEmpty() && told.last().first().toString().contains("comment kept"));
        ed->setCursorPosition(2, 0); // M30: a new frame goes after it
        QTimer::singleShot(0, &tab, [&] {
            if (auto* m = qobject_cast<FrameMaster*>(QApplication::activeModalWidget())) {
                said = m->placement();
                m->reject();
            }
        });
        tab.openMaster();
        QVERIFY2(said.contains("replaces line 3"), qPrintable(said)); // M30 is a frame too
        ed->setCursorPosition(0, 0);
        QTimer::singleShot(0, &tab, [&] {
            if (auto* m = qobject_cast<FrameMaster*>(QApplication::activeModalWidget())) {
                said = m->placement();
                m->reject();
            }
        });
        tab.openMaster();
        QVERIFY2(said.contains("inserts a new line after line 1"), qPrintable(said));
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

    void renumberMoveCopyAndFormatKeepJumpsAndCalls() {
        EditorTab tab(nullptr);
        tab.newFile();
        ProgramEditor* ed = tab.currentEditor();
        ed->setText("%L1\nN5 G1 X1 FX50\nN7 IF R1>0 GOTO 5\nL7\nM30\n\n%L7\nN1 G1 X2 FX50\nM17\n");
        QVERIFY(tab.refactor()->renumber(1, 10, 10));
        const QString renumbered = ed->text();
        QVERIFY2(renumbered.contains("N10 G1 X1 FX50"), qPrintable(renumbered));
        QVERIFY2(renumbered.contains("N20 IF R1>0 GOTO 10"), qPrintable(renumbered));
        QVERIFY(renumbered.contains("N1 G1 X2 FX50")); // L7 kept its numbers
        // One undo step gives the text back.
        ed->undo();
        QCOMPARE(ed->text(), QString("%L1\nN5 G1 X1 FX50\nN7 IF R1>0 GOTO 5\nL7\nM30\n\n%L7\nN1 G1 X2 FX50\nM17\n"));
        // Move L7 to L8: the call follows.
        QVERIFY(tab.refactor()->moveProgram(7, 8, false));
        QVERIFY2(ed->text().contains("%L8") && !ed->text().contains("%L7"), qPrintable(ed->text()));
        QVERIFY(ed->text().contains("\nL8\n"));
        // Copy L8 to L9: the call stays on L8.
        QVERIFY(tab.refactor()->moveProgram(8, 9, true));
        QVERIFY(ed->text().contains("%L8") && ed->text().contains("%L9") && ed->text().contains("\nL8\n"));
        ed->validateNow();
        QVERIFY(ed->diagnostics().empty());
        // Onto an existing number: refused, nothing changed.
        const QString before = ed->text();
        QSignalSpy status(&tab, &EditorTab::statusMessage);
        QVERIFY(!tab.refactor()->moveProgram(8, 1, false));
        QCOMPARE(ed->text(), before);
        QVERIFY(!status.isEmpty());
        // Format: the canonical text of core's formatter; a syntax error refuses.
        ed->setText("%L1\nn5   g1 x1.500 fx50\nM30\n");
        QVERIFY(tab.refactor()->formatFile());
        QCOMPARE(ed->text(), QString("%L1\nN5 G1 X1.5 FX50\nM30\n"));
        ed->setText("%L1\nN2 G1 X5..3\nM30\n");
        QVERIFY(!tab.refactor()->formatFile());
        QCOMPARE(ed->text(), QString("%L1\nN2 G1 X5..3\nM30\n"));
    }

    void listingAndPdfExport() {
        EditorTab tab(nullptr);
        tab.newFile();
        ProgramEditor* ed = tab.currentEditor();
        QString text = "%L1 (listing)\nN1 G1 X1 FX50\nN2 G1 X5..3\n";
        for (int i = 3; i < 200; ++i)
            text += QStringLiteral("N%1 G1 X%1 FX50\n").arg(i);
        text += "M30\n";
        ed->setText(text);
        ed->validateNow();
        QCOMPARE(int(ed->diagnostics().size()), 1);
        const std::vector<ListingRow> rows = listingRows(ed->text(), ed->diagnostics());
        QCOMPARE(int(rows.size()), 201 + 1); // every line, and the diagnostic under line 3
        QCOMPARE(rows[2].line, 3);
        QCOMPARE(rows[3].line, 0);
        QVERIFY(rows[3].error);
        QVERIFY2(rows[3].text.startsWith("      ^ ") && rows[3].text.contains("[M33]"), qPrintable(rows[3].text));
        const ListingInfo info{"p.k528", "training-lathe", QDateTime(QDate(2026, 12, 2), QTime(1, 30))};
        const QStringList header = listingHeader(info, ed->diagnostics(), 2, 5);
        QVERIFY(header.join('\n').contains("p.k528"));
        QVERIFY(header.join('\n').contains("training-lathe"));
        QVERIFY(header.join('\n').contains("2026-12-02 01:30"));
        QVERIFY(header.join('\n').contains("2") && header.join('\n').contains("5"));
        // The PDF: as many page objects as pages painted, more than one here.
        QTemporaryDir dir;
        const QString path = dir.filePath("listing.pdf");
        const int pages = tab.listing()->exportPdf(path);
        QVERIFY(pages >= 2);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray pdf = f.readAll();
        QVERIFY(pdf.startsWith("%PDF-"));
        QCOMPARE(int(pdf.count("/Type /Page\n") + pdf.count("/Type /Page ") + pdf.count("/Type /Page/") +
                     pdf.count("/Type /Page>")),
                 pages);
        // A place that cannot be written: said, nothing painted.
        QCOMPARE(tab.listing()->exportPdf(dir.filePath("no/such/dir/listing.pdf")), 0);
    }

    void theMachineOfEachFile() {
        testrig::SimulatedSeam lathe(profile::builtin("training-lathe"));
        EditorTab tab(&lathe.seam);
        tab.setPreviewBeforeSending(false);
        tab.newFile();
        ProgramEditor* ed = tab.currentEditor();
        ed->setText("%L1\nG1 X9999 FX50\nM30\n");
        QCOMPARE(tab.checkedMachineName(0), QString("training-lathe"));
        auto limits = [&] {
            ed->validateNow();
            bool found = false;
            for (const auto& d : ed->diagnostics())
                found |= d.rule == program::Rule::SoftLimit || d.rule == program::Rule::FeedAboveMax;
            return found;
        };
        QVERIFY(limits());
        QVERIFY(tab.setFileMachine(0, EditorTab::kNoMachine));
        QCOMPARE(tab.checkedMachineName(0), QString());
        QVERIFY(!limits());
        QVERIFY(tab.setFileMachine(0, "grinder-205"));
        QCOMPARE(tab.checkedMachineName(0), QString("grinder-205"));
        QCOMPARE(tab.fileMachine(0), QString("grinder-205"));
        QVERIFY(tab.setFileMachine(0, QString()));
        QCOMPARE(tab.checkedMachineName(0), QString("training-lathe"));
        // A machine that does not exist: said, checked for none.
        QVERIFY(!tab.setFileMachine(0, "no-such-machine"));
        QCOMPARE(tab.checkedMachineName(0), QString());
    }

    // The completion popup after M offers the M-codes of the machine the file
    // is checked for (its PLC description's, with their text) besides the
    // built-in ones; checked for the language only, the built-in ones alone.
    void completionOffersTheMachinesPlcMCodes() {
        testrig::SimulatedSeam lathe(profile::builtin("training-lathe"));
        EditorTab tab(&lathe.seam);
        tab.resize(900, 600);
        tab.show();
        tab.newFile();
        ProgramEditor* ed = tab.currentEditor();
        ed->setText("%L1\n\nM30\n");
        QCOMPARE(tab.checkedMachineName(0), QString("training-lathe"));
        const auto offered = [&] {
            ed->SendScintilla(QsciScintilla::SCI_AUTOCCANCEL);
            ed->setCursorPosition(1, 0);
            ed->setFocus();
            QTest::keyClicks(ed, "M");
            QStringList items;
            if (!ed->isListActive())
                return items;
            for (QWidget* w : QApplication::allWidgets())
                if (auto* list = qobject_cast<QListWidget*>(w); list && list->isVisible())
                    for (int i = 0; i < list->count(); ++i)
                        items << list->item(i)->text();
            ed->SendScintilla(QsciScintilla::SCI_AUTOCCANCEL);
            ed->setText("%L1\n\nM30\n");
            return items;
        };
        const auto has = [](const QStringList& items, const QString& word) {
            for (const QString& it : items)
                if (it.section(QChar(' '), 0, 0) == word)
                    return true;
            return false;
        };
        QStringList items = offered();
        QVERIFY2(has(items, "M30"), qPrintable(items.join('|')));
        // The lathe's spindle and turret M-codes, with the description's text.
        QVERIFY2(has(items, "M3"), qPrintable(items.join('|')));
        QVERIFY2(has(items, "M64"), qPrintable(items.join('|')));
        QVERIFY2(items.filter("spindle clockwise").size() == 1, qPrintable(items.join('|')));
        QVERIFY(tab.setFileMachine(0, "grinder-205"));
        items = offered();
        QVERIFY2(has(items, "M13") && has(items, "M20"), qPrintable(items.join('|')));
        QVERIFY2(!has(items, "M64"), qPrintable(items.join('|')));
        QVERIFY(tab.setFileMachine(0, EditorTab::kNoMachine));
        items = offered();
        QVERIFY2(has(items, "M30"), qPrintable(items.join('|')));
        QVERIFY2(!has(items, "M3") && !has(items, "M13"), qPrintable(items.join('|')));
    }

    // The status line gives the cycle time of the file's first program on the
    // machine it is checked for: the run of `k528 run` (212.184 s for the
    // lathe sample, test cli.cycle_time), measured off the window's thread;
    // an edit measures again, an error says there is none.
    void theCycleTimeIsInTheStatusLine() {
        testrig::SimulatedSeam lathe(profile::builtin("training-lathe"));
        EditorTab tab(&lathe.seam);
        QFile sample(QStringLiteral(K528_SOURCE_DIR "/resources/samples/lathe-shaft.k528"));
        QVERIFY(sample.open(QIODevice::ReadOnly));
        tab.newFile();
        ProgramEditor* ed = tab.currentEditor();
        CycleTimeLabel* cycle = tab.cycleTime();
        QVERIFY(cycle);
        QSignalSpy measured(cycle, &CycleTimeLabel::measured);
        ed->setText(QString::fromUtf8(sample.readAll()));
        QTRY_VERIFY_WITH_TIMEOUT(cycle->seconds().has_value(), 30000);
        QCOMPARE(std::llround(*cycle->seconds() * 1000), 212184LL);
        QVERIFY2(cycle->text().contains("L1") && cycle->text().contains("Training lathe with the K528-05") &&
                     cycle->text().contains("3 min 32.2 s"),
                 qPrintable(cycle->text()));
        // One more roughing pass (R12=6): a longer cycle, measured again.
        ed->setText(ed->text().replace("N6 R12=5", "N6 R12=6").replace("N4 R10=40000", "N4 R10=42000"));
        QTRY_VERIFY_WITH_TIMEOUT(cycle->seconds().has_value() && *cycle->seconds() > 212.2, 30000);
        // An error in the file: no figure, and the line says why.
        ed->setText("%L1\nN1 G1 X\nM30\n");
        ed->validateNow();
        QTRY_VERIFY_WITH_TIMEOUT(cycle->text().contains("errors"), 10000);
        QVERIFY(!cycle->seconds());
        QCOMPARE(CycleTimeLabel::durationText(49.519), QString("49.5 s"));
    }

    void databaseProgramsAreSavedAsTheNextRevision() {
        const std::string dbPath = qgetenv("K528_DB").toStdString();
        int before = 0;
        {
            const db::Database d = db::Database::open(dbPath); // seeded with the built-in machines
            QVERIFY(d.hasMachine("training-lathe"));
            before = d.machine("training-lathe")->revision;
        }
        EditorTab tab(nullptr);
        tab.setCloseQuestion([](const QString&) { return EditorTab::CloseChoice::Discard; });
        QVERIFY(tab.openFromDatabase("training-lathe"));
        QCOMPARE(tab.databaseMachine(0), QString("training-lathe"));
        QCOMPARE(tab.databaseRevision(0), before);
        QCOMPARE(tab.checkedMachineName(0), QString("training-lathe"));
        ProgramEditor* ed = tab.currentEditor();
        const QString opened = ed->text();
        QVERIFY(opened.contains("%L"));
        // A new program before the messages (or at the end).
        QString edited = opened;
        const QString program = "%L98 (from the editor)\nN1 G1 X1 FX50\nM30\n";
        const int messages = edited.indexOf("%MESSAGES");
        edited.insert(messages >= 0 ? messages : edited.size(), program + "\n");
        ed->setText(edited);
        QVERIFY(ed->isModified());
        QVERIFY(tab.save());
        QVERIFY(!ed->isModified());
        QCOMPARE(tab.databaseRevision(0), before + 1);
        {
            const db::Database d = db::Database::open(dbPath);
            QCOMPARE(d.machine("training-lathe")->revision, before + 1);
            const auto text = d.programText("training-lathe", 98, before + 1);
            QVERIFY(text.has_value());
            QCOMPARE(QString::fromStdString(*text), program);
            // The programs that were not edited are not changes of the revision.
            for (const db::HistoryEntry& h : d.history("training-lathe", std::nullopt, 1))
                QCOMPARE(QString::fromStdString(h.change.key), QString("L98"));
        }
        // Saved again unchanged: no new revision.
        QVERIFY(tab.save());
        QCOMPARE(tab.databaseRevision(0), before + 1);
        // Someone else saved meanwhile: refused, the edits stay.
        EditorTab other(nullptr);
        other.setCloseQuestion([](const QString&) { return EditorTab::CloseChoice::Discard; });
        QVERIFY(other.openFromDatabase("training-lathe"));
        other.currentEditor()->setText(other.currentEditor()->text().replace("X1 FX50", "X2 FX50"));
        QVERIFY(other.save());
        ed->setText(ed->text().replace("X1 FX50", "X3 FX50"));
        QVERIFY(!tab.save());
        QVERIFY(ed->isModified());
        QVERIFY(ed->text().contains("X3 FX50"));
    }

    void reloadWhenChangedOnDisk() {
        QTemporaryDir dir;
        const QString path = writeBytes(dir, "r.k528", "%L1\nM30\n");
        EditorTab tab(nullptr);
        QVERIFY(tab.openFile(path));
        ProgramEditor* ed = tab.currentEditor();
        int asked = 0;
        tab.setReloadQuestion([&](const QString&) {
            ++asked;
            return false;
        });
        // Not modified here: the new text is read without a question.
        writeBytes(dir, "r.k528", "%L1\nG1 X1 FX50\nM30\n");
        QTRY_COMPARE_WITH_TIMEOUT(ed->text(), QString("%L1\nG1 X1 FX50\nM30\n"), 5000);
        QCOMPARE(asked, 0);
        QVERIFY(!ed->isModified());
        // Modified here: asked; «no» keeps the edits.
        ed->setCursorPosition(1, 0);
        ed->insert("N1 ");
        writeBytes(dir, "r.k528", "%L1\nG1 X2 FX50\nM30\n");
        QTRY_COMPARE_WITH_TIMEOUT(asked, 1, 5000);
        QCOMPARE(ed->text(), QString("%L1\nN1 G1 X1 FX50\nM30\n"));
        QVERIFY(ed->isModified());
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
        QVERIFY(tab->problems()->model()->rowCount() >= 2);
        QTest::qWait(50);
        const QImage img = window.grab().toImage();
        K528_VERIFY_SHOT(img, QStringLiteral("editor-screenshot.png"));
    }
};

QTEST_MAIN(TestEditor)
#include "test_editor.moc"
