// The profile rows of both backends: the machines and their current state —
// C values, R presets, programs (the view of their last versions), messages,
// PLC texts and simulation settings.
#include "catalog/cparams.h"
#include "db/revisions.h"
#include "db/sha256.h"
#include "db/postgres.h"
#include "db/sql_store.h"


namespace k528::db {

namespace cat = k528::catalog;
using profile::Change;
using profile::DiffSection;
using profile::MachineProfile;

std::vector<std::string> SqlStore::where(const MachineRow& row) const {
    return {row.info.name, path_.string()};
}

std::vector<MachineInfo> SqlStore::machines() {
    std::vector<MachineInfo> out;
    auto& q = query("SELECT name, title, revision, created_at, changed_at, changed_by FROM "
                  "machines ORDER BY name");
    while (q.step())
        out.push_back(MachineInfo{q.text(0), q.text(1), q.i32(2), q.text(3), q.text(4), q.text(5)});
    return out;
}

namespace {

constexpr std::string_view kFindMachine =
    "SELECT id, name, title, revision, created_at, changed_at, changed_by FROM machines WHERE "
    "name = ?1";

MachineRow machineRow(const sql::Query& q) {
    MachineRow r;
    r.id = q.i64(0);
    r.info = MachineInfo{q.text(1), q.text(2), q.i32(3), q.text(4), q.text(5), q.text(6)};
    return r;
}

// The tables of a machine's current state, in the order readCurrent reads
// them, of the machine by its id (?1).
constexpr std::string_view kCurrentById[] = {
    "SELECT number, value FROM c_values WHERE machine_id = ?1",
    "SELECT number, value FROM r_values WHERE machine_id = ?1",
    "SELECT number, text, sha256, revision FROM programs WHERE machine_id = ?1",
    "SELECT number, text FROM messages WHERE machine_id = ?1",
    "SELECT grp, number, text FROM plc_messages WHERE machine_id = ?1",
    "SELECT key, value FROM settings WHERE machine_id = ?1 ORDER BY position",
};
constexpr std::size_t kCurrentTables = std::size(kCurrentById);

// PostgreSQL: the machine's row (tag 0) and each table of kCurrentById
// (tag 1 + its index, the same columns in the same order, as texts) by the
// machine's name (?1) in one statement — one snapshot of its own, no
// transaction around it, one plan and one execution on the server instead
// of eight. Rows of each table come in that table's order (settings sorted
// by position inside its branch); the tables may come in any order. The
// current programs (the view `programs`: each number's newest version unless
// deleted) are read as one backward scan of program_revisions' index here
// rather than the view's probe for the newest revision of every number, and
// the server compares each text with its SHA-256 (a fifth column, `true`
// when they match: sha256() of PostgreSQL 11, OpenSSL's) where the client
// would hash every text again on its side of the connection. The C values
// and R presets (two integers a row, 421 rows of a full machine) come packed
// as one text each, "n v n v …" (sql::IntegerPairs): a row of the result
// costs both sides more than its two numbers.
constexpr std::string_view kLoadNamedPostgres =
    "WITH m AS (SELECT id, name, title, revision, created_at, changed_at, changed_by FROM machines "
    "WHERE name = ?1) "
    "SELECT 0, id::text, name, title, revision::text, created_at, changed_at, changed_by FROM m "
    "UNION ALL SELECT 1, string_agg(number::text || ' ' || value::text, ' '), NULL, NULL, NULL, "
    "NULL, NULL, NULL FROM c_values WHERE machine_id = (SELECT id FROM m) "
    "UNION ALL SELECT 2, string_agg(number::text || ' ' || value::text, ' '), NULL, NULL, NULL, "
    "NULL, NULL, NULL FROM r_values WHERE machine_id = (SELECT id FROM m) "
    "UNION ALL SELECT 3, number::text, text, sha256, revision::text, "
    "(encode(sha256(convert_to(text, 'UTF8')), 'hex') = sha256)::text, NULL, NULL FROM "
    "(SELECT DISTINCT ON (number) number, text, sha256, revision FROM program_revisions "
    "WHERE machine_id = (SELECT id FROM m) ORDER BY number DESC, revision DESC) p "
    "WHERE text IS NOT NULL "
    "UNION ALL SELECT 4, number::text, text, NULL, NULL, NULL, NULL, NULL FROM messages "
    "WHERE machine_id = (SELECT id FROM m) "
    "UNION ALL SELECT 5, grp, number::text, text, NULL, NULL, NULL, NULL FROM plc_messages "
    "WHERE machine_id = (SELECT id FROM m) "
    "UNION ALL (SELECT 6, key, value, NULL, NULL, NULL, NULL, NULL FROM settings "
    "WHERE machine_id = (SELECT id FROM m) ORDER BY position)";

} // namespace

std::optional<MachineRow> SqlStore::findMachine(std::string_view name) {
    auto& q = query(kFindMachine);
    q.bind(1, name);
    if (!q.step())
        return std::nullopt;
    MachineRow r = machineRow(q);
    q.reset();
    return r;
}

MachineProfile SqlStore::loadCurrent(const MachineRow& row) {
    sql::Query* queries[kCurrentTables];
    for (std::size_t i = 0; i < kCurrentTables; ++i)
        queries[i] = &query(kCurrentById[i]).bind(1, row.id);
    connection().runTogether(queries); // one round trip on PostgreSQL
    return readCurrent(row, queries);
}

std::optional<LoadedMachine> SqlStore::loadNamed(std::string_view name) {
    if (connection().dialect() == sql::Dialect::Sqlite) { // no round trips to save
        ReadSnapshot tx(*this);                            // seven statements, one snapshot
        auto row = findMachine(name);
        if (!row)
            return std::nullopt;
        MachineProfile p = loadCurrent(*row);
        return LoadedMachine{std::move(*row), std::move(p)};
    }
    // The machine's row and its tables in one statement, each row tagged
    // with its part.
    auto& q = static_cast<sql::PgQuery&>(query(kLoadNamedPostgres)); // this connection's
    q.bind(1, name);
    q.runNow();
    sql::PgPart find(q, 0);
    if (!find.step()) {
        q.reset();
        return std::nullopt;
    }
    MachineRow row = machineRow(find);
    std::optional<sql::PgPart> parts[kCurrentTables];
    std::optional<sql::IntegerPairs> pairs[2]; // the C values and R presets, packed
    sql::Query* queries[kCurrentTables];
    for (std::size_t i = 0; i < kCurrentTables; ++i)
        queries[i] = &parts[i].emplace(q, static_cast<int>(1 + i));
    for (std::size_t i = 0; i < 2; ++i) {
        sql::PgPart& packed = *parts[i];
        std::string text = packed.step() && !packed.isNull(0) ? packed.text(0) : std::string();
        queries[i] = &pairs[i].emplace(std::move(text), i == 0 ? "corrupt.c-values" : "corrupt.r-presets",
                                       where(row));
    }
    MachineProfile p = readCurrent(row, queries);
    q.reset(); // the rows (the programs' texts) are not kept
    return LoadedMachine{std::move(row), std::move(p)};
}

MachineProfile SqlStore::readCurrent(const MachineRow& row, std::span<sql::Query* const> queries) {
    MachineProfile p;
    p.name = row.info.name;
    p.title = row.info.title;
    // The machine and the file, then what is wrong.
    const auto corrupt = [&](std::string id, std::vector<std::string> args) {
        std::vector<std::string> all = where(row);
        all.insert(all.end(), args.begin(), args.end());
        return Error(ErrorKind::Corrupt, ErrorText{std::move(id), std::move(all)});
    };
    // Each row of table i (of kCurrentById).
    const auto rows = [&](std::size_t i, const auto& take) {
        sql::Query& q = *queries[i];
        while (q.step())
            take(q);
        q.reset(); // its rows (the programs' texts) are not kept
    };
    int count = 0;
    rows(0, [&](const sql::Query& q) {
        const int n = q.i32(0);
        if (n < 1 || n > cat::kCParamCount)
            throw corrupt("corrupt.c-number", {std::to_string(n)});
        p.c[static_cast<std::size_t>(n)] = q.i64(1);
        ++count;
    });
    if (count != cat::kCParamCount)
        throw corrupt("corrupt.c-count", {std::to_string(count)});
    rows(1,
         [&](const sql::Query& q) { p.r[q.i32(0)] = q.i64(1); });
    // The programs' texts against their SHA-256: here, or by the backend
    // that read them when it says so (a fifth column: `true` or `false`).
    rows(2,
         [&](const sql::Query& q) {
             std::string text = q.text(1);
             const bool checked = q.columns() > 4 && !q.isNull(4);
             if (checked ? q.text(4) != "true" : sha256Hex(text) != q.text(2))
                 throw corrupt("corrupt.current-program", {std::to_string(q.i32(0)), std::to_string(q.i32(3))});
             p.programs[q.i32(0)] = std::move(text);
         });
    rows(3,
         [&](const sql::Query& q) { p.messages[q.i32(0)] = q.text(1); });
    rows(4, [&](const sql::Query& q) {
        const std::string g = q.text(0);
        const auto group = revision::plcGroupOf(g.empty() ? '?' : g[0]);
        if (!group)
            throw corrupt("corrupt.plc-group", {g});
        p.plcTexts(*group)[q.i32(1)] = q.text(2);
    });
    rows(5,
         [&](const sql::Query& q) {
             try {
                 p.simulation.set(q.text(0), q.text(1));
             } catch (const profile::SettingError&) {
                 throw corrupt("corrupt.setting", {q.text(0), q.text(1)});
             }
         });
    return p;
}

std::int64_t SqlStore::insertMachine(const MachineProfile& p, const std::string& at,
                                        const std::string& author) {
    auto& q = query("INSERT INTO machines (name, title, revision, created_at, changed_at, "
                    "changed_by) VALUES (?1, ?2, 1, ?3, ?3, ?4) RETURNING id");
    q.bind(1, p.name).bind(2, p.title).bind(3, at).bind(4, author);
    if (!q.step())
        throw sql::internalError("the new machine's row has no id", path_.string());
    const std::int64_t id = q.i64(0);
    q.reset();
    return id;
}

void SqlStore::updateMachine(std::int64_t id, const MachineProfile& p, int revision,
                                const std::string& at, const std::string& author) {
    auto& q = query("UPDATE machines SET name = ?2, title = ?3, revision = ?4, changed_at = ?5, "
                  "changed_by = ?6 WHERE id = ?1");
    q.bind(1, id).bind(2, p.name).bind(3, p.title).bind(4, revision).bind(5, at).bind(6, author);
    connection().runLater(q);
}

void SqlStore::deleteMachine(std::int64_t id) {
    auto& q = query("DELETE FROM machines WHERE id = ?1");
    q.bind(1, id);
    connection().runLater(q);
}

void SqlStore::writeItem(std::int64_t id, bool isNew, const MachineProfile& p, const Change& c) {
    const auto num = revision::keyNumber(c.key);
    switch (c.section) {
    case DiffSection::Machine:    // the machines row (updateMachine)
    case DiffSection::Program:    // its versions (insertProgramVersion)
    case DiffSection::Simulation: // written whole (writeSettings)
        return;
    case DiffSection::C: {
        auto& q = query(isNew ? "INSERT INTO c_values (machine_id, number, value) VALUES (?1, ?2, ?3)"
                            : "UPDATE c_values SET value = ?3 WHERE machine_id = ?1 AND number = ?2");
        q.bind(1, id).bind(2, *num).bind(3, p.cValue(*num));
        connection().runLater(q);
        return;
    }
    case DiffSection::R:
    case DiffSection::Message:
    case DiffSection::PlcMessage:
        break;
    }
    // An R preset, a message or a PLC text: its row set, or removed with the item.
    const bool plc = c.section == DiffSection::PlcMessage;
    const char* sql = nullptr;
    if (c.section == DiffSection::R)
        sql = c.after ? "INSERT INTO r_values (machine_id, number, value) VALUES (?1, ?2, ?3) "
                        "ON CONFLICT (machine_id, number) DO UPDATE SET value = excluded.value"
                      : "DELETE FROM r_values WHERE machine_id = ?1 AND number = ?2";
    else if (!plc)
        sql = c.after ? "INSERT INTO messages (machine_id, number, text) VALUES (?1, ?2, ?3) "
                        "ON CONFLICT (machine_id, number) DO UPDATE SET text = excluded.text"
                      : "DELETE FROM messages WHERE machine_id = ?1 AND number = ?2";
    else
        sql = c.after ? "INSERT INTO plc_messages (machine_id, number, grp, text) VALUES "
                        "(?1, ?2, ?4, ?3) ON CONFLICT (machine_id, grp, number) DO UPDATE "
                        "SET text = excluded.text"
                      : "DELETE FROM plc_messages WHERE machine_id = ?1 AND number = ?2 AND grp = ?4";
    auto& q = query(sql);
    q.bind(1, id).bind(2, *num);
    if (c.after && c.section == DiffSection::R)
        q.bind(3, p.r.at(*num));
    else if (c.after)
        q.bind(3, *c.after);
    if (plc)
        q.bind(4, c.key.substr(0, 1));
    connection().runLater(q);
}

void SqlStore::writeSettings(std::int64_t id, const MachineProfile& p) {
    auto& del = query("DELETE FROM settings WHERE machine_id = ?1");
    del.bind(1, id);
    connection().runLater(del);
    auto& q = query("INSERT INTO settings (machine_id, position, key, value) VALUES (?1, ?2, ?3, ?4)");
    int pos = 0;
    for (const auto& [k, v] : p.simulation.entries()) {
        q.reset();
        q.bind(1, id).bind(2, pos++).bind(3, k).bind(4, v);
        connection().runLater(q);
    }
}

} // namespace k528::db
