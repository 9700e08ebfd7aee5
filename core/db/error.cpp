#include "db/error.h"

#include "db/db_texts.h"

#include <iterator>

namespace k528::db {

namespace fs = std::filesystem;

std::string_view errorKindName(ErrorKind k) {
    // In the order of ErrorKind.
    static constexpr std::string_view kNames[] = {
        "io",          "foreign",     "corrupt",  "too-new", "busy",      "no-machine",
        "machine-exists", "no-revision", "conflict", "invalid", "read-only", "sql", "denied"};
    const auto i = static_cast<std::size_t>(k);
    return i < std::size(kNames) ? kNames[i] : std::string_view();
}

namespace {

// By ReadOnlyReason.
constexpr std::string_view kReasonIds[] = {
    "", "read-only.permission", "read-only.folder", "read-only.file-system", "read-only.requested",
};

// By ReadOnlyRefusal.
constexpr std::string_view kRefusalIds[] = {
    "read-only.write", "read-only.create", "read-only.upgrade", "read-only.recover",
};

ErrorText readOnlyText(const fs::path& path, ReadOnlyReason reason, ReadOnlyRefusal refusal) {
    ErrorText t{std::string(kRefusalIds[static_cast<int>(refusal)]), {path.string()}};
    t.within.push_back(ErrorText{std::string(readOnlyReasonId(reason))});
    return t;
}

} // namespace

std::string_view readOnlyReasonId(ReadOnlyReason r) {
    return kReasonIds[static_cast<int>(r)];
}

std::string readOnlyReasonText(ReadOnlyReason r, Lang lang) {
    return dbTexts().render(readOnlyReasonId(r), {}, lang == Lang::Ru);
}

std::string renderText(const ErrorText& t, bool russian) {
    std::vector<std::string> args = t.args;
    for (const ErrorText& part : t.within)
        args.push_back(renderText(part, russian));
    return (t.at.empty() ? std::string() : t.at + ": ") + dbTexts().render(t.id, args, russian) +
           dbTexts().render(t.tail, t.tailArgs, russian);
}

Error::Error(ErrorKind kind, ErrorText text, std::string detail)
    : std::runtime_error(renderText(text, false)), kind_(kind), detail_(std::move(detail)),
      text_(std::move(text)) {}

Error::Error(const std::string& what, ErrorKind kind, ErrorText text, std::string detail)
    : std::runtime_error(what), kind_(kind), detail_(std::move(detail)), text_(std::move(text)) {}

namespace {

ErrorText rejectionText(const std::string& machine, std::size_t errors) {
    return ErrorText{errors == 1 ? "rejected.error" : "rejected.errors", {machine, std::to_string(errors)}};
}

std::string rejectionLines(const ErrorText& head, const std::vector<profile::Finding>& findings, bool russian) {
    std::string s = renderText(head, russian);
    for (const profile::Finding& f : findings)
        s += "\n  " + profile::formatFinding(f, russian);
    return s;
}

std::string problemRejection(const ErrorText& head, const profile::Problem& problem, bool russian) {
    return renderText(head, russian) + " " + profile::problemText(problem, russian);
}

} // namespace

ValidationError::ValidationError(const std::string& machine, std::vector<profile::Finding> findings)
    : Error(rejectionLines(rejectionText(machine, findings.size()), findings, false), ErrorKind::Invalid,
            rejectionText(machine, findings.size())),
      findings_(std::move(findings)) {}

ValidationError::ValidationError(const std::string& machine, profile::Problem problem)
    : Error(problemRejection(ErrorText{"rejected.problem", {machine}}, problem, false), ErrorKind::Invalid,
            ErrorText{"rejected.problem", {machine}}),
      problem_(std::move(problem)) {}

std::string ValidationError::head(Lang lang) const {
    const bool russian = lang == Lang::Ru;
    if (!problem_.empty())
        return problemRejection(catalogText(), problem_, russian);
    return renderText(catalogText(), russian);
}

std::string ValidationError::text(Lang lang) const {
    if (!problem_.empty() || findings_.empty())
        return head(lang);
    return rejectionLines(catalogText(), findings_, lang == Lang::Ru);
}

namespace {

// By ErrorKind: what an error without a text of the catalog is, in Russian.
constexpr const char* kKindsRu[] = {
    "база данных недоступна, не читается или не записывается",
    "это не база данных K528 Studio",
    "база данных повреждена",
    "базу данных записала более новая K528 Studio",
    "другой процесс слишком долго держит базу данных",
    "нет такого станка",
    "станок с таким именем уже есть",
    "нет такой ревизии",
    "станок изменён после того, как его прочитали",
    "значение или изменение отклонено",
    "база данных доступна только для чтения",
    "непредвиденная ошибка базы данных (пожалуйста, сообщите о ней)",
    "сервер базы данных отказал этому пользователю",
};

} // namespace

std::string Error::text(Lang lang) const {
    if (!text_.id.empty())
        return renderText(text_, lang == Lang::Ru);
    if (lang != Lang::Ru)
        return what();
    const auto k = static_cast<std::size_t>(kind_);
    std::string s = text_.at.empty() ? std::string() : text_.at + ": ";
    s += k < std::size(kKindsRu) ? kKindsRu[k] : "ошибка базы данных";
    if (!detail_.empty())
        s += " («" + detail_ + "»)";
    return s + dbTexts().render(text_.tail, text_.tailArgs, true);
}

ReadOnlyError::ReadOnlyError(fs::path path, ReadOnlyReason reason, ReadOnlyRefusal refusal)
    : Error(ErrorKind::ReadOnly, readOnlyText(path, reason, refusal)), path_(std::move(path)), reason_(reason),
      refusal_(refusal) {}

namespace {

// By DeniedAction.
constexpr std::string_view kActionIds[] = {
    "denied.create-machine",  "denied.change-machine",   "denied.delete-machine",  "denied.release-program",
    "denied.withdraw-program", "denied.record-transfer", "denied.record-messages", "denied.record-attempt",
    "denied.create-tables",   "denied.set-up-roles",     "denied.grant-role",      "denied.lock-constants",
    "denied.record-state-times",
};

// By DeniedHolder.
constexpr std::string_view kHolderIds[] = {
    "denied.role", "denied.database-owner", "denied.tables-creator", "denied.role-admin",
};

ErrorText deniedText(const std::string& database, DeniedAction action, DeniedHolder holder, const std::string& role,
                     const std::string& user, const std::string& userRoles) {
    ErrorText t = userRoles.empty() ? ErrorText{"denied.no-role", {database, user}}
                                    : ErrorText{"denied", {database, user, userRoles}};
    t.within.push_back(ErrorText{std::string(kActionIds[static_cast<int>(action)])});
    t.within.push_back(holder == DeniedHolder::Role ? ErrorText{"denied.role", {role}}
                                                     : ErrorText{std::string(kHolderIds[static_cast<int>(holder)])});
    return t;
}

// The refusal as an Error: said by the catalog (`t`); what() is its English
// and the server's words (kept for a log; the texts leave them out).
Error deniedError(ErrorText t, const std::string& serverMessage) {
    std::string what = renderText(t, false);
    if (!serverMessage.empty())
        what += " (the server said: " + serverMessage + ")";
    return Error(what, ErrorKind::Denied, std::move(t), serverMessage);
}

} // namespace

DeniedError::DeniedError(std::string database, DeniedAction action, std::string role, std::string user,
                         std::string userRoles, const std::string& serverMessage)
    : DeniedError(database, action, DeniedHolder::Role, std::move(role), std::move(user), userRoles, serverMessage) {}

DeniedError::DeniedError(std::string database, DeniedAction action, DeniedHolder holder, std::string user,
                         std::string userRoles, const std::string& serverMessage)
    : DeniedError(database, action, holder, std::string(), std::move(user), userRoles, serverMessage) {}

DeniedError::DeniedError(const std::string& database, DeniedAction action, DeniedHolder holder, std::string role,
                         std::string user, const std::string& userRoles, const std::string& serverMessage)
    : Error(deniedError(deniedText(database, action, holder, role, user, userRoles), serverMessage)),
      action_(action), holder_(holder), role_(std::move(role)), user_(std::move(user)) {}

} // namespace k528::db
