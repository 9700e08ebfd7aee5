#include "db/sql.h"

#include <charconv>

namespace k528::db::sql {

Error internalError(std::string what, std::string at) {
    ErrorText t("internal", {std::move(what)});
    t.at = std::move(at);
    return Error(ErrorKind::Sql, std::move(t));
}

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
        throw internalError("\"" + std::string(text) + "\" returned no row");
    const std::int64_t v = q.i64(0);
    q.reset();
    return v;
}

IntegerPairs::IntegerPairs(std::string packed, std::string idStem, std::vector<std::string> args)
    : packed_(std::move(packed)), idStem_(std::move(idStem)), args_(std::move(args)) {}

Query& IntegerPairs::bind(int, std::int64_t) {
    throw internalError("packed rows take no parameters");
}

Query& IntegerPairs::bind(int, std::string_view) {
    throw internalError("packed rows take no parameters");
}

Query& IntegerPairs::bindNull(int) {
    throw internalError("packed rows take no parameters");
}

std::int64_t IntegerPairs::next() {
    const char* begin = packed_.data() + at_;
    const char* end = packed_.data() + packed_.size();
    std::int64_t v = 0;
    const auto [stop, ec] = std::from_chars(begin, end, v);
    if (ec != std::errc() || (stop != end && *stop != ' '))
    {
        std::vector<std::string> args = args_;
        args.push_back(packed_.substr(at_, 40));
        throw Error(ErrorKind::Corrupt, ErrorText{idStem_ + ".pairs", std::move(args)});
    }
    at_ = static_cast<std::size_t>(stop - packed_.data()) + (stop != end ? 1 : 0);
    return v;
}

bool IntegerPairs::step() {
    if (at_ >= packed_.size())
        return false;
    first_ = next();
    if (at_ >= packed_.size())
        throw Error(ErrorKind::Corrupt, ErrorText{idStem_ + ".odd", args_});
    second_ = next();
    return true;
}

} // namespace k528::db::sql
