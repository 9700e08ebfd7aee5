// The programs and messages of a machine of the shop's database in the
// editor: opened as one file (every program under its %L header,
// then %MESSAGES: profile::programsFileText) at the machine's current
// revision, and saved as its next revision (db::Database::saveMachine with
// the revision that was opened, so a change made meanwhile by someone else
// is refused, not overwritten). Each program keeps its text as written: the
// file is cut at the programs' headers, not re-formatted, so a program that
// was not edited is not a change of the revision.
#pragma once

#include <QString>
#include <QStringList>

namespace k528::studio {

struct DatabasePrograms {
    bool ok = false;
    QString machine;
    int revision = 0; // the machine's revision the text is of
    QString text;
    QString error;
};

// The machines of the database (db::defaultDatabasePath(), $K528_DB).
QStringList databaseMachines(QString* error = nullptr);

DatabasePrograms loadDatabasePrograms(const QString& machine);

struct DatabaseSave {
    int revision = 0;     // the machine's revision after the save, 0 when it failed
    bool changed = false; // false: the database already held these programs
    QString error;
};

// Makes the programs and messages of `text` those of `machine` (programs the
// text no longer holds are deleted), refused when the machine is no longer at
// `expectedRevision` or the text has syntax errors.
DatabaseSave saveDatabasePrograms(const QString& machine, const QString& text, int expectedRevision);

} // namespace k528::studio
