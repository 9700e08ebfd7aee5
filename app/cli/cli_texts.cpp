#include "cli_texts.h"

#include <array>
#include <span>

namespace k528::cli {

namespace {

using util::CatalogText;

// The labels of a report's lines are as wide in each language (the values
// start in one column): 10 characters in English, 12 in Russian.
constexpr std::array kTexts = {
    // ---- k528 db: what the subcommands report on standard output.
    CatalogText{"db.database", "база данных %1", "database  %1"},
    CatalogText{"db.init.created", "схема       версия %1 (создана)", "schema    version %1 (created)"},
    CatalogText{"db.init.upgraded", "схема       версия %1 (обновлена с версии %2)",
                "schema    version %1 (upgraded from version %2)"},
    CatalogText{"db.init.current", "схема       версия %1 (актуальна)", "schema    version %1 (up to date)"},
    CatalogText{"db.init.loaded", "загружены   %1 (встроенные станки)", "loaded    %1 (built-in machines)"},
    CatalogText{"db.init.recovered", "восстановлено: %1-journal — прерванная транзакция откачена",
                "recovered %1-journal: an interrupted transaction was rolled back"},
    CatalogText{"db.init.read-only", "доступ      только чтение (%1)", "access    read-only (%1)"},
    CatalogText{"db.init.machines", "станков     %1", "machines  %1"},
    // `db machines`: the columns and an empty list.
    CatalogText{"db.machines.machine", "СТАНОК", "MACHINE"},
    CatalogText{"db.machines.revision", "РЕВ", "REV"},
    CatalogText{"db.machines.changed", "ИЗМЕНЁН", "CHANGED"},
    CatalogText{"db.machines.by", "КЕМ", "BY"},
    CatalogText{"db.machines.title", "НАЗВАНИЕ", "TITLE"},
    CatalogText{"db.machines.none", "(станков нет: k528 db import ФАЙЛ добавляет станок)",
                "(no machines: k528 db import FILE adds one)"},
    // A machine's head lines (`db show`) and its programs.
    CatalogText{"db.show.machine", "станок      %1", "machine   %1"},
    CatalogText{"db.show.revision-of", "ревизия     %1 (текущая %2)", "revision  %1 (current %2)"},
    CatalogText{"db.show.revision", "ревизия     %1, изменил %3, %2", "revision  %1, changed %2 by %3"},
    CatalogText{"db.show.program-lines", "строк: %1  sha256 %2", "%1 lines  sha256 %2"},
    CatalogText{"db.show.no-program", "у станка %1 нет программы L%2", "machine %1 has no program L%2"},
    CatalogText{"db.show.note", "  примечание: %1", "  note: %1"},
    CatalogText{"db.state.draft", "черновик", "draft"},
    CatalogText{"db.state.released", "выпущена", "released"},
    CatalogText{"db.state.withdrawn", "отозвана", "withdrawn"},
    CatalogText{"db.state.released-revision", " (выпущена ревизия %1)", " (released: revision %1)"},
    CatalogText{"db.state.released-by", " — выпустил %1, %2", " by %1 %2"},
    // Changes: of a revision (`db show --history`), of a write (`db set`, `db import`).
    CatalogText{"db.change.added", "добавлена", "added"},
    CatalogText{"db.change.removed", "удалена", "removed"},
    CatalogText{"db.change.changed", "изменена", "changed"},
    CatalogText{"db.change.none", "(нет)", "(none)"},
    CatalogText{"db.changes.one", "1 изменение", "1 change"},
    CatalogText{"db.changes.many", "изменений: %1", "%1 changes"},
    CatalogText{"db.saved", "%1: ревизия %2 (%3)", "%1: revision %2 (%3)"},
    CatalogText{"db.saved.nothing", "%1: изменений нет (ревизия %2)", "%1: no changes (revision %2)"},
    CatalogText{"db.history.of", "история %1:", "history of %1:"},
    CatalogText{"db.history.of-none", "история %1: изменений не записано", "history of %1: no changes recorded"},
    CatalogText{"db.history.entry", "  ревизия %1  %2  %3: ", "  revision %1  %2  %3: "},
    CatalogText{"db.history.revision", "ревизия %1  %2  %3  %4 (%5)", "revision %1  %2  %3  %4 (%5)"},
    CatalogText{"db.history.first", "  (станок в первом сохранённом виде: k528 db export %1@1)",
                "  (the machine as first stored: k528 db export %1@1)"},
    // `db diff`.
    CatalogText{"db.diff.none", "различий нет", "no differences"},
    CatalogText{"db.diff.builtin", "%1 (встроенный)", "%1 (built-in)"},
    CatalogText{"db.diff.neither", "«%1» — не станок %2, не СТАНОК@РЕВ, не файл станка и не встроенный профиль",
                "'%1' is neither a machine of %2, MACHINE@REV, a machine file nor a built-in profile"},
    // `db import`.
    CatalogText{"db.import.exists",
                "станок %1 уже есть в %2 (ревизия %3): с --replace файл записывается его следующей ревизией, "
                "с --as ИМЯ — под другим именем; ничего не импортировано",
                "machine %1 already exists in %2 (revision %3): --replace stores the file as its next revision, "
                "--as NAME imports it under another name; nothing was imported"},
    // `db copy`.
    CatalogText{"db.copy.copied", "скопирована  %1 -> %2", "copied    %1 -> %2"},
    CatalogText{"db.copy.machines", "станков     %1, ревизий %2, версий программ %3, выпусков %4",
                "machines  %1, revisions %2, program versions %3, releases %4"},
    CatalogText{"db.copy.logs", "журналы     сообщений %1, записей аудита %2, передач %3",
                "logs      %1 messages, %2 audit entries, %3 transfers"},
    CatalogText{"db.copy.rows", "строк       %1 в одной транзакции", "rows      %1 in one transaction"},
    // `db release`, `db withdraw`.
    CatalogText{"db.released", "выпущена    %1 L%2 в ревизии %3 (SHA-256 %4…): %5, %6%7",
                "released  %1 L%2 as of revision %3 (SHA-256 %4…) by %5 at %6%7"},
    CatalogText{"db.withdrawn", "отозвана    %1 L%2 в ревизии %3 (SHA-256 %4…): %5, %6%7",
                "withdrawn %1 L%2 as of revision %3 (SHA-256 %4…) by %5 at %6%7"},
    // `db log`: the transfers.
    CatalogText{"db.log.none", "передач в журнале нет", "no transfers on record"},
    CatalogText{"db.log.none-for", "передач станка %1 в журнале нет", "no transfers on record for %1"},
    CatalogText{"db.log.messages", "сообщения", "messages"},
    CatalogText{"db.log.push", "в станок", "push"},
    CatalogText{"db.log.pull", "из станка", "pull"},
    CatalogText{"db.log.ok", "успешно", "ok"},
    CatalogText{"db.log.partial", "частично", "partial"},
    CatalogText{"db.log.failed", "ошибка", "failed"},
    // `db roles`.
    CatalogText{"db.roles.sqlite",
                "роли        нет: у базы данных SQLite один пользователь, которому можно всё (роли "
                "k528_technologist, k528_operator и k528_viewer есть у PostgreSQL)",
                "roles     none: an SQLite database has one user, who may do everything (the roles "
                "k528_technologist, k528_operator and k528_viewer are PostgreSQL's)"},
    CatalogText{"db.roles.members", "члены: %1", "members: %1"},
    CatalogText{"db.roles.no-members", "нет", "none"},
    CatalogText{"db.role.viewer", "читать станки, программы, историю, сообщения и передачи",
                "read machines, programs, history, messages and transfers"},
    CatalogText{"db.role.operator", "то же, что наблюдатель; записывать передачи и сообщения; передавать в станок "
                                    "выпущенные программы",
                "a viewer's; record transfers and messages; push released programs"},
    CatalogText{"db.role.technologist",
                "то же, что оператор; изменять станки, выпускать и отзывать программы, передавать черновики, "
                "где станок это разрешает",
                "an operator's; change machines, release and withdraw programs, push drafts where the machine "
                "allows"},
    CatalogText{"db.role.trainer",
                "то же, что технолог; блокировать и разблокировать константы станка для группы (constants.lock), "
                "записывать и читать учебные попытки группы",
                "a technologist's; lock and unlock the machine constants for a class (constants.lock), record and "
                "read the class's training attempts"},

    // ---- k528 db: usage errors.
    CatalogText{"db.usage.revision", "«%1»: после @ нужен номер ревизии больше 0",
                "'%1': the revision after @ must be a positive number"},
    CatalogText{"db.usage.release", "db %1 нужны станок и программа: k528 db %1 СТАНОК L<n> [--note ТЕКСТ]",
                "db %1 takes a machine and a program: k528 db %1 MACHINE L<n> [--note TEXT]"},
    CatalogText{"db.usage.program", "«%1»: программа — L1..L99", "'%1': a program is L1..L99"},
    CatalogText{"db.usage.log", "db log принимает не больше одного станка: k528 db log [СТАНОК] [--since ВРЕМЯ]",
                "db log takes at most one machine: k528 db log [MACHINE] [--since TIME]"},
    CatalogText{"db.usage.since", "после --since нужно время вида 2024-05-17 или 2024-05-17T08:30:00Z, а не «%1»",
                "--since takes a time as 2024-05-17 or 2024-05-17T08:30:00Z, not '%1'"},
    CatalogText{"db.usage.limit", "--limit N: N — 0 (все) или больше", "--limit N: N must be 0 (all) or more"},
    CatalogText{"db.usage.show-one", "db show принимает один из параметров --c, --r, --programs, --program, --messages",
                "db show takes one of --c, --r, --programs, --program, --messages"},
    CatalogText{"db.usage.show-c", "--c: «%1» — не номер C-параметра 1..152",
                "--c: '%1' is not a C-parameter number 1..152"},
    CatalogText{"db.usage.show-r", "--r: «%1» — не номер R-параметра 0..299",
                "--r: '%1' is not an R-parameter number 0..299"},
    CatalogText{"db.usage.show-program", "--program: «%1» — не номер программы 1..99",
                "--program: '%1' is not a program number 1..99"},
    CatalogText{"db.usage.history", "--history N: N — число ревизий (0 — все)",
                "--history N: N must be a number of revisions (0 = all)"},
    CatalogText{"db.usage.format", "--format — k528m или csv, а не «%1»", "--format is k528m or csv, not '%1'"},
    CatalogText{"db.usage.import", "db import нужен один ФАЙЛ (файл станка .k528m или CSV с --as)",
                "db import needs one FILE (a machine file .k528m, or CSV with --as)"},
    CatalogText{"db.usage.import-csv",
                "в файле CSV только константы: назовите станок, чьи константы он заменяет, через --as ИМЯ",
                "a CSV file holds only the constants: name the machine whose constants it replaces with --as NAME"},

    // ---- k528 shop.
    CatalogText{"shop.usage", "shop нужна подкоманда status или publish: k528 shop status [--json] [СТАНОК…], "
                              "k528 shop publish --mqtt mqtt://ХОСТ[:ПОРТ] [СТАНОК…]",
                "shop needs status or publish: k528 shop status [--json] [MACHINE…], "
                "k528 shop publish --mqtt mqtt://HOST[:PORT] [MACHINE…]"},
    CatalogText{"shop.usage.mqtt", "shop publish нужен --mqtt mqtt://ХОСТ[:ПОРТ]",
                "shop publish needs --mqtt mqtt://HOST[:PORT]"},
    CatalogText{"shop.no-machine", "нет станка «%1» в базе данных (список станков: k528 db machines)",
                "no machine '%1' in the database (k528 db machines lists them)"},
    CatalogText{"shop.no-line",
                "у станка «%1» нет линии: k528 db set %1 line=tcp://ХОСТ:ПОРТ/УСТРОЙСТВО (или "
                "line=serial:ПОРТ?address=1)",
                "machine '%1' has no line: k528 db set %1 line=tcp://HOST:PORT/UNIT (or "
                "line=serial:DEVICE?address=1)"},
    CatalogText{"shop.bad-line", "станок «%1»: %2", "machine '%1': %2"},
    CatalogText{"shop.no-lines",
                "k528 shop: ни у одного станка базы данных нет линии (k528 db set СТАНОК "
                "line=tcp://ХОСТ:ПОРТ/УСТРОЙСТВО)",
                "k528 shop: no machine of the database has a line (k528 db set MACHINE "
                "line=tcp://HOST:PORT/UNIT)"},
    // A machine's state, one line (`shop status`, `shop status --watch`).
    CatalogText{"shop.online", "на связи", "online"},
    CatalogText{"shop.offline", "нет связи", "offline"},
    CatalogText{"shop.run", "работа", "run"},
    CatalogText{"shop.idle", "простой", "idle"},
    CatalogText{"shop.alarm", "авария", "alarm"},
    CatalogText{"shop.live", " F%1%2, программа %3 N%4", " F%1%2, program %3 N%4"},
    CatalogText{"shop.live-alarm", "; авария %1", "; alarm %1"},
    CatalogText{"shop.since", "; с %1 (%2 с)", "; since %1 (%2 s)"},
    CatalogText{"shop.alarm-raised", "%1: авария %2 возникла в %3", "%1 alarm %2 raised at %3"},
    CatalogText{"shop.alarm-cleared", "%1: авария %2 снята в %3", "%1 alarm %2 cleared at %3"},
    // `shop publish` on standard error.
    CatalogText{"shop.publish.start", "k528 shop publish: станков: %1, каждые %2 мс в %3 как %4",
                "k528 shop publish: %1 machines every %2 ms to %3 as %4"},
    CatalogText{"shop.publish.no-broker", "k528 shop publish: нет подключения к %1: «%2»",
                "k528 shop publish: cannot connect to %1: %2"},
    CatalogText{"shop.publish.unacknowledged", "k528 shop publish: брокер подтвердил не все сообщения",
                "k528 shop publish: the broker did not acknowledge every message"},
    CatalogText{"shop.publish.stopped", "k528 shop publish: остановлен; отправлено сообщений: %1",
                "k528 shop publish: stopped after %1 messages"},
    CatalogText{"shop.stdout-lost", "k528: стандартный вывод не записывается", "k528: cannot write standard output"},
    // Usage errors of k528-link's half.
    CatalogText{"shop.usage.sub", "shop принимает status или publish", "shop takes status or publish"},
    CatalogText{"shop.usage.line", "после --line нужно СТАНОК=ЛИНИЯ, а не «%1»", "--line takes MACHINE=LINE, not '%1'"},
    CatalogText{"shop.usage.line-machine", "станок %1: %2", "machine %1: %2"},
    CatalogText{"shop.usage.interval", "после --interval-ms нужно 10..3600000", "--interval-ms takes 10..3600000"},
    CatalogText{"shop.usage.mqtt-status", "--mqtt — параметр shop publish", "--mqtt is an option of shop publish"},
    CatalogText{"shop.usage.watch", "--interval-ms и --seconds — параметры shop status --watch и shop publish",
                "--interval-ms and --seconds go with shop status --watch or shop publish"},

    // ---- Options several commands share.
    CatalogText{"opt.lang", "--lang — ru или en, а не «%1»", "--lang is ru or en, not '%1'"},
    CatalogText{"opt.timeout", "после --timeout-ms нужно 10..60000", "--timeout-ms takes 10..60000"},
    CatalogText{"opt.seconds", "после --seconds нужна длительность в секундах", "--seconds takes a duration in seconds"},
};

} // namespace

util::TextCatalog cliTexts() { return util::TextCatalog(kTexts); }

std::string cliText(std::string_view id, std::initializer_list<std::string> args, bool russian) {
    return cliTexts().render(id, std::span<const std::string>(args.begin(), args.size()), russian);
}

} // namespace k528::cli
