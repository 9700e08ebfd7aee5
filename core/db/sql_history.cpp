// The history of both backends: revisions, the changes each recorded and
// every version of every program.
#include "db/sha256.h"
#include "db/sql_store.h"

#include <algorithm>
#include <charconv>
#include <map>

namespace k528::db {

namespace {

// An entry of item_history (schema version 9): revision, seq, author, at,
// section, label, before, after, each as its length in bytes, ':' and its
// bytes, or '-' for none — what the schema's migration builds with SQL from
// the changes written before.
void appendField(std::string& out, std::string_view v) {
    char digits[24];
    const auto [end, ec] = std::to_chars(digits, digits + sizeof digits, v.size());
    out.append(digits, end);
    out += ':';
    out.append(v);
}

void appendOptField(std::string& out, const std::optional<std::string>& v) {
    if (v)
        appendField(out, std::string_view(*v));
    else
        out += '-';
}

std::string itemEntry(int revision, int seq, std::string_view author, std::string_view at,
                      std::string_view section, std::string_view label,
                      const std::optional<std::string>& before,
                      const std::optional<std::string>& after) {
    std::string out;
    appendField(out, std::to_string(revision));
    appendField(out, std::to_string(seq));
    appendField(out, author);
    appendField(out, at);
    appendField(out, section);
    appendField(out, label);
    appendOptField(out, before);
    appendOptField(out, after);
    return out;
}

// The next field of `s` (consumed): false when `s` does not begin with one.
bool readField(std::string_view& s, std::optional<std::string_view>& field) {
    if (!s.empty() && s.front() == '-') {
        field.reset();
        s.remove_prefix(1);
        return true;
    }
    std::size_t n = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    const std::size_t at = static_cast<std::size_t>(end - s.data()) + 1; // after the ':'
    if (ec != std::errc() || end == s.data() + s.size() || *end != ':' || s.size() - at < n)
        return false;
    field = s.substr(at, n);
    s.remove_prefix(at + n);
    return true;
}

bool readInt(std::string_view& s, int& v) {
    std::optional<std::string_view> f;
    if (!readField(s, f) || !f)
        return false;
    const auto [end, ec] = std::from_chars(f->data(), f->data() + f->size(), v);
    return ec == std::errc() && end == f->data() + f->size();
}

bool readText(std::string_view& s, std::string& v) {
    std::optional<std::string_view> f;
    if (!readField(s, f) || !f)
        return false;
    v.assign(*f);
    return true;
}

bool readOptText(std::string_view& s, std::optional<std::string>& v) {
    std::optional<std::string_view> f;
    if (!readField(s, f))
        return false;
    if (f)
        v.emplace(*f);
    else
        v.reset();
    return true;
}

// An entry of item_history read, with its place in its revision.
struct ItemEntry {
    int seq = 0;
    ChangeRow row;
};

// An item's entries, the oldest first (by revision and seq); nullopt when
// they are not in their form. Written in that order, one revision after the
// other, or in any order by the migration that built them.
std::optional<std::vector<ItemEntry>> readEntries(std::string_view s, const std::string& key) {
    std::vector<ItemEntry> entries;
    while (!s.empty()) {
        ItemEntry e;
        if (!readInt(s, e.row.revision) || !readInt(s, e.seq) || !readText(s, e.row.author) ||
            !readText(s, e.row.at) || !readText(s, e.row.section) || !readText(s, e.row.label) ||
            !readOptText(s, e.row.before) || !readOptText(s, e.row.after))
            return std::nullopt;
        e.row.key = key;
        entries.push_back(std::move(e));
    }
    const auto oldestFirst = [](const ItemEntry& a, const ItemEntry& b) {
        return a.row.revision != b.row.revision ? a.row.revision < b.row.revision : a.seq < b.seq;
    };
    if (!std::is_sorted(entries.begin(), entries.end(), oldestFirst))
        std::stable_sort(entries.begin(), entries.end(), oldestFirst);
    return entries;
}

// The same in the history's order: the newest revision first, a revision's
// changes in their order.
std::optional<std::vector<ChangeRow>> itemEntries(std::string_view s, const std::string& key) {
    auto entries = readEntries(s, key);
    if (!entries)
        return std::nullopt;
    std::vector<ChangeRow> out;
    out.reserve(entries->size());
    for (std::size_t end = entries->size(); end > 0;) {
        std::size_t begin = end - 1;
        while (begin > 0 && (*entries)[begin - 1].row.revision == (*entries)[end - 1].row.revision)
            --begin;
        for (std::size_t i = begin; i < end; ++i)
            out.push_back(std::move((*entries)[i].row));
        end = begin;
    }
    return out;
}

} // namespace

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
    if (!itemHistoryKept())
        return;
    auto& h = query("INSERT INTO item_history (machine_id, key, entries) VALUES (?1, ?2, ?3) ON "
                    "CONFLICT (machine_id, key) DO UPDATE SET entries = item_history.entries || "
                    "excluded.entries");
    h.bind(1, id).bind(2, c.key).bind(3, itemEntry(revision, seq, author, at,
                                                   profile::diffSectionName(c.section), c.label,
                                                   c.before, c.after));
    connection().runLater(h);
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
    const bool limited = limitRevisions > 0;
    if (key && !limited && itemHistoryKept()) {
        // The item's whole history: its one row, one value sent (schema
        // version 9) rather than a row of changes for each entry.
        auto& q = query("SELECT h.entries FROM item_history h WHERE h.machine_id = (SELECT id FROM "
                        "machines WHERE name = ?1) AND h.key = ?2");
        q.bind(1, name).bind(2, *key);
        // No row: no such machine, or no such item. A row not in its form
        // (SQL that altered it; checkIntegrity names it): the history is
        // still there in the changes. The caller then reads those.
        if (!q.step())
            return std::nullopt;
        const std::string entries = q.text(0);
        q.reset();
        return itemEntries(entries, *key);
    }
    // The machine's row and its changes in one statement.
    static const std::string kTexts[2][2] = {
        {historyByNameText(false, false), historyByNameText(false, true)},
        {historyByNameText(true, false), historyByNameText(true, true)}};
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

std::vector<IntegrityProblem> SqlStore::checkRows() {
    using K = IntegrityProblem::Kind;
    std::vector<IntegrityProblem> problems;
    const auto add = [&](K kind, std::vector<std::string> args) { problems.push_back({kind, std::move(args)}); };
    {
        auto& q = query("SELECT m.name, p.number, p.revision, p.text, p.sha256 FROM "
                        "program_revisions p JOIN machines m ON m.id = p.machine_id WHERE "
                        "p.text IS NOT NULL ORDER BY m.name, p.number, p.revision");
        while (q.step())
            if (sha256Hex(q.text(3)) != q.text(4))
                add(K::ProgramChecksum, {q.text(0), std::to_string(q.i32(1)), std::to_string(q.i32(2))});
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
            add(K::ChangeAuthors, {q.text(0), std::to_string(q.i32(1)), std::to_string(q.i64(2))});
    }
    if (itemHistoryKept()) {
        // Each item's row of item_history holds its changes, no more, no
        // fewer, as they are: SQL that changed one and not the other would
        // show a history that is not the revisions'.
        std::map<std::pair<std::string, std::string>, std::string> expected;
        auto& c = query("SELECT m.name, c.key, c.revision, c.seq, c.author, c.at, c.section, "
                        "c.label, c.before, c.after FROM changes c JOIN machines m ON m.id = "
                        "c.machine_id ORDER BY c.machine_id, c.key, c.revision, c.seq");
        while (c.step())
            expected[{c.text(0), c.text(1)}] += itemEntry(
                c.i32(2), c.i32(3), c.text(4), c.text(5), c.text(6), c.text(7), c.optText(8),
                c.optText(9));
        auto& h = query("SELECT m.name, h.key, h.entries FROM item_history h JOIN machines m ON "
                        "m.id = h.machine_id ORDER BY m.name, h.key");
        while (h.step()) {
            const std::string name = h.text(0), key = h.text(1);
            std::string kept;
            if (const auto entries = readEntries(h.text(2), key))
                for (const ItemEntry& e : *entries)
                    kept += itemEntry(e.row.revision, e.seq, e.row.author, e.row.at,
                                      e.row.section, e.row.label, e.row.before, e.row.after);
            const auto it = expected.find({name, key});
            if (it == expected.end() || it->second != kept)
                add(K::ItemHistoryDiffers, {name, key});
            if (it != expected.end())
                expected.erase(it);
        }
        for (const auto& [item, entries] : expected)
            add(K::ItemHistoryMissing, {item.first, item.second});
    }
    auto& r = query("SELECT m.name, m.revision, (SELECT max(r.revision) FROM revisions r WHERE "
                    "r.machine_id = m.id), (SELECT count(*) FROM revisions r WHERE r.machine_id = "
                    "m.id) FROM machines m ORDER BY m.name");
    while (r.step())
        if (r.i64(1) != r.i64(2) || r.i64(1) != r.i64(3))
            add(K::Revisions, {r.text(0), std::to_string(r.i64(1)), std::to_string(r.i64(3)),
                               std::to_string(r.i64(2))});
    return problems;
}

} // namespace k528::db
