// The constants pane and the shop's database shared by many PCs:
//   - another process's or PC's revision of the window's machine
//     (DatabaseWatch) is told in the pane; the simulated controller takes its
//     constants at once (with its own rules: refused while a program runs),
//     a real controller on the link keeps its own (a push applies them);
//   - a change refused because it was based on an older revision than the
//     database's newest (someone else's) is told with the database's words
//     (who, when), and the pane offers the differences between the two
//     revisions and applying the user's change again on top of the newest;
//   - File > Database… switched the window to another database: the pane
//     shows the machine as that database holds it (the simulated controller
//     takes its constants; a real one keeps its own until a push), the next
//     change is based on that database's revision, and the undo steps kept
//     in the other database are gone.
#pragma once

#include <QDialog>
#include <QObject>
#include <QPointer>
#include <QString>

class QLabel;
class QPushButton;

namespace k528::studio {

class ConstantsPane;
struct RevisionElsewhere;

// The offer made when a change was refused.
class ConflictDialog : public QDialog {
    Q_OBJECT
public:
    ConflictDialog(ConstantsPane& pane, int number, qint64 value, const QString& note, const QString& why,
                   int known, int newest);
    QLabel* message() const { return message_; }
    QPushButton* diffButton() const { return diff_; }
    QPushButton* applyButton() const { return apply_; }
    // The differences known -> newest (DiffDialog, comparing at once).
    void showDifferences();
    // The change again, on the newest revision.
    void applyOnNewest();

private:
    ConstantsPane& pane_;
    int number_;
    qint64 value_;
    QString note_;
    int known_, newest_;
    QLabel* message_;
    QPushButton* diff_;
    QPushButton* apply_;
};

class ConstantsFollow : public QObject {
    Q_OBJECT
public:
    explicit ConstantsFollow(ConstantsPane& pane);
    // The offer of the last refusal (nullptr once closed).
    ConflictDialog* offer() const { return offer_; }

signals:
    // The pane shows `revision`'s constants (taken by the simulated controller).
    void followed(int revision);
    // After File > Database…: the pane shows the new database's machine at
    // `revision` (0: that database has no such machine; the constants stay).
    void databaseFollowed(int revision);

private:
    void elsewhere(const RevisionElsewhere& r);
    void switchedDatabase(const QString& where);
    ConstantsPane& pane_;
    QPointer<ConflictDialog> offer_;
};

} // namespace k528::studio
