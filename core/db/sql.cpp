#include "db/sql.h"

namespace k528::db::sql {

Query& Query::bind(int i, const Value& v) {
    if (const auto* n = std::get_if<std::int64_t>(&v))
        return bind(i, *n);
    if (const auto* s = std::get_if<std::string>(&v))
        return bind(i, std::string_view(*s));
    return bindNull(i);
}

std::int64_t Connection::queryInt(std::string_view text) {
    Query& q = (*this)(text);
    if (!q.step())
        throw Error(ErrorKind::Sql, "\"" + std::string(text) + "\" returned no row");
    const std::int64_t v = q.i64(0);
    q.reset();
    return v;
}

} // namespace k528::db::sql
