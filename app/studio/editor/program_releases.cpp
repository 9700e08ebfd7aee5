#include "editor/program_releases.h"

#include "db/error.h"
#include "session/shop_database.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QLineEdit>
#include <QColor>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace k528::studio {

namespace {

QString fromStd(const std::string& s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

const db::ProgramRelease* stateOf(const std::vector<db::ProgramRelease>& states, int number) {
    for (const db::ProgramRelease& p : states)
        if (p.number == number)
            return &p;
    return nullptr;
}

} // namespace

ProgramReleases::ProgramReleases(QWidget* parent) : QWidget(parent) {
    setObjectName("editor.releases");
    title_ = new QLabel(this);
    title_->setObjectName("releases.title");
    title_->setWordWrap(true);
    list_ = new QTreeWidget(this);
    list_->setObjectName("releases.list");
    list_->setColumnCount(3);
    list_->setRootIsDecorated(false);
    list_->setUniformRowHeights(true);
    list_->setAllColumnsShowFocus(true);
    list_->header()->setStretchLastSection(true);
    release_ = new QPushButton(this);
    release_->setObjectName("releases.release");
    withdraw_ = new QPushButton(this);
    withdraw_->setObjectName("releases.withdraw");
    auto* buttons = new QHBoxLayout;
    buttons->setContentsMargins(0, 0, 0, 0);
    buttons->addWidget(release_);
    buttons->addWidget(withdraw_);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(title_);
    layout->addWidget(list_, 1);
    layout->addLayout(buttons);
    connect(list_, &QTreeWidget::currentItemChanged, this, &ProgramReleases::updateButtons);
    connect(release_, &QPushButton::clicked, this, [this] { act(true); });
    connect(withdraw_, &QPushButton::clicked, this, [this] { act(false); });
    ask_ = [this](const QString& title) -> std::optional<QString> {
        bool ok = false;
        const QString note = QInputDialog::getText(this, title, tr("Note (why, what was checked):"),
                                                   QLineEdit::Normal, QString(), &ok);
        if (!ok)
            return std::nullopt;
        return note;
    };
    retranslate();
    hide();
}

QString ProgramReleases::stateText(db::ProgramState s) {
    switch (s) {
    case db::ProgramState::Draft: return tr("draft");
    case db::ProgramState::Released: return tr("released");
    case db::ProgramState::Withdrawn: return tr("withdrawn");
    }
    return {};
}

void ProgramReleases::setMachine(const QString& machine) {
    if (machine != machine_) {
        machine_ = machine;
        states_.clear();
        list_->clear();
    }
    setVisible(!machine_.isEmpty());
    refresh();
}

void ProgramReleases::refresh() {
    if (machine_.isEmpty())
        return;
    const int selected = selectedNumber();
    try {
        const std::string name = machine_.toStdString();
        states_ = ShopDatabase::at()->use([&](db::Database& d) { return d.programReleases(name); });
    } catch (const std::exception& e) {
        states_.clear();
        list_->clear();
        title_->setText(tr("Release states of %1 cannot be read: %2").arg(machine_, databaseErrorText(e)));
        updateButtons();
        return;
    }
    list_->clear();
    for (const db::ProgramRelease& p : states_) {
        auto* item = new QTreeWidgetItem(list_);
        item->setData(0, Qt::UserRole, p.number);
        item->setText(0, QStringLiteral("L%1").arg(p.number));
        item->setText(1, stateText(p.state));
        QString tip;
        if (p.last) {
            const db::ReleaseEntry& e = *p.last;
            item->setText(2, fromStd(e.author));
            if (p.state == db::ProgramState::Released)
                tip = tr("Released as of revision %1 by %2 at %3").arg(e.revision).arg(fromStd(e.author), fromStd(e.at));
            else if (p.state == db::ProgramState::Draft)
                tip = tr("Changed since its release: revision %1 is released (by %2 at %3) and a push takes that one")
                          .arg(e.revision)
                          .arg(fromStd(e.author), fromStd(e.at));
            else if (p.revision == 0)
                tip = tr("Deleted from the machine since its release (by %1 at %2)").arg(fromStd(e.author), fromStd(e.at));
            else
                tip = tr("Withdrawn by %1 at %2 (revision %3 was released)")
                          .arg(fromStd(e.author), fromStd(e.at))
                          .arg(e.revision);
            if (!e.note.empty())
                tip += QStringLiteral("\n") + tr("Note: %1").arg(fromStd(e.note));
        } else {
            tip = tr("Never released: a push to a controller does not take it");
        }
        for (int c = 0; c < 3; ++c)
            item->setToolTip(c, tip);
        if (p.state == db::ProgramState::Released)
            item->setForeground(1, QColor(0x1b, 0x5e, 0x20));
        else if (p.state == db::ProgramState::Withdrawn)
            item->setForeground(1, QColor(0xb7, 0x1c, 0x1c));
        if (p.number == selected)
            list_->setCurrentItem(item);
    }
    retranslate();
    for (int c = 0; c < 2; ++c)
        list_->resizeColumnToContents(c);
    updateButtons();
}

int ProgramReleases::selectedNumber() const {
    const QTreeWidgetItem* item = list_->currentItem();
    return item ? item->data(0, Qt::UserRole).toInt() : 0;
}

void ProgramReleases::updateButtons() {
    const db::ProgramRelease* p = stateOf(states_, selectedNumber());
    // Release: a current version that is not the released one; withdraw: a released one.
    release_->setEnabled(p && p->revision != 0 && p->state != db::ProgramState::Released);
    withdraw_->setEnabled(p && p->last && p->last->released);
}

void ProgramReleases::act(bool release) {
    const int n = selectedNumber();
    if (n == 0)
        return;
    const auto note = ask_(release ? tr("Release L%1 of %2").arg(n).arg(machine_)
                                   : tr("Withdraw L%1 of %2").arg(n).arg(machine_));
    if (!note)
        return;
    if (release)
        this->release(n, *note);
    else
        withdraw(n, *note);
}

QString ProgramReleases::release(int number, const QString& note) {
    QString why;
    const db::ProgramRelease* p = stateOf(states_, number);
    if (p && p->revision == 0)
        why = tr("L%1 is no longer a program of %2: there is nothing to release").arg(number).arg(machine_);
    else if (p && p->state == db::ProgramState::Released)
        why = tr("L%1 is released already (revision %2)").arg(number).arg(p->revision);
    const std::string text = note.toStdString();
    return change(
        number, why, [&](db::Database& d, const std::string& name) { return d.releaseProgram(name, number, text); },
        [&](const db::ReleaseEntry& e) {
            return tr("Released L%1 of %2 as of revision %3 by %4 at %5")
                .arg(number)
                .arg(machine_)
                .arg(e.revision)
                .arg(fromStd(e.author), fromStd(e.at));
        },
        tr("L%1 was not released: %2"));
}

QString ProgramReleases::withdraw(int number, const QString& note) {
    QString why;
    const db::ProgramRelease* p = stateOf(states_, number);
    if (p && !p->last)
        why = tr("L%1 was never released: there is nothing to withdraw").arg(number);
    else if (p && !p->last->released)
        why = tr("L%1 is withdrawn already").arg(number);
    const std::string text = note.toStdString();
    return change(
        number, why, [&](db::Database& d, const std::string& name) { return d.withdrawProgram(name, number, text); },
        [&](const db::ReleaseEntry& e) {
            return tr("Withdrew L%1 of %2 by %3 at %4").arg(number).arg(machine_).arg(fromStd(e.author), fromStd(e.at));
        },
        tr("L%1 was not withdrawn: %2"));
}

QString ProgramReleases::change(int number, QString why, const Write& write,
                                const std::function<QString(const db::ReleaseEntry&)>& done,
                                const QString& notDone) {
    if (why.isEmpty()) {
        try {
            const std::string name = machine_.toStdString();
            const db::ReleaseEntry e = ShopDatabase::at()->use([&](db::Database& d) { return write(d, name); });
            refresh();
            emit statusMessage(done(e));
            return {};
        } catch (const std::exception& e) {
            why = databaseErrorText(e);
        }
    }
    why = notDone.arg(number).arg(why);
    refresh();
    emit statusMessage(why);
    return why;
}

void ProgramReleases::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) {
        retranslate();
        refresh();
    }
    QWidget::changeEvent(e);
}

void ProgramReleases::retranslate() {
    title_->setText(tr("Programs of %1 for the controllers").arg(machine_));
    list_->setHeaderLabels({tr("No."), tr("State"), tr("By")});
    release_->setText(tr("Release..."));
    release_->setToolTip(tr("Makes the program's current version the one a push to a controller takes (k528 db release)"));
    withdraw_->setText(tr("Withdraw..."));
    withdraw_->setToolTip(tr("Withdraws the released version: a push no longer takes it (k528 db withdraw)"));
}

} // namespace k528::studio
