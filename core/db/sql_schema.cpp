// The schema's steps and the C-parameter definitions, for both backends.
#include "catalog/cparams.h"
#include "db/db_texts.h"
#include "db/sha256.h"
#include "db/sql_store.h"

namespace k528::db {

namespace cat = k528::catalog;

namespace {

// The definition rows' content, for detecting a changed catalog.
std::string catalogDigest() {
    std::string s;
    const auto add = [&](std::string_view v) {
        s += v;
        s += '\x1f';
    };
    for (const cat::CParamDef& d : cat::cParams()) {
        add(std::to_string(d.number));
        add(cat::axisName(d.axis));
        add(cat::kindName(d.kind));
        add(cat::unitSymbol(d.unit));
        add(cat::unitRu(d.unit));
        add(cat::unitEn(d.unit));
        add(std::to_string(d.min));
        add(std::to_string(d.max));
        add(d.address.text());
        add(d.address.textEn());
        add(d.name);
        add(d.nameEn);
        add(d.descriptionRu);
        add(d.descriptionEn);
        add(d.hintRu);
        add(d.hintEn);
        add(d.note);
        s += '\x1e';
    }
    return sha256Hex(s);
}

} // namespace

void SqlStore::migrate(std::span<const Migration> migrations, std::int64_t from) {
    const bool postgres = connection().dialect() == sql::Dialect::Postgres;
    for (const Migration& m : migrations) {
        if (m.version <= from)
            continue;
        try {
            if (postgres) {
                if (!m.sql.empty())
                    connection().exec(postgresSchemaSql(m.sql));
                if (!m.postgresOnly.empty())
                    connection().exec(m.postgresOnly);
            } else {
                if (!m.sql.empty())
                    connection().exec(m.sql);
                if (!m.sqliteOnly.empty())
                    connection().exec(m.sqliteOnly);
            }
        } catch (const Error& e) {
            // What failed as it was said (its kind, its text or the
            // library's words), where, and that the upgrade changed nothing.
            ErrorText t = e.catalogText();
            t.at = path_.string();
            t.tail = "migrate.failed";
            t.tailArgs = {std::to_string(m.version)};
            if (!t.id.empty())
                throw Error(e.kind(), std::move(t), e.detail());
            const std::string message = path_.string() + ": " + e.what() + dbText(t.tail, t.tailArgs, false);
            throw Error(e.kind(), message, e.detail(), std::move(t));
        }
    }
}

void SqlStore::upgrade(std::span<const Migration> migrations, std::int64_t found,
                       const std::string& author, const Fill& fill) {
    const int latest = migrations.back().version;
    if (found < latest) {
        migrate(migrations, found);
        stampSchema(latest);
        report_.version = latest; // the rows written from here on are the new schema's
        if (found == 0) {
            auto& meta = query("INSERT INTO meta (key, value) VALUES (?1, ?2)");
            meta.bind(1, "created_at").bind(2, now());
            meta.run();
            insertAudit(AuditEntry{0, now(), author, "create-database", "", 0,
                                   "schema version " + std::to_string(latest) + " created"});
            syncDefinitions(author);
            if (fill)
                report_.seeded = fill(*this);
        } else {
            insertAudit(AuditEntry{0, now(), author, "migrate", "", 0,
                                   "schema version " + std::to_string(found) + " -> " +
                                       std::to_string(latest)});
        }
    }
    report_.fromVersion = static_cast<int>(found);
    report_.created = found == 0; // not when another process created it meanwhile
}

bool SqlStore::definitionsCurrent() {
    auto& q = query("SELECT value FROM meta WHERE key = 'catalog_sha256'");
    const bool same = q.step() && q.text(0) == catalogDigest();
    q.reset();
    return same;
}

void SqlStore::syncDefinitions(const std::string& author) {
    const std::string digest = catalogDigest();
    {
        auto& q = query("SELECT value FROM meta WHERE key = 'catalog_sha256'");
        if (q.step() && q.text(0) == digest) {
            q.reset();
            return;
        }
        q.reset();
    }
    auto& q = query(R"SQL(INSERT INTO c_definitions (number, axis, kind, unit, unit_ru, unit_en,
        min_value, max_value, address, address_en, name, name_en, description_ru, description_en,
        hint_ru, hint_en, note) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13,
        ?14, ?15, ?16, ?17) ON CONFLICT (number) DO UPDATE SET axis = excluded.axis,
        kind = excluded.kind, unit = excluded.unit, unit_ru = excluded.unit_ru,
        unit_en = excluded.unit_en, min_value = excluded.min_value, max_value = excluded.max_value,
        address = excluded.address, address_en = excluded.address_en, name = excluded.name,
        name_en = excluded.name_en, description_ru = excluded.description_ru,
        description_en = excluded.description_en, hint_ru = excluded.hint_ru,
        hint_en = excluded.hint_en, note = excluded.note)SQL");
    for (const cat::CParamDef& d : cat::cParams()) {
        q.reset();
        q.bind(1, d.number)
            .bind(2, cat::axisName(d.axis))
            .bind(3, cat::kindName(d.kind))
            .bind(4, cat::unitSymbol(d.unit))
            .bind(5, cat::unitRu(d.unit))
            .bind(6, cat::unitEn(d.unit))
            .bind(7, d.min)
            .bind(8, d.max)
            .bind(9, d.address.text())
            .bind(10, d.address.textEn())
            .bind(11, d.name)
            .bind(12, d.nameEn)
            .bind(13, d.descriptionRu)
            .bind(14, d.descriptionEn)
            .bind(15, d.hintRu)
            .bind(16, d.hintEn)
            .bind(17, d.note);
        q.run();
    }
    auto& m = query("INSERT INTO meta (key, value) VALUES ('catalog_sha256', ?1) ON CONFLICT (key) "
                 "DO UPDATE SET value = excluded.value");
    m.bind(1, digest);
    m.run();
    insertAudit(AuditEntry{0, now(), author, "definitions", "", 0,
                           "C-parameter definitions (appendix Е) written from the catalog, digest " +
                               digest.substr(0, 12)});
    report_.definitionsUpdated = true;
}

} // namespace k528::db
