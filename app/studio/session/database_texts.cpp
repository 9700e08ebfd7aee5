#include "session/database_texts.h"

#include "db/error.h"
#include "session/translated_texts.h"

#include <QCoreApplication>

namespace k528::studio {

namespace {

// The English of each id of db::dbTexts() (core/db/db_texts.cpp), translated
// by translations/pairs/database-texts.ru.tsv.
const TranslatedText kTexts[] = {
    {"no-machine", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "no machine \"%1\" in %2 (machines: %3)")},
    {"no-machine.none", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "no machine \"%1\" in %2 (machines: none)")},
    {"machine-exists", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "a machine named %1 already exists in %2")},
    {"machine.said", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1: %2")},
    {"rename-exists", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "cannot rename %1 to %2: a machine of that name exists")},
    {"constants-locked", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1: the machine constants are locked by the trainer for the class «%2» (setting %3): %4 not changed; nothing was written (the trainer unlocks them first: k528 db set %1 %3=)")},
    {"rejected.error", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1: rejected, nothing was written (%2 error):")},
    {"rejected.errors", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1: rejected, nothing was written (%2 errors):")},
    {"rejected.problem", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1: rejected, nothing was written:")},
    {"no-revision", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 has revisions 1..%2; there is no revision %3")},
    {"conflict", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 is at revision %2, not %3")},
    {"conflict.detailed", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 is at revision %2 (changed by %3 at %4), not %5 as read: load it again and repeat the change")},
    {"author-too-long", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the author's name is %1 bytes long; a name has at most %2 (UTF-8); nothing was written")},
    {"corrupt.history-entry", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 revision %2 in %3: history entry %4 %5 of revision %6 cannot be read")},
    {"corrupt.revision-missing", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 revision %2 in %3: the revision is missing from the revision table")},
    {"corrupt.revision-program", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 revision %2 in %3: program L%4 of revision %5 does not match its SHA-256 checksum")},
    {"corrupt.history-section", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1: history has an unknown section %2")},
    {"corrupt.program", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1: program L%2 does not match its SHA-256 checksum")},
    {"corrupt.settings-order-key", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 revision %2 in %3: simulation key %4 of the stored order has no value")},
    {"corrupt.settings-order-incomplete", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 revision %2 in %3: the stored order of the simulation settings does not list every key")},
    {"corrupt.c-values.pairs", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 in %2: C values: \"%3\" where integer pairs belong")},
    {"corrupt.c-values.odd", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 in %2: C values: a number without its value")},
    {"corrupt.r-presets.pairs", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 in %2: R presets: \"%3\" where integer pairs belong")},
    {"corrupt.r-presets.odd", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 in %2: R presets: a number without its value")},
    {"corrupt.c-number", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 in %2: C-parameter number %3 is not 1..152")},
    {"corrupt.c-count", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 in %2: %3 of the 152 C-parameter values are stored")},
    {"corrupt.current-program", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 in %2: program L%3 of revision %4 does not match its SHA-256 checksum (the text was altered outside K528 Studio)")},
    {"corrupt.plc-group", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 in %2: unknown PLC message group %3")},
    {"corrupt.setting", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 in %2: the simulation setting %3=%4 cannot be read")},
    {"corrupt.column-type", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "column %1 holds a value that is neither an integer nor a text (query: %2)")},
    {"corrupt.column-integer", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "column %1 holds a value where an integer belongs: %2")},
    {"migrate.failed", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "; the migration to schema version %1 failed, nothing was changed")},
    {"read-only.write", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the database is read-only: %1 (%2); nothing was written")},
    {"read-only.create", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the database is read-only: %1 (%2); a new database cannot be created there")},
    {"read-only.upgrade", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the database is read-only: %1 (%2); its schema is older than this program's and cannot be upgraded")},
    {"read-only.recover", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the database is read-only: %1 (%2); it has an unfinished transaction (a hot -journal) that only a user who may write the file can roll back; the file was left untouched")},
    {"read-only.permission", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "permission denied")},
    {"read-only.folder", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "no permission to create files in its folder")},
    {"read-only.file-system", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "read-only file system")},
    {"read-only.requested", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "opened read-only")},
    {"denied", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the database %1 refused the user %2: %4 needs %5; the user has %3; nothing was written")},
    {"denied.no-role", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the database %1 refused the user %2: %3 needs %4; the user has no K528 Studio role; nothing was written")},
    {"denied.create-machine", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "creating a machine")},
    {"denied.change-machine", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "changing a machine")},
    {"denied.delete-machine", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "deleting a machine")},
    {"denied.release-program", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "releasing a program")},
    {"denied.withdraw-program", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "withdrawing a program")},
    {"denied.record-transfer", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "recording a transfer")},
    {"denied.record-messages", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "recording messages")},
    {"denied.record-attempt", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "recording a training attempt")},
    {"denied.create-tables", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "creating the database's tables")},
    {"denied.set-up-roles", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "setting up the roles")},
    {"denied.grant-role", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "granting a role")},
    {"denied.lock-constants", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "setting or clearing the constants lock")},
    {"denied.record-state-times", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "recording the machines' time in each state")},
    {"denied.role", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the role %1")},
    {"denied.database-owner", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the owner of the database")},
    {"denied.tables-creator", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the owner of the database's tables with CREATEROLE")},
    {"denied.role-admin", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the role's admin (its creator, or CREATEROLE)")},
    {"internal", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "an unexpected database error (please report it): %1")},
    {"schema-lacks.messages", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: the database has no message history (schema version %2 below %3: open it once with write access to upgrade it)")},
    {"schema-lacks.attempts", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: the database has no training attempts (schema version %2 below %3: open it once with write access to upgrade it)")},
    {"schema-lacks.state-times", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: the database has no time in each state of the shop's machines (schema version %2 below %3: open it once with write access to upgrade it)")},
    {"attempt.no-student", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "an attempt needs its student's name; nothing was written")},
    {"attempt.no-exercise", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "an attempt needs its exercise; nothing was written")},
    {"attempt.score", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the attempt of \"%1\" at \"%2\": a score is 0..100, not %3; nothing was written")},
    {"attempt.cycle-time", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the attempt of \"%1\" at \"%2\": a negative cycle time; nothing was written")},
    {"transfer.direction", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "a transfer is a push or a pull, not \"%1\"")},
    {"transfer.result", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "a transfer's result is ok, partial or failed, not \"%1\"")},
    {"state-time.invalid", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "a time in a state needs a machine, a day (YYYY-MM-DD), run, idle, alarm or offline and 0 ms or more, not '%1' '%2' '%3' %4 ms; nothing was written")},
    {"release.no-program", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1 has no program L%2 (at revision %3); nothing was released")},
    {"release.never", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "program L%2 of machine %1 was never released; nothing was written")},
    {"release.withdrawn", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "program L%2 of machine %1 is withdrawn already; nothing was written")},
    {"roles.sqlite", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: an SQLite database has one user, who may do everything; the roles are PostgreSQL's")},
    {"location.none", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "no database location: set K528_DB, XDG_DATA_HOME or HOME")},
    {"location.postgres", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "K528_DB names a PostgreSQL database (%1), not a file")},
    {"open.no-database", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "no database at %1")},
    {"open.no-database.init", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "no database at %1 (create one with: k528 db init --db %1)")},
    {"open.no-folder", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "cannot create the database %1: the folder %2 does not exist")},
    {"open.directory", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: is a directory, not a database file")},
    {"open.not-empty", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: not an empty database (schema version %2); a copy goes only into a new or empty one")},
    {"open.foreign-short", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "not a K528 Studio database: the file has only %1 bytes, too few for an SQLite database")},
    {"open.foreign-header", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "not a K528 Studio database: the file does not start with the SQLite header (another kind of file, or a database whose first page is damaged)")},
    {"open.foreign-program", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "not a K528 Studio database: it is another program's SQLite database (application_id %1, ours is %2)")},
    {"open.foreign-objects", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "not a K528 Studio database: it is another program's SQLite database (application_id %1, %2 schema objects)")},
    {"open.too-new", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the database has schema version %1, written by a newer K528 Studio; this program knows versions up to %2. Use the newer program")},
    {"open.untouched", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "; the file was left untouched")},
    {"open.recovered", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "; only the unfinished transaction in %1 was rolled back (SQLite's crash recovery of a K528 Studio database), nothing else was changed")},
    {"busy.write", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: another process is writing to the database and kept it locked longer than the busy timeout; nothing was written, try again")},
    {"copy.schema", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1 has schema version %2; a copy needs version %3 (open it once with write access to upgrade it)")},
    {"copy.itself", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "a database cannot be copied into itself")},
    {"item.syntax", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "'%1' is not ITEM=VALUE (e.g. C022=2133, R12=5, #3=TEXT, A01=TEXT)")},
    {"item.c-none", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: no such C-parameter (1..152)")},
    {"item.r-none", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: no such R-parameter (0..299)")},
    {"item.message-none", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: no such technological message (#1..#99)")},
    {"item.plc-none", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: no such PLC message (%2..%3)")},
    {"item.not-whole", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: '%2' is not a whole number")},
    {"item.unknown", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "'%1' is not an item: C<n>, R<n>, #<n>, A<nn>, W<nn>, S<nn>, title or a simulation key")},
    {"item.twice", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1 is given twice ('%2' and '%3'); give each item once")},
    {"item.unknown-key", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "'%1' is not a known simulation key; nothing was saved. The keys are listed in docs/profile-format.md; --allow-unknown stores it anyway")},
    {"item.unknown-key.close", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "'%1' is not a known simulation key; nothing was saved (did you mean %2?). The keys are listed in docs/profile-format.md; --allow-unknown stores it anyway")},
    {"location.empty", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "database location \"%1\": empty; give a file path or a postgresql:// URI")},
    {"location.password", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "database location \"%1\": a password does not go into a database location (every user of this PC can read a command line, and shells keep it): put it in ~/.pgpass (PGPASSFILE) or a service file (PGSERVICEFILE, postgresql://?service=NAME), or log in without one")},
    {"location.sqlite-path", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "database location \"%1\": sqlite: needs a file path (sqlite:/srv/k528/shop.db)")},
    {"location.unknown-kind", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "database location \"%1\": unknown kind of database \"%2\"; K528 Studio keeps its database in SQLite (a file path or sqlite:PATH) or PostgreSQL (postgresql://…)")},
    {"connect.failed", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "cannot connect to the database %1: %2")},
    {"connect.lost", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the connection to the server was lost and cannot be made again")},
    {"open.cannot", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "cannot open: %1")},
    {"open.unreadable", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "cannot be read: %1")},
    {"open.not-regular.character-device", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: is not a regular file (a character device); a database is a regular file — give another --db path")},
    {"open.not-regular.block-device", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: is not a regular file (a block device); a database is a regular file — give another --db path")},
    {"open.not-regular.fifo", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: is not a regular file (a FIFO); a database is a regular file — give another --db path")},
    {"open.not-regular.socket", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: is not a regular file (a socket); a database is a regular file — give another --db path")},
    {"open.not-regular.other", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: is not a regular file (not a file); a database is a regular file — give another --db path")},
    {"open.no-handle", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "cannot be read: SQLite did not open the file")},
    {"open.busy", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "another program kept the database locked longer than the busy timeout (%1)")},
    {"open.not-database", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "cannot be read as a database (%1)")},
    {"open.damaged", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the database is damaged (integrity check: %1)")},
    {"open.damaged-keys", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the database is damaged (integrity check: %1 rows break foreign keys (first: %2 row %3 -> %4))")},
    {"open.no-version", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "K528 Studio database without a schema version")},
    {"open.foreign-journal", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "not a K528 Studio database: an SQLite database without K528 Studio's application_id, with an unfinished transaction of another program (the hot journal %1, begun on a file of %2 pages), which is not ours to roll back: let that program open it first")},
    {"open.foreign-journal.size", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "not a K528 Studio database: an SQLite database without K528 Studio's application_id, with an unfinished transaction of another program (the hot journal %1, begun on a file of unknown size), which is not ours to roll back: let that program open it first")},
    {"open.foreign-writer", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "another program wrote into the file while it was being created")},
    {"open.wal", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "cannot switch to WAL journal mode (mode \"%1\"): another process kept the database busy longer than the busy timeout")},
    {"pg.no-schema", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the search path names no schema that exists; create it or set search_path (options=-csearch_path=…)")},
    {"pg.foreign-tables", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "not a K528 Studio database: it holds %1 tables or views of another program (no k528_schema); nothing was changed")},
    {"pg.foreign-application", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "not a K528 Studio database (k528_schema says \"%1\"); nothing was changed")},
    {"pg.schema-empty", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the table k528_schema is empty")},
    {"pg.no-database", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "no K528 Studio database at %1 (the database is empty; create one with: k528 db init --db %1)")},
    {"pg.not-empty", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: not an empty database (schema version %2); a copy goes only into an empty one")},
    {"pg.old-server", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "PostgreSQL %1 is too old; K528 Studio needs version 11 or newer")},
    {"pg.encoding", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the database's encoding is %1; K528 Studio keeps Russian texts and needs UTF8 (createdb --encoding=UTF8 --template=template0)")},
    {"busy.write.session", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1: another session is writing to the database and kept it locked longer than the busy timeout; nothing was written, try again")},
    {"role.unknown", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "no role \"%1\": the roles are trainer, technologist, operator and viewer")},
    {"messages.no-run", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "no message run %1; nothing was written")},
    {"messages.no-run-id", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "the new run has no id")},
    {"messages.busy", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "another process kept the database locked longer than the busy timeout; the messages were not written")},
    {"messages.no-how", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "message event %1 of run %2: acknowledged without saying how")},
    {"messages.not-raised", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "message event %1 of run %2: no such message was raised")},
    {"messages.bad-source", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "message history row %1: unknown source \"%2\"")},
    {"messages.none-written", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "; none of the batch's %1 events was written")},
    {"push.unreleased", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "machine %1: a push takes released programs only; not released as they are:")},
    {"push.not-in-database", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "L%1: not in the database, nothing of it released")},
    {"push.draft", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "L%1: draft, nothing of it released")},
    {"push.withdrawn", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "L%1: withdrawn, nothing of it released")},
    {"push.not-released-version", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "L%1: not the released version (revision %2)")},
    {"push.release-them", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "release them (k528 db release %1 L<n>), or let technologists push drafts: k528 db set %1 push.unreleased=true")},
    {"push.release-them.technologist", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "release them (k528 db release %1 L<n>), or push as a technologist (the machine allows drafts: push.unreleased)")},
    {"list.or", QT_TRANSLATE_NOOP("k528::studio::DatabaseTexts", "%1 or %2")},
};

const TranslatedTexts kDatabaseTexts("k528::studio::DatabaseTexts", kTexts);

} // namespace

bool hasDatabaseText(std::string_view id) { return kDatabaseTexts.has(id); }

QString databaseText(std::string_view id, const std::vector<std::string>& args) {
    return kDatabaseTexts.text(id, args).value_or(QString());
}

QString databaseText(const db::ErrorText& t) {
    if (!hasDatabaseText(t.id) || (!t.tail.empty() && !hasDatabaseText(t.tail)))
        return {};
    bool said = true;
    QString s = t.at.empty() ? QString() : QString::fromStdString(t.at) + QStringLiteral(": ");
    s += sayWithin({&kDatabaseTexts}, t.id, t.args, t.within,
                   [&](const db::ErrorText& part) {
                       QString text = databaseText(part);
                       said = said && !text.isEmpty();
                       return text;
                   },
                   [] { return QString(); });
    if (!said)
        return {}; // a part the desktop lacks: the caller says core's words
    if (!t.tail.empty())
        s += databaseText(t.tail, t.tailArgs);
    return s;
}

} // namespace k528::studio
