#include "constants/constants_follow.h"
#include "session/core_texts.h"

#include "constants/constants_dialogs.h"
#include "constants/constants_dock.h"
#include "constants/constants_editor.h"
#include "controller/controller.h"
#include "database/database_ui.h"
#include "session/shop_database.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QPushButton>
#include <QUndoStack>
#include <QVBoxLayout>

namespace k528::studio {

ConflictDialog::ConflictDialog(ConstantsPane& pane, int number, qint64 value, const QString& note,
                               const QString& why, int known, int newest)
    : QDialog(&pane), pane_(pane), number_(number), value_(value), note_(note), known_(known), newest_(newest) {
    setObjectName("constants.conflictDialog");
    setWindowTitle(tr("Changed on another PC — %1").arg(pane.editor().store().qName()));
    message_ = new QLabel(
        tr("C%1 = %2 was applied to the controller but not kept in the database: %3\n\n"
           "Your change was based on revision %4; revision %5 is the newest now.")
            .arg(number, 3, 10, QChar('0'))
            .arg(value)
            .arg(why)
            .arg(known)
            .arg(newest),
        this);
    message_->setObjectName("conflict.message");
    message_->setWordWrap(true);
    message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    auto* buttons = new QDialogButtonBox(this);
    diff_ = buttons->addButton(tr("Show the differences"), QDialogButtonBox::ActionRole);
    diff_->setObjectName("conflict.diff");
    apply_ = buttons->addButton(tr("Apply my change on top"), QDialogButtonBox::AcceptRole);
    apply_->setObjectName("conflict.apply");
    buttons->addButton(tr("Do not keep it"), QDialogButtonBox::RejectRole);
    connect(diff_, &QPushButton::clicked, this, &ConflictDialog::showDifferences);
    connect(apply_, &QPushButton::clicked, this, &ConflictDialog::applyOnNewest);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(message_);
    layout->addWidget(buttons);
    setMinimumWidth(480);
}

void ConflictDialog::showDifferences() {
    auto* d = new DiffDialog(pane_, &pane_);
    d->setAttribute(Qt::WA_DeleteOnClose);
    d->show();
    d->compareRevisions(known_, newest_);
}

void ConflictDialog::applyOnNewest() {
    pane_.editor().keep(number_, value_, note_, true);
    accept();
}

ConstantsFollow::ConstantsFollow(ConstantsPane& pane) : QObject(&pane), pane_(pane) {
    connect(DatabaseWatch::instance(), &DatabaseWatch::revision, this, &ConstantsFollow::elsewhere);
    connect(DatabaseWatch::instance(), &DatabaseWatch::switched, this, &ConstantsFollow::switchedDatabase);
    connect(&pane.editor(), &ConstantsEditor::conflicted, this,
            [this](int number, qint64 value, const QString& note, const QString& why, int known, int newest) {
                pane_.say(tr("Not kept in the database: %1").arg(QString(why).replace(QLatin1Char('\n'), QStringLiteral("; "))), true);
                if (offer_)
                    offer_->close();
                offer_ = new ConflictDialog(pane_, number, value, note, why, known, newest);
                offer_->setAttribute(Qt::WA_DeleteOnClose);
                offer_->open();
            });
}

void ConstantsFollow::elsewhere(const RevisionElsewhere& r) {
    ConstantsEditor& editor = pane_.editor();
    const MachineStore& store = editor.store();
    if (r.machine != store.qName())
        return;
    if (!editor.controller().simulated()) {
        pane_.say(r.text() + QStringLiteral("; ") +
                       tr("the controller on the link keeps its own constants until they are pushed to it"),
                   false);
        return;
    }
    int revision = 0;
    profile::MachineProfile p;
    try {
        const auto revisions = store.revisions();
        if (revisions.empty())
            return;
        revision = revisions.front().revision;
        p = store.load(revision);
    } catch (const std::exception& e) {
        pane_.say(r.text() + QStringLiteral("; ") + coreErrorText(e), true);
        return;
    }
    const auto shown = editor.values();
    if (std::equal(p.c.begin(), p.c.end(), shown.begin(), shown.begin() + static_cast<std::ptrdiff_t>(p.c.size()))) {
        store.setKnown(revision);
        pane_.say(r.text(), false);
        emit followed(revision);
        return;
    }
    const QString told = r.text();
    QPointer<ConstantsFollow> self(this);
    editor.applyAll(std::vector<std::int64_t>(p.c.begin(), p.c.end()), [self, told, revision](const QString& why) {
        if (!self)
            return;
        if (!why.isEmpty()) {
            // The window's view stays on the revision it knew: the next change is refused and offered again.
            self->pane_.say(told + QStringLiteral("; ") + tr("the simulated controller did not take it now: %1").arg(why),
                             true);
            return;
        }
        self->pane_.editor().store().setKnown(revision);
        self->pane_.editor().undoStack()->clear(); // its steps were of the revision before
        self->pane_.say(told + QStringLiteral("; ") + tr("the constants shown are this revision's"), false);
        emit self->followed(revision);
    });
}

void ConstantsFollow::switchedDatabase(const QString& where) {
    ConstantsEditor& editor = pane_.editor();
    const MachineStore& store = editor.store();
    editor.undoStack()->clear(); // its steps were kept in the other database
    if (offer_)
        offer_->close(); // an offer about the other database's revisions
    MachineStore::Reloaded m;
    try {
        m = store.reload();
    } catch (const std::exception& e) {
        pane_.say(tr("Database %1: the machine %2 is not read from it: %3")
                       .arg(where, store.qName(), databaseErrorText(e)),
                   true);
        return;
    }
    if (m.revision == 0) {
        pane_.say(tr("Database %1 has no machine %2: the constants shown stay as they were; the first change "
                      "kept creates the machine there")
                       .arg(where, store.qName()),
                   false);
        emit databaseFollowed(0);
        return;
    }
    const int revision = m.revision;
    if (!editor.controller().simulated()) {
        pane_.say(tr("Database %1: %2 is at revision %3 there; the controller on the link keeps its own "
                      "constants until they are pushed to it")
                       .arg(where, store.qName())
                       .arg(revision),
                   false);
        emit databaseFollowed(revision);
        return;
    }
    const QString told = tr("Database %1: the constants shown are those of revision %2 of %3")
                             .arg(where)
                             .arg(revision)
                             .arg(store.qName());
    const auto shown = editor.values();
    const auto& c = m.profile.c;
    if (std::equal(c.begin(), c.end(), shown.begin(), shown.begin() + static_cast<std::ptrdiff_t>(c.size()))) {
        pane_.say(told, false);
        emit databaseFollowed(revision);
        return;
    }
    QPointer<ConstantsFollow> self(this);
    editor.applyAll(std::vector<std::int64_t>(c.begin(), c.end()),
                    [self, where, told, revision, name = store.qName()](const QString& why) {
                        if (!self)
                            return;
                        if (!why.isEmpty()) {
                            self->pane_.say(tr("Database %1: revision %2 of %3 has other constants; the simulated "
                                                "controller did not take them now: %4")
                                                 .arg(where)
                                                 .arg(revision)
                                                 .arg(name, why),
                                             true);
                            return;
                        }
                        self->pane_.say(told, false);
                        emit self->databaseFollowed(revision);
                    });
}

} // namespace k528::studio
