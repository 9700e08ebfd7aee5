#include "db/db_texts.h"

#include <array>

namespace k528::db {

namespace {

constexpr std::array kTexts = {
    // A machine and its revisions.
    util::CatalogText{"no-machine",
                "нет станка «%1» в %2 (станки: %3)",
                "no machine \"%1\" in %2 (machines: %3)"},
    util::CatalogText{"no-machine.none",
                "нет станка «%1» в %2 (станков нет)",
                "no machine \"%1\" in %2 (machines: none)"},
    util::CatalogText{"machine-exists",
                "станок с именем %1 уже есть в %2",
                "a machine named %1 already exists in %2"},
    util::CatalogText{"rename-exists",
                "нельзя переименовать %1 в %2: станок с таким именем уже есть",
                "cannot rename %1 to %2: a machine of that name exists"},
    util::CatalogText{"constants-locked",
                "станок %1: константы станка заблокированы преподавателем для группы «%2» (параметр %3): "
                "%4 не изменены; ничего не записано (сначала преподаватель снимает блокировку: "
                "k528 db set %1 %3=)",
                "machine %1: the machine constants are locked by the trainer for the class «%2» (setting %3): "
                "%4 not changed; nothing was written (the trainer unlocks them first: k528 db set %1 %3=)"},
    util::CatalogText{"no-revision",
                "у станка %1 ревизии 1..%2; ревизии %3 нет",
                "machine %1 has revisions 1..%2; there is no revision %3"},
    util::CatalogText{"conflict",
                "станок %1 — на ревизии %2, а не %3",
                "machine %1 is at revision %2, not %3"},
    util::CatalogText{"conflict.detailed",
                "станок %1 — на ревизии %2 (изменил %3, %4), а не %5, как было прочитано: загрузите его "
                "снова и повторите изменение",
                "machine %1 is at revision %2 (changed by %3 at %4), not %5 as read: load it again and "
                "repeat the change"},
    util::CatalogText{"author-too-long",
                "имя автора длиной %1 байт; имя — не длиннее %2 байт (UTF-8); ничего не записано",
                "the author's name is %1 bytes long; a name has at most %2 (UTF-8); nothing was written"},
    // Stored data that break their own rules.
    util::CatalogText{"corrupt.history-entry",
                "станок %1, ревизия %2 в %3: запись истории %4 %5 ревизии %6 не читается",
                "machine %1 revision %2 in %3: history entry %4 %5 of revision %6 cannot be read"},
    util::CatalogText{"corrupt.revision-missing",
                "станок %1, ревизия %2 в %3: ревизии нет в таблице ревизий",
                "machine %1 revision %2 in %3: the revision is missing from the revision table"},
    util::CatalogText{"corrupt.revision-program",
                "станок %1, ревизия %2 в %3: программа L%4 ревизии %5 не совпадает со своей "
                "контрольной суммой SHA-256",
                "machine %1 revision %2 in %3: program L%4 of revision %5 does not match its SHA-256 "
                "checksum"},
    util::CatalogText{"corrupt.history-section",
                "станок %1: в истории неизвестный раздел %2",
                "machine %1: history has an unknown section %2"},
    util::CatalogText{"corrupt.program",
                "станок %1: программа L%2 не совпадает со своей контрольной суммой SHA-256",
                "machine %1: program L%2 does not match its SHA-256 checksum"},
    // A schema older than what a table needs.
    util::CatalogText{"schema-lacks.messages",
                "%1: в базе данных нет истории сообщений (версия схемы %2 ниже %3: откройте её один раз "
                "с правом записи, чтобы обновить)",
                "%1: the database has no message history (schema version %2 below %3: open it once with "
                "write access to upgrade it)"},
    util::CatalogText{"schema-lacks.attempts",
                "%1: в базе данных нет учебных попыток (версия схемы %2 ниже %3: откройте её один раз "
                "с правом записи, чтобы обновить)",
                "%1: the database has no training attempts (schema version %2 below %3: open it once with "
                "write access to upgrade it)"},
    util::CatalogText{"schema-lacks.state-times",
                "%1: в базе данных нет времени станков цеха в каждом состоянии (версия схемы %2 ниже %3: "
                "откройте её один раз с правом записи, чтобы обновить)",
                "%1: the database has no time in each state of the shop's machines (schema version %2 "
                "below %3: open it once with write access to upgrade it)"},
    // Training attempts, transfers, times in a state.
    util::CatalogText{"attempt.no-student",
                "у попытки должно быть имя учащегося; ничего не записано",
                "an attempt needs its student's name; nothing was written"},
    util::CatalogText{"attempt.no-exercise",
                "у попытки должно быть упражнение; ничего не записано",
                "an attempt needs its exercise; nothing was written"},
    util::CatalogText{"attempt.score",
                "попытка «%1» в «%2»: оценка — 0..100, а не %3; ничего не записано",
                "the attempt of \"%1\" at \"%2\": a score is 0..100, not %3; nothing was written"},
    util::CatalogText{"attempt.cycle-time",
                "попытка «%1» в «%2»: отрицательное время цикла; ничего не записано",
                "the attempt of \"%1\" at \"%2\": a negative cycle time; nothing was written"},
    util::CatalogText{"transfer.direction",
                "передача — это push или pull, а не «%1»",
                "a transfer is a push or a pull, not \"%1\""},
    util::CatalogText{"transfer.result",
                "результат передачи — ok, partial или failed, а не «%1»",
                "a transfer's result is ok, partial or failed, not \"%1\""},
    util::CatalogText{"state-time.invalid",
                "для времени в состоянии нужны станок, день (ГГГГ-ММ-ДД), run, idle, alarm или offline и "
                "0 мс или больше, а не '%1' '%2' '%3' %4 мс; ничего не записано",
                "a time in a state needs a machine, a day (YYYY-MM-DD), run, idle, alarm or offline and "
                "0 ms or more, not '%1' '%2' '%3' %4 ms; nothing was written"},
    // Programs released to the controllers.
    util::CatalogText{"release.no-program",
                "у станка %1 нет программы L%2 (на ревизии %3); ничего не выпущено",
                "machine %1 has no program L%2 (at revision %3); nothing was released"},
    util::CatalogText{"release.never",
                "программа L%2 станка %1 ни разу не выпускалась; ничего не записано",
                "program L%2 of machine %1 was never released; nothing was written"},
    util::CatalogText{"release.withdrawn",
                "программа L%2 станка %1 уже отозвана; ничего не записано",
                "program L%2 of machine %1 is withdrawn already; nothing was written"},
    util::CatalogText{"roles.sqlite",
                "%1: у базы данных SQLite один пользователь, которому можно всё; роли есть только у "
                "PostgreSQL",
                "%1: an SQLite database has one user, who may do everything; the roles are PostgreSQL's"},
    // Where the database is, opening and copying it.
    util::CatalogText{"location.none",
                "место базы данных не задано: задайте K528_DB, XDG_DATA_HOME или HOME",
                "no database location: set K528_DB, XDG_DATA_HOME or HOME"},
    util::CatalogText{"location.postgres",
                "K528_DB называет базу данных PostgreSQL (%1), а не файл",
                "K528_DB names a PostgreSQL database (%1), not a file"},
    util::CatalogText{"open.no-database",
                "нет базы данных %1",
                "no database at %1"},
    util::CatalogText{"open.no-database.init",
                "нет базы данных %1 (создать её: k528 db init --db %1)",
                "no database at %1 (create one with: k528 db init --db %1)"},
    util::CatalogText{"open.no-folder",
                "нельзя создать базу данных %1: папки %2 нет",
                "cannot create the database %1: the folder %2 does not exist"},
    util::CatalogText{"open.directory",
                "%1: это папка, а не файл базы данных",
                "%1: is a directory, not a database file"},
    util::CatalogText{"open.not-empty",
                "%1: база данных не пуста (версия схемы %2); копия записывается только в новую или пустую",
                "%1: not an empty database (schema version %2); a copy goes only into a new or empty one"},
    // Said after the file's path ("PATH: …").
    util::CatalogText{"open.foreign-short",
                "это не база данных K528 Studio: в файле всего %1 байт, слишком мало для базы данных SQLite",
                "not a K528 Studio database: the file has only %1 bytes, too few for an SQLite database"},
    util::CatalogText{"open.foreign-header",
                "это не база данных K528 Studio: файл не начинается с заголовка SQLite (файл другого "
                "рода или база данных с повреждённой первой страницей)",
                "not a K528 Studio database: the file does not start with the SQLite header (another "
                "kind of file, or a database whose first page is damaged)"},
    util::CatalogText{"open.foreign-program",
                "это не база данных K528 Studio: это база данных SQLite другой программы "
                "(application_id %1, у нас %2)",
                "not a K528 Studio database: it is another program's SQLite database (application_id "
                "%1, ours is %2)"},
    util::CatalogText{"open.foreign-objects",
                "это не база данных K528 Studio: это база данных SQLite другой программы "
                "(application_id %1, объектов схемы: %2)",
                "not a K528 Studio database: it is another program's SQLite database (application_id "
                "%1, %2 schema objects)"},
    util::CatalogText{"open.too-new",
                "версия схемы базы данных — %1, её записала более новая K528 Studio; эта программа "
                "знает версии до %2. Откройте её более новой программой",
                "the database has schema version %1, written by a newer K528 Studio; this program "
                "knows versions up to %2. Use the newer program"},
    util::CatalogText{"open.untouched",
                "; файл не изменён",
                "; the file was left untouched"},
    util::CatalogText{"open.recovered",
                "; откачена только незавершённая транзакция в %1 (восстановление SQLite после сбоя "
                "базы данных K528 Studio), больше ничего не изменено",
                "; only the unfinished transaction in %1 was rolled back (SQLite's crash recovery of a "
                "K528 Studio database), nothing else was changed"},
    util::CatalogText{"busy.write",
                "%1: другой процесс пишет в базу данных и держит её заблокированной дольше времени "
                "ожидания; ничего не записано, повторите",
                "%1: another process is writing to the database and kept it locked longer than the busy "
                "timeout; nothing was written, try again"},
    util::CatalogText{"copy.schema",
                "у %1 версия схемы %2; для копии нужна версия %3 (откройте её один раз с правом записи, "
                "чтобы обновить)",
                "%1 has schema version %2; a copy needs version %3 (open it once with write access to "
                "upgrade it)"},
    util::CatalogText{"copy.itself",
                "базу данных нельзя скопировать в неё саму",
                "a database cannot be copied into itself"},
    // The items of `k528 db set` (db::Edit).
    util::CatalogText{"item.syntax",
                "«%1» — не ПУНКТ=ЗНАЧЕНИЕ (например, C022=2133, R12=5, #3=ТЕКСТ, A01=ТЕКСТ)",
                "'%1' is not ITEM=VALUE (e.g. C022=2133, R12=5, #3=TEXT, A01=TEXT)"},
    util::CatalogText{"item.c-none",
                "%1: такого C-параметра нет (1..152)",
                "%1: no such C-parameter (1..152)"},
    util::CatalogText{"item.r-none",
                "%1: такого R-параметра нет (0..299)",
                "%1: no such R-parameter (0..299)"},
    util::CatalogText{"item.message-none",
                "%1: такого технологического сообщения нет (#1..#99)",
                "%1: no such technological message (#1..#99)"},
    util::CatalogText{"item.plc-none",
                "%1: такого сообщения ПЛК нет (%2..%3)",
                "%1: no such PLC message (%2..%3)"},
    util::CatalogText{"item.not-whole",
                "%1: «%2» — не целое число",
                "%1: '%2' is not a whole number"},
    util::CatalogText{"item.unknown",
                "«%1» — не пункт: C<n>, R<n>, #<n>, A<nn>, W<nn>, S<nn>, title или параметр моделирования",
                "'%1' is not an item: C<n>, R<n>, #<n>, A<nn>, W<nn>, S<nn>, title or a simulation key"},
    util::CatalogText{"item.twice",
                "%1 задан дважды («%2» и «%3»); задайте каждый пункт один раз",
                "%1 is given twice ('%2' and '%3'); give each item once"},
    util::CatalogText{"item.unknown-key",
                "«%1» — неизвестный параметр моделирования; ничего не сохранено. Параметры перечислены "
                "в docs/profile-format.md; с --allow-unknown он сохраняется всё равно",
                "'%1' is not a known simulation key; nothing was saved. The keys are listed in "
                "docs/profile-format.md; --allow-unknown stores it anyway"},
    util::CatalogText{"item.unknown-key.close",
                "«%1» — неизвестный параметр моделирования; ничего не сохранено (может быть, %2?). "
                "Параметры перечислены в docs/profile-format.md; с --allow-unknown он сохраняется всё равно",
                "'%1' is not a known simulation key; nothing was saved (did you mean %2?). The keys are "
                "listed in docs/profile-format.md; --allow-unknown stores it anyway"},
    util::CatalogText{"list.or",
                "%1 или %2",
                "%1 or %2"},
};

} // namespace

util::TextCatalog dbTexts() { return util::TextCatalog(kTexts); }

std::string dbText(std::string_view id, std::span<const std::string> args, bool russian) {
    return dbTexts().render(id, args, russian);
}

} // namespace k528::db
