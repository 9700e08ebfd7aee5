#include "constants/constants_dock.h"
#include "session/file_problem.h"
#include "constants/cutting_dialog.h"
#include "db/notes.h"
#include "session/core_texts.h"

#include "constants/constants_lock.h"
#include "constants/constants_follow.h"

#include "catalog/cparams.h"
#include "constants/constants_dialogs.h"
#include "constants/constants_editor.h"
#include "constants/constants_model.h"
#include "engine/positioner.h"
#include "profile/csv.h"
#include "profile/text_format.h"
#include "controller/controller.h"
#include "controller/push_preview.h"
#include "parameters/cell_text_delegate.h"
#include "widgets.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QPointer>
#include <QProgressBar>
#include <QPromise>
#include <QSaveFile>
#include <QTableView>
#include <QToolButton>
#include <QUndoStack>
#include <QtConcurrent/QtConcurrentRun>

namespace k528::studio {

namespace {

// The value column's editor: every keystroke is checked as the controller
// would check the value (range and cross-checks); a value it would refuse
// is shown red with the manual's message, and Enter does not commit it.
// Its cells are drawn as the table's others (CellTextDelegate).
class ValueDelegate : public CellTextDelegate {
public:
    ValueDelegate(ConstantsEditor& e, std::function<void(const QString&, bool)> say, QObject* parent)
        : CellTextDelegate(parent), editor_(e), say_(std::move(say)) {}

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem&, const QModelIndex& index) const override {
        auto* line = new QLineEdit(parent);
        line->setObjectName("constants.valueEditor");
        const int number = index.data(ConstantsModel::NumberRole).toInt();
        QObject::connect(line, &QLineEdit::textEdited, line, [this, line, number](const QString& t) {
            line->setProperty("refused", false);
            bool ok = false;
            const qlonglong v = t.trimmed().toLongLong(&ok);
            QString why;
            if (!ok && !t.trimmed().isEmpty() && t.trimmed() != QLatin1String("-"))
                why = ConstantsPane::tr("«%1» is not a whole number").arg(t);
            else if (ok) {
                const CEditCheck c = editor_.check(number, v);
                if (!c.ok)
                    why = c.text;
                else if (!c.warnings.isEmpty())
                    say_(c.warnings.join(QLatin1Char('\n')), false);
                else
                    say_(QString(), false);
            }
            line->setProperty("refused", !why.isEmpty());
            line->setStyleSheet(why.isEmpty() ? QString() : QStringLiteral("background:#ffd7d7;"));
            line->setToolTip(why);
            if (!why.isEmpty())
                say_(why, true);
        });
        return line;
    }
    void setEditorData(QWidget* w, const QModelIndex& index) const override {
        static_cast<QLineEdit*>(w)->setText(index.data(Qt::EditRole).toString());
    }
    void setModelData(QWidget* w, QAbstractItemModel* model, const QModelIndex& index) const override {
        auto* line = static_cast<QLineEdit*>(w);
        if (line->text() == index.data(Qt::EditRole).toString())
            return;
        model->setData(index, line->text(), Qt::EditRole);
    }

private:
    ConstantsEditor& editor_;
    std::function<void(const QString&, bool)> say_;
};

} // namespace

ConstantsPane::ConstantsPane(ViewedController& viewed, const profile::MachineProfile& machine, QWidget* parent)
    : ParameterTablePane(viewed, "constants", MemoryArea::C,
                         {QT_TR_NOOP("Machine constants"),
                          QT_TR_NOOP("The constants of the controller on the line, read every 10 s."),
                          QT_TR_NOOP("A change is written to it at once and kept in the database.")},
                         parent) {
    editor_ = new ConstantsEditor(viewed, machine, this);
    model_ = new ConstantsModel(*editor_, this);
    filter_ = new ConstantsFilter(this);

    axis_ = filterChoice(this, "constants.axis", 4, filter_, &ConstantsFilter::setAxisFilter);
    hideReserved_ = new QCheckBox(this);
    hideReserved_->setObjectName("constants.hideReserved");

    undoButton_ = toolButton("undo", QT_TR_NOOP("Undo"));
    redoButton_ = toolButton("redo", QT_TR_NOOP("Redo"));
    historyButton_ =
        toolButton("history", QT_TR_NOOP("History..."), QT_TR_NOOP("Every revision that changed the selected constant"));
    diffButton_ = toolButton("diff", QT_TR_NOOP("Compare revisions..."));
    importButton_ = toolButton("import", QT_TR_NOOP("Import..."),
                               QT_TR_NOOP("A machine file (.k528m) or the constants as CSV, checked as «k528 db "
                                          "import» checks them"));
    exportButton_ = toolButton("export", QT_TR_NOOP("Export..."));
    calcButton_ = toolButton("calculator", QT_TR_NOOP("Calculator..."));
    cuttingButton_ = toolButton("cuttingData", QT_TR_NOOP("Cutting data..."),
                                QT_TR_NOOP("Spindle speed from the cutting speed and the diameter, feed per minute, "
                                           "the grinding wheel's surface speed from R207"));
    QUndoStack* undo = editor_->undoStack();
    undoButton_->setEnabled(false);
    redoButton_->setEnabled(false);
    connect(undo, &QUndoStack::canUndoChanged, undoButton_, &QWidget::setEnabled);
    connect(undo, &QUndoStack::canRedoChanged, redoButton_, &QWidget::setEnabled);
    connect(undoButton_, &QToolButton::clicked, undo, &QUndoStack::undo);
    connect(redoButton_, &QToolButton::clicked, undo, &QUndoStack::redo);
    connect(historyButton_, &QToolButton::clicked, this, &ConstantsPane::showHistory);
    connect(diffButton_, &QToolButton::clicked, this, &ConstantsPane::showDiff);
    connect(importButton_, &QToolButton::clicked, this, &ConstantsPane::chooseImport);
    connect(exportButton_, &QToolButton::clicked, this, &ConstantsPane::chooseExport);
    connect(calcButton_, &QToolButton::clicked, this, &ConstantsPane::showCalculator);
    connect(cuttingButton_, &QToolButton::clicked, this, &ConstantsPane::showCuttingData);
    progress_ = new QProgressBar(this);
    progress_->setObjectName("constants.progress");
    progress_->setMaximumWidth(220);
    progress_->hide();
    build(model_, filter_, {axis_, hideReserved_},
          {undoButton_, redoButton_, historyButton_, diffButton_, importButton_, exportButton_, calcButton_,
           cuttingButton_},
          // No., axis, panel name, meaning, unit, range, address, value
          {5, 3, 12, 22, 8, 7, 10, 7}, {progress_});
    table()->setItemDelegateForColumn(
        ConstantsModel::Value, new ValueDelegate(*editor_, [this](const QString& t, bool bad) { say(t, bad); }, table()));

    connect(hideReserved_, &QCheckBox::toggled, filter_, &ConstantsFilter::setHideReserved);
    editor_->setNoteProvider([this] { return note_->text(); });
    connect(editor_, &ConstantsEditor::refused, this, [this](const QString& why) { say(why, true); });
    // The trainer's lock told as it comes and goes (and when the dock opens on a locked machine).
    connect(editor_->lock(), &ConstantsLock::changed, this, [this](const QString& holder) {
        if (holder.isEmpty())
            say(tr("The trainer has unlocked the machine constants"), false);
        else
            say(editor_->lockRefusal(), true);
    });
    if (editor_->lock()->locked())
        say(editor_->lockRefusal(), true);
    connect(editor_, &ConstantsEditor::notKept, this, [this](const QString& why) {
        say(tr("Applied to the controller, but not kept in the database: %1").arg(why), true);
    });
    connect(editor_, &ConstantsEditor::kept, this, [this](int revision, const QString& note) {
        say(tr("%1 — kept as revision %2 of %3")
                .arg(revisionNoteText(note.toStdString()))
                .arg(revision)
                .arg(editor_->store().qName()),
            false);
        note_->clear();
    });
    new ConstantsFollow(*this); // constants/constants_follow.cpp: other PCs' revisions, refusals
    retranslate();
}

void ConstantsPane::retranslatePane() {
    searchField()->setPlaceholderText(tr("Search: number, panel name, meaning, unit, address"));
    setItemTexts(axis_, {tr("All axes"), tr("Axis X"), tr("Axis Z"), tr("Common")});
    hideReserved_->setText(tr("Hide reserved"));
    note_->setPlaceholderText(tr("why the next change is made (kept with its revision)"));
}

void ConstantsPane::selectConstant(int number) {
    selectSource(model_->index(ConstantsModel::rowOf(number), ConstantsModel::Value));
}

void ConstantsPane::showHistory() {
    const int n = selectedNumber();
    if (n <= 0) {
        say(tr("Select a constant first"), true);
        return;
    }
    auto* d = new HistoryDialog(editor_->store(), n, this);
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->show();
}

void ConstantsPane::showDiff() {
    auto* d = new DiffDialog(*this, this);
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->show();
}

void ConstantsPane::showCalculator() {
    auto* d = new CalculatorDialog(*editor_, this);
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->show();
}

void ConstantsPane::showCuttingData() {
    auto* d = new CuttingDataDialog(editor_->store().current(), &editor_->controller(), this);
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->show();
}

void ConstantsPane::chooseImport() {
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Import machine constants"), QString(),
        tr("Machine files (*.k528m);;Constants as CSV (*.csv);;All files (*)"));
    if (!path.isEmpty())
        importFile(path);
}

void ConstantsPane::chooseExport() {
    QString selected;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export machine constants"), editor_->store().qName() + ".k528m",
        tr("Machine files (*.k528m);;Constants as CSV (*.csv)"), &selected);
    if (!path.isEmpty())
        exportFile(path);
}

void ConstantsPane::runLong(const QString& what,
                            std::function<LongResult(std::function<void(int, int)>)> work,
                            std::function<void(const LongResult&)> done) {
    if (busy_) {
        say(tr("Another operation is under way"), true);
        return;
    }
    busy_ = true;
    for (QToolButton* b : {importButton_, exportButton_, diffButton_})
        b->setEnabled(false);
    progress_->setRange(0, 0);
    progress_->setFormat(what + QStringLiteral(" %p%"));
    progress_->show();
    say(what, false);
    auto* watcher = new QFutureWatcher<LongResult>(this);
    connect(watcher, &QFutureWatcher<LongResult>::progressRangeChanged, progress_, &QProgressBar::setRange);
    connect(watcher, &QFutureWatcher<LongResult>::progressValueChanged, progress_, &QProgressBar::setValue);
    connect(watcher, &QFutureWatcher<LongResult>::finished, this, [this, watcher, done] {
        LongResult r;
        if (watcher->future().resultCount() > 0)
            r = watcher->result();
        else
            r.error = tr("interrupted");
        watcher->deleteLater();
        progress_->hide();
        busy_ = false;
        for (QToolButton* b : {importButton_, exportButton_, diffButton_})
            b->setEnabled(true);
        done(r);
        emit finished(r);
    });
    watcher->setFuture(QtConcurrent::run([work](QPromise<LongResult>& promise) {
        promise.addResult(work([&promise](int done, int total) {
            promise.setProgressRange(0, total);
            promise.setProgressValue(done);
        }));
    }));
}

void ConstantsPane::importFile(const QString& path) {
    if (const QString why = editor_->lockRefusal(); !why.isEmpty()) {
        say(tr("Nothing was imported: %1").arg(why), true);
        return;
    }
    const MachineStore store = editor_->store();
    const QString file = QFileInfo(path).fileName();
    runLong(tr("Importing %1").arg(file), [store, path, file](std::function<void(int, int)> progress) {
        LongResult r;
        std::string text;
        if (!readTextFile(path, text, r.error))
            return r;
        const bool csv = path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive) ||
                         text.rfind("number;", 0) == 0 || text.rfind("\xEF\xBB\xBFnumber;", 0) == 0;
        profile::MachineProfile p;
        try {
            // The whole file is read and checked before the database is touched.
            if (csv) {
                p = store.current();
                const profile::CValues c = profile::readCParamsCsv(text, file.toStdString());
                p.c = c;
            } else {
                p = profile::readMachineText(text, file.toStdString());
            }
        } catch (const std::exception& e) {
            r.error = coreErrorText(e);
            return r;
        }
        const MachineStore::Kept k = store.keepProfile(
            p, QString::fromStdString(db::noteText({"studio.import", {file.toStdString()}})),
            [&progress](std::size_t done, std::size_t total) {
                progress(static_cast<int>(done), static_cast<int>(total));
            });
        if (k.revision == 0) {
            r.error = k.error;
            return r;
        }
        r.revision = k.revision;
        r.haveConstants = true;
        r.constants.assign(p.c.begin(), p.c.end());
        r.message = ConstantsPane::tr("%1 imported: revision %2 of %3 (%4 changes)")
                        .arg(file)
                        .arg(k.revision)
                        .arg(store.qName())
                        .arg(k.changes);
        return r;
    }, [this](const LongResult& r) {
        if (!r.error.isEmpty()) {
            say(tr("Nothing was imported: %1").arg(r.error), true);
            return;
        }
        say(r.message + QStringLiteral("; ") + tr("sending them to the controller..."), false);
        const QString message = r.message;
        QPointer<ConstantsPane> self(this);
        editor_->applyAll(r.constants, [self, message](const QString& why) {
            if (!self)
                return;
            if (!why.isEmpty())
                self->say(message + QStringLiteral("; ") + tr("the controller did not take them: %1").arg(why), true);
            else
                self->say(message, false);
        });
    });
}

void ConstantsPane::exportFile(const QString& path) {
    const MachineStore store = editor_->store();
    const auto c = editor_->values();
    profile::CValues values{};
    std::copy(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(values.size()), values.begin());
    const QString file = QFileInfo(path).fileName();
    runLong(tr("Exporting %1").arg(file), [store, values, path, file](std::function<void(int, int)>) {
        LongResult r;
        try {
            std::string text;
            if (path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive)) {
                text = profile::writeCParamsCsv(values);
            } else {
                profile::MachineProfile p = store.current();
                p.c = values; // the constants the controller runs
                text = profile::writeMachineText(p);
            }
            SaveFile f(path);
            if (!f.open(QIODevice::WriteOnly) ||
                f.write(text.data(), static_cast<qint64>(text.size())) != static_cast<qint64>(text.size()) ||
                !f.commit()) {
                r.error = ConstantsPane::tr("cannot write %1: %2").arg(path, fileProblem(f));
                return r;
            }
        } catch (const std::exception& e) {
            r.error = coreErrorText(e);
            return r;
        }
        r.message = ConstantsPane::tr("The constants written to %1").arg(file);
        return r;
    }, [this](const LongResult& r) {
        if (!r.error.isEmpty())
            say(tr("Nothing was exported: %1").arg(r.error), true);
        else
            say(r.message, false);
    });
}

QFuture<LongResult> ConstantsPane::diffRevisions(int a, int b) {
    const MachineStore store = editor_->store();
    const auto c = editor_->values();
    profile::CValues values{};
    std::copy(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(values.size()), values.begin());
    return QtConcurrent::run([store, values, a, b](QPromise<LongResult>& promise) {
        LongResult r;
        promise.setProgressRange(0, 3);
        try {
            const auto at = [&](int rev) {
                if (rev > 0)
                    return store.load(rev);
                profile::MachineProfile p = store.current();
                p.c = values;
                return p;
            };
            const profile::MachineProfile pa = at(a);
            promise.setProgressValue(1);
            const profile::MachineProfile pb = at(b);
            promise.setProgressValue(2);
            const auto changes = profile::diff(pa, pb);
            r.text = diffText(changes);
            r.message = ConstantsPane::tr("Changes: %1").arg(changes.size());
            promise.setProgressValue(3);
        } catch (const std::exception& e) {
            r.error = coreErrorText(e);
        }
        promise.addResult(r);
    });
}

QDockWidget* addConstantsDock(QMainWindow* window, ViewedController& viewed, const profile::MachineProfile& machine) {
    return addParameterTableDock(window, new ConstantsPane(viewed, machine));
}

} // namespace k528::studio
