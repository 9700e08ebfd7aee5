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

std::string Error::text(Lang lang) const {
    if (text_.id.empty())
        return what();
    return renderText(text_, lang == Lang::Ru);
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
      action_(std::move(action)), role_(std::move(role)) {}

} // namespace k528::db
