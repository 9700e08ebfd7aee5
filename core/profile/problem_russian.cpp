#include "profile/problem_russian.h"

#include "profile/calculator.h"
#include "profile/cutting.h"
#include "profile/tools.h"
#include "profile/text_format.h"

#include <array>
#include <vector>

namespace k528::profile {

namespace {

struct RussianText {
    std::string_view id, ru;
};

// The Russian of problemTexts(), id by id (the desktop's translation of the
// same English: studio.ui_language compares the two).
constexpr std::array kRussian = {
    RussianText{"file.cannot-read",
                "файл нельзя прочитать: %1"},
    RussianText{"file.cannot-create",
                "файл нельзя создать"},
    RussianText{"file.cannot-write",
                "файл нельзя записать"},
    RussianText{"file.utf8",
                "текст не в кодировке UTF-8"},
    RussianText{"file.bom",
                "позиция %1: U+FEFF (метка порядка байтов) — невидимый символ; такая метка может стоять только в самом начале файла (файлы склеены командой cat?) — удалите её"},
    RussianText{"file.twice",
                "%1 задан дважды (впервые в строке %2)"},
    RussianText{"file.header-bracket",
                "заголовок раздела без «]»: %1"},
    RussianText{"file.end-without-program",
                "[end program] без [program N]"},
    RussianText{"file.unknown-section",
                "неизвестный раздел [%1] (известны: machine, c, r, program N, messages, plc-messages, simulation)"},
    RussianText{"file.program-number",
                "[program N]: N должно быть числом 1..99, а не «%1»"},
    RussianText{"file.program-empty",
                "программа %1 пуста"},
    RussianText{"file.program-bracket",
                "строка программы не может начинаться с «[» (нет [end program] у программы %1 из строки %2?)"},
    RussianText{"file.program-unended",
                "у программы %1 нет [end program]"},
    RussianText{"file.outside-section",
                "строка вне разделов: %1"},
    RussianText{"file.no-equals",
                "ожидалось «ключ=значение»: %1"},
    RussianText{"file.machine-key",
                "неизвестный ключ «%1» в разделе [machine] (format, name, title)"},
    RussianText{"file.format-nan",
                "format: «%1» — не число"},
    RussianText{"file.format-unknown",
                "формат %1 эта программа не читает (читает %2)"},
    RussianText{"file.c-key",
                "неизвестный ключ «%1» в разделе [c] (C001..C152)"},
    RussianText{"file.r-key",
                "неизвестный ключ «%1» в разделе [r] (R0..R299)"},
    RussianText{"file.not-integer",
                "%1: «%2» — не целое число"},
    RussianText{"file.message-key",
                "в разделе [messages] ожидалось #k=текст, а не «%1»"},
    RussianText{"file.message-number",
                "номер сообщения %1 вне #1..#99"},
    RussianText{"file.plc-key",
                "в разделе [plc-messages] ожидалось A01..A32, W01..W32 или S01..S16, а не «%1»"},
    RussianText{"file.plc-number",
                "сообщение ПЛК «%1»: номер должен быть 1..%2"},
    RussianText{"file.no-machine",
                "нет раздела [machine]"},
    RussianText{"file.no-format",
                "в разделе [machine] нет format=%1"},
    RussianText{"file.no-name",
                "в разделе [machine] нет name="},
    RussianText{"file.no-c",
                "нет раздела [c] (152 константы станка)"},
    RussianText{"file.c-lacks",
                "в разделе [c] нет %1 (нужны все 152)"},
    RussianText{"file.c-lacks-more",
                "в разделе [c] нет %1 и ещё %2 (нужны все 152)"},
    RussianText{"builtin.unknown",
                "встроенного профиля с таким именем нет (встроенные: %1)"},
    RussianText{"builtin.none-given",
                "профиль не указан (встроенные: %1)"},
    RussianText{"builtin.neither",
                "это не встроенный профиль (%1) и не файл станка"},
    RussianText{"csv.header",
                "первая строка должна быть заголовком «%1»"},
    RussianText{"csv.fields",
                "ожидалось 5 полей (номер;ось;имя;значение;единица), найдено %1"},
    RussianText{"csv.number",
                "номер «%1» — не C-параметр 1..152"},
    RussianText{"csv.axis",
                "%1 относится к оси «%2», а в строке — «%3»"},
    RussianText{"csv.twice",
                "%1 задан дважды"},
    RussianText{"csv.value",
                "%1: значение «%2» — не целое число"},
    RussianText{"csv.empty",
                "файл пуст: нет строки заголовка"},
    RussianText{"csv.missing",
                "нет %1 (нужны все 152)"},
    RussianText{"csv.quote-open",
                "поле в кавычках не закрыто"},
    RussianText{"csv.quote-text",
                "текст после закрывающей кавычки"},
    RussianText{"name.empty",
                "имя пусто"},
    RussianText{"name.long",
                "имя длиннее 64 символов"},
    RussianText{"name.start",
                "имя «%1» начинается не с a-z и не с 0-9"},
    RussianText{"name.char",
                "в имени «%1» есть символ, кроме a-z, 0-9, «-», «_», «.»"},
    RussianText{"title",
                "название: %1"},
    RussianText{"text.empty",
                "текст пуст"},
    RussianText{"text.utf8",
                "текст не в кодировке UTF-8"},
    RussianText{"text.control",
                "в тексте управляющий символ или перевод строки"},
    RussianText{"text.long",
                "в тексте %1 символов, больше %2"},
    RussianText{"text.trailing-blank",
                "текст кончается пробелом"},
    RussianText{"text.leading-blank",
                "текст начинается с пробела"},
    RussianText{"c.none",
                "C-параметра %1 нет (1..152)"},
    RussianText{"c.range",
                "%1 = %2 вне диапазона %3 константы «%4»"},
    RussianText{"r.none",
                "R-параметра %1 нет (0..299)"},
    RussianText{"r.read-only",
                "R%1 только для чтения (R232..R262): его нельзя задать заранее"},
    RussianText{"r.range",
                "R%1 = %2 вне 32-разрядного диапазона"},
    RussianText{"program.number",
                "номер программы %1 вне 1..99"},
    RussianText{"program.empty",
                "программа L%1: пуста"},
    RussianText{"program.utf8",
                "программа L%1: текст не в кодировке UTF-8"},
    RussianText{"program.no-line-break",
                "программа L%1: текст не кончается переводом строки"},
    RussianText{"program.carriage-return",
                "программа L%1: в тексте возврат каретки (строки кончаются символом LF)"},
    RussianText{"program.bracket",
                "программа L%1: строка %2 начинается с «[» (так начинаются разделы файла станка)"},
    RussianText{"program.header",
                "программа L%1: строка %2 — заголовок программы L%3 (одна программа в записи)"},
    RussianText{"program.messages",
                "программа L%1: строка %2: %MESSAGES место в разделе [messages] файла станка"},
    RussianText{"program.blank",
                "программа L%1: только пустые строки"},
    RussianText{"message.number",
                "номер технологического сообщения %1 вне 1..99"},
    RussianText{"message.text",
                "сообщение #%1: %2"},
    RussianText{"plc.number",
                "сообщение ПЛК %1 вне 1..%2"},
    RussianText{"plc.text",
                "сообщение ПЛК %1: %2"},
    RussianText{"setting.key",
                "моделирование: %1"},
    RussianText{"setting.value",
                "моделирование, %1: %2"},
    RussianText{"key.empty",
                "пустой ключ"},
    RussianText{"key.long",
                "ключ длиннее 64 символов"},
    RussianText{"key.start",
                "ключ «%1» начинается не с буквы a-z"},
    RussianText{"key.char",
                "в ключе «%1» есть символ, кроме a-z, 0-9, «_», «.»"},
    RussianText{"value.utf8",
                "значение не в кодировке UTF-8"},
    RussianText{"value.long",
                "значение длиннее 200 символов"},
    RussianText{"value.lines",
                "значение занимает несколько строк"},
    RussianText{"value.control",
                "в значении управляющий символ"},
    RussianText{"value.semicolon",
                "в значении есть «;» (в файлах станков с неё начинается комментарий)"},
    RussianText{"value.blank",
                "значение начинается или кончается пробелом"},
    RussianText{"value.range",
                "значение %1 вне %2..%3"},
    RussianText{"value.integer",
                "значение «%1» — не целое число"},
    RussianText{"value.number",
                "значение «%1» — не число"},
    RussianText{"value.bool",
                "значение «%1» — не true/false"},
    RussianText{"value.line",
                "%1"},
    RussianText{"tool.kind",
                "«%1» — не вид инструмента (turning, facing, grooving, boring, drill, threading)"},
    RussianText{"tool.value",
                "%1"},
    RussianText{"tool.orientation",
                "«%1» — не одно из +z+x, -z+x, +z-x, -z-x"},
    RussianText{"tool.tip-radius",
                "нужно 0..50 мм"},
    RussianText{"tool.size",
                "нужно больше 0, не больше 1000 мм"},
    RussianText{"tool.depth",
                "нужно 0..100 мм (0 — без предела)"},
    RussianText{"tool.offset",
                "нужен пользовательский R-параметр 0..148 (в нём X, в следующем Z)"},
    RussianText{"tool.key",
                "ключ инструмента — tool.<позиция 1..8>.<ключ>"},
    RussianText{"tool.field",
                "«%1» — не ключ инструмента"},
    RussianText{"tool.no-kind",
                "у инструмента позиции %1 не задан вид (tool.%1.kind)"},
    RussianText{"machine.item",
                "станок %1: %2"},
    RussianText{"calc.vmax",
                "Vmax должна быть положительным числом"},
    RussianText{"calc.run-up",
                "время разгона должно быть положительным числом"},
    RussianText{"calc.braking",
                "путь торможения должен быть положительным числом"},
    RussianText{"calc.acceleration",
                "ускорение должно быть положительным числом"},
    RussianText{"calc.umax",
                "Umax должно быть положительным числом"},
    RussianText{"calc.kv",
                "Kv должен быть положительным числом"},
    RussianText{"calc.screw-lead",
                "шаг винта должен быть положительным числом"},
    RussianText{"calc.gear-ratio",
                "передаточное отношение должно быть положительным числом"},
    RussianText{"calc.encoder-lines",
                "у датчика должен быть хотя бы один штрих"},
    RussianText{"calc.lead-discretes",
                "шаг винта %1 мм — не целое число дискрет (%2 мм)"},
    RussianText{"calc.gear-fraction",
                "передаточное отношение %1 — не дробь со знаменателем до 100000"},
    RussianText{"calc.speed",
                "скорость должна быть нулевой или положительной"},
    RussianText{"calc.feed-reach",
                "наибольшая подача %1 мм/мин больше той, что привод даёт при МАКС.ЦАП (%2 мм/мин)"},
    RussianText{"cutting.cutting-speed",
                "скорость резания должна быть положительным числом"},
    RussianText{"cutting.diameter",
                "диаметр должен быть положительным числом"},
    RussianText{"cutting.spindle-speed",
                "частота вращения шпинделя должна быть положительным числом"},
    RussianText{"cutting.feed",
                "подача на оборот должна быть положительным числом"},
    RussianText{"cutting.wheel-diameter",
                "диаметр круга должен быть положительным числом"},
    RussianText{"cutting.wheel-speed",
                "частота вращения круга должна быть положительным числом"},
    RussianText{"cutting.no-r207",
                "станок не задаёт R207 (диаметр круга)"},
    RussianText{"cutting.no-offset",
                "у инструмента %1 нет R-параметров коррекции (tool.%1.offset_r)"},
    RussianText{"cutting.not-numbers",
                "измеренный размер и размер по чертежу должны быть числами"},
    RussianText{"cutting.r-range",
                "R%1 вышел бы за диапазон R-параметров"},
    RussianText{"cutting.no-tool",
                "нет инструмента в позиции %1"},
};

} // namespace

std::string_view problemRussian(std::string_view id) {
    for (const RussianText& t : kRussian)
        if (t.id == id)
            return t.ru;
    return {};
}

std::string problemText(const Problem& p, bool russian) {
    if (!russian)
        return p.text();
    if (p.id.empty())
        return {};
    std::vector<std::string> all = p.args;
    for (const Problem& w : p.within)
        all.push_back(problemText(w, true));
    const std::string_view ru = problemRussian(p.id);
    return ru.empty() ? p.text() : fillPattern(ru, all);
}

std::string fileErrorText(const FileError& e, bool russian) {
    if (!russian)
        return e.what();
    // The shape of what(): "<source>:<line>: <problem>", as a compiler's.
    return e.source() + (e.line() > 0 ? ":" + std::to_string(e.line()) : std::string()) + ": " +
           problemText(e.problem(), true);
}

std::string errorText(const std::exception& e, bool russian) {
    if (const auto* f = dynamic_cast<const FileError*>(&e))
        return fileErrorText(*f, russian);
    if (const auto* c = dynamic_cast<const cutting::CuttingError*>(&e))
        return problemText(c->problem, russian);
    if (const auto* c = dynamic_cast<const calc::CalcError*>(&e))
        return problemText(c->problem, russian);
    if (const auto* t = dynamic_cast<const ToolError*>(&e))
        return problemText(t->problem(), russian);
    return e.what();
}

} // namespace k528::profile
