// The history of both backends: revisions, the changes each recorded and
// every version of every program.
#include "db/sha256.h"
#include "db/sql_store.h"


namespace k528::db {

void SqlStore::insertRevision(std::int64_t id, int revision, const std::string& author,
                                 const std::string& at, const std::string& summary,
                                 const std::string& settingsOrder) {
    auto& q = query("INSERT INTO revisions (machine_id, revision, author, at, summary, "
                  "settings_order) VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
    q.bind(1, id).bind(2, revision).bind(3, author).bind(4, at).bind(5, summary).bind(6, settingsOrder);
    connection().runLater(q);
}

void SqlStore::insertProgramVersion(std::int64_t id, const ProgramRow& v) {
    auto& q = query("INSERT INTO program_revisions (machine_id, number, revision, text, "
                  "sha256) VALUES (?1, ?2, ?3, ?4, ?5)");
    q.bind(1, id).bind(2, v.number).bind(3, v.revision).bind(4, v.text).bind(5, v.sha256);
    connection().runLater(q);
}

void SqlStore::insertChange(std::int64_t id, int revision, int seq, const std::string& author,
                            const std::string& at, const profile::Change& c) {
    auto& q = changesKeepAuthors()
                  ? query("INSERT INTO changes (machine_id, revision, seq, section, key, label, "
                          "before, after, author, at) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, "
                          "?10)")
                  : query("INSERT INTO changes (machine_id, revision, seq, section, key, label, "
                          "before, after) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)");
    q.bind(1, id)
        .bind(2, revision)
        .bind(3, seq)
        .bind(4, profile::diffSectionName(c.section))
        .bind(5, c.key)
        .bind(6, c.label)
        .bind(7, c.before)
        .bind(8, c.after);
    if (changesKeepAuthors())
        q.bind(9, author).bind(10, at);
    connection().runLater(q);
}

std::vector<ChangeRow> SqlStore::changesUpTo(std::int64_t id, int revision) {
    auto& q = query("SELECT section, key, after, revision FROM changes WHERE machine_id = ?1 AND "
                  "revision <= ?2 AND section <> 'program' ORDER BY revision, seq");
    q.bind(1, id).bind(2, revision);
    std::vector<ChangeRow> out;
    while (q.step()) {
        ChangeRow r;
        r.section = q.text(0);
        r.key = q.text(1);
        r.after = q.optText(2);
        r.revision = q.i32(3);
        out.push_back(std::move(r));
    }
    return out;
}

std::optional<std::string> SqlStore::settingsOrder(std::int64_t id, int revision) {
    auto& q = query("SELECT settings_order FROM revisions WHERE machine_id = ?1 AND revision = ?2");
    q.bind(1, id).bind(2, revision);
    if (!q.step())
        return std::nullopt;
    std::string order = q.text(0);
    q.reset();
    return order;
}

std::vector<ProgramRow> SqlStore::programsAt(std::int64_t id, int revision) {
    auto& q = query("SELECT p.number, p.text, p.sha256, p.revision FROM program_revisions p "
                  "WHERE p.machine_id = ?1 AND p.revision = (SELECT max(q.revision) FROM "
                  "program_revisions q WHERE q.machine_id = p.machine_id AND q.number = "
                  "p.number AND q.revision <= ?2) AND p.text IS NOT NULL");
    q.bind(1, id).bind(2, revision);
    std::vector<ProgramRow> out;
    while (q.step())
        out.push_back(ProgramRow{q.i32(0), q.i32(3), q.optText(1), q.optText(2)});
    return out;
}

std::vector<RevisionInfo> SqlStore::revisions(std::int64_t id) {
    auto& q = query("SELECT r.revision, r.author, r.at, r.summary, (SELECT count(*) FROM changes c "
                  "WHERE c.machine_id = r.machine_id AND c.revision = r.revision) FROM "
                  "revisions r WHERE r.machine_id = ?1 ORDER BY r.revision DESC");
    q.bind(1, id);
    std::vector<RevisionInfo> out;
    while (q.step())
        out.push_back(RevisionInfo{q.i32(0), q.text(1), q.text(2), q.text(3), q.i32(4)});
    return out;
}

namespace {

// The changes with their revisions' author and time (schema version 7: kept
// in each change); the machine by its id (?1, from revision ?2 on) or by its
// name (?1, of its last ?2 revisions). Two texts each rather than "(?3 IS
// NULL OR c.key = ?3)": each backend then plans one of them with the index
// on (machine, key, revision DESC, seq) — one range of it, in the history's
// order, no join and no sort.
constexpr std::string_view kHistorySelect =
    "SELECT c.revision, c.author, c.at, c.section, c.key, c.label, c.before, c.after FROM "
    "changes c ";
constexpr std::string_view kById = "WHERE c.machine_id = ?1 AND c.revision >= ?2";
constexpr std::string_view kOfKey = " AND c.key = ?3";
constexpr std::string_view kOrder = " ORDER BY c.revision DESC, c.seq";

// Before version 7 (an older database read as it is), from the revisions.
constexpr std::string_view kHistorySelectJoined =
    "SELECT c.revision, r.author, r.at, c.section, c.key, c.label, c.before, c.after FROM "
    "changes c JOIN revisions r ON r.machine_id = c.machine_id AND r.revision = c.revision ";

std::string historyText(bool ofKey, bool joined) {
    return std::string(joined ? kHistorySelectJoined : kHistorySelect) + std::string(kById) +
           (ofKey ? std::string(kOfKey) : std::string()) + std::string(kOrder);
}

// By the machine's name (?1): one statement (one snapshot, no transaction
// needed); no rows when there is no such machine or it has no such changes.
// The machine's id (and for the last ?2 revisions its revision) as
// subqueries of its unique name, each run once before the changes are read,
// rather than a join: the server then knows the one machine and reads the
// range of changes_history in the history's order, without a sort. Each
// part the server has no need of is left out, as each costs it work for
// every one of the (hundreds of) rows: of the whole history, the bound on
// the revision (the second subquery, and a third condition the scan checks
// on every index entry); of one item's history, its key (the caller's own,
// filled in by historyRows) — each row formatted and sent with one field
// fewer. The item's key is then ?2 (whole history) or ?3 (last revisions).
std::string historyByNameText(bool ofKey, bool limited) {
    return std::string("SELECT c.revision, c.author, c.at, c.section, ") +
           (ofKey ? "" : "c.key, ") +
           "c.label, c.before, c.after FROM changes c "
           "WHERE c.machine_id = (SELECT id FROM machines WHERE name = ?1)" +
           (limited ? " AND c.revision > (SELECT revision FROM machines WHERE name = ?1) - ?2"
                    : "") +
           (ofKey ? (limited ? " AND c.key = ?3" : " AND c.key = ?2") : "") + std::string(kOrder);
}

// The rows of a history statement: revision, author, at, section, key,
// label, before, after — without the key when `key` is given (it is each
// row's).
std::vector<ChangeRow> historyRows(sql::Query& q, const std::optional<std::string>& key = {}) {
    std::vector<ChangeRow> out;
    const int k = key ? 0 : 1; // columns after the section: one fewer without the key
    while (q.step())
        out.push_back(ChangeRow{q.i32(0), q.text(1), q.text(2), q.text(3), key ? *key : q.text(4),
                                q.text(4 + k), q.optText(5 + k), q.optText(6 + k)});
    q.reset();
    return out;
}

} // namespace

std::vector<ChangeRow> SqlStore::history(std::int64_t id, int fromRevision,
                                         const std::optional<std::string>& key) {
    static const std::string kAll = historyText(false, false);
    static const std::string kKey = historyText(true, false);
    static const std::string kAllJoined = historyText(false, true);
    static const std::string kKeyJoined = historyText(true, true);
    auto& q = changesKeepAuthors() ? query(key ? kKey : kAll) : query(key ? kKeyJoined : kAllJoined);
    q.bind(1, id).bind(2, fromRevision);
    if (key)
        q.bind(3, *key);
    return historyRows(q);
}

std::optional<std::vector<ChangeRow>> SqlStore::historyNamed(std::string_view name,
                                                             int limitRevisions,
                                                             const std::optional<std::string>& key) {
    if (connection().dialect() == sql::Dialect::Sqlite || // no round trips to save
        !changesKeepAuthors()) {                            // or an older database
        ReadSnapshot tx(*this);                            // two statements, one snapshot
        const auto row = findMachine(name);
        if (!row)
            return std::nullopt;
        return history(row->id,
                       limitRevisions > 0 ? row->info.revision - limitRevisions + 1 : 1, key);
    }
    // The machine's row and its changes in one statement.
    static const std::string kTexts[2][2] = {
        {historyByNameText(false, false), historyByNameText(false, true)},
        {historyByNameText(true, false), historyByNameText(true, true)}};
    const bool limited = limitRevisions > 0;
    auto& q = query(kTexts[key ? 1 : 0][limited ? 1 : 0]);
    q.bind(1, name);
    int next = 2;
    if (limited)
        q.bind(next++, limitRevisions);
    if (key)
        q.bind(next, *key);
    std::vector<ChangeRow> out = historyRows(q, key);
    if (out.empty()) // no such machine, or none of its changes: the caller asks again
        return std::nullopt;
    return out;
}

std::vector<ProgramRow> SqlStore::programVersions(std::int64_t id, int number) {
    auto& q = query("SELECT revision, text, sha256 FROM program_revisions WHERE machine_id = ?1 "
                  "AND number = ?2 ORDER BY revision DESC");
    q.bind(1, id).bind(2, number);
    std::vector<ProgramRow> out;
    while (q.step())
        out.push_back(ProgramRow{number, q.i32(0), q.optText(1), q.optText(2)});
    return out;
}

std::optional<ProgramRow> SqlStore::programAt(std::int64_t id, int number, int revision) {
    auto& q = query("SELECT revision, text, sha256 FROM program_revisions WHERE machine_id = ?1 AND "
                  "number = ?2 AND revision <= ?3 ORDER BY revision DESC LIMIT 1");
    q.bind(1, id).bind(2, number).bind(3, revision);
    if (!q.step())
        return std::nullopt;
    ProgramRow r{number, q.i32(0), q.optText(1), q.optText(2)};
    q.reset();
    return r;
}

std::string SqlStore::checkRows() {
    std::string problems;
    const auto add = [&](const std::string& p) {
        problems += (problems.empty() ? "" : "; ") + p;
    };
    {
        auto& q = query("SELECT m.name, p.number, p.revision, p.text, p.sha256 FROM "
                        "program_revisions p JOIN machines m ON m.id = p.machine_id WHERE "
                        "p.text IS NOT NULL ORDER BY m.name, p.number, p.revision");
        while (q.step())
            if (sha256Hex(q.text(3)) != q.text(4))
                add("machine " + q.text(0) + " program L" + std::to_string(q.i32(1)) +
                    " of revision " + std::to_string(q.i32(2)) +
                    " does not match its SHA-256 checksum");
    }
    if (changesKeepAuthors()) {
        // Each change carries its revision's author and time (copies made in
        // the revision's transaction): SQL that changed one and not the other
        // would show a history that is not the revisions'.
        auto& q = query("SELECT m.name, c.revision, count(*) FROM changes c JOIN revisions r ON "
                        "r.machine_id = c.machine_id AND r.revision = c.revision JOIN machines m "
                        "ON m.id = c.machine_id WHERE c.author <> r.author OR c.at <> r.at "
                        "GROUP BY m.name, c.revision ORDER BY m.name, c.revision");
        while (q.step())
            add("machine " + q.text(0) + " revision " + std::to_string(q.i32(1)) + ": " +
                std::to_string(q.i64(2)) +
                " of its changes do not name the revision's author and time");
    }
    auto& r = query("SELECT m.name, m.revision, (SELECT max(r.revision) FROM revisions r WHERE "
                    "r.machine_id = m.id), (SELECT count(*) FROM revisions r WHERE r.machine_id = "
                    "m.id) FROM machines m ORDER BY m.name");
    while (r.step())
        if (r.i64(1) != r.i64(2) || r.i64(1) != r.i64(3))
            add("machine " + r.text(0) + " is at revision " + std::to_string(r.i64(1)) +
                " but its history holds " + std::to_string(r.i64(3)) + " revisions up to " +
                std::to_string(r.i64(2)));
    return problems;
}

} // namespace k528::db
