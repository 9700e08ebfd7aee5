// The technologist's prove-out pane (proveout/proveout_pane.h): the editor's
// file proved on its machine — a rapid through the blank found with its
// frame, the editor taken to its line, the same program made safe finds
// nothing — after each edit on a worker; the machine's tools with their
// offsets; the reasons when nothing can be proved.
#include "editor/editor_tab.h"
#include "editor/setup_sheet_actions.h"
#include "editor/program_editor.h"
#include "main_window.h"
#include "profile/builtin.h"
#include "profile/english.h"
#include "profile/tools.h"
#include "proveout/proveout_pane.h"
#include "rig/facing.h"
#include "rig/studio_rig.h"
#include "editor/problems_model.h"
#include "language.h"

#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QProcess>
#include <QRegularExpression>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTreeView>
#include <QHeaderView>
#include <QtTest>

using namespace k528;
using namespace k528::studio;

namespace {

using testrig::kBadFacing;
using testrig::kSafeFacing;

// The editor with its prove-out pane on the training lathe's simulated
// controller, as the technologist's workspace has them.
struct PaneOnTheLathe {
    testrig::SimulatedSeam rig{profile::builtin("training-lathe")};
    EditorTab tab{&rig.seam};
    ProveoutPane pane{&tab};
    // A new file in the editor holding `text`: its editor.
    ProgramEditor* newFile(const std::string& text) {
        tab.newFile();
        tab.currentEditor()->setText(QString::fromStdString(text));
        return tab.currentEditor();
    }
};

} // namespace

class TestProveoutPane : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName("k528-test-proveout-pane");
        QVERIFY(dir_.isValid());
        qputenv("K528_DB", dir_.filePath("machines.sqlite").toUtf8());
    }

    void cleanup() { setLanguage("en"); }

    void findsTheRapidAndShowsItsLine() {
        PaneOnTheLathe fixture;
        ProveoutPane& pane = fixture.pane;
        ProgramEditor* ed = fixture.newFile(kBadFacing);
        ed->validateNow();
        pane.proveNow();
        QCOMPARE(pane.findings().size(), std::size_t(1));
        const proveout::Finding& f = pane.findings()[0];
        QCOMPARE(f.rule, proveout::Rule::RapidIntoMaterial);
        QCOMPARE(f.n, 4);
        QCOMPARE(f.line, 6);
        QCOMPARE(pane.findingsTable()->rowCount(), 1);
        QCOMPARE(pane.findingsTable()->item(0, 0)->data(ProveoutPane::kRuleRole).toString(),
                 QString("rapid-into-material"));
        QCOMPARE(pane.findingsTable()->item(0, 2)->text(), QString("N4"));
        QCOMPARE(pane.findingsTable()->item(0, 3)->text(), QString("6"));
        QVERIFY(pane.findingsTable()->item(0, 4)->text().contains("X"));
        QVERIFY2(pane.summary()->text().contains("UCG"), qPrintable(pane.summary()->text()));
        // The finding's line is marked in the editor, no other.
        const auto marked = [&](int line0) {
            const long pos = ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, line0) + 2;
            return ed->SendScintilla(QsciScintilla::SCI_INDICATORVALUEAT, ProveoutPane::kIndicator, pos) != 0;
        };
        QVERIFY(marked(5));
        QVERIFY(!marked(4));
        QVERIFY(!marked(6));

        // Activated: the editor's cursor on the finding's line.
        ed->setCursorPosition(0, 0);
        QSignalSpy shown(&pane, &ProveoutPane::lineShown);
        emit pane.findingsTable()->cellActivated(0, 4);
        QCOMPARE(shown.count(), 1);
        int line = -1, col = -1;
        ed->getCursorPosition(&line, &col);
        QCOMPARE(line, 5);

        // Without the file's blank: nothing to hit, and the summary says so;
        // the pane's blank gives it one.
        QString noBlank = QString::fromStdString(kBadFacing);
        noBlank.remove(0, noBlank.indexOf('\n') + 1);
        ed->setText(noBlank);
        ed->validateNow();
        pane.proveNow();
        QVERIFY(pane.findings().empty());
        QVERIFY(!marked(4));
        QVERIFY2(pane.summary()->text().contains("No blank"), qPrintable(pane.summary()->text()));
        pane.blankEdit()->setText("UCG,2,Z-80Z0,X40X0,S0S0,0,-5");
        pane.proveNow();
        QCOMPARE(pane.findings().size(), std::size_t(1));
        QCOMPARE(pane.findings()[0].line, 5);
        QVERIFY(marked(4));
        // A blank that is not one: said, nothing proved.
        pane.blankEdit()->setText("UCG,2,Z-80");
        pane.proveNow();
        QVERIFY(pane.findings().empty());
        QVERIFY2(pane.summary()->text().contains("blank"), qPrintable(pane.summary()->text()));
        QVERIFY(!marked(4));
    }

    // The findings in the editor's Problems list after its diagnostics:
    // severity, program, line, the rule's id, «N4: text» in the window's
    // language; activated, the cursor goes to the line; the boxed line's
    // hover says the finding. The safe program leaves none.
    void theFindingsAreInTheProblemsList() {
        PaneOnTheLathe fixture;
        EditorTab& tab = fixture.tab;
        ProveoutPane& pane = fixture.pane;
        tab.newFile();
        ProgramEditor* ed = tab.currentEditor();
        QAbstractItemModel* problems = tab.problems()->model();
        for (const QString lang : {"en", "ru"}) {
            QVERIFY(setLanguage(lang));
            QCoreApplication::processEvents(); // the language change reaches the widgets
            ed->setText(QString::fromStdString(kBadFacing));
            ed->validateNow();
            pane.proveNow();
            QCOMPARE(problems->rowCount(), 1);
            QCOMPARE(problems->index(0, 0).data().toString(), lang == "ru" ? QString("ошибка") : QString("error"));
            QCOMPARE(problems->index(0, 1).data().toString(), QString("L1"));
            QCOMPARE(problems->index(0, 2).data().toString(), QString("6"));
            // The rule's short name in the window's language, its id in the tooltip.
            QCOMPARE(problems->index(0, 3).data().toString(),
                     lang == "ru" ? QString("G00 в материал") : QString("rapid into material"));
            QVERIFY(problems->index(0, 3).data(Qt::ToolTipRole).toString().endsWith(": rapid-into-material"));
            QCOMPARE(problems->index(0, 0).data(ProblemsModel::kRuleRole).toString(), QString("rapid-into-material"));
            // The Code column shows the rule's name whole, in either language.
            QVERIFY2(tab.problems()->header()->sectionSize(3) >
                         tab.problems()->fontMetrics().horizontalAdvance(problems->index(0, 3).data().toString()),
                     qPrintable(QString::number(tab.problems()->header()->sectionSize(3))));
            const QString text = problems->index(0, 4).data().toString();
            QVERIFY2(text.startsWith("N4: "), qPrintable(text));
            const QRegularExpression cyrillic("[\\x{0400}-\\x{04FF}]");
            if (lang == "ru")
                QVERIFY2(text.contains(cyrillic) && !text.mid(4).contains(QRegularExpression("[a-z]{3,}")), qPrintable(text));
            else
                QVERIFY2(!text.contains(cyrillic) && text.contains("rapid", Qt::CaseInsensitive), qPrintable(text));
            QCOMPARE(text.mid(4), pane.findingsTable()->item(0, 4)->text());
            QVERIFY2(tab.problemCount()->text().contains('1'), qPrintable(tab.problemCount()->text()));
            // The hover over the boxed line: the finding's text; a line without a box: nothing.
            const long inLine = ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, 5) + 3;
            QCOMPARE(ed->hoverText(static_cast<int>(inLine)), text);
            const long otherLine = ed->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, 4) + 3;
            QVERIFY(ed->hoverText(static_cast<int>(otherLine)).isEmpty());
            // Activated (a double click): the cursor on its line, the place told.
            ed->setCursorPosition(0, 0);
            QSignalSpy place(&tab, &EditorTab::proveoutFindingActivated);
            emit tab.problems()->activated(problems->index(0, 4));
            int line = -1, col = -1;
            ed->getCursorPosition(&line, &col);
            QCOMPARE(line, 5);
            QCOMPARE(place.count(), 1);
            QCOMPARE(place.at(0).at(1).toInt(), 6);
            QCOMPARE(place.at(0).at(2).toDouble(), pane.findings()[0].at.z);
            QCOMPARE(place.at(0).at(3).toDouble(), pane.findings()[0].at.x);

            // Made safe: nothing listed, boxed or said.
            ed->setText(QString::fromStdString(kSafeFacing));
            ed->validateNow();
            pane.proveNow();
            QCOMPARE(problems->rowCount(), 0);
            QVERIFY(ed->hoverText(static_cast<int>(inLine)).isEmpty());
            QCOMPARE(ed->SendScintilla(QsciScintilla::SCI_INDICATORVALUEAT, ProgramEditor::kProveoutIndicator, inLine), 0L);
        }
        QVERIFY(setLanguage("en"));
        // The blank changed: the finding comes and goes with it.
        QString noBlank = QString::fromStdString(kBadFacing);
        noBlank.remove(0, noBlank.indexOf('\n') + 1);
        ed->setText(noBlank);
        ed->validateNow();
        pane.proveNow();
        QCOMPARE(problems->rowCount(), 0);
        pane.blankEdit()->setText("UCG,2,Z-80Z0,X40X0,S0S0,0,-5");
        pane.proveNow();
        QCOMPARE(problems->rowCount(), 1);
        QCOMPARE(problems->index(0, 2).data().toString(), QString("5"));
        // Another document: its Problems hold none of the first one's findings.
        tab.newFile();
        QTRY_COMPARE(tab.problems()->model()->rowCount(), 0);
        pane.proveNow();
        QCOMPARE(tab.problems()->model()->rowCount(), 0);
        QVERIFY(ed->proveoutFindings().empty()); // the first one's box is cleared when another is proved
    }

    void anEditProvesAgainOnTheWorker() {
        PaneOnTheLathe fixture;
        ProveoutPane& pane = fixture.pane;
        ProgramEditor* ed = fixture.newFile(kBadFacing);
        QTRY_COMPARE_WITH_TIMEOUT(pane.findings().size(), std::size_t(1), 20000);
        ed->setText(QString::fromStdString(kSafeFacing));
        QTRY_VERIFY_WITH_TIMEOUT(pane.findings().empty() && pane.summary()->text().startsWith("Nothing"),
                                 20000);
        QCOMPARE(pane.findingsTable()->rowCount(), 0);
    }

    void theMachinesToolsWithTheirOffsets() {
        const profile::MachineProfile lathe = profile::builtin("training-lathe");
        PaneOnTheLathe fixture;
        ProveoutPane& pane = fixture.pane;
        fixture.newFile(kSafeFacing)->validateNow();
        pane.proveNow();
        const std::vector<profile::Tool> tools = profile::tools(lathe);
        QCOMPARE(tools.size(), std::size_t(4));
        QCOMPARE(pane.toolsTable()->rowCount(), 4);
        for (int r = 0; r < 4; ++r) {
            const profile::Tool& t = tools[std::size_t(r)];
            const profile::ToolOffsets o = profile::toolOffsets(t, lathe);
            QCOMPARE(pane.toolsTable()->item(r, 0)->text(), QString::number(t.station));
            QCOMPARE(pane.toolsTable()->item(r, 3)->text(), QString::number(o.xMm, 'f', 3));
            QCOMPARE(pane.toolsTable()->item(r, 4)->text(), QString::number(o.zMm, 'f', 3));
            QCOMPARE(pane.toolsTable()->item(r, 5)->text(),
                     QString("R%1, R%2").arg(t.offsetR).arg(t.offsetR + 1));
        }
        // Station 2's offsets are preset (R102, R103): not zero.
        QVERIFY(pane.toolsTable()->item(1, 4)->text() != QString("0.000"));
        QCOMPARE(pane.toolsTable()->item(3, 1)->text(), QString("drill"));
        // Each tool's name as the machine gives it in the window's language:
        // its English in an English window, its Russian in a Russian one.
        QCOMPARE(pane.toolsTable()->horizontalHeaderItem(7)->text(), QString("Tool"));
        QCOMPARE(pane.toolsTable()->item(0, 7)->text(), QString("Straight turning tool T15K6"));
        QCOMPARE(pane.toolsTable()->item(3, 7)->text(), QString("Drill D10"));
        QVERIFY(setLanguage("ru"));
        QTRY_COMPARE(pane.toolsTable()->horizontalHeaderItem(7)->text(), QString("Инструмент")); // the change told
        QCOMPARE(pane.toolsTable()->rowCount(), 4);
        for (int r = 0; r < 4; ++r)
            QCOMPARE(pane.toolsTable()->item(r, 7)->text(), QString::fromStdString(tools[std::size_t(r)].name));
        QCOMPARE(pane.toolsTable()->item(3, 7)->text(), QString("Сверло D10"));
        QVERIFY(setLanguage("en"));
        QTRY_COMPARE(pane.toolsTable()->item(3, 7)->text(), QString("Drill D10"));
    }

    void saysWhyNothingIsProved() {
        PaneOnTheLathe fixture;
        EditorTab& tab = fixture.tab;
        ProveoutPane& pane = fixture.pane;
        pane.proveNow();
        QVERIFY2(pane.summary()->text().contains("Open"), qPrintable(pane.summary()->text()));
        ProgramEditor* ed = fixture.newFile(kBadFacing);
        QVERIFY(tab.setFileMachine(0, EditorTab::kNoMachine));
        ed->validateNow();
        pane.proveNow();
        QVERIFY(pane.findings().empty());
        QVERIFY2(pane.summary()->text().contains("no machine"), qPrintable(pane.summary()->text()));
        QVERIFY(tab.setFileMachine(0, QString()));
        ed->setText("%L1\nN1 GOTO 7\nN2 M30\n"); // a jump to nowhere: an error of the file
        ed->validateNow();
        pane.proveNow();
        QVERIFY2(pane.summary()->text().contains("errors"), qPrintable(pane.summary()->text()));
    }

    void aDockOfTheTechnologist() {
        MainWindow w;
        auto* dock = w.findChild<QDockWidget*>("dock.proveout");
        QVERIFY(dock);
        QVERIFY(dock->findChild<ProveoutPane*>());
        QVERIFY(!dock->windowTitle().isEmpty());
    }

    // Editor > Setup sheet: the editor's file on its machine as PDF — every
    // tool of the machine, the cycle time, the R presets (pdftotext reads it
    // back); without a machine it says why and writes nothing.
    void theSetupSheetOfTheEditorsFile() {
        testrig::SimulatedSeam lathe(profile::builtin("training-lathe"));
        EditorTab tab(&lathe.seam);
        tab.newFile();
        ProgramEditor* ed = tab.currentEditor();
        ed->setText(QString::fromStdString(kSafeFacing));
        ed->validateNow();
        auto* menu = tab.findChild<QMenu*>("menu.editor.setupSheet");
        QVERIFY(menu);
        QVERIFY(tab.editorMenu()->actions().contains(menu->menuAction()));
        QCOMPARE(menu->actions().size(), 2);
        const QString pdf = dir_.filePath("sheet.pdf");
        // The window in English: the tools' English names (the machine gives
        // them), none of their Russian; in Russian the other way round.
        const profile::MachineProfile machine = profile::builtin("training-lathe");
        QString text;
        for (const char* lang : {"ru", "en"}) {
            QVERIFY(setLanguage(lang));
            const bool english = QLatin1String(lang) == QLatin1String("en");
            QCOMPARE(tab.setupSheets()->exportPdf(pdf), QString());
            QProcess p;
            p.start("pdftotext", {"-layout", pdf, "-"});
            QVERIFY(p.waitForFinished(30000));
            text = QString::fromUtf8(p.readAllStandardOutput());
            for (const profile::Tool& t : profile::tools(machine)) {
                const QString name = QString::fromStdString(profile::toolName(machine, t, english));
                const QString other = QString::fromStdString(profile::toolName(machine, t, !english));
                QVERIFY(name != other);
                for (const QString& word : name.split(' ')) // a cell may wrap it
                    QVERIFY2(text.contains(word), qPrintable(name + "\n" + text));
                QVERIFY2(!text.contains(other.split(' ').front()), qPrintable(other + "\n" + text));
            }
            const QString title = QString::fromStdString(profile::titleText(machine, english));
            QVERIFY2(text.simplified().contains(title.left(20)), qPrintable(title + "\n" + text));
        }
        QVERIFY2(text.contains("FACE"), qPrintable(text));
        QVERIFY(QRegularExpression("L1\\s+FACE\\s+\\d+\\.\\d").match(text).hasMatch());
        QVERIFY(QRegularExpression("R220\\s+200000\\s").match(text).hasMatch());

        ed->setText("%L1\nN1 G0 X\n"); // errors: no sheet
        ed->validateNow();
        QVERIFY(!tab.setupSheets()->exportPdf(dir_.filePath("bad.pdf")).isEmpty());
        QVERIFY(!QFile::exists(dir_.filePath("bad.pdf")));
    }
};

QTEST_MAIN(TestProveoutPane)
#include "test_proveout_pane.moc"
