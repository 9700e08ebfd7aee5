// The tools of the editor tab: refactoring (renumber, move/copy a
// program, format the file), the listing (print, PDF), the machine each file
// is checked for, and database machines' programs. Kept apart from
// editor_tab.cpp, which holds the files, tabs and lists.
#include "editor/database_programs.h"
#include "session/core_texts.h"
#include "editor/editor_tab.h"
#include "editor/program_releases.h"
#include "editor/listing.h"
#include "editor/program_editor.h"
#include "editor/text_refactor.h"
#include "engine/self_test.h"
#include "session/machine_source.h"
#include "controller/controller.h"
#include "language.h"
#include "sheet/sheet_render.h"
#include "editing/teach.h"
#include "units/units.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QInputDialog>
#include <QMenu>
#include <QPrintDialog>
#include <QPrinter>
#include <QPrintPreviewDialog>
#include <QGuiApplication>
#include <QMessageBox>
#include <QRegularExpression>
#include <QScreen>
#include <QSpinBox>
#include <QTabWidget>
#include <QToolBar>
#include <QToolButton>

namespace k528::studio {

namespace {
constexpr const char* kMachineProperty = "k528.machine"; // the file's machine choice
constexpr const char* kDbMachineProperty = "k528.dbMachine";
constexpr const char* kDbRevisionProperty = "k528.dbRevision";
constexpr const char* kUntitledProperty = "k528.untitled";
constexpr const char* kSampleProperty = "k528.sample"; // as editor_tab.cpp

QToolButton* menuButton(QToolBar* bar, QAction* a, QMenu* m) {
    a->setMenu(m);
    auto* b = qobject_cast<QToolButton*>(bar->widgetForAction(a));
    if (b)
        b->setPopupMode(QToolButton::InstantPopup);
    return b;
}
} // namespace

void EditorTab::createTools() {
    editorMenu_ = new QMenu(this);
    editorMenu_->setObjectName("menu.editor");
    refactorMenu_ = new QMenu(this);
    renumberAction_ = refactorMenu_->addAction(QString(), this, &EditorTab::renumberDialog);
    moveAction_ = refactorMenu_->addAction(QString(), this, &EditorTab::moveProgramDialog);
    formatAction_ = refactorMenu_->addAction(QString(), this, [this] { formatFile(); });
    formatAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    listingMenu_ = new QMenu(this);
    printAction_ = listingMenu_->addAction(QString(), this, &EditorTab::printDialog);
    printAction_->setShortcut(QKeySequence::Print);
    pdfAction_ = listingMenu_->addAction(QString(), this, &EditorTab::exportPdfDialog);
    sheetMenu_ = new QMenu(this);
    sheetMenu_->setObjectName("menu.editor.setupSheet");
    sheetPreviewAction_ = sheetMenu_->addAction(QString(), this, &EditorTab::previewSetupSheet);
    sheetPdfAction_ = sheetMenu_->addAction(QString(), this, &EditorTab::exportSetupSheetDialog);
    teachMenu_ = new QMenu(this);
    teachMenu_->setObjectName("menu.editor.teach");
    teachFrameAction_ = teachMenu_->addAction(QString(), this, [this] { teachPosition(); });
    teachFrameAction_->setObjectName("editor.teachFrame");
    teachFrameAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::ALT | Qt::Key_T));
    teachRMenu_ = teachMenu_->addMenu(QString());
    teachRMenu_->setObjectName("menu.editor.teachR");
    connect(teachRMenu_, &QMenu::aboutToShow, this, &EditorTab::fillTeachRMenu);
    fileMachineMenu_ = new QMenu(this);
    fileMachineMenu_->setObjectName("menu.editor.fileMachine");
    connect(fileMachineMenu_, &QMenu::aboutToShow, this, &EditorTab::fillFileMachineMenu);
    openDbAction_ = new QAction(this);
    connect(openDbAction_, &QAction::triggered, this, &EditorTab::openDatabaseDialog);

    toolbar_->addSeparator();
    refactorAction_ = toolbar_->addAction(QString());
    menuButton(toolbar_, refactorAction_, refactorMenu_);
    listingAction_ = toolbar_->addAction(QString());
    menuButton(toolbar_, listingAction_, listingMenu_);
    fileMachineAction_ = toolbar_->addAction(QString());
    fileMachineAction_->setObjectName("editor.fileMachine");
    menuButton(toolbar_, fileMachineAction_, fileMachineMenu_);
    toolbar_->addAction(openDbAction_);

    editorMenu_->addMenu(refactorMenu_);
    editorMenu_->addMenu(listingMenu_);
    editorMenu_->addMenu(sheetMenu_);
    editorMenu_->addMenu(teachMenu_);
    editorMenu_->addMenu(fileMachineMenu_);
    editorMenu_->addAction(openDbAction_);
    connect(tabs_, &QTabWidget::currentChanged, this, &EditorTab::retranslateTools);
}

void EditorTab::retranslateTools() {
    editorMenu_->setTitle(tr("&Editor"));
    refactorMenu_->setTitle(tr("Refactor"));
    refactorAction_->setText(tr("Refactor"));
    renumberAction_->setText(tr("Renumber frames…"));
    moveAction_->setText(tr("Move or copy a program…"));
    formatAction_->setText(tr("Format the file"));
    listingMenu_->setTitle(tr("Listing"));
    listingAction_->setText(tr("Listing"));
    printAction_->setText(tr("Print…"));
    pdfAction_->setText(tr("Export PDF…"));
    sheetMenu_->setTitle(tr("Setup sheet"));
    sheetPreviewAction_->setText(tr("Print preview…"));
    sheetPreviewAction_->setToolTip(tr("The setup sheet of this file on its machine: the blank, the tools with their "
                                       "offsets, the programs with their cycle times, the R-parameters to preset"));
    sheetPdfAction_->setText(tr("Export PDF…"));
    teachMenu_->setTitle(tr("Teach-in"));
    teachFrameAction_->setText(tr("Insert the controller's position as a frame"));
    teachFrameAction_->setToolTip(tr("The position the viewed controller's axes are at (current coordinates, as "
                                     "its panel shows them) as a frame after the cursor's line"));
    teachRMenu_->setTitle(tr("Position into an R-parameter"));
    fillTeachRMenu();
    fileMachineMenu_->setTitle(tr("Machine of this file"));
    const int i = tabs_ ? tabs_->currentIndex() : -1;
    const QString m = i >= 0 ? checkedMachineName(i) : QString();
    fileMachineAction_->setText(tr("Machine: %1").arg(m.isEmpty() ? tr("none") : m));
    fileMachineAction_->setToolTip(tr("The machine this file is checked for: its limits, feeds and axes"));
    openDbAction_->setText(tr("Open from the database…"));
    openDbAction_->setToolTip(tr("The programs and messages of a machine of the database; saving writes its next revision"));
}

// --- The machine of each file ------------------------------------------------------

void EditorTab::applyMachine(ProgramEditor* ed) {
    const QString choice = ed->property(kMachineProperty).toString();
    if (!checkMachine_ || choice == kNoMachine) {
        ed->setMachine(std::nullopt);
    } else if (choice.isEmpty()) {
        if (viewed_) // the controller shown: its constants and the programs it holds
            ed->setMachine(viewed_->current().profile(), viewed_->current().programs());
        else
            ed->setMachine(std::nullopt);
    } else {
        try {
            const MachineChoice c = loadMachine(choice);
            bool intact = true;
            program::ProgramStore programs = engine::loadStore(c.profile, intact);
            ed->setMachine(c.profile, std::move(programs));
        } catch (const std::exception& e) {
            emit statusMessage(tr("The machine %1 cannot be loaded: %2").arg(choice, coreErrorText(e)));
            ed->setMachine(std::nullopt);
        }
    }
    if (tabs_ && ed == currentEditor())
        retranslateTools();
}

void EditorTab::reapplyWorkstationMachine() {
    // Another controller shown: the files checked for "the workstation's
    // machine" are checked for it now.
    for (int i = 0; i < documentCount(); ++i)
        if (ProgramEditor* ed = editorAt(i); ed && ed->property(kMachineProperty).toString().isEmpty()) {
            applyMachine(ed);
            ed->validateNow();
        }
}

bool EditorTab::setFileMachine(int index, const QString& choice) {
    ProgramEditor* ed = editorAt(index);
    if (!ed)
        return false;
    ed->setProperty(kMachineProperty, choice);
    applyMachine(ed);
    const bool ok = choice.isEmpty() || choice == kNoMachine || ed->hasMachine();
    ed->validateNow();
    return ok;
}

QString EditorTab::fileMachine(int index) const {
    ProgramEditor* ed = editorAt(index);
    return ed ? ed->property(kMachineProperty).toString() : QString();
}

QString EditorTab::checkedMachineName(int index) const {
    ProgramEditor* ed = editorAt(index);
    if (!ed || !ed->machine())
        return {};
    return QString::fromStdString(ed->machine()->name);
}

void EditorTab::fillFileMachineMenu() {
    fileMachineMenu_->clear();
    const int i = tabs_->currentIndex();
    if (i < 0) {
        fileMachineMenu_->addAction(tr("No file is open"))->setEnabled(false);
        return;
    }
    const QString current = fileMachine(i);
    auto add = [&](const QString& text, const QString& choice) {
        QAction* a = fileMachineMenu_->addAction(text);
        a->setCheckable(true);
        a->setChecked(current == choice);
        a->setObjectName("action.fileMachine." + (choice.isEmpty() ? QStringLiteral("workstation") : choice));
        connect(a, &QAction::triggered, this, [this, i, choice] { setFileMachine(i, choice); });
    };
    add(viewed_ ? tr("The workstation's machine (%1)").arg(QString::fromStdString(viewed_->current().profile().name))
                 : tr("The workstation's machine (none)"),
        QString());
    add(tr("None: the language only"), kNoMachine);
    fileMachineMenu_->addSeparator();
    QString warning;
    for (const QString& n : machineNames(&warning))
        add(n, n);
    if (!warning.isEmpty())
        fileMachineMenu_->addAction(warning)->setEnabled(false);
}

// --- Refactoring -------------------------------------------------------------------

void EditorTab::replaceText(ProgramEditor* ed, const QString& text) {
    int line = 0, index = 0;
    ed->getCursorPosition(&line, &index);
    const int first = ed->firstVisibleLine();
    const QByteArray bytes = text.toUtf8();
    ed->beginUndoAction();
    ed->SendScintilla(QsciScintilla::SCI_SETTARGETSTART, 0UL);
    ed->SendScintilla(QsciScintilla::SCI_SETTARGETEND, static_cast<unsigned long>(ed->length()));
    ed->SendScintilla(QsciScintilla::SCI_REPLACETARGET, static_cast<unsigned long>(bytes.size()), bytes.constData());
    ed->endUndoAction();
    ed->setCursorPosition(std::min(line, std::max(0, ed->lines() - 1)), 0);
    ed->setFirstVisibleLine(first);
    ed->validateNow();
}

namespace {
bool applyRefactor(EditorTab* tab, ProgramEditor* ed, const TextRefactor& r, const QString& done,
                   const std::function<void(ProgramEditor*, const QString&)>& replace) {
    if (!r.ok) {
        emit tab->statusMessage(r.error);
        return false;
    }
    if (r.text != ed->text())
        replace(ed, r.text);
    emit tab->statusMessage(done);
    return true;
}
} // namespace

bool EditorTab::renumber(int program, int start, int step) {
    ProgramEditor* ed = currentEditor();
    if (!ed)
        return false;
    return applyRefactor(this, ed, renumberText(ed->text(), program, start, step),
                         program == 0 ? tr("Renumbered every program from %1 by %2").arg(start).arg(step)
                                      : tr("Renumbered L%1 from %2 by %3").arg(program).arg(start).arg(step),
                         [this](ProgramEditor* e, const QString& t) { replaceText(e, t); });
}

bool EditorTab::moveProgram(int from, int to, bool copy) {
    ProgramEditor* ed = currentEditor();
    if (!ed)
        return false;
    return applyRefactor(this, ed, moveProgramText(ed->text(), from, to, copy),
                         copy ? tr("Copied L%1 to L%2").arg(from).arg(to) : tr("Moved L%1 to L%2").arg(from).arg(to),
                         [this](ProgramEditor* e, const QString& t) { replaceText(e, t); });
}

bool EditorTab::formatFile() {
    ProgramEditor* ed = currentEditor();
    if (!ed)
        return false;
    return applyRefactor(this, ed, formatText(ed->text()), tr("Formatted"),
                         [this](ProgramEditor* e, const QString& t) { replaceText(e, t); });
}

void EditorTab::renumberDialog() {
    ProgramEditor* ed = currentEditor();
    if (!ed)
        return;
    ed->validateNow();
    QDialog d(this);
    d.setObjectName("editor.renumberDialog");
    d.setWindowTitle(tr("Renumber frames"));
    auto* form = new QFormLayout(&d);
    auto* program = new QComboBox(&d);
    program->addItem(tr("Every program"), 0);
    for (const program::Program& p : ed->store().programs())
        program->addItem(QStringLiteral("L%1").arg(p.number), p.number);
    const int here = ed->programAtLine([&] {
        int line = 0, index = 0;
        ed->getCursorPosition(&line, &index);
        return line;
    }());
    if (const int at = program->findData(here); here > 0 && at >= 0)
        program->setCurrentIndex(at);
    auto* start = new QSpinBox(&d);
    start->setRange(1, program::kMaxFrameNumber);
    start->setValue(10);
    auto* step = new QSpinBox(&d);
    step->setRange(1, program::kMaxFrameNumber);
    step->setValue(10);
    form->addRow(tr("Program"), program);
    form->addRow(tr("First number"), start);
    form->addRow(tr("Step"), step);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &d);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, &d, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &d, &QDialog::reject);
    if (d.exec() == QDialog::Accepted)
        renumber(program->currentData().toInt(), start->value(), step->value());
}

void EditorTab::moveProgramDialog() {
    ProgramEditor* ed = currentEditor();
    if (!ed)
        return;
    ed->validateNow();
    if (ed->store().empty()) {
        emit statusMessage(tr("The file has no program"));
        return;
    }
    QDialog d(this);
    d.setObjectName("editor.moveDialog");
    d.setWindowTitle(tr("Move or copy a program"));
    auto* form = new QFormLayout(&d);
    auto* from = new QComboBox(&d);
    for (const program::Program& p : ed->store().programs())
        from->addItem(QStringLiteral("L%1").arg(p.number), p.number);
    auto* to = new QSpinBox(&d);
    to->setRange(1, 99);
    to->setPrefix(QStringLiteral("L"));
    int free = 1;
    while (free < 99 && ed->store().contains(free))
        ++free;
    to->setValue(free);
    auto* copy = new QCheckBox(tr("Keep the program (copy)"), &d);
    form->addRow(tr("Program"), from);
    form->addRow(tr("New number"), to);
    form->addRow(copy);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &d);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, &d, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &d, &QDialog::reject);
    if (d.exec() == QDialog::Accepted)
        moveProgram(from->currentData().toInt(), to->value(), copy->isChecked());
}

// --- The listing -------------------------------------------------------------------

QString EditorTab::documentName(int index) const {
    ProgramEditor* ed = editorAt(index);
    if (!ed)
        return {};
    const QString db = databaseMachine(index);
    if (!db.isEmpty())
        return tr("%1 (database, revision %2)").arg(db).arg(databaseRevision(index));
    const QString p = pathOf(index);
    if (p.isEmpty() && !ed->property(kSampleProperty).toString().isEmpty())
        return tr("%1 (sample)").arg(ed->property(kSampleProperty).toString());
    return p.isEmpty() ? tr("untitled %1").arg(ed->property(kUntitledProperty).toInt()) : QFileInfo(p).fileName();
}

int EditorTab::exportPdf(const QString& path) {
    ProgramEditor* ed = currentEditor();
    if (!ed)
        return 0;
    ed->validateNow();
    const int i = tabs_->currentIndex();
    const ListingInfo info{pathOf(i).isEmpty() ? documentName(i) : pathOf(i), checkedMachineName(i),
                           QDateTime::currentDateTime()};
    QString error;
    const int pages = exportListingPdf(ed->text(), ed->diagnostics(), info, path, &error);
    emit statusMessage(pages > 0 ? tr("Listing of %1 pages written to %2").arg(pages).arg(path) : error);
    return pages;
}

void EditorTab::exportPdfDialog() {
    const int i = tabs_->currentIndex();
    if (i < 0)
        return;
    QString suggestion = pathOf(i);
    if (!suggestion.isEmpty())
        suggestion = QFileInfo(suggestion).path() + "/" + QFileInfo(suggestion).completeBaseName() + ".pdf";
    const QString p = QFileDialog::getSaveFileName(this, tr("Export the listing"), suggestion, tr("PDF (*.pdf)"));
    if (!p.isEmpty())
        exportPdf(p);
}

void EditorTab::printDialog() {
    ProgramEditor* ed = currentEditor();
    if (!ed)
        return;
    ed->validateNow();
    QPrinter printer(QPrinter::HighResolution);
    QPrintDialog dialog(&printer, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const int i = tabs_->currentIndex();
    const ListingInfo info{pathOf(i).isEmpty() ? documentName(i) : pathOf(i), checkedMachineName(i),
                           QDateTime::currentDateTime()};
    const int pages = printListing(ed->text(), ed->diagnostics(), info, printer);
    emit statusMessage(pages > 0 ? tr("Printed %1 pages").arg(pages) : tr("The listing could not be printed"));
}

// --- The setup sheet --------------------------------------------------------------

bool EditorTab::setupSheet(proveout::SetupSheet& sheet, QString& why) {
    ProgramEditor* ed = currentEditor();
    if (!ed) {
        why = tr("Open a program file in the editor: its setup sheet is made on the machine it is checked for.");
        return false;
    }
    ed->validateNow();
    if (!ed->machine()) {
        why = tr("The file is checked for no machine: choose one (Editor menu) for its setup sheet.");
        return false;
    }
    if (program::hasErrors(ed->diagnostics())) {
        why = tr("The file has errors (Problems): its setup sheet is made once they are fixed.");
        return false;
    }
    const int i = tabs_->currentIndex();
    const QString name = pathOf(i).isEmpty() ? documentName(i) : QFileInfo(pathOf(i)).fileName();
    QGuiApplication::setOverrideCursor(Qt::WaitCursor);
    try {
        sheet = proveout::setupSheet(*ed->machine(), ed->store(), ed->text().toStdString(), name.toStdString());
    } catch (const std::exception& e) {
        QGuiApplication::restoreOverrideCursor();
        why = tr("The setup sheet cannot be made: %1").arg(coreErrorText(e));
        return false;
    }
    QGuiApplication::restoreOverrideCursor();
    return true;
}

QString EditorTab::exportSetupSheet(const QString& path) {
    proveout::SetupSheet sheet;
    QString why;
    if (!setupSheet(sheet, why)) {
        emit statusMessage(why);
        return why;
    }
    const QString error = writeSetupSheetPdf(sheet, currentLanguage() == QLatin1String("ru"), path);
    emit statusMessage(error.isEmpty() ? tr("Setup sheet written to %1").arg(path)
                                       : tr("Cannot write %1: %2").arg(path, error));
    return error;
}

void EditorTab::exportSetupSheetDialog() {
    const int i = tabs_->currentIndex();
    if (i < 0)
        return;
    QString suggestion = pathOf(i);
    if (!suggestion.isEmpty())
        suggestion = QFileInfo(suggestion).path() + "/" + QFileInfo(suggestion).completeBaseName() + "-setup.pdf";
    const QString p =
        QFileDialog::getSaveFileName(this, tr("Export the setup sheet"), suggestion, tr("PDF (*.pdf)"));
    if (!p.isEmpty())
        exportSetupSheet(p);
}

void EditorTab::previewSetupSheet() {
    proveout::SetupSheet sheet;
    QString why;
    if (!setupSheet(sheet, why)) {
        emit statusMessage(why);
        QMessageBox::information(this, tr("Setup sheet"), why);
        return;
    }
    const bool russian = currentLanguage() == QLatin1String("ru");
    QPrinter printer(QPrinter::HighResolution);
    printer.setPageSize(QPageSize(QPageSize::A4));
    printer.setPageMargins(QMarginsF(12, 12, 12, 12), QPageLayout::Millimeter);
    printer.setDocName(tr("Setup sheet") + QStringLiteral(": ") + QString::fromStdString(sheet.file));
    QPrintPreviewDialog dialog(&printer, this);
    dialog.setObjectName("dialog.setupSheet");
    dialog.setWindowTitle(tr("Setup sheet: %1").arg(QString::fromStdString(sheet.file)));
    if (const QScreen* screen = window()->screen()) // the page large enough to read
        dialog.resize(screen->availableGeometry().size() * 0.85);
    connect(&dialog, &QPrintPreviewDialog::paintRequested, this,
            [&sheet, russian](QPrinter* p) { printSetupSheet(sheet, russian, *p); });
    dialog.exec();
}

// --- Teach-in ----------------------------------------------------------------------

void EditorTab::fillTeachRMenu() {
    teachRMenu_->clear();
    const bool ru = currentLanguage() == QLatin1String("ru");
    for (const editing::TeachTarget& t : editing::teachTargets()) {
        const QString meaning = QString::fromUtf8(std::string(ru ? t.meaningRu : t.meaningEn).c_str());
        QAction* a = teachRMenu_->addAction(QStringLiteral("R%1 — %2").arg(t.r).arg(meaning));
        a->setData(t.r);
        connect(a, &QAction::triggered, this, [this, r = t.r] { teachIntoR(r); });
    }
}

int EditorTab::frameNumberAtCursor() const {
    ProgramEditor* ed = currentEditor();
    if (!ed)
        return 0;
    int line = 0, index = 0;
    ed->getCursorPosition(&line, &index);
    static const QRegularExpression n(QStringLiteral("^\\s*/?\\s*N(\\d+)"));
    const QRegularExpressionMatch m = n.match(ed->text(line));
    return m.hasMatch() ? m.captured(1).toInt() : 0;
}

bool EditorTab::insertTaught(const QString& text, bool replaceLine) {
    ProgramEditor* ed = currentEditor();
    if (!ed)
        return false;
    int line = 0, index = 0;
    ed->getCursorPosition(&line, &index);
    ed->beginUndoAction();
    const QString cur = ed->text(line);
    int len = static_cast<int>(cur.size());
    while (len > 0 && (cur.at(len - 1) == '\n' || cur.at(len - 1) == '\r'))
        --len;
    if (replaceLine || cur.trimmed().isEmpty()) {
        const QString kept = replaceLine ? commentsOfLine(cur.left(len)) : QString();
        ed->setSelection(line, 0, line, len);
        ed->replaceSelectedText(kept.isEmpty() ? text : text + " " + kept);
    } else {
        ed->insertAt(text + "\n", line + 1, 0);
        if (line + 1 >= ed->lines() - 1 && !cur.endsWith('\n'))
            ed->insertAt("\n", line + 1, 0);
        ++line;
    }
    ed->endUndoAction();
    ed->setCursorPosition(line, static_cast<int>(ed->text(line).size()) - (ed->text(line).endsWith('\n') ? 1 : 0));
    ed->setFocus();
    return true;
}

bool EditorTab::teachPosition(QString* taught) {
    if (!currentEditor()) {
        emit statusMessage(tr("Open a program file in the editor to teach a position into it"));
        return false;
    }
    if (!viewed_) {
        emit statusMessage(tr("No controller is viewed: no position to teach"));
        return false;
    }
    const ControllerState& st = viewed_->current().state();
    std::optional<double> x, z;
    for (const engine::AxisView& a : st.axes) {
        if (!a.present)
            continue;
        (a.axis == engine::AxisId::X ? x : z) = units::discToMm(a.currentDisc, a.scale);
    }
    const std::string frame = editing::teachFrame(editing::nextFrameNumber(frameNumberAtCursor()), x, z);
    if (frame.empty()) {
        emit statusMessage(tr("The viewed controller has no axes: no position to teach"));
        return false;
    }
    const QString text = QString::fromStdString(frame);
    insertTaught(text, false);
    if (taught)
        *taught = text;
    emit statusMessage(tr("Taught: %1").arg(text));
    return true;
}

bool EditorTab::teachIntoR(int r, QString* taught) {
    ProgramEditor* ed = currentEditor();
    if (!ed) {
        emit statusMessage(tr("Open a program file in the editor to teach a position into it"));
        return false;
    }
    if (!viewed_) {
        emit statusMessage(tr("No controller is viewed: no position to teach"));
        return false;
    }
    std::optional<editing::TeachTarget> target;
    for (const editing::TeachTarget& t : editing::teachTargets())
        if (t.r == r)
            target = t;
    if (!target)
        return false;
    const engine::AxisId id = target->axis == catalog::Axis::X ? engine::AxisId::X : engine::AxisId::Z;
    const engine::AxisView* axis = nullptr;
    for (const engine::AxisView& a : viewed_->current().state().axes)
        if (a.present && a.axis == id)
            axis = &a;
    if (!axis) {
        emit statusMessage(tr("The viewed controller has no axis %1").arg(id == engine::AxisId::X ? "X" : "Z"));
        return false;
    }
    const std::int64_t disc = target->machineCoordinate ? axis->machineDisc : axis->currentDisc;
    // The cursor's line sets this R already: it gets the new value, its N and comments kept.
    int line = 0, index = 0;
    ed->getCursorPosition(&line, &index);
    const QRegularExpression sets(QStringLiteral("^\\s*(/?\\s*N(\\d+)\\s*)?R0*%1\\s*=").arg(r));
    const QRegularExpressionMatch m = sets.match(ed->text(line));
    const bool replace = m.hasMatch();
    const int n = replace ? m.captured(2).toInt() : editing::nextFrameNumber(frameNumberAtCursor());
    const QString text = QString::fromStdString(editing::teachRFrame(n, r, disc));
    insertTaught(text, replace);
    if (taught)
        *taught = text;
    emit statusMessage(tr("Taught: %1 (%2 mm)").arg(text).arg(units::discToMm(disc, axis->scale), 0, 'f', 3));
    return true;
}

// --- Database machines ---------------------------------------------------------------

QString EditorTab::databaseMachine(int index) const {
    ProgramEditor* ed = editorAt(index);
    return ed ? ed->property(kDbMachineProperty).toString() : QString();
}

int EditorTab::databaseRevision(int index) const {
    ProgramEditor* ed = editorAt(index);
    return ed ? ed->property(kDbRevisionProperty).toInt() : 0;
}

bool EditorTab::openFromDatabase(const QString& machine) {
    for (int i = 0; i < tabs_->count(); ++i)
        if (databaseMachine(i) == machine) {
            tabs_->setCurrentIndex(i);
            return true;
        }
    const DatabasePrograms r = loadDatabasePrograms(machine);
    if (!r.ok) {
        emit statusMessage(r.error);
        return false;
    }
    const int i = addDocument(QString(), r.text);
    ProgramEditor* ed = editorAt(i);
    ed->setProperty(kDbMachineProperty, machine);
    ed->setProperty(kDbRevisionProperty, r.revision);
    ed->setProperty(kMachineProperty, machine); // checked for the machine it belongs to
    applyMachine(ed);
    ed->validateNow();
    refreshTitles();
    releases_->setMachine(databaseMachine(tabs_->currentIndex()));
    emit statusMessage(tr("Opened the programs of %1, revision %2").arg(machine).arg(r.revision));
    return true;
}

void EditorTab::openDatabaseDialog() {
    QString error;
    const QStringList machines = databaseMachines(&error);
    if (machines.isEmpty()) {
        emit statusMessage(error.isEmpty() ? tr("The database has no machines") : error);
        return;
    }
    bool ok = false;
    const QString m = QInputDialog::getItem(this, tr("Open from the database"), tr("Machine"), machines, 0, false, &ok);
    if (ok && !m.isEmpty())
        openFromDatabase(m);
}

bool EditorTab::saveToDatabase(int index) {
    ProgramEditor* ed = editorAt(index);
    const QString machine = databaseMachine(index);
    if (!ed || machine.isEmpty())
        return false;
    const DatabaseSave s = saveDatabasePrograms(machine, ed->text(), databaseRevision(index));
    if (s.revision == 0) {
        emit statusMessage(s.error);
        return false;
    }
    ed->setProperty(kDbRevisionProperty, s.revision);
    ed->setModified(false);
    refreshTitles();
    if (releases_->machine() == machine)
        releases_->refresh(); // a changed program is a draft again
    emit statusMessage(s.changed ? tr("%1 saved as revision %2").arg(machine).arg(s.revision)
                                 : tr("%1: the database already holds these programs (revision %2)")
                                       .arg(machine)
                                       .arg(s.revision));
    return true;
}

} // namespace k528::studio
