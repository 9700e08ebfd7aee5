#include "link/link_texts.h"

#include "profile/problem.h"
#include "program/diagnostic_texts.h"

#include <array>

namespace k528::link {

namespace {

using util::CatalogText;

constexpr std::array kTexts = {
    // Joins: the words around them are texts of their own.
    CatalogText{"link.join", "%1: %2", "%1: %2"},
    CatalogText{"link.then", "%1; %2", "%1; %2"},
    CatalogText{"link.list", "%1, %2", "%1, %2"},
    // The controller's exceptions (shared/spec/link.md).
    CatalogText{"link.exception-1", "исключение 01: контроллер не знает этой функции",
                "exception 01: the controller does not know this function"},
    CatalogText{"link.exception-2", "исключение 02: регистр вне карты контроллера (или запись в регистр только для чтения)",
                "exception 02: a register outside the controller's map (or a read-only one written)"},
    CatalogText{"link.exception-3", "исключение 03: значение вне своего диапазона; ничего из запроса не записано",
                "exception 03: a value outside its range; nothing of the request was written"},
    CatalogText{"link.exception-6",
                "исключение 06: контроллер не в F7 «РАБОТА С ПЭВМ» (УПРАВЛЕНИЕ ДАННЫМИ): выберите этот пункт на K923, "
                "чтобы записывать",
                "exception 06: the controller is not in F7 «РАБОТА С ПЭВМ» (УПРАВЛЕНИЕ ДАННЫМИ): select it on the "
                "K923 to write"},
    CatalogText{"link.exception", "исключение %1", "exception %1"},
    // The transfer's status register.
    CatalogText{"link.status-0", "свободен", "idle"},
    CatalogText{"link.status-1", "готов", "ready"},
    CatalogText{"link.status-2", "записано", "committed"},
    CatalogText{"link.status-16", "контроллер не в F7 «РАБОТА С ПЭВМ»", "the controller is not in F7 «РАБОТА С ПЭВМ»"},
    CatalogText{"link.status-17", "такой программы в контроллере нет", "no such program in the controller"},
    CatalogText{"link.status-18", "контроллер отклонил текст", "the controller refused the text"},
    CatalogText{"link.status-19", "не совпали CRC или длина: текст пришёл повреждённым и не сохранён",
                "CRC or length mismatch: the text arrived damaged and was not stored"},
    CatalogText{"link.status-20", "память контроллера заполнена", "the controller's memory is full"},
    CatalogText{"link.status", "состояние %1", "status %1"},
    // What an exchange did.
    CatalogText{"link.reading", "чтение регистров %1", "reading registers %1"},
    CatalogText{"link.writing", "запись регистров %1", "writing registers %1"},
    CatalogText{"link.echo", "эхо", "echo"},
    CatalogText{"link.diagnostics", "диагностика %1", "diagnostics %1"},
    CatalogText{"link.server-id", "идентификатор сервера", "server id"},
    // No answer after every attempt.
    CatalogText{"link.no-answer", "%1: контроллер не отвечает (попыток: %2)",
                "%1: the controller does not answer (%2 attempts)"},
    CatalogText{"link.no-answer-1", "%1: контроллер не отвечает (попыток: 1)",
                "%1: the controller does not answer (1 attempt)"},
    CatalogText{"link.no-answer-last", "%1: контроллер не отвечает (попыток: %2, последняя: %3)",
                "%1: the controller does not answer (%2 attempts, last: %3)"},
    CatalogText{"link.no-answer-1-last", "%1: контроллер не отвечает (попыток: 1, последняя: %2)",
                "%1: the controller does not answer (1 attempt, last: %2)"},
    // The transport's word on the last attempt.
    CatalogText{"link.timeout", "время ожидания истекло", "timeout"},
    CatalogText{"link.crc-error", "ошибка CRC", "CRC error"},
    CatalogText{"link.port-closed", "порт закрыт", "the port is closed"},
    CatalogText{"link.connection-closed", "соединение закрыто", "the connection is closed"},
    CatalogText{"link.echo-differs", "эхо не совпадает", "the echo differs"},
    CatalogText{"link.empty-answer", "пустой ответ", "an empty answer"},
    CatalogText{"link.port-reopen", "порт закрыт и не открывается снова: %1",
                "the port is closed and does not open again: %1"},
    CatalogText{"link.port-failed", "отказ порта: %1", "the port failed: %1"},
    CatalogText{"link.connection-reopen", "соединение закрыто и не открывается снова: %1",
                "the connection is closed and does not open again: %1"},
    CatalogText{"link.connection-failed", "отказ соединения: %1", "the connection failed: %1"},
    CatalogText{"link.cannot-connect", "нет соединения с %1: %2", "cannot connect to %1: %2"},
    // A frame's own words (English: the frame log's) said by kind in Russian.
    CatalogText{"link.damaged", "повреждённый кадр", "%1"},
    CatalogText{"link.bad-reply", "ответ не к этому запросу", "%1"},
    CatalogText{"link.lost", "нет ответа", "%1"},
    // The line's failures (the plugins map Qt's error codes to these).
    CatalogText{"line.refused", "соединение отклонено", "connection refused"},
    CatalogText{"line.remote-closed", "другая сторона закрыла соединение", "the other end closed the connection"},
    CatalogText{"line.host-not-found", "узел не найден", "host not found"},
    CatalogText{"line.connect-timeout", "нет соединения за %1 мс", "no connection within %1 ms"},
    CatalogText{"line.socket-timeout", "время ожидания сокета истекло", "the socket timed out"},
    CatalogText{"line.network", "сеть недоступна", "the network is unreachable"},
    CatalogText{"line.socket-access", "нет доступа к сокету", "access to the socket denied"},
    CatalogText{"line.address-in-use", "адрес уже занят", "the address is in use"},
    CatalogText{"line.socket-other", "ошибка сокета: %1", "socket error: %1"},
    CatalogText{"line.port-not-found", "порт не найден", "no such port"},
    CatalogText{"line.port-permission", "нет доступа к порту (или он занят другой программой)",
                "permission denied (or another program holds the port)"},
    CatalogText{"line.port-open", "порт уже открыт", "the port is already open"},
    CatalogText{"line.port-unsupported", "порт не принимает эти настройки", "the port does not take these settings"},
    CatalogText{"line.port-gone", "порт пропал (отключён?)", "the port is gone (unplugged?)"},
    CatalogText{"line.port-io", "ошибка чтения или записи порта", "the port failed to read or write"},
    CatalogText{"line.port-timeout", "время ожидания порта истекло", "the port timed out"},
    CatalogText{"line.port-not-open", "порт не открыт", "the port is not open"},
    CatalogText{"line.port-other", "ошибка порта: %1", "port error: %1"},
    CatalogText{"line.bad-address", "«%1» — не ХОСТ:ПОРТ (порт 1..65535)", "'%1' is not HOST:PORT (a port 1..65535)"},
    // Not in F7 «РАБОТА С ПЭВМ»: what to do on the K923 (%1 the action).
    CatalogText{"link.not-ready-menu",
                "контроллер в F7 УПРАВЛЕНИЕ ДАННЫМИ, но не на «РАБОТА С ПЭВМ»: выберите «РАБОТА С ПЭВМ» в его меню "
                "на K923 (▲ ▼, ENTER) и повторите %1; ничего не отправлено",
                "the controller is in F7 УПРАВЛЕНИЕ ДАННЫМИ but not on «РАБОТА С ПЭВМ»: choose «РАБОТА С ПЭВМ» in its "
                "menu on the K923 (▲ ▼, ENTER), then %1 again; nothing was sent"},
    CatalogText{"link.not-ready-mode",
                "контроллер не в F7 «РАБОТА С ПЭВМ» (сейчас режим F%2): нажмите F7 (УПРАВЛЕНИЕ ДАННЫМИ) на K923, "
                "выберите «РАБОТА С ПЭВМ» и повторите %1; ничего не отправлено",
                "the controller is not in F7 «РАБОТА С ПЭВМ» (mode F%2 now): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on the "
                "K923 and choose «РАБОТА С ПЭВМ», then %1 again; nothing was sent"},
    CatalogText{"link.not-ready-power",
                "контроллер не в F7 «РАБОТА С ПЭВМ» (идёт включение): нажмите F7 (УПРАВЛЕНИЕ ДАННЫМИ) на K923, "
                "выберите «РАБОТА С ПЭВМ» и повторите %1; ничего не отправлено",
                "the controller is not in F7 «РАБОТА С ПЭВМ» (powering on): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on the "
                "K923 and choose «РАБОТА С ПЭВМ», then %1 again; nothing was sent"},
    CatalogText{"link.action-push", "передачу", "push"},
    CatalogText{"link.action-clear-c", "очистку C", "clear C"},
    CatalogText{"link.action-clear-r", "очистку R", "clear R"},
    CatalogText{"link.action-set", "запись %1", "set %1"},
    // The parts a transfer moves.
    CatalogText{"link.part-c", "C-параметры", "C-parameters"},
    CatalogText{"link.part-r", "R-параметры", "R-parameters"},
    CatalogText{"link.part-r-range", "R-параметры (%1)", "R-parameters (%1)"},
    CatalogText{"link.part-messages", "сообщения", "messages"},
    CatalogText{"link.part-program", "программа %1", "program %1"},
    // Transfers and their checks.
    CatalogText{"link.clear-c", "очистка C", "clear C"},
    CatalogText{"link.clear-r", "очистка R", "clear R"},
    CatalogText{"link.clear-c-not-zero", "очистка C: блок C не читается нулями",
                "clear C: the C block does not read back as zeros"},
    CatalogText{"link.text-length", "контроллер объявил текст длиной %1 байт",
                "the controller announces a text of %1 bytes"},
    CatalogText{"link.text-crc", "прочитанный текст не совпадает со своей CRC-32",
                "the text read does not match its CRC-32"},
    CatalogText{"link.refused-at-line", "%1 в строке %2", "%1 at line %2"},
    CatalogText{"link.window-offset", "окно карты не следует за своим смещением",
                "the map's window does not follow its offset"},
    CatalogText{"link.text-differs", "%1: текст, прочитанный обратно, отличается от отправленного",
                "%1: the text read back differs from the text sent"},
    CatalogText{"link.block-refused", "%1: контроллер отклонил блок", "%1: the controller refused the block"},
    CatalogText{"link.block-refused-at", "%1: контроллер отклонил блок на C%2",
                "%1: the controller refused the block at C%2"},
    CatalogText{"link.block-differs", "%1: значения, прочитанные обратно, отличаются от отправленных",
                "%1: the values read back differ from those sent"},
    CatalogText{"link.c-no-address", "C%1 не имеет адреса в позиционере (таблица Е.1): её нельзя записать",
                "C%1 has no address in the positioner (table Е.1): it cannot be written"},
    CatalogText{"link.c-value-refused", "C%1 = %2: контроллер отклонил значение (вне таблицы Е.1)",
                "C%1 = %2: the controller refused the value (outside table Е.1)"},
    CatalogText{"link.read-back-differs", "%1: контроллер при чтении не возвращает то, что записано",
                "%1: the controller does not read back what was written"},
    CatalogText{"link.r-read-only", "R%1 по линии только читается (ПЭВМ записывает %2)",
                "R%1 is read only over the link (the PC writes %2)"},
    CatalogText{"link.r-32-bits", "R%1 = %2 не помещается в 32 бита", "R%1 = %2 is outside 32 bits"},
    // A file to push that is wrong: nothing was sent.
    CatalogText{"link.nothing-sent", "%1; ничего не отправлено", "%1; nothing was sent"},
    CatalogText{"link.c-table", "C%1 (%2): %3 (таблица Е.1)", "C%1 (%2): %3 (table Е.1)"},
    CatalogText{"link.r-outside", "R%1 не помещается в 32 бита", "R%1 is outside the 32-bit range"},
    CatalogText{"link.program-line", "программа %1, строка %2: %3", "program %1, line %2: %3"},
    CatalogText{"link.program-not-one", "программа %1 содержит не ровно одну эту программу",
                "program %1 does not hold exactly that program"},
    CatalogText{"link.program-says", "программа %1: %2", "program %1: %2"},
    CatalogText{"link.file-line", "%1:%2: %3", "%1:%2: %3"},
    CatalogText{"link.file-empty", "%1 не содержит ни программы (%L), ни %MESSAGES",
                "%1 holds no program (%L) and no %MESSAGES"},
    CatalogText{"link.file-before-header", "%1: текст до первого заголовка %L не относится ни к одной программе",
                "%1: the text before the first %L header belongs to no program"},
    CatalogText{"link.file-controller", "%1:%2: %3 (проверено по константам и программам контроллера)",
                "%1:%2: %3 (checked against the controller's constants and programs)"},
    // Where a push ended.
    CatalogText{"link.push-new", "записано: %1", "new: %1"},
    CatalogText{"link.push-in-doubt",
                "под вопросом (линия оборвалась во время записи; считайте память, чтобы узнать): %1",
                "in doubt (the line broke while it was committed; pull to see): %1"},
    CatalogText{"link.push-as-it-was", "как было: %1", "as they were: %1"},
    // A line's counters (describe(LineStats)).
    CatalogText{"link.stats-answer", "ответов: %1", "%1 answer"},
    CatalogText{"link.stats-answers", "ответов: %1", "%1 answers"},
    CatalogText{"link.stats-timeout", "тайм-аутов: %1", "%1 timeout"},
    CatalogText{"link.stats-timeouts", "тайм-аутов: %1", "%1 timeouts"},
    CatalogText{"link.stats-crc-error", "ошибок CRC: %1", "%1 CRC error"},
    CatalogText{"link.stats-crc-errors", "ошибок CRC: %1", "%1 CRC errors"},
    CatalogText{"link.stats-bad-reply", "неподходящих ответов: %1", "%1 bad reply"},
    CatalogText{"link.stats-bad-replies", "неподходящих ответов: %1", "%1 bad replies"},
    CatalogText{"link.stats-exception", "исключений: %1", "%1 exception"},
    CatalogText{"link.stats-exceptions", "исключений: %1", "%1 exceptions"},
    CatalogText{"link.stats-retry", "повторов: %1", "%1 retry"},
    CatalogText{"link.stats-retries", "повторов: %1", "%1 retries"},
    CatalogText{"link.stats-split", "запросов, посланных снова половинами: %1", "%1 request sent again in halves"},
    CatalogText{"link.stats-splits", "запросов, посланных снова половинами: %1", "%1 requests sent again in halves"},
    CatalogText{"link.stats-round-trip", "; время отклика: медиана %1 мс, 95-й процентиль %2 мс",
                "; round trip median %1 ms, p95 %2 ms"},
    // A station of a bus scan (describe(StationInfo)).
    CatalogText{"link.scan-station", "адрес %1: %2", "address %1: %2"},
    CatalogText{"link.scan-no-answer", "нет ответа", "no answer"},
    CatalogText{"link.scan-garbled", "повреждённый ответ (другая скорость или чётность?)",
                "a damaged answer (another baud rate or parity?)"},
    CatalogText{"link.scan-echo-ok", "эхо в порядке", "echo ok"},
    CatalogText{"link.scan-echo-exception", "исключение %1 в ответ на эхо", "exception %1 to the echo"},
    CatalogText{"link.scan-server-id", "; идентификатор сервера %1", "; server id %1"},
    CatalogText{"link.scan-running", ", работает", ", running"},
    CatalogText{"link.scan-no-server-id", "; нет идентификатора сервера (функция 17)", "; no server id (FC 17)"},
    CatalogText{"link.scan-map", "; карта K528-05: режим F%1", "; K528-05 map: mode F%1"},
    CatalogText{"link.scan-program", ", программа %1", ", program %1"},
    CatalogText{"link.scan-programs", ", программ: %1", ", %1 programs"},
    CatalogText{"link.scan-alarms", ", аварии", ", alarms"},
    CatalogText{"link.scan-round-trip", "; время отклика %1 мс", "; round trip %1 ms"},
    // The desktop's own reasons.
    CatalogText{"link.cancelled", "отменено пользователем", "cancelled by the user"},
    CatalogText{"link.closed", "соединение закрыто", "closed"},
};

constexpr char kMark = kLineErrorMark;

} // namespace

util::TextCatalog linkTexts() { return util::TextCatalog(kTexts); }

Said saidDiagnostic(const program::Diagnostic& d) {
    Said s;
    s.diagnostic = std::make_shared<const program::Diagnostic>(d);
    return s;
}

Said saidProblem(const profile::Problem& p) {
    Said s;
    s.problem = std::make_shared<const profile::Problem>(p);
    return s;
}

std::string render(const Said& s, bool russian) {
    if (s.diagnostic)
        return program::diagnosticText(*s.diagnostic, russian);
    if (s.problem)
        return profile::problemText(*s.problem, russian);
    if (s.id.empty())
        return s.word;
    std::vector<std::string> args;
    args.reserve(s.args.size());
    for (const Said& a : s.args)
        args.push_back(render(a, russian));
    return linkTexts().render(s.id, args, russian);
}

Said decodeSaid(std::string_view text) {
    if (text.empty() || text.front() != kMark)
        return Said(std::string(text));
    text.remove_prefix(1);
    std::vector<Said> parts;
    std::size_t pos = 0;
    for (;;) {
        const std::size_t next = text.find(kMark, pos);
        parts.emplace_back(std::string(text.substr(pos, next == std::string_view::npos ? text.npos : next - pos)));
        if (next == std::string_view::npos)
            break;
        pos = next + 1;
    }
    Said s(parts.front().word, {});
    s.args.assign(parts.begin() + 1, parts.end());
    return s;
}

} // namespace k528::link
