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

struct Text {
    const char* en;
    const char* ru;
};

// By ReadOnlyReason.
constexpr Text kReasons[] = {
    {"", ""},
    {"permission denied", "нет права на запись"},
    {"no permission to create files in its folder", "нет права создавать файлы в её папке"},
    {"read-only file system", "файловая система только для чтения"},
    {"opened read-only", "открыта только для чтения"},
};

// By ReadOnlyRefusal.
constexpr Text kRefusals[] = {
    {"; nothing was written", "; ничего не записано"},
    {"; a new database cannot be created there", "; создать там новую базу данных нельзя"},
    {"; its schema is older than this program's and cannot be upgraded",
     "; её схема старше схемы этой программы, и обновить её нельзя"},
    {"; it has an unfinished transaction (a hot -journal) that only a user who may write the "
     "file can roll back; the file was left untouched",
     "; в ней незавершённая транзакция (горячий журнал -journal), откатить которую может только "
     "пользователь с правом записи; файл не изменён"},
};

const char* pick(const Text& t, Lang lang) {
    return lang == Lang::Ru ? t.ru : t.en;
}

std::string readOnlyMessage(const fs::path& path, ReadOnlyReason reason, ReadOnlyRefusal refusal,
                            Lang lang) {
    return std::string(lang == Lang::Ru ? "база данных доступна только для чтения: "
                                        : "the database is read-only: ") +
           path.string() + " (" + pick(kReasons[static_cast<int>(reason)], lang) + ")" +
           pick(kRefusals[static_cast<int>(refusal)], lang);
}

} // namespace

std::string_view readOnlyReasonText(ReadOnlyReason r, Lang lang) {
    return pick(kReasons[static_cast<int>(r)], lang);
}

std::string renderText(const ErrorText& t, bool russian) {
    return (t.at.empty() ? std::string() : t.at + ": ") + dbTexts().render(t.id, t.args, russian) +
           dbTexts().render(t.tail, t.tailArgs, russian);
}

Error::Error(ErrorKind kind, ErrorText text, std::string detail)
    : std::runtime_error(renderText(text, false)), kind_(kind), detail_(std::move(detail)),
      text_(std::move(text)) {}

Error::Error(const std::string& what, ErrorKind kind, ErrorText text)
    : std::runtime_error(what), kind_(kind), text_(std::move(text)) {}

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

// A role refusal's action (DeniedError::action) and the role it needs when
// that is no role's name, in Russian.
constexpr Text kDeniedWords[] = {
    {"creating a machine", "создание станка"},
    {"changing a machine", "изменение станка"},
    {"deleting a machine", "удаление станка"},
    {"releasing a program", "выпуск программы"},
    {"withdrawing a program", "отзыв программы"},
    {"recording a transfer", "запись передачи в журнал"},
    {"recording messages", "запись сообщений"},
    {"recording a training attempt", "запись учебной попытки"},
    {"creating the database's tables", "создание таблиц базы данных"},
    {"setting up the roles", "настройка ролей"},
    {"granting a role", "выдача роли"},
    {"setting or clearing the constants lock", "установка или снятие блокировки констант"},
    {"recording the machines' time in each state", "запись времени станков в каждом состоянии"},
    {"the owner of the database", "владелец базы данных"},
    {"the owner of the database's tables with CREATEROLE", "владелец таблиц базы данных с правом CREATEROLE"},
    {"the role's admin (its creator, or CREATEROLE)", "администратор роли (её создатель или CREATEROLE)"},
};

std::string deniedWord(const std::string& en, Lang lang) {
    if (lang == Lang::Ru)
        for (const Text& t : kDeniedWords)
            if (en == t.en)
                return t.ru;
    return en;
}

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
    : Error(ErrorKind::ReadOnly, readOnlyMessage(path, reason, refusal, Lang::En)),
      path_(std::move(path)), reason_(reason), refusal_(refusal) {}

std::string ReadOnlyError::text(Lang lang) const {
    return readOnlyMessage(path_, reason_, refusal_, lang);
}

DeniedError::DeniedError(std::string action, std::string role, std::string user,
                         std::string userRoles, const std::string& serverMessage)
    : Error(ErrorKind::Denied, "permission denied: " + action + " needs the role " + role +
                                   " (the database user " + user + " has " +
                                   (userRoles.empty() ? std::string("no K528 Studio role")
                                                      : userRoles) +
                                   "; the server said: " + serverMessage + "); nothing was written"),
      action_(std::move(action)), role_(std::move(role)), user_(std::move(user)),
      userRoles_(std::move(userRoles)) {}

std::string DeniedError::text(Lang lang) const {
    if (lang != Lang::Ru)
        return what();
    return "отказано: для действия «" + deniedWord(action_, lang) + "» нужна роль " +
           deniedWord(role_, lang) + " (у пользователя базы данных " + user_ + ": " +
           (userRoles_.empty() ? std::string("ни одной роли K528 Studio") : userRoles_) +
           "); ничего не записано";
}

} // namespace k528::db
