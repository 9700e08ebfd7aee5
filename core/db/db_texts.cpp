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
    // A text of another module about a machine ("machine NAME: the text").
    util::CatalogText{"machine.said",
                "станок %1: %2",
                "machine %1: %2"},
    util::CatalogText{"rename-exists",
                "нельзя переименовать %1 в %2: станок с таким именем уже есть",
                "cannot rename %1 to %2: a machine of that name exists"},
    util::CatalogText{"constants-locked",
                "станок %1: константы станка заблокированы преподавателем для группы «%2» (параметр %3): "
                "%4 не изменены; ничего не записано (сначала преподаватель снимает блокировку: "
                "k528 db set %1 %3=)",
                "machine %1: the machine constants are locked by the trainer for the class «%2» (setting %3): "
                "%4 not changed; nothing was written (the trainer unlocks them first: k528 db set %1 %3=)"},
    // A write the machine's own rules reject (db::ValidationError): the
    // findings follow a line each, or the item's problem after the colon.
    util::CatalogText{"rejected.error",
                "станок %1: отклонено, ничего не записано (ошибок: %2):",
                "machine %1: rejected, nothing was written (%2 error):"},
    util::CatalogText{"rejected.errors",
                "станок %1: отклонено, ничего не записано (ошибок: %2):",
                "machine %1: rejected, nothing was written (%2 errors):"},
    util::CatalogText{"rejected.problem",
                "станок %1: отклонено, ничего не записано:",
                "machine %1: rejected, nothing was written:"},
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
    util::CatalogText{"corrupt.settings-order-key",
                "станок %1, ревизия %2 в %3: у ключа моделирования %4 из сохранённого порядка нет значения",
                "machine %1 revision %2 in %3: simulation key %4 of the stored order has no value"},
    util::CatalogText{"corrupt.settings-order-incomplete",
                "станок %1, ревизия %2 в %3: сохранённый порядок настроек моделирования перечисляет не все ключи",
                "machine %1 revision %2 in %3: the stored order of the simulation settings does not list every key"},
    // The current state of a machine as stored (the machine and the file first).
    util::CatalogText{"corrupt.c-values.pairs",
                "станок %1 в %2: значения C-параметров: «%3» там, где должны быть пары целых чисел",
                "machine %1 in %2: C values: \"%3\" where integer pairs belong"},
    util::CatalogText{"corrupt.c-values.odd",
                "станок %1 в %2: значения C-параметров: номер без значения",
                "machine %1 in %2: C values: a number without its value"},
    util::CatalogText{"corrupt.r-presets.pairs",
                "станок %1 в %2: предустановки R-параметров: «%3» там, где должны быть пары целых чисел",
                "machine %1 in %2: R presets: \"%3\" where integer pairs belong"},
    util::CatalogText{"corrupt.r-presets.odd",
                "станок %1 в %2: предустановки R-параметров: номер без значения",
                "machine %1 in %2: R presets: a number without its value"},
    util::CatalogText{"corrupt.c-number",
                "станок %1 в %2: номер C-параметра %3 — не из 1..152",
                "machine %1 in %2: C-parameter number %3 is not 1..152"},
    util::CatalogText{"corrupt.c-count",
                "станок %1 в %2: хранится значений C-параметров: %3 из 152",
                "machine %1 in %2: %3 of the 152 C-parameter values are stored"},
    util::CatalogText{"corrupt.current-program",
                "станок %1 в %2: программа L%3 ревизии %4 не совпадает со своей контрольной суммой SHA-256 "
                "(текст изменён не в K528 Studio)",
                "machine %1 in %2: program L%3 of revision %4 does not match its SHA-256 checksum (the text "
                "was altered outside K528 Studio)"},
    util::CatalogText{"corrupt.plc-group",
                "станок %1 в %2: неизвестная группа сообщений ПЛК %3",
                "machine %1 in %2: unknown PLC message group %3"},
    util::CatalogText{"corrupt.setting",
                "станок %1 в %2: настройку моделирования %3=%4 прочитать нельзя",
                "machine %1 in %2: the simulation setting %3=%4 cannot be read"},
    // A value of a type we never store, written by another program: SQLite
    // (%2 the query, as written) and PostgreSQL (%2 the value, as stored).
    util::CatalogText{"corrupt.column-type",
                "столбец %1 содержит значение, которое не является ни целым числом, ни текстом (запрос «%2»)",
                "column %1 holds a value that is neither an integer nor a text (query: %2)"},
    util::CatalogText{"corrupt.column-integer",
                "столбец %1 содержит значение там, где должно быть целое число: «%2»",
                "column %1 holds a value where an integer belongs: %2"},
    // Said after why a step of a schema upgrade failed.
    util::CatalogText{"migrate.failed",
                "; переход на версию схемы %1 не удался, ничего не изменено",
                "; the migration to schema version %1 failed, nothing was changed"},
    // A database this process may only read (db::ReadOnlyError): the refusal,
    // %1 the file, %2 the reason (read-only.permission, …).
    util::CatalogText{"read-only.write",
                "база данных доступна только для чтения: %1 (%2); ничего не записано",
                "the database is read-only: %1 (%2); nothing was written"},
    util::CatalogText{"read-only.create",
                "база данных доступна только для чтения: %1 (%2); создать там новую базу данных нельзя",
                "the database is read-only: %1 (%2); a new database cannot be created there"},
    util::CatalogText{"read-only.upgrade",
                "база данных доступна только для чтения: %1 (%2); её схема старше схемы этой программы, и обновить её нельзя",
                "the database is read-only: %1 (%2); its schema is older than this program's and cannot be upgraded"},
    util::CatalogText{"read-only.recover",
                "база данных доступна только для чтения: %1 (%2); в ней незавершённая транзакция (горячий журнал -journal), откатить которую может только пользователь с правом записи; файл не изменён",
                "the database is read-only: %1 (%2); it has an unfinished transaction (a hot -journal) that only a user who may write the file can roll back; the file was left untouched"},
    util::CatalogText{"read-only.permission",
                "нет права на запись",
                "permission denied"},
    util::CatalogText{"read-only.folder",
                "нет права создавать файлы в её папке",
                "no permission to create files in its folder"},
    util::CatalogText{"read-only.file-system",
                "файловая система только для чтения",
                "read-only file system"},
    util::CatalogText{"read-only.requested",
                "открыта только для чтения",
                "opened read-only"},
    // An action the server refused for this user (db::DeniedError): %1 the
    // database, %2 the user, %3 the user's K528 Studio roles; then the action
    // (denied.create-machine, …) and who may do it (denied.role, …).
    util::CatalogText{"denied",
                "база данных %1 отказала пользователю %2: для действия «%4» требуется %5; у пользователя: %3; ничего не записано",
                "the database %1 refused the user %2: %4 needs %5; the user has %3; nothing was written"},
    util::CatalogText{"denied.no-role",
                "база данных %1 отказала пользователю %2: для действия «%3» требуется %4; у пользователя нет ни одной роли K528 Studio; ничего не записано",
                "the database %1 refused the user %2: %3 needs %4; the user has no K528 Studio role; nothing was written"},
    util::CatalogText{"denied.create-machine",
                "создание станка",
                "creating a machine"},
    util::CatalogText{"denied.change-machine",
                "изменение станка",
                "changing a machine"},
    util::CatalogText{"denied.delete-machine",
                "удаление станка",
                "deleting a machine"},
    util::CatalogText{"denied.release-program",
                "выпуск программы",
                "releasing a program"},
    util::CatalogText{"denied.withdraw-program",
                "отзыв программы",
                "withdrawing a program"},
    util::CatalogText{"denied.record-transfer",
                "запись передачи в журнал",
                "recording a transfer"},
    util::CatalogText{"denied.record-messages",
                "запись сообщений",
                "recording messages"},
    util::CatalogText{"denied.record-attempt",
                "запись учебной попытки",
                "recording a training attempt"},
    util::CatalogText{"denied.create-tables",
                "создание таблиц базы данных",
                "creating the database's tables"},
    util::CatalogText{"denied.set-up-roles",
                "настройка ролей",
                "setting up the roles"},
    util::CatalogText{"denied.grant-role",
                "выдача роли",
                "granting a role"},
    util::CatalogText{"denied.lock-constants",
                "установка или снятие блокировки констант",
                "setting or clearing the constants lock"},
    util::CatalogText{"denied.record-state-times",
                "запись времени станков в каждом состоянии",
                "recording the machines' time in each state"},
    util::CatalogText{"denied.role",
                "роль %1",
                "the role %1"},
    util::CatalogText{"denied.database-owner",
                "владелец базы данных",
                "the owner of the database"},
    util::CatalogText{"denied.tables-creator",
                "владелец таблиц базы данных с правом CREATEROLE",
                "the owner of the database's tables with CREATEROLE"},
    util::CatalogText{"denied.role-admin",
                "администратор роли (её создатель или CREATEROLE)",
                "the role's admin (its creator, or CREATEROLE)"},
    // A bug of core/db's own code (sql::internalError): %1 its English, for the report.
    util::CatalogText{"internal",
                "непредвиденная ошибка базы данных (пожалуйста, сообщите о ней): «%1»",
                "an unexpected database error (please report it): %1"},
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
    // A database location (--db, K528_DB) that is not one.
    util::CatalogText{"location.empty",
                "место базы данных «%1»: пусто; укажите путь к файлу или URI postgresql://",
                "database location \"%1\": empty; give a file path or a postgresql:// URI"},
    util::CatalogText{"location.password",
                "место базы данных «%1»: пароль в место базы данных не пишется (командную строку видит "
                "любой пользователь этого ПК, и оболочки её сохраняют): запишите его в ~/.pgpass "
                "(PGPASSFILE) или в файл служб (PGSERVICEFILE, postgresql://?service=ИМЯ) либо входите "
                "без пароля",
                "database location \"%1\": a password does not go into a database location (every user "
                "of this PC can read a command line, and shells keep it): put it in ~/.pgpass "
                "(PGPASSFILE) or a service file (PGSERVICEFILE, postgresql://?service=NAME), or log in "
                "without one"},
    util::CatalogText{"location.sqlite-path",
                "место базы данных «%1»: после sqlite: нужен путь к файлу (sqlite:/srv/k528/shop.db)",
                "database location \"%1\": sqlite: needs a file path (sqlite:/srv/k528/shop.db)"},
    util::CatalogText{"location.unknown-kind",
                "место базы данных «%1»: неизвестный вид базы данных «%2»; K528 Studio хранит базу данных "
                "в SQLite (путь к файлу или sqlite:ПУТЬ) или в PostgreSQL (postgresql://…)",
                "database location \"%1\": unknown kind of database \"%2\"; K528 Studio keeps its "
                "database in SQLite (a file path or sqlite:PATH) or PostgreSQL (postgresql://…)"},
    // Reaching a database, and what the system or the library said (%2: its
    // own words, quoted in Russian).
    util::CatalogText{"connect.failed",
                "нет подключения к базе данных %1: «%2»",
                "cannot connect to the database %1: %2"},
    util::CatalogText{"connect.lost",
                "связь с сервером потеряна и не восстанавливается",
                "the connection to the server was lost and cannot be made again"},
    util::CatalogText{"open.cannot",
                "файл не открывается: «%1»",
                "cannot open: %1"},
    util::CatalogText{"open.unreadable",
                "файл не читается: «%1»",
                "cannot be read: %1"},
    util::CatalogText{"open.not-regular.character-device",
                "%1: это не обычный файл (символьное устройство); база данных — обычный файл: укажите другой путь --db",
                "%1: is not a regular file (a character device); a database is a regular file — give another --db path"},
    util::CatalogText{"open.not-regular.block-device",
                "%1: это не обычный файл (блочное устройство); база данных — обычный файл: укажите другой путь --db",
                "%1: is not a regular file (a block device); a database is a regular file — give another --db path"},
    util::CatalogText{"open.not-regular.fifo",
                "%1: это не обычный файл (именованный канал); база данных — обычный файл: укажите другой путь --db",
                "%1: is not a regular file (a FIFO); a database is a regular file — give another --db path"},
    util::CatalogText{"open.not-regular.socket",
                "%1: это не обычный файл (сокет); база данных — обычный файл: укажите другой путь --db",
                "%1: is not a regular file (a socket); a database is a regular file — give another --db path"},
    util::CatalogText{"open.not-regular.other",
                "%1: это не обычный файл (не файл); база данных — обычный файл: укажите другой путь --db",
                "%1: is not a regular file (not a file); a database is a regular file — give another --db path"},
    util::CatalogText{"open.no-handle",
                "файл не читается: SQLite не открыла его",
                "cannot be read: SQLite did not open the file"},
    util::CatalogText{"open.busy",
                "другая программа держала базу данных заблокированной дольше времени ожидания (SQLite: «%1»)",
                "another program kept the database locked longer than the busy timeout (%1)"},
    util::CatalogText{"open.not-database",
                "файл не читается как база данных (SQLite: «%1»)",
                "cannot be read as a database (%1)"},
    util::CatalogText{"open.damaged",
                "база данных повреждена (проверка целостности, SQLite: «%1»)",
                "the database is damaged (integrity check: %1)"},
    util::CatalogText{"open.damaged-keys",
                "база данных повреждена (проверка целостности: %1 строк нарушают внешние ключи; первая — "
                "%2, строка %3 -> %4)",
                "the database is damaged (integrity check: %1 rows break foreign keys (first: %2 row %3 "
                "-> %4))"},
    util::CatalogText{"open.no-version",
                "база данных K528 Studio без версии схемы",
                "K528 Studio database without a schema version"},
    util::CatalogText{"open.foreign-journal",
                "это не база данных K528 Studio: база данных SQLite без application_id K528 Studio, с "
                "незавершённой транзакцией другой программы (горячий журнал %1, начат на файле из %2 "
                "страниц), откатывать её не нам: пусть сначала её откроет та программа",
                "not a K528 Studio database: an SQLite database without K528 Studio's application_id, "
                "with an unfinished transaction of another program (the hot journal %1, begun on a file "
                "of %2 pages), which is not ours to roll back: let that program open it first"},
    util::CatalogText{"open.foreign-journal.size",
                "это не база данных K528 Studio: база данных SQLite без application_id K528 Studio, с "
                "незавершённой транзакцией другой программы (горячий журнал %1, начат на файле "
                "неизвестного размера), откатывать её не нам: пусть сначала её откроет та программа",
                "not a K528 Studio database: an SQLite database without K528 Studio's application_id, "
                "with an unfinished transaction of another program (the hot journal %1, begun on a file "
                "of unknown size), which is not ours to roll back: let that program open it first"},
    util::CatalogText{"open.foreign-writer",
                "пока файл создавался, в него записала другая программа",
                "another program wrote into the file while it was being created"},
    util::CatalogText{"open.wal",
                "не переключается в режим журнала WAL (режим «%1»): другой процесс держал базу данных "
                "занятой дольше времени ожидания",
                "cannot switch to WAL journal mode (mode \"%1\"): another process kept the database busy "
                "longer than the busy timeout"},
    // PostgreSQL's database that is not ours, or not yet.
    util::CatalogText{"pg.no-schema",
                "путь поиска не называет ни одной существующей схемы; создайте её или задайте search_path "
                "(options=-csearch_path=…)",
                "the search path names no schema that exists; create it or set search_path "
                "(options=-csearch_path=…)"},
    util::CatalogText{"pg.foreign-tables",
                "это не база данных K528 Studio: в ней %1 таблиц или представлений другой программы (нет "
                "k528_schema); ничего не изменено",
                "not a K528 Studio database: it holds %1 tables or views of another program (no "
                "k528_schema); nothing was changed"},
    util::CatalogText{"pg.foreign-application",
                "это не база данных K528 Studio (в k528_schema — «%1»); ничего не изменено",
                "not a K528 Studio database (k528_schema says \"%1\"); nothing was changed"},
    util::CatalogText{"pg.schema-empty",
                "таблица k528_schema пуста",
                "the table k528_schema is empty"},
    util::CatalogText{"pg.no-database",
                "нет базы данных K528 Studio в %1 (база данных пуста; создать её: k528 db init --db %1)",
                "no K528 Studio database at %1 (the database is empty; create one with: k528 db init --db "
                "%1)"},
    util::CatalogText{"pg.not-empty",
                "%1: база данных не пуста (версия схемы %2); копия записывается только в пустую",
                "%1: not an empty database (schema version %2); a copy goes only into an empty one"},
    util::CatalogText{"pg.old-server",
                "PostgreSQL %1 слишком стар; K528 Studio нужна версия 11 или новее",
                "PostgreSQL %1 is too old; K528 Studio needs version 11 or newer"},
    util::CatalogText{"pg.encoding",
                "кодировка базы данных — %1; K528 Studio хранит русские тексты, ей нужна UTF8 "
                "(createdb --encoding=UTF8 --template=template0)",
                "the database's encoding is %1; K528 Studio keeps Russian texts and needs UTF8 "
                "(createdb --encoding=UTF8 --template=template0)"},
    util::CatalogText{"busy.write.session",
                "%1: другой сеанс пишет в базу данных и держит её заблокированной дольше времени "
                "ожидания; ничего не записано, повторите",
                "%1: another session is writing to the database and kept it locked longer than the "
                "busy timeout; nothing was written, try again"},
    util::CatalogText{"role.unknown",
                "нет роли «%1»: роли — trainer, technologist, operator и viewer",
                "no role \"%1\": the roles are trainer, technologist, operator and viewer"},
    // The message history (db/message_log.h).
    util::CatalogText{"messages.no-run",
                "нет прогона сообщений %1; ничего не записано",
                "no message run %1; nothing was written"},
    util::CatalogText{"messages.no-run-id",
                "у нового прогона нет номера",
                "the new run has no id"},
    util::CatalogText{"messages.busy",
                "другой процесс держал базу данных заблокированной дольше времени ожидания; сообщения "
                "не записаны",
                "another process kept the database locked longer than the busy timeout; the messages "
                "were not written"},
    util::CatalogText{"messages.no-how",
                "событие сообщения %1 прогона %2: квитировано без указания, как",
                "message event %1 of run %2: acknowledged without saying how"},
    util::CatalogText{"messages.not-raised",
                "событие сообщения %1 прогона %2: такое сообщение не выдавалось",
                "message event %1 of run %2: no such message was raised"},
    util::CatalogText{"messages.bad-source",
                "строка истории сообщений %1: неизвестный источник «%2»",
                "message history row %1: unknown source \"%2\""},
    util::CatalogText{"messages.none-written",
                "; ни одно из %1 событий пакета не записано",
                "; none of the batch's %1 events was written"},
    // A push of a database machine's programs (transfer::checkReleased).
    util::CatalogText{"push.unreleased",
                "станок %1: передаются только выпущенные программы; не выпущены в этом виде:",
                "machine %1: a push takes released programs only; not released as they are:"},
    util::CatalogText{"push.not-in-database",
                "L%1: нет в базе данных, ничего из неё не выпущено",
                "L%1: not in the database, nothing of it released"},
    util::CatalogText{"push.draft",
                "L%1: черновик, ничего из неё не выпущено",
                "L%1: draft, nothing of it released"},
    util::CatalogText{"push.withdrawn",
                "L%1: отозвана, ничего из неё не выпущено",
                "L%1: withdrawn, nothing of it released"},
    util::CatalogText{"push.not-released-version",
                "L%1: не выпущенная версия (ревизия %2)",
                "L%1: not the released version (revision %2)"},
    util::CatalogText{"push.release-them",
                "выпустите их (k528 db release %1 L<n>) или разрешите технологам передавать черновики: "
                "k528 db set %1 push.unreleased=true",
                "release them (k528 db release %1 L<n>), or let technologists push drafts: k528 db set %1 "
                "push.unreleased=true"},
    util::CatalogText{"push.release-them.technologist",
                "выпустите их (k528 db release %1 L<n>) или передайте их как технолог (станок разрешает "
                "черновики: push.unreleased)",
                "release them (k528 db release %1 L<n>), or push as a technologist (the machine allows "
                "drafts: push.unreleased)"},
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
