// The database schema, one migration a version (PRAGMA user_version).
// docs/database.md describes the tables. A new version: append a Migration
// whose SQL turns version N-1 into N (never edit a released step), and test
// the path from N-1 in tests/db/test_schema.cpp.
#include "db/database.h"

#include <algorithm>

namespace k528::db {

namespace {

constexpr std::string_view kSchemaV1 = R"SQL(
CREATE TABLE meta (
    key   TEXT PRIMARY KEY,
    value TEXT NOT NULL
) WITHOUT ROWID;

-- The 152 C-parameter definitions of appendix Е (table Е.1), from core/catalog.
CREATE TABLE c_definitions (
    number         INTEGER PRIMARY KEY CHECK (number BETWEEN 1 AND 152),
    axis           TEXT NOT NULL CHECK (axis IN ('X', 'Z', '')),
    kind           TEXT NOT NULL CHECK (kind IN ('flag', 'integer', 'code', 'reserved')),
    unit           TEXT NOT NULL,
    unit_ru        TEXT NOT NULL,
    unit_en        TEXT NOT NULL,
    min_value      INTEGER NOT NULL,
    max_value      INTEGER NOT NULL CHECK (max_value >= min_value),
    address        TEXT NOT NULL,
    address_en     TEXT NOT NULL,
    name           TEXT NOT NULL,
    name_en        TEXT NOT NULL,
    description_ru TEXT NOT NULL,
    description_en TEXT NOT NULL,
    hint_ru        TEXT NOT NULL,
    hint_en        TEXT NOT NULL,
    note           TEXT NOT NULL
);

CREATE TABLE machines (
    id         INTEGER PRIMARY KEY,
    name       TEXT NOT NULL UNIQUE,
    title      TEXT NOT NULL,
    revision   INTEGER NOT NULL CHECK (revision >= 1),
    created_at TEXT NOT NULL,
    changed_at TEXT NOT NULL,
    changed_by TEXT NOT NULL
);

CREATE TABLE revisions (
    machine_id     INTEGER NOT NULL REFERENCES machines(id) ON DELETE CASCADE,
    revision       INTEGER NOT NULL CHECK (revision >= 1),
    author         TEXT NOT NULL,
    at             TEXT NOT NULL,
    summary        TEXT NOT NULL,
    settings_order TEXT NOT NULL,
    PRIMARY KEY (machine_id, revision)
) WITHOUT ROWID;

CREATE TABLE c_values (
    machine_id INTEGER NOT NULL REFERENCES machines(id) ON DELETE CASCADE,
    number     INTEGER NOT NULL REFERENCES c_definitions(number),
    value      INTEGER NOT NULL,
    PRIMARY KEY (machine_id, number)
) WITHOUT ROWID;

CREATE TABLE r_values (
    machine_id INTEGER NOT NULL REFERENCES machines(id) ON DELETE CASCADE,
    number     INTEGER NOT NULL CHECK (number BETWEEN 0 AND 299 AND number NOT BETWEEN 232 AND 262),
    value      INTEGER NOT NULL CHECK (value BETWEEN -2147483648 AND 2147483647),
    PRIMARY KEY (machine_id, number)
) WITHOUT ROWID;

CREATE TABLE messages (
    machine_id INTEGER NOT NULL REFERENCES machines(id) ON DELETE CASCADE,
    number     INTEGER NOT NULL CHECK (number BETWEEN 1 AND 99),
    text       TEXT NOT NULL,
    PRIMARY KEY (machine_id, number)
) WITHOUT ROWID;

CREATE TABLE plc_messages (
    machine_id INTEGER NOT NULL REFERENCES machines(id) ON DELETE CASCADE,
    grp        TEXT NOT NULL CHECK (grp IN ('A', 'W', 'S')),
    number     INTEGER NOT NULL CHECK (number >= 1 AND number <= CASE grp WHEN 'S' THEN 16 ELSE 32 END),
    text       TEXT NOT NULL,
    PRIMARY KEY (machine_id, grp, number)
) WITHOUT ROWID;

CREATE TABLE settings (
    machine_id INTEGER NOT NULL REFERENCES machines(id) ON DELETE CASCADE,
    position   INTEGER NOT NULL,
    key        TEXT NOT NULL,
    value      TEXT NOT NULL,
    PRIMARY KEY (machine_id, key),
    UNIQUE (machine_id, position)
) WITHOUT ROWID;

-- Every version of every program; text NULL: deleted at that revision.
-- (A rowid table: its rows are large, which WITHOUT ROWID stores poorly.)
CREATE TABLE program_revisions (
    id         INTEGER PRIMARY KEY,
    machine_id INTEGER NOT NULL,
    number     INTEGER NOT NULL CHECK (number BETWEEN 1 AND 99),
    revision   INTEGER NOT NULL,
    text       TEXT,
    sha256     TEXT CHECK (sha256 IS NULL OR length(sha256) = 64),
    CHECK ((text IS NULL) = (sha256 IS NULL)),
    UNIQUE (machine_id, number, revision),
    FOREIGN KEY (machine_id, revision) REFERENCES revisions(machine_id, revision) ON DELETE CASCADE
);

-- The current programs: the newest version of each number, unless deleted.
CREATE VIEW programs AS
SELECT p.machine_id, p.number, p.revision, p.text, p.sha256
FROM program_revisions p
WHERE p.revision = (SELECT max(q.revision) FROM program_revisions q
                    WHERE q.machine_id = p.machine_id AND q.number = p.number)
  AND p.text IS NOT NULL;

-- What each revision changed, old -> new (NULL: absent). Programs: SHA-256.
CREATE TABLE changes (
    machine_id INTEGER NOT NULL,
    revision   INTEGER NOT NULL,
    seq        INTEGER NOT NULL,
    section    TEXT NOT NULL CHECK (section IN ('machine', 'c', 'r', 'program', 'message',
                                                'plc-message', 'simulation')),
    key        TEXT NOT NULL,
    label      TEXT NOT NULL,
    before     TEXT,
    after      TEXT,
    PRIMARY KEY (machine_id, revision, seq),
    FOREIGN KEY (machine_id, revision) REFERENCES revisions(machine_id, revision) ON DELETE CASCADE
) WITHOUT ROWID;

CREATE INDEX changes_by_key ON changes (machine_id, key, revision);

-- C-parameter history for people using SQL directly.
CREATE VIEW c_history AS
SELECT m.name AS machine, ch.key AS parameter, ch.label AS name, ch.before AS old_value,
       ch.after AS new_value, r.revision, r.author, r.at
FROM changes ch
JOIN revisions r ON r.machine_id = ch.machine_id AND r.revision = ch.revision
JOIN machines m ON m.id = ch.machine_id
WHERE ch.section = 'c';

CREATE TABLE audit (
    id       INTEGER PRIMARY KEY AUTOINCREMENT,
    at       TEXT NOT NULL,
    author   TEXT NOT NULL,
    action   TEXT NOT NULL,
    machine  TEXT NOT NULL,
    revision INTEGER NOT NULL,
    detail   TEXT NOT NULL
);
)SQL";

// A C value outside its definition's range is refused by the database too.
constexpr std::string_view kSchemaV1Sqlite = R"SQL(
CREATE TRIGGER c_values_range_insert BEFORE INSERT ON c_values
WHEN NEW.value NOT BETWEEN (SELECT min_value FROM c_definitions WHERE number = NEW.number)
                       AND (SELECT max_value FROM c_definitions WHERE number = NEW.number)
BEGIN
    SELECT RAISE(ABORT, 'C-parameter value outside the range of its definition');
END;

CREATE TRIGGER c_values_range_update BEFORE UPDATE OF value ON c_values
WHEN NEW.value NOT BETWEEN (SELECT min_value FROM c_definitions WHERE number = NEW.number)
                       AND (SELECT max_value FROM c_definitions WHERE number = NEW.number)
BEGIN
    SELECT RAISE(ABORT, 'C-parameter value outside the range of its definition');
END;
)SQL";

constexpr std::string_view kSchemaV1Postgres = R"SQL(
CREATE FUNCTION c_values_range() RETURNS trigger LANGUAGE plpgsql AS $$
BEGIN
    IF NEW.value NOT BETWEEN (SELECT min_value FROM c_definitions WHERE number = NEW.number)
                         AND (SELECT max_value FROM c_definitions WHERE number = NEW.number) THEN
        RAISE EXCEPTION 'C-parameter value outside the range of its definition'
            USING ERRCODE = 'check_violation';
    END IF;
    RETURN NEW;
END $$;

CREATE TRIGGER c_values_range BEFORE INSERT OR UPDATE OF value ON c_values
FOR EACH ROW EXECUTE FUNCTION c_values_range();
)SQL";

// Version 2: the message history (core/db/message_log.h). Every message the
// positioner and the PLC raised on a simulated (or linked) machine, one row an
// occurrence; a "run" is one session of one machine (the desktop's start).
// Not tied to the machines table: the log outlives a deleted machine.
constexpr std::string_view kSchemaV2 = R"SQL(
CREATE TABLE message_runs (
    id         INTEGER PRIMARY KEY,
    machine    TEXT NOT NULL,
    started_at TEXT NOT NULL,
    started_ms INTEGER NOT NULL,
    author     TEXT NOT NULL
);

CREATE TABLE message_history (
    id          INTEGER PRIMARY KEY,
    run_id      INTEGER NOT NULL REFERENCES message_runs(id) ON DELETE CASCADE,
    seq         INTEGER NOT NULL CHECK (seq >= 1),
    machine     TEXT NOT NULL,
    machine_ms  INTEGER NOT NULL CHECK (machine_ms >= 0),
    day_ms      INTEGER NOT NULL,
    source      TEXT NOT NULL CHECK (source IN ('positioner', 'plc-alarm', 'plc-system',
                                                'plc-work', 'program')),
    number      INTEGER NOT NULL CHECK (number BETWEEN 1 AND 99),
    text        TEXT NOT NULL,
    text_en     TEXT NOT NULL,
    program     INTEGER NOT NULL CHECK (program BETWEEN 0 AND 99),
    line        INTEGER NOT NULL CHECK (line >= 0),
    cleared_ms  INTEGER,
    ack_ms      INTEGER,
    ack_day_ms  INTEGER,
    ack_how     TEXT,
    CHECK ((ack_ms IS NULL) = (ack_how IS NULL) AND (ack_ms IS NULL) = (ack_day_ms IS NULL)),
    UNIQUE (run_id, seq)
);

CREATE INDEX message_history_by_machine ON message_history (machine, id);
)SQL";

// Version 3: programs released for the controllers and every transfer on
// record. A program's state is its newest row of program_states; the user of
// a transfer and the author of a release are, on PostgreSQL, the server's
// current_user (a default the roles cannot override: row security).
constexpr std::string_view kSchemaV3 = R"SQL(
CREATE TABLE program_states (
    id         INTEGER PRIMARY KEY,
    machine_id INTEGER NOT NULL,
    number     INTEGER NOT NULL CHECK (number BETWEEN 1 AND 99),
    revision   INTEGER NOT NULL,
    sha256     TEXT NOT NULL CHECK (length(sha256) = 64),
    state      TEXT NOT NULL CHECK (state IN ('released', 'withdrawn')),
    at         TEXT NOT NULL,
    author     TEXT NOT NULL,
    note       TEXT NOT NULL,
    FOREIGN KEY (machine_id, number, revision)
        REFERENCES program_revisions(machine_id, number, revision) ON DELETE CASCADE
);

CREATE INDEX program_states_by_program ON program_states (machine_id, number, id);

CREATE TABLE transfers (
    id         INTEGER PRIMARY KEY,
    at         TEXT NOT NULL,
    db_user    TEXT NOT NULL,
    host       TEXT NOT NULL,
    machine    TEXT NOT NULL,
    revision   INTEGER NOT NULL CHECK (revision >= 0),
    controller TEXT NOT NULL,
    direction  TEXT NOT NULL CHECK (direction IN ('push', 'pull')),
    result     TEXT NOT NULL CHECK (result IN ('ok', 'partial', 'failed')),
    detail     TEXT NOT NULL
);

CREATE INDEX transfers_by_machine ON transfers (machine, id);

CREATE TABLE transfer_items (
    transfer_id INTEGER NOT NULL REFERENCES transfers(id) ON DELETE CASCADE,
    seq         INTEGER NOT NULL,
    kind        TEXT NOT NULL CHECK (kind IN ('program', 'c', 'r', 'messages')),
    number      INTEGER NOT NULL CHECK (number BETWEEN 0 AND 99),
    crc32       TEXT NOT NULL CHECK (length(crc32) = 8),
    sha256      TEXT CHECK (sha256 IS NULL OR length(sha256) = 64),
    state       TEXT NOT NULL CHECK (state IN ('new', 'as-it-was', 'in-doubt', 'read')),
    PRIMARY KEY (transfer_id, seq)
) WITHOUT ROWID;
)SQL";

constexpr std::string_view kSchemaV3Postgres = R"SQL(
ALTER TABLE transfers ALTER COLUMN db_user SET DEFAULT current_user;
ALTER TABLE transfers ENABLE ROW LEVEL SECURITY;
CREATE POLICY transfers_read ON transfers FOR SELECT USING (true);
CREATE POLICY transfers_own ON transfers FOR INSERT WITH CHECK (db_user = current_user);
ALTER TABLE transfer_items ENABLE ROW LEVEL SECURITY;
CREATE POLICY transfer_items_read ON transfer_items FOR SELECT USING (true);
CREATE POLICY transfer_items_own ON transfer_items FOR INSERT WITH CHECK (
    EXISTS (SELECT 1 FROM transfers t WHERE t.id = transfer_id AND t.db_user = current_user));
ALTER TABLE program_states ALTER COLUMN author SET DEFAULT current_user;
ALTER TABLE program_states ENABLE ROW LEVEL SECURITY;
CREATE POLICY program_states_read ON program_states FOR SELECT USING (true);
CREATE POLICY program_states_own ON program_states FOR INSERT WITH CHECK (author = current_user);
)SQL";

// Version 4: the training course's graded attempts (Database::recordAttempt,
// docs/training-course.md): one row an attempt — the student, the exercise,
// the program text graded (and its SHA-256), the score, whether it passed,
// how the run ended, the cycle time and the whole grade as `k528 grade
// --json` gives it (the deductions with their text ids and arguments). Who
// recorded it is, on PostgreSQL, the server's current_user (row security,
// as for the transfers).
constexpr std::string_view kSchemaV4 = R"SQL(
CREATE TABLE training_attempts (
    id            INTEGER PRIMARY KEY,
    at            TEXT NOT NULL,
    recorded_by   TEXT NOT NULL,
    host          TEXT NOT NULL,
    student       TEXT NOT NULL CHECK (length(student) > 0),
    exercise      TEXT NOT NULL CHECK (length(exercise) > 0),
    file          TEXT NOT NULL,
    program       TEXT NOT NULL,
    sha256        TEXT NOT NULL CHECK (length(sha256) = 64),
    score         INTEGER NOT NULL CHECK (score BETWEEN 0 AND 100),
    passed        INTEGER NOT NULL CHECK (passed IN (0, 1)),
    status        TEXT NOT NULL,
    cycle_time_ms INTEGER NOT NULL CHECK (cycle_time_ms >= 0),
    grade         TEXT NOT NULL
);

CREATE INDEX training_attempts_by_student ON training_attempts (student, id);
CREATE INDEX training_attempts_by_exercise ON training_attempts (exercise, id);
)SQL";

constexpr std::string_view kSchemaV4Postgres = R"SQL(
ALTER TABLE training_attempts ALTER COLUMN recorded_by SET DEFAULT current_user;
ALTER TABLE training_attempts ENABLE ROW LEVEL SECURITY;
CREATE POLICY training_attempts_read ON training_attempts FOR SELECT USING (true);
CREATE POLICY training_attempts_own ON training_attempts FOR INSERT WITH CHECK (recorded_by = current_user);
)SQL";

// The shop's time in each state (docs/shop.md): per machine, the poller's
// local day, the poller (source) and the state, the milliseconds counted;
// pollers add to their rows (INSERT … ON CONFLICT DO UPDATE) once a minute
// and when a state changes, not at every poll.
constexpr std::string_view kSchemaV5 = R"SQL(
CREATE TABLE state_times (
    machine    TEXT NOT NULL CHECK (length(machine) > 0),
    day        TEXT NOT NULL CHECK (length(day) = 10),
    source     TEXT NOT NULL,
    state      TEXT NOT NULL CHECK (state IN ('run', 'idle', 'alarm', 'offline')),
    ms         INTEGER NOT NULL CHECK (ms >= 0),
    changed_at TEXT NOT NULL,
    PRIMARY KEY (machine, day, source, state)
) WITHOUT ROWID;
)SQL";

// Version 6: the history of one item read along one index. changes_by_key
// (machine, key, revision) becomes (machine, key, revision DESC, seq): the
// rows of a key come in the history's order (newest first), unsorted. On
// PostgreSQL, whose tables are heaps,
// the revisions' author and time also stand in an index of their own, so the
// history's join reads them from the index (the revision's settings order
// makes its table rows wide); SQLite's revisions table is that index already
// (WITHOUT ROWID, keyed by machine and revision). docs/database.md: Speed.
constexpr std::string_view kSchemaV6 = R"SQL(
DROP INDEX changes_by_key;
CREATE INDEX changes_history ON changes (machine_id, key, revision DESC, seq);
)SQL";

constexpr std::string_view kSchemaV6Postgres = R"SQL(
CREATE INDEX revisions_authors ON revisions (machine_id, revision) INCLUDE (author, at);
)SQL";

// Version 7: each recorded change carries its revision's author and time
// (written in the same transaction as the revision, from the same values),
// so the history of one item is one range of changes_history and its table
// rows, no join with the revisions. The rows of version 6 take them from
// their revisions; the empty default only stands until that UPDATE. On
// PostgreSQL the revisions' authors index of version 6 served only that
// join: dropped. docs/database.md: Speed.
constexpr std::string_view kSchemaV7 = R"SQL(
ALTER TABLE changes ADD COLUMN author TEXT NOT NULL DEFAULT '';
ALTER TABLE changes ADD COLUMN at TEXT NOT NULL DEFAULT '';
UPDATE changes SET (author, at) = (SELECT r.author, r.at FROM revisions r
                                    WHERE r.machine_id = changes.machine_id
                                      AND r.revision = changes.revision);
)SQL";

constexpr std::string_view kSchemaV7Postgres = R"SQL(
DROP INDEX revisions_authors;
)SQL";

// Version 8: the history of one item read from the index alone. On
// PostgreSQL changes_history carries the columns the history reads (INCLUDE:
// not part of the key, stored beside it), so its rows come from one range of
// the index in the history's order, whatever order the table's heap holds
// them in — a shop's own revisions interleave every machine's changes in the
// heap, one page a row of the history; the index keeps each item's entries
// together. The index-only scan reads the table only for pages the
// visibility map does not know as all-visible: PostgresStore::open vacuums
// `changes` after an upgrade, autovacuum after new revisions — from
// PostgreSQL 13 on, after every 1000 changes written rather than after a
// fifth of the table (its default for a table only added to, which would
// leave a large shop's newest months of history to be read from the
// table); such a vacuum only reads the pages written since. The entries'
// size stays within the index's row limit (2704 bytes): a setting's value is
// at most 200 characters, a title 120, an author 256 bytes, and PostgreSQL
// compresses the longer ones. SQLite: the version only. Its changes table is
// clustered by machine and revision already (WITHOUT ROWID), so one
// machine's history lies together in it; a covering index there would double
// the table's pages in the file that every open checks whole.
// docs/database.md: Speed.
constexpr std::string_view kSchemaV8Postgres = R"SQL(
DROP INDEX changes_history;
CREATE INDEX changes_history ON changes (machine_id, key, revision DESC, seq)
    INCLUDE (section, label, before, after, author, at);
DO $$
BEGIN
    IF current_setting('server_version_num')::int >= 130000 THEN
        ALTER TABLE changes SET (autovacuum_vacuum_insert_threshold = 1000,
                                 autovacuum_vacuum_insert_scale_factor = 0);
    END IF;
END $$;
)SQL";

// Version 9: the whole history of each item (machine and key) in one row
// of its own, kept beside `changes` by the transaction that writes a
// revision (each change appended to its item's row). The history of one
// item — the constants dock's, `k528 db show --history` — is then one row
// read by its key and sent as one value: on PostgreSQL each of the
// hundreds of rows of `changes` cost the server a scan step and a row
// formatted and sent, more than the rest of the call together. `entries`:
// each change's revision, seq, author, at, section, label, before and
// after, in that order, each written as its length in bytes, ':' and its
// bytes, or '-' for none (sql_history.cpp writes and reads it). The rows
// of the changes made before are built here from them (in any order: the
// reader orders them by revision and seq). docs/database.md: Speed.
constexpr std::string_view kSchemaV9 = R"SQL(
CREATE TABLE item_history (
    machine_id INTEGER NOT NULL REFERENCES machines(id) ON DELETE CASCADE,
    key        TEXT NOT NULL,
    entries    TEXT NOT NULL,
    PRIMARY KEY (machine_id, key)
) WITHOUT ROWID;
)SQL";

constexpr std::string_view kSchemaV9Sqlite = R"SQL(
INSERT INTO item_history (machine_id, key, entries)
SELECT machine_id, key, group_concat(
    length(CAST(revision AS TEXT)) || ':' || revision ||
    length(CAST(seq AS TEXT)) || ':' || seq ||
    length(CAST(author AS BLOB)) || ':' || author ||
    length(CAST(at AS BLOB)) || ':' || at ||
    length(CAST(section AS BLOB)) || ':' || section ||
    length(CAST(label AS BLOB)) || ':' || label ||
    CASE WHEN before IS NULL THEN '-' ELSE length(CAST(before AS BLOB)) || ':' || before END ||
    CASE WHEN after IS NULL THEN '-' ELSE length(CAST(after AS BLOB)) || ':' || after END, '')
FROM changes GROUP BY machine_id, key;
)SQL";

// The roles of `k528 db roles`, when set up before: the new table's rights
// as the other tables of the history have them.
constexpr std::string_view kSchemaV9Postgres = R"SQL(
INSERT INTO item_history (machine_id, key, entries)
SELECT machine_id, key, string_agg(
    octet_length(revision::text) || ':' || revision ||
    octet_length(seq::text) || ':' || seq ||
    octet_length(author) || ':' || author ||
    octet_length(at) || ':' || at ||
    octet_length(section) || ':' || section ||
    octet_length(label) || ':' || label ||
    CASE WHEN before IS NULL THEN '-' ELSE octet_length(before) || ':' || before END ||
    CASE WHEN after IS NULL THEN '-' ELSE octet_length(after) || ':' || after END, ''
    ORDER BY revision, seq)
FROM changes GROUP BY machine_id, key;
DO $$
BEGIN
    IF EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'k528_viewer') THEN
        GRANT SELECT ON item_history TO k528_viewer;
    END IF;
    IF EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'k528_technologist') THEN
        GRANT INSERT, UPDATE, DELETE ON item_history TO k528_technologist;
    END IF;
END $$;
)SQL";

const Migration kMigrations[] = {
    {1,
     "machines, C-parameter definitions and values, R presets, programs with revisions, "
     "messages, PLC texts, settings, history, audit log",
     kSchemaV1, kSchemaV1Sqlite, kSchemaV1Postgres},
    {2, "message history: every message of the positioner and the PLC, acknowledged when and how",
     kSchemaV2},
    {3, "programs released for the controllers; the transfer log", kSchemaV3, {},
     kSchemaV3Postgres},
    {4, "the training course's graded attempts", kSchemaV4, {}, kSchemaV4Postgres},
    {5, "the shop's time in each state per machine and day", kSchemaV5},
    {6, "the history of one item read along one index", kSchemaV6, {}, kSchemaV6Postgres},
    {7, "each change keeps its revision's author and time: the history without a join",
     kSchemaV7, {}, kSchemaV7Postgres},
    {8, "the history of one item read from its index alone", {}, {}, kSchemaV8Postgres},
    {9, "the whole history of each item in one row", kSchemaV9, kSchemaV9Sqlite, kSchemaV9Postgres},
};

bool wordAt(std::string_view s, std::size_t i, std::string_view word) {
    const auto isWord = [](char c) {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    };
    return s.substr(i, word.size()) == word && (i == 0 || !isWord(s[i - 1])) &&
           (i + word.size() >= s.size() || !isWord(s[i + word.size()]));
}

} // namespace

std::string postgresSchemaSql(std::string_view sql) {
    static constexpr std::pair<std::string_view, std::string_view> kWords[] = {
        {"INTEGER PRIMARY KEY AUTOINCREMENT", "BIGINT GENERATED BY DEFAULT AS IDENTITY PRIMARY KEY"},
        {"INTEGER PRIMARY KEY", "BIGINT GENERATED BY DEFAULT AS IDENTITY PRIMARY KEY"},
        {"INTEGER", "BIGINT"},
        {" WITHOUT ROWID", ""},
    };
    std::string out;
    out.reserve(sql.size() + sql.size() / 8);
    bool quoted = false; // inside '…': copied as it is
    for (std::size_t i = 0; i < sql.size();) {
        if (!quoted && sql.substr(i, 2) == "--") { // a comment: to the end of its line
            const std::size_t end = std::min(sql.find('\n', i), sql.size());
            out += sql.substr(i, end - i);
            i = end;
            continue;
        }
        if (sql[i] == '\'') {
            quoted = !quoted;
            out += sql[i++];
            continue;
        }
        bool replaced = false;
        if (!quoted)
            for (const auto& [from, to] : kWords)
                if (wordAt(sql, from[0] == ' ' ? i + 1 : i, from[0] == ' ' ? from.substr(1) : from) &&
                    (from[0] != ' ' || sql[i] == ' ')) {
                    out += to;
                    i += from.size();
                    replaced = true;
                    break;
                }
        if (!replaced)
            out += sql[i++];
    }
    return out;
}

std::span<const Migration> schemaMigrations() {
    return kMigrations;
}

int latestSchemaVersion() {
    return kMigrations[std::size(kMigrations) - 1].version;
}

} // namespace k528::db
