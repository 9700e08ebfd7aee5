// The SQLite backend's history: revisions, the changes each recorded and
// every version of every program.
#include "db/sqlite_store.h"

namespace k528::db {

void SqliteStore::insertRevision(std::int64_t id, int revision, const std::string& author,
                                 const std::string& at, const std::string& summary,
                                 const std::string& settingsOrder) {
    auto& q = st_("INSERT INTO revisions (machine_id, revision, author, at, summary, "
                  "settings_order) VALUES (?1, ?2, ?3, ?4, ?5, ?6)");
    q.bind(1, id).bind(2, revision).bind(3, author).bind(4, at).bind(5, summary).bind(6, settingsOrder);
    q.run();
}

void SqliteStore::insertProgramVersion(std::int64_t id, const ProgramRow& v) {
    auto& q = st_("INSERT INTO program_revisions (machine_id, number, revision, text, "
                  "sha256) VALUES (?1, ?2, ?3, ?4, ?5)");
    q.bind(1, id).bind(2, v.number).bind(3, v.revision).bind(4, v.text).bind(5, v.sha256);
    q.run();
}

void SqliteStore::insertChange(std::int64_t id, int revision, int seq, const profile::Change& c) {
    auto& q = st_("INSERT INTO changes (machine_id, revision, seq, section, key, label, before, "
                  "after) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)");
    q.bind(1, id)
        .bind(2, revision)
        .bind(3, seq)
        .bind(4, profile::diffSectionName(c.section))
        .bind(5, c.key)
        .bind(6, c.label)
        .bind(7, c.before)
        .bind(8, c.after);
    q.run();
}

std::vector<ChangeRow> SqliteStore::changesUpTo(std::int64_t id, int revision) {
    auto& q = st_("SELECT section, key, after, revision FROM changes WHERE machine_id = ?1 AND "
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

std::optional<std::string> SqliteStore::settingsOrder(std::int64_t id, int revision) {
    auto& q = st_("SELECT settings_order FROM revisions WHERE machine_id = ?1 AND revision = ?2");
    q.bind(1, id).bind(2, revision);
    if (!q.step())
        return std::nullopt;
    std::string order = q.text(0);
    q.reset();
    return order;
}

std::vector<ProgramRow> SqliteStore::programsAt(std::int64_t id, int revision) {
    auto& q = st_("SELECT p.number, p.text, p.sha256, p.revision FROM program_revisions p "
                  "WHERE p.machine_id = ?1 AND p.revision = (SELECT max(q.revision) FROM "
                  "program_revisions q WHERE q.machine_id = p.machine_id AND q.number = "
                  "p.number AND q.revision <= ?2) AND p.text IS NOT NULL");
    q.bind(1, id).bind(2, revision);
    std::vector<ProgramRow> out;
    while (q.step())
        out.push_back(ProgramRow{q.i32(0), q.i32(3), q.optText(1), q.optText(2)});
    return out;
}

std::vector<RevisionInfo> SqliteStore::revisions(std::int64_t id) {
    auto& q = st_("SELECT r.revision, r.author, r.at, r.summary, (SELECT count(*) FROM changes c "
                  "WHERE c.machine_id = r.machine_id AND c.revision = r.revision) FROM "
                  "revisions r WHERE r.machine_id = ?1 ORDER BY r.revision DESC");
    q.bind(1, id);
    std::vector<RevisionInfo> out;
    while (q.step())
        out.push_back(RevisionInfo{q.i32(0), q.text(1), q.text(2), q.text(3), q.i32(4)});
    return out;
}

std::vector<ChangeRow> SqliteStore::history(std::int64_t id, int fromRevision,
                                            const std::optional<std::string>& key) {
    auto& q = st_("SELECT c.revision, r.author, r.at, c.section, c.key, c.label, c.before, c.after "
                  "FROM changes c JOIN revisions r ON r.machine_id = c.machine_id AND r.revision = "
                  "c.revision WHERE c.machine_id = ?1 AND c.revision >= ?2 AND (?3 IS NULL OR "
                  "c.key = ?3) ORDER BY c.revision DESC, c.seq");
    q.bind(1, id).bind(2, fromRevision).bind(3, key);
    std::vector<ChangeRow> out;
    while (q.step())
        out.push_back(ChangeRow{q.i32(0), q.text(1), q.text(2), q.text(3), q.text(4), q.text(5),
                                q.optText(6), q.optText(7)});
    return out;
}

std::vector<ProgramRow> SqliteStore::programVersions(std::int64_t id, int number) {
    auto& q = st_("SELECT revision, text, sha256 FROM program_revisions WHERE machine_id = ?1 "
                  "AND number = ?2 ORDER BY revision DESC");
    q.bind(1, id).bind(2, number);
    std::vector<ProgramRow> out;
    while (q.step())
        out.push_back(ProgramRow{number, q.i32(0), q.optText(1), q.optText(2)});
    return out;
}

std::optional<ProgramRow> SqliteStore::programAt(std::int64_t id, int number, int revision) {
    auto& q = st_("SELECT revision, text, sha256 FROM program_revisions WHERE machine_id = ?1 AND "
                  "number = ?2 AND revision <= ?3 ORDER BY revision DESC LIMIT 1");
    q.bind(1, id).bind(2, number).bind(3, revision);
    if (!q.step())
        return std::nullopt;
    ProgramRow r{number, q.i32(0), q.optText(1), q.optText(2)};
    q.reset();
    return r;
}

} // namespace k528::db
