// The release states of a database machine's programs beside the editor's
// document of that machine (docs/database.md, *Programs released*): each
// program with its state — draft, released, withdrawn («черновик»,
// «выпущена», «отозвана») — who released or withdrew it, when and why (its
// tooltip), and Release / Withdraw with a note. Thin over core: the same
// db::Database::programReleases / releaseProgram / withdrawProgram as
// `k528 db show --programs`, `k528 db release` and `k528 db withdraw`, on the
// window's database (ShopDatabase). A refused action (the role on
// PostgreSQL, the program's state) says why in the window's language.
#pragma once

#include "db/database.h"

#include <QString>
#include <QWidget>
#include <functional>
#include <optional>
#include <vector>

class QLabel;
class QPushButton;
class QTreeWidget;

namespace k528::studio {

class ProgramReleases : public QWidget {
    Q_OBJECT
public:
    explicit ProgramReleases(QWidget* parent = nullptr);

    // The database machine shown ("" hides the pane).
    void setMachine(const QString& machine);
    QString machine() const { return machine_; }
    // Reads the states again (after a save of the machine's programs, a
    // release elsewhere).
    void refresh();

    QTreeWidget* list() const { return list_; }
    QPushButton* releaseButton() const { return release_; }
    QPushButton* withdrawButton() const { return withdraw_; }
    const std::vector<db::ProgramRelease>& states() const { return states_; }
    // The word of a state in the window's language.
    static QString stateText(db::ProgramState s);

    // Releases / withdraws program `number` of the machine with `note`:
    // "" when done, else why not (also said by statusMessage()).
    QString release(int number, const QString& note);
    QString withdraw(int number, const QString& note);
    // The note asked before an action (nullopt: cancelled); tests replace it.
    void setNoteQuestion(std::function<std::optional<QString>(const QString& title)> ask) { ask_ = std::move(ask); }

signals:
    void statusMessage(const QString& text);

protected:
    void changeEvent(QEvent* e) override;

private:
    void retranslate();
    void updateButtons();
    int selectedNumber() const;
    void act(bool release);
    // What release() and withdraw() share: with `why` empty, `write` runs on
    // the database (the machine's name given) and its entry is said with
    // `done`; a failure (a role refusal names the role itself) with
    // `notDone` (%1 L, %2 why).
    using Write = std::function<db::ReleaseEntry(db::Database&, const std::string&)>;
    QString change(int number, QString why, const Write& write,
                   const std::function<QString(const db::ReleaseEntry&)>& done, const QString& notDone);

    QString machine_;
    QLabel* title_ = nullptr;
    QTreeWidget* list_ = nullptr;
    QPushButton* release_ = nullptr;
    QPushButton* withdraw_ = nullptr;
    std::vector<db::ProgramRelease> states_;
    std::function<std::optional<QString>(const QString& title)> ask_;
};

} // namespace k528::studio
