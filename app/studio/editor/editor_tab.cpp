#include "editor/editor_tab.h"
#include "session/file_problem.h"
#include "editor/cycle_time_label.h"

#include "editor/database_programs.h"
#include "editor/debug_panel.h"
#include "editor/editor_menu.h"
#include "editor/listing_actions.h"
#include "editor/refactor_actions.h"
#include "editor/setup_sheet_actions.h"
#include "editor/teach_in.h"
#include "engine/self_test.h"
#include "session/core_texts.h"
#include "session/machine_source.h"
#include "editor/frame_master.h"
#include "editor/problems_model.h"
#include "proveout/proveout.h"
#include "program/parser.h"
#include "resources/embedded.h"
#include "editor/program_editor.h"
#include "language.h"
#include "controller/controller.h"
#include "controller/push_preview.h"
#include "controller/simulated_controller.h"
#include "profile/text_format.h"
#include "editor/program_releases.h"
#include "session/shop_database.h"
#include "workspace/elided_label.h"

#include <algorithm>

#include <QCoreApplication>
#include <QDir>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QStyle>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QRegularExpression>
#include <QSettings>
#include <QSplitter>
#include <QTabBar>
#include <QTabWidget>
#include <QPointer>
#include <memory>
#include <QTemporaryFile>
#include <QToolBar>
#include <QToolButton>
#include <QTreeView>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace k528::studio {

namespace {
constexpr const char* kPathProperty = "k528.path";
constexpr const char* kMachineProperty = "k528.machine"; // the file's machine choice
constexpr const char* kDbMachineProperty = "k528.dbMachine";
constexpr const char* kDbRevisionProperty = "k528.dbRevision";
constexpr const char* kUntitledProperty = "k528.untitled";
constexpr const char* kSampleProperty = "k528.sample"; // a shipped sample's name, until saved as a file
constexpr int kRecentMax = 8;
} // namespace

EditorTab::EditorTab(ViewedController* viewed, QWidget* parent) : QWidget(parent), viewed_(viewed) {
    setObjectName("programEditorTab");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    toolbar_ = new QToolBar(this);
    toolbar_->setObjectName("editor.toolbar");
    layout->addWidget(toolbar_);
    newAction_ = toolbar_->addAction(QString(), this, &EditorTab::newFile);
    openAction_ = toolbar_->addAction(QString(), this, &EditorTab::openDialog);
    recentMenu_ = new QMenu(this);
    recentAction_ = toolbar_->addAction(QString());
    recentAction_->setMenu(recentMenu_);
    if (auto* b = qobject_cast<QToolButton*>(toolbar_->widgetForAction(recentAction_)))
        b->setPopupMode(QToolButton::InstantPopup);
    saveAction_ = toolbar_->addAction(QString(), this, [this] { save(); });
    saveAsAction_ = toolbar_->addAction(QString(), this, [this] { saveAs(); });
    toolbar_->addSeparator();
    machineAction_ = toolbar_->addAction(QString());
    machineAction_->setCheckable(true);
    machineAction_->setChecked(true);
    connect(machineAction_, &QAction::toggled, this, &EditorTab::setCheckAgainstMachine);
    sendAction_ = toolbar_->addAction(QString(), this, [this] { sendToController(); });
    sendAction_->setObjectName("editor.sendToController");
    openControllerAction_ = toolbar_->addAction(QString(), this, [this] { openFromController(); });
    openControllerAction_->setObjectName("editor.openFromController");
    toolbar_->addSeparator();
    masterAction_ = toolbar_->addAction(QString(), this, &EditorTab::openMaster);
    newAction_->setObjectName("editor.new");
    openAction_->setObjectName("editor.open");
    saveAction_->setObjectName("editor.save");
    saveAsAction_->setObjectName("editor.saveAs");
    newAction_->setShortcut(QKeySequence::New);
    saveAction_->setShortcut(QKeySequence::Save);

    auto* split = new QSplitter(Qt::Vertical, this);
    auto* top = new QSplitter(Qt::Horizontal, split);
    // The outline, and under it the release states of a database machine's programs.
    auto* left = new QSplitter(Qt::Vertical, top);
    left->setObjectName("editor.left");
    outline_ = new QTreeWidget(left);
    outline_->setObjectName("editor.outline");
    outline_->setColumnCount(1);
    outline_->setRootIsDecorated(false);
    tabs_ = new QTabWidget(top);
    tabs_->setObjectName("editor.tabs");
    tabs_->setTabsClosable(true);
    tabs_->setDocumentMode(true);
    releases_ = new ProgramReleases(left);
    connect(releases_, &ProgramReleases::statusMessage, this, &EditorTab::statusMessage);
    left->addWidget(outline_);
    left->addWidget(releases_);
    left->setStretchFactor(0, 1);
    left->setStretchFactor(1, 1);
    top->addWidget(left);
    top->addWidget(tabs_);
    // The text takes the room: the outline as wide as a program's title
    // needs, the Problems as tall as a few lines (both splitters' handles
    // give them more), the rest and every resize to the editor.
    top->setStretchFactor(0, 0);
    top->setStretchFactor(1, 1);
    if (viewed_)
        connect(viewed_, &ViewedController::changed, this, &EditorTab::reapplyWorkstationMachine);
    auto* simulated = viewed_ ? dynamic_cast<SimulatedController*>(&viewed_->simulatedController()) : nullptr;
    if (simulated) { // the debugger on the simulated machine
        debug_ = new DebugPanel(this, &simulated->session(), top);
        top->addWidget(debug_);
        connect(debug_, &DebugPanel::statusMessage, this, &EditorTab::statusMessage);
    }
    const int outlineWidth = fontMetrics().horizontalAdvance(QLatin1Char('M')) * 17;
    top->setSizes(debug_ ? QList<int>{outlineWidth, 4000, 2000} : QList<int>{outlineWidth, 4000});
    problems_ = new QTreeView(split);
    problems_->setObjectName("editor.problems");
    problemsModel_ = new ProblemsModel(problems_);
    problems_->setModel(problemsModel_);
    problems_->setRootIsDecorated(false);
    problems_->setUniformRowHeights(true);
    problems_->setAllColumnsShowFocus(true);
    problems_->header()->setStretchLastSection(true);
    split->addWidget(top);
    split->addWidget(problems_);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 0);
    split->setSizes({4000, fontMetrics().lineSpacing() * 8});
    layout->addWidget(split, 1);
    auto* status = new QHBoxLayout;
    count_ = new ElidedLabel(this); // cut rather than widen the window
    count_->setObjectName("editor.problemCount");
    status->addWidget(count_, 1);
    cycle_ = new CycleTimeLabel(this);
    status->addWidget(cycle_, 2);
    layout->addLayout(status);
    refactor_ = new RefactorActions(*this);
    listing_ = new ListingActions(*this);
    setupSheets_ = new SetupSheetActions(*this);
    teachIn_ = new TeachIn(*this, viewed_);
    connect(refactor_, &RefactorActions::statusMessage, this, &EditorTab::statusMessage);
    connect(listing_, &ListingActions::statusMessage, this, &EditorTab::statusMessage);
    connect(setupSheets_, &SetupSheetActions::statusMessage, this, &EditorTab::statusMessage);
    connect(teachIn_, &TeachIn::statusMessage, this, &EditorTab::statusMessage);
    menu_ = new EditorMenu(*this, toolbar_, viewed_);
    connect(tabs_, &QTabWidget::currentChanged, menu_, &EditorMenu::retranslate);

    connect(tabs_, &QTabWidget::tabCloseRequested, this, [this](int i) { closeDocument(i); });
    connect(tabs_, &QTabWidget::currentChanged, this, [this] {
        refreshProblems();
        refreshOutline();
        cycle_->follow(currentEditor());
        releases_->setMachine(databaseMachine(tabs_->currentIndex()));
    });
    connect(problems_, &QTreeView::activated, this, [this](const QModelIndex& index) {
        ProgramEditor* ed = currentEditor();
        if (!ed || !index.isValid())
            return;
        const int line = index.data(ProblemsModel::kLineRole).toInt();
        const int col = index.data(ProblemsModel::kColumnRole).toInt();
        ed->setCursorPosition(line - 1, std::max(0, col - 1));
        ed->ensureLineVisible(line - 1);
        ed->setFocus();
        const int finding = index.data(ProblemsModel::kFindingRole).toInt();
        if (finding >= 0 && finding < static_cast<int>(ed->proveoutFindings().size())) {
            const proveout::Finding& f = ed->proveoutFindings()[static_cast<std::size_t>(finding)];
            emit proveoutFindingActivated(f.program, f.line, f.at.z, f.at.x);
        }
    });
    connect(outline_, &QTreeWidget::itemActivated, this, [this](QTreeWidgetItem* item) {
        if (ProgramEditor* ed = currentEditor(); ed && item) {
            const int line = item->data(0, Qt::UserRole).toInt();
            ed->setCursorPosition(std::max(0, line - 1), 0);
            ed->ensureLineVisible(std::max(0, line - 1));
        }
    });
    connect(&watcher_, &QFileSystemWatcher::fileChanged, this, &EditorTab::fileChangedOnDisk);
    ask_ = [this](const QString& name) {
        const auto b = QMessageBox::question(this, tr("Unsaved changes"),
                                             tr("%1 has unsaved changes. Save them?").arg(name),
                                             QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
        return b == QMessageBox::Save ? CloseChoice::Save : b == QMessageBox::Discard ? CloseChoice::Discard
                                                                                   : CloseChoice::Cancel;
    };
    askReload_ = [this](const QString& path) {
        return QMessageBox::question(this, tr("File changed on disk"),
                                     tr("%1 was changed on disk. Reload it and lose your changes?").arg(path)) ==
               QMessageBox::Yes;
    };
    retranslate();
    fillRecentMenu();
    // The unsaved-changes guard: the window does not close while a modified
    // document's question is answered «Cancel».
    if (parent && parent->window())
        parent->window()->installEventFilter(this);
}

bool EditorTab::eventFilter(QObject* watched, QEvent* e) {
    if (e->type() == QEvent::Close && watched == window()) {
        rememberOpenFiles(); // before closeAll() empties the tabs
        if (!closeAll()) {
            e->ignore();
            return true;
        }
    }
    return QWidget::eventFilter(watched, e);
}

ProgramEditor* EditorTab::currentEditor() const { return qobject_cast<ProgramEditor*>(tabs_->currentWidget()); }
int EditorTab::documentCount() const { return tabs_->count(); }
ProgramEditor* EditorTab::editorAt(int index) const { return qobject_cast<ProgramEditor*>(tabs_->widget(index)); }
int EditorTab::currentIndex() const { return tabs_ ? tabs_->currentIndex() : -1; }
QMenu* EditorTab::editorMenu() const { return menu_->menu(); }
QString EditorTab::pathOf(int index) const {
    QWidget* w = tabs_->widget(index);
    return w ? w->property(kPathProperty).toString() : QString();
}

void EditorTab::setCheckAgainstMachine(bool on) {
    checkMachine_ = on;
    for (int i = 0; i < tabs_->count(); ++i)
        if (ProgramEditor* ed = editorAt(i))
            applyMachine(ed);
}

int EditorTab::addDocument(const QString& path, const QString& text) {
    auto* ed = new ProgramEditor(tabs_);
    ed->setProperty(kPathProperty, path);
    if (path.isEmpty())
        ed->setProperty(kUntitledProperty, ++untitled_);
    applyMachine(ed);
    ed->setText(text);
    ed->setModified(false);
    connect(ed, &ProgramEditor::validated, this, [this, ed] {
        if (ed == currentEditor()) {
            refreshProblems();
            refreshOutline();
            cycle_->follow(ed);
        }
    });
    connect(ed, &QsciScintilla::modificationChanged, this, &EditorTab::refreshTitles);
    connect(ed, &QsciScintilla::cursorPositionChanged, this, [this, ed](int line, int) {
        if (ed == currentEditor() && line != ed->property("k528.cursorLine").toInt() - 1) {
            ed->setProperty("k528.cursorLine", line + 1);
            emit cursorLineChanged(ed->programAtLine(line), line + 1);
        }
    });
    const int i = tabs_->addTab(ed, QString());
    tabs_->setCurrentIndex(i);
    refreshTitles();
    ed->validateNow();
    return i;
}

bool EditorTab::showLine(int program, int line) {
    QList<int> order{tabs_->currentIndex()};
    for (int i = 0; i < tabs_->count(); ++i)
        if (i != tabs_->currentIndex())
            order.append(i);
    for (int i : order) {
        ProgramEditor* ed = editorAt(i);
        if (!ed || line < 1 || line > ed->lines() || ed->programAtLine(line - 1) != program)
            continue;
        tabs_->setCurrentIndex(i);
        ed->setCursorPosition(line - 1, 0);
        ed->ensureLineVisible(line - 1);
        return true;
    }
    return false;
}

void EditorTab::rememberOpenFiles() {
    QStringList paths;
    for (int i = 0; i < tabs_->count(); ++i)
        if (!pathOf(i).isEmpty() && databaseMachine(i).isEmpty())
            paths << pathOf(i);
    QSettings().setValue("editor/open", paths);
}

void EditorTab::openStartDocuments(const QString& machineName) {
    QSettings s;
    const bool kept = s.contains("editor/open");
    const QStringList paths = s.value("editor/open").toStringList();
    int opened = 0;
    for (const QString& p : paths)
        if (QFileInfo(p).isFile() && openFile(p))
            ++opened;
    if (opened == 0 && (!kept || !paths.isEmpty())) {
        const QString sample = sampleFor(machineName);
        if (!sample.isEmpty())
            openSample(sample);
    }
}

QString EditorTab::sampleFor(const QString& machineName) {
    const std::vector<resources::Resource> samples = resources::under("samples/");
    if (samples.empty())
        return {};
    const auto nameOf = [](const resources::Resource& r) {
        return QString::fromUtf8(r.path.data(), static_cast<qsizetype>(r.path.size())).section('/', -1);
    };
    static const QRegularExpression separators(QStringLiteral("[-_.]"));
    const QStringList words = machineName.split(separators, Qt::SkipEmptyParts);
    for (const resources::Resource& r : samples) {
        const QStringList sampleWords = nameOf(r).section('.', 0, 0).split(separators, Qt::SkipEmptyParts);
        for (const QString& w : words)
            if (w.size() > 2 && !w.front().isDigit() && sampleWords.contains(w, Qt::CaseInsensitive))
                return nameOf(r);
    }
    return nameOf(samples.front());
}

bool EditorTab::openSample(const QString& name) {
    const auto text = resources::find("samples/" + name.toStdString());
    if (!text) {
        emit statusMessage(tr("There is no sample program %1").arg(name));
        return false;
    }
    const int i = addDocument(QString(), QString::fromUtf8(text->data(), static_cast<qsizetype>(text->size())));
    editorAt(i)->setProperty(kSampleProperty, name);
    refreshTitles();
    return true;
}

void EditorTab::newFile() { addDocument(QString(), QStringLiteral("%L1\nM30\n")); }

bool EditorTab::openFile(const QString& path) {
    const QString abs = QFileInfo(path).absoluteFilePath();
    for (int i = 0; i < tabs_->count(); ++i)
        if (pathOf(i) == abs) {
            tabs_->setCurrentIndex(i);
            return true;
        }
    if (ShopDatabase::isOpenDatabaseFile(abs.toStdString())) {
        emit statusMessage(tr("%1 is the database this window uses: it is not opened as a program").arg(abs));
        return false;
    }
    std::string text;
    QString error;
    if (!readTextFile(abs, text, error)) { // why in the window's language
        emit statusMessage(error);
        return false;
    }
    addDocument(abs, QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size())));
    watcher_.addPath(abs);
    addRecent(abs);
    return true;
}

void EditorTab::openDialog() {
    const QStringList paths = QFileDialog::getOpenFileNames(this, tr("Open program"), QString(),
                                                            tr("K528 programs (*.k528 *.txt);;All files (*)"));
    for (const QString& p : paths)
        openFile(p);
}

bool EditorTab::saveTo(int index, const QString& path) {
    ProgramEditor* ed = editorAt(index);
    if (!ed)
        return false;
    if (ShopDatabase::isOpenDatabaseFile(path.toStdString())) {
        emit statusMessage(tr("%1 is the database this window uses: a program is not written over it").arg(path));
        return false;
    }
    const QString old = pathOf(index);
    if (!old.isEmpty())
        watcher_.removePath(old);
    SaveFile f(path); // the old text stays whole until the new one is
    if (!f.open(QIODevice::WriteOnly) || f.write(ed->text().toUtf8()) < 0 || !f.commit()) {
        emit statusMessage(tr("%1 cannot be written: %2").arg(path, fileProblem(f)));
        if (!old.isEmpty())
            watcher_.addPath(old);
        return false;
    }
    const QString abs = QFileInfo(path).absoluteFilePath();
    ed->setProperty(kPathProperty, abs);
    ed->setModified(false);
    watcher_.addPath(abs);
    addRecent(abs);
    refreshTitles();
    emit statusMessage(tr("Saved %1").arg(QFileInfo(abs).fileName()));
    return true;
}

bool EditorTab::save() {
    const int i = tabs_->currentIndex();
    if (i < 0)
        return false;
    if (!databaseMachine(i).isEmpty())
        return saveToDatabase(i);
    if (pathOf(i).isEmpty())
        return saveAs();
    return saveTo(i, pathOf(i));
}

bool EditorTab::saveAs() {
    const int i = tabs_->currentIndex();
    if (i < 0)
        return false;
    const QString p = QFileDialog::getSaveFileName(this, tr("Save program as"), pathOf(i),
                                                   tr("K528 programs (*.k528 *.txt);;All files (*)"));
    return !p.isEmpty() && saveTo(i, p);
}

bool EditorTab::closeDocument(int index) {
    ProgramEditor* ed = editorAt(index);
    if (!ed)
        return false;
    if (ed->isModified()) {
        switch (ask_(documentName(index))) { // the name, not the tab's «name *»
        case CloseChoice::Cancel:
            return false;
        case CloseChoice::Save:
            tabs_->setCurrentIndex(index);
            if (!save())
                return false;
            break;
        case CloseChoice::Discard:
            break;
        }
    }
    if (!pathOf(index).isEmpty())
        watcher_.removePath(pathOf(index));
    tabs_->removeTab(index);
    ed->deleteLater();
    return true;
}

bool EditorTab::closeAll() {
    while (tabs_->count() > 0)
        if (!closeDocument(tabs_->count() - 1))
            return false;
    return true;
}

void EditorTab::fileChangedOnDisk(const QString& path) {
    for (int i = 0; i < tabs_->count(); ++i) {
        if (pathOf(i) != path)
            continue;
        ProgramEditor* ed = editorAt(i);
        QFile f(path);
        if (!f.exists() || !f.open(QIODevice::ReadOnly))
            return;
        const QString text = QString::fromUtf8(f.readAll());
        if (text == ed->text())
            return;
        // Unsaved edits are never thrown away: ask first.
        if (ed->isModified() && !askReload_(path)) {
            watcher_.addPath(path); // a file replaced on disk leaves the watch list
            return;
        }
        int line = 0, index = 0;
        ed->getCursorPosition(&line, &index);
        ed->setText(text);
        ed->setModified(false);
        ed->setCursorPosition(std::min(line, ed->lines() - 1), 0);
        watcher_.addPath(path); // some editors replace the file
        emit statusMessage(tr("Reloaded %1").arg(QFileInfo(path).fileName()));
    }
}

bool EditorTab::sendToController() {
    ProgramEditor* ed = currentEditor();
    if (!ed || !viewed_)
        return false;
    Controller& c = viewed_->current();
    const QString name = documentName(tabs_->currentIndex());
    const QString text = ed->text(); // as it is now, not as saved
    if (c.busy()) {
        emit statusMessage(tr("The controller is busy with a transfer: send again when it has ended"));
        return false;
    }
    if (!previewBeforeSending_) {
        auto result = std::make_shared<int>(-1);
        connect(this, &EditorTab::sent, this, [result](bool ok) { *result = ok ? 1 : 0; }, Qt::SingleShotConnection);
        send(text, name);
        return *result != 0;
    }
    // First the controller's memory as it is, for the preview of what changes.
    emit statusMessage(tr("Reading the controller's memory to show what %1 changes...").arg(name));
    QPointer<EditorTab> self(this);
    c.readMemory([self, text, name](bool ok, const QString& why, const profile::MachineProfile& memory) {
        if (!self)
            return;
        if (!ok) {
            const QString m = tr("%1 was not sent: the controller's memory could not be read (%2)").arg(name, why);
            emit self->statusMessage(m);
            emit self->sent(false, m);
            return;
        }
        const profile::MachineProfile after = afterPrograms(memory, text.toStdString());
        self->sendPreview_ = showPushPreview(self, tr("Send %1").arg(name), memory, after, tr("Send"),
                                             [self, text, name](bool send) {
                                                 if (!self)
                                                     return;
                                                 self->sendPreview_ = nullptr;
                                                 if (send) {
                                                     self->send(text, name);
                                                 } else {
                                                     const QString m = tr("%1 not sent; nothing changed").arg(name);
                                                     emit self->statusMessage(m);
                                                     emit self->sent(false, m);
                                                 }
                                             });
        emit self->sendPreviewShown();
    });
    return true;
}

void EditorTab::send(const QString& text, const QString& name) {
    Controller& c = viewed_->current();
    emit statusMessage(tr("Sending %1 to the controller...").arg(name));
    QPointer<EditorTab> self(this);
    c.loadPrograms(text.toStdString(), name, [self, name](bool ok, const QString& message) {
        if (!self)
            return;
        const QString m = ok ? (message.isEmpty() ? tr("Sent %1 to the controller").arg(name)
                                                  : tr("Sent %1 to the controller, with warnings: %2").arg(name, message))
                             : tr("%1 was not sent: %2").arg(name, message);
        emit self->statusMessage(m);
        emit self->sent(ok, m);
    });
}

bool EditorTab::openFromController() {
    if (!viewed_)
        return false;
    Controller& c = viewed_->current();
    if (c.busy()) {
        emit statusMessage(tr("The controller is busy with a transfer: open again when it has ended"));
        return false;
    }
    emit statusMessage(tr("Reading the programs of the controller..."));
    QPointer<EditorTab> self(this);
    const QString where = c.description();
    c.readMemory([self, where](bool ok, const QString& why, const profile::MachineProfile& memory) {
        if (!self)
            return;
        if (!ok) {
            const QString m = tr("The programs of the controller could not be read: %1").arg(why);
            emit self->statusMessage(m);
            emit self->openedFromController(false, m);
            return;
        }
        const int i = self->addDocument(QString(), QString::fromStdString(profile::programsFileText(memory)));
        if (ProgramEditor* ed = self->editorAt(i))
            ed->validateNow();
        const QString m = tr("Opened the %1 programs of the controller (%2)").arg(memory.programs.size()).arg(where);
        emit self->statusMessage(m);
        emit self->openedFromController(true, m);
    });
    return true;
}

void EditorTab::openMaster() {
    ProgramEditor* ed = currentEditor();
    if (!ed)
        return;
    int line = 0, index = 0;
    ed->getCursorPosition(&line, &index);
    FrameMaster master(this);
    QString current = ed->text(line);
    while (current.endsWith('\n') || current.endsWith('\r'))
        current.chop(1);
    const bool editing = !current.trimmed().isEmpty() && !current.trimmed().startsWith('%') &&
                         master.setFromLine(current);
    // Said before OK, not found out after: which line goes, what stays.
    const QString kept = commentsOfLine(current);
    master.setPlacement(editing ? (kept.isEmpty() ? tr("OK replaces line %1: %2").arg(line + 1).arg(current.trimmed())
                                                  : tr("OK replaces line %1: %2\nIts comment stays: %3")
                                                        .arg(line + 1)
                                                        .arg(current.trimmed(), kept))
                                : tr("OK inserts a new line after line %1.").arg(line + 1));
    if (master.exec() == QDialog::Accepted && master.valid())
        insertFromMaster(master.text(), editing);
}

QString EditorTab::commentsOfLine(const QString& line) {
    // The parser's comments of the line, as written: "(…)" and "; …" last.
    const program::ParseResult r = program::parse("%L1\n" + line.toStdString() + "\n");
    if (r.store.empty() || r.store.programs()[0].frames.size() != 1)
        return {};
    QStringList parens;
    QString semicolon;
    for (const program::Comment& c : r.store.programs()[0].frames[0].comments) {
        if (c.style == program::Comment::Style::Parens)
            parens << QStringLiteral("(%1)").arg(QString::fromStdString(c.text));
        else
            semicolon = QStringLiteral(";") + QString::fromStdString(c.text);
    }
    if (!semicolon.isEmpty())
        parens << semicolon;
    return parens.join(' ');
}

EditorTab::PlacedLine EditorTab::placeLine(const QString& text, bool replaceLine) {
    ProgramEditor* ed = currentEditor();
    if (!ed)
        return {};
    PlacedLine placed;
    int index = 0;
    ed->getCursorPosition(&placed.line, &index);
    const int line = placed.line;
    ed->beginUndoAction();
    const QString cur = ed->text(line);
    int len = static_cast<int>(cur.size());
    while (len > 0 && (cur.at(len - 1) == '\n' || cur.at(len - 1) == '\r'))
        --len;
    if (replaceLine || cur.trimmed().isEmpty()) {
        // The line's comments — "(…)" anywhere and "; …" — stay after the new frame.
        const QString kept = replaceLine ? commentsOfLine(cur.left(len)) : QString();
        placed.keptComment = !kept.isEmpty();
        ed->setSelection(line, 0, line, len);
        ed->replaceSelectedText(kept.isEmpty() ? text : text + " " + kept);
    } else {
        ed->insertAt(text + "\n", line + 1, 0);
        if (line + 1 >= ed->lines() - 1 && !cur.endsWith('\n'))
            ed->insertAt("\n", line + 1, 0);
        ++placed.line;
    }
    ed->endUndoAction();
    return placed;
}

void EditorTab::insertFromMaster(const QString& text, bool replaceLine) {
    const PlacedLine placed = placeLine(text, replaceLine);
    if (placed.line < 0)
        return;
    if (replaceLine)
        emit statusMessage(placed.keptComment ? tr("Line %1 replaced by the master; its comment kept").arg(placed.line + 1)
                                              : tr("Line %1 replaced by the master").arg(placed.line + 1));
    currentEditor()->setCursorPosition(placed.line, 0);
}

void EditorTab::refreshProblems() {
    ProgramEditor* ed = currentEditor();
    problemsModel_->setDiagnostics(ed ? &ed->diagnostics() : nullptr);
    problemsModel_->setFindings(ed ? &ed->proveoutFindings() : nullptr);
    fitCodeColumn();
    std::size_t errors = 0, warnings = 0;
    if (ed) {
        errors = program::countErrors(ed->diagnostics());
        warnings = ed->diagnostics().size() - errors;
    }
    refreshCount();
    emit problemCountChanged(static_cast<int>(errors), static_cast<int>(warnings));
}

void EditorTab::fitCodeColumn() {
    // The rule's name whole, as wide as its header at least: measured from
    // the distinct codes, not by laying out every row (ResizeToContents
    // did, after each validation, 20 ms of a big file's typing).
    const int margin = 2 * (problems_->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, problems_) + 1) +
                       problems_->fontMetrics().horizontalAdvance(QLatin1Char(' '));
    const int width = std::max(problems_->header()->sectionSizeHint(3),
                               problemsModel_->widestCode(problems_->fontMetrics()) + margin);
    problems_->header()->resizeSection(3, width);
}

void EditorTab::refreshCount() {
    ProgramEditor* ed = currentEditor();
    std::size_t errors = 0, warnings = 0;
    if (ed) {
        errors = program::countErrors(ed->diagnostics());
        warnings = ed->diagnostics().size() - errors;
        for (const proveout::Finding& f : ed->proveoutFindings())
            (f.isError() ? errors : warnings) += 1;
    }
    count_->setText(tr("Errors: %1, warnings: %2").arg(errors).arg(warnings));
}

void EditorTab::setProveoutFindings(ProgramEditor* ed, const std::vector<proveout::Finding>& findings) {
    if (!ed)
        return;
    ed->setProveoutFindings(findings);
    if (ed != currentEditor())
        return;
    problemsModel_->setFindings(&ed->proveoutFindings());
    fitCodeColumn();
    refreshCount();
}

void EditorTab::refreshOutline() {
    outline_->clear();
    ProgramEditor* ed = currentEditor();
    if (!ed)
        return;
    for (const program::Program& p : ed->store().programs()) {
        auto* it = new QTreeWidgetItem(outline_);
        QString t = QStringLiteral("L%1").arg(p.number);
        if (p.title)
            t += QStringLiteral("  ") + QString::fromStdString(*p.title);
        it->setText(0, t);
        it->setData(0, Qt::UserRole, p.headerLine);
    }
    if (ed->store().messages.present) {
        auto* it = new QTreeWidgetItem(outline_);
        it->setText(0, QStringLiteral("%MESSAGES"));
        it->setData(0, Qt::UserRole, ed->store().messages.headerLine);
    }
}

void EditorTab::refreshTitles() {
    for (int i = 0; i < tabs_->count(); ++i) {
        ProgramEditor* ed = editorAt(i);
        const QString p = pathOf(i);
        QString name = documentName(i);
        if (ed->isModified())
            name += QStringLiteral(" *");
        tabs_->setTabText(i, name);
        tabs_->setTabToolTip(i, p);
    }
}

void EditorTab::addRecent(const QString& path) {
    QSettings s;
    QStringList r = s.value("editor/recent").toStringList();
    r.removeAll(path);
    r.prepend(path);
    while (r.size() > kRecentMax)
        r.removeLast();
    s.setValue("editor/recent", r);
    fillRecentMenu();
}

void EditorTab::fillRecentMenu() {
    recentMenu_->clear();
    const QStringList r = QSettings().value("editor/recent").toStringList();
    for (const QString& p : r)
        recentMenu_->addAction(p, this, [this, p] { openFile(p); });
    recentAction_->setEnabled(!r.isEmpty());
}

void EditorTab::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(e);
}

void EditorTab::retranslate() {
    // Qt gives a tab's close button its tool tip once, when the tab is made.
    for (int i = 0; i < tabs_->count(); ++i)
        if (QWidget* close = tabs_->tabBar()->tabButton(i, QTabBar::RightSide))
            close->setToolTip(QCoreApplication::translate("CloseButton", "Close Tab"));
    newAction_->setText(tr("New"));
    openAction_->setText(tr("Open…"));
    recentAction_->setText(tr("Recent"));
    saveAction_->setText(tr("Save"));
    saveAsAction_->setText(tr("Save as…"));
    machineAction_->setText(tr("Check for the machine"));
    machineAction_->setToolTip(tr("Also check the machine's software limits, feeds and axes"));
    sendAction_->setText(tr("Send to the controller"));
    sendAction_->setToolTip(tr("The file's programs and messages into the controller shown, after a preview of what changes"));
    openControllerAction_->setText(tr("Open from the controller"));
    openControllerAction_->setToolTip(tr("The programs and messages of the controller shown as a new file"));
    masterAction_->setText(tr("Master…"));
    masterAction_->setToolTip(tr("Build or edit the frame at the cursor"));
    outline_->setHeaderLabels({tr("Programs")});
    problemsModel_->setTexts({tr("Severity"), tr("Program"), tr("Line"), tr("Code"), tr("Message")}, tr("error"),
                             tr("warning"));
    menu_->retranslate();
    refreshTitles();
    refreshProblems();
}

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
    if (menu_ && ed == currentEditor())
        menu_->retranslate();
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

QString EditorTab::checkedMachineTitle(int index) const {
    ProgramEditor* ed = editorAt(index);
    return ed && ed->machine() ? machineTitle(*ed->machine()) : QString();
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
