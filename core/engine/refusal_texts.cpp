#include "engine/refusal_texts.h"

#include "engine/types.h"
#include "profile/problem.h"

#include <array>

namespace k528::engine {

namespace {

constexpr std::array kTexts = {
    // A refusal of its kind only (an OpResult without an id of its own):
    // refusalKindId.
    util::CatalogText{"kind.mode-from-plc",
                "режим задан из ПЛК",
                "the PLC sets the mode"},
    util::CatalogText{"kind.wrong-mode",
                "не в этом режиме",
                "not in this mode"},
    util::CatalogText{"kind.program-active",
                "выполняется программа",
                "a program is active"},
    util::CatalogText{"kind.read-only",
                "параметр только для чтения",
                "read-only parameter"},
    util::CatalogText{"kind.no-parameter",
                "нет такого параметра",
                "no such parameter"},
    util::CatalogText{"kind.out-of-range",
                "значение вне диапазона",
                "value out of range"},
    util::CatalogText{"kind.no-program",
                "программа отсутствует",
                "no such program"},
    util::CatalogText{"kind.axis-absent",
                "ось отсутствует",
                "the axis is not present"},
    util::CatalogText{"kind.no-key",
                "нет такой клавиши",
                "no such key"},
    util::CatalogText{"kind.not-powered",
                "устройство выключено",
                "the controller is off"},
    util::CatalogText{"mode-key",
                "F%1 не выбирает режим",
                "F%1 selects no mode"},
    util::CatalogText{"mode-from-plc",
                "режим задан из ПЛК (Z1000.8-10 = %1)",
                "the PLC sets the mode (Z1000.8-10 = %1)"},
    util::CatalogText{"override-key",
                "клавиши коррекции — L1..L4, а не L%1",
                "override keys are L1..L4, not L%1"},
    util::CatalogText{"program-number",
                "номера программ — 1..99, а не %1",
                "program numbers are 1..99, not %1"},
    util::CatalogText{"r-number",
                "R-параметры — R0..R299, а не R%1",
                "R-parameters are R0..R299, not R%1"},
    util::CatalogText{"r-read-only",
                "R%1 только для чтения (R232..R262)",
                "R%1 is read only (R232..R262)"},
    util::CatalogText{"r-range",
                "%1 вне диапазона -2147483648..2147483647",
                "%1 is outside -2147483648..2147483647"},
    util::CatalogText{"program-executing",
                "выполняется программа",
                "a program is executing"},
    util::CatalogText{"program-active",
                "программа выполняется или остановлена",
                "a program is active (running or held)"},
    util::CatalogText{"c-number",
                "C-параметры — 1..152, а не %1",
                "C-parameters are 1..152, not %1"},
    util::CatalogText{"c-range",
                "%1 = %2 вне диапазона %3 константы «%4»",
                "%1 = %2 is outside the range %3 of «%4»"},
    util::CatalogText{"c-mode",
                "C-параметры редактируются в режиме РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ (F5)",
                "C-parameters are edited in РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ (F5)"},
    util::CatalogText{"c-count",
                "нужно 153 значения (C1..C152 на местах 1..152)",
                "153 values expected (C1..C152 at 1..152)"},
    util::CatalogText{"c-load-mode",
                "C-параметры загружаются с ЭВМ в режиме УПРАВЛЕНИЕ ДАННЫМИ (F7)",
                "C-parameters are loaded from the PC in УПРАВЛЕНИЕ ДАННЫМИ (F7)"},
    util::CatalogText{"clear-mode",
                "память стирается в режиме УПРАВЛЕНИЕ ДАННЫМИ (F7)",
                "memory is cleared in УПРАВЛЕНИЕ ДАННЫМИ (F7)"},
    util::CatalogText{"axis-absent",
                "ось %1 отсутствует",
                "axis %1 is not present"},
    util::CatalogText{"set-actual-mode",
                "текущее значение задаётся в режиме ПРЕДУСТАНОВКИ (F4)",
                "the current value is set in ПРЕДУСТАНОВКИ (F4)"},
    util::CatalogText{"zero-offset-range",
                "смещение нуля вышло бы за 32-разрядный диапазон",
                "the zero offset would leave the 32-bit range"},
};

} // namespace

util::TextCatalog refusalTexts() { return util::TextCatalog(kTexts); }

std::string_view refusalKindId(Refusal r) {
    switch (r) {
    case Refusal::None:
        return {};
    case Refusal::ModeFromPlc:
        return "kind.mode-from-plc";
    case Refusal::WrongMode:
        return "kind.wrong-mode";
    case Refusal::ProgramActive:
        return "kind.program-active";
    case Refusal::ReadOnly:
        return "kind.read-only";
    case Refusal::NoSuchParameter:
        return "kind.no-parameter";
    case Refusal::ValueOutOfRange:
        return "kind.out-of-range";
    case Refusal::NoSuchProgram:
        return "kind.no-program";
    case Refusal::AxisAbsent:
        return "kind.axis-absent";
    case Refusal::NoSuchKey:
        return "kind.no-key";
    case Refusal::NotPowered:
        return "kind.not-powered";
    }
    return {};
}

std::string refusalText(const OpResult& r, bool russian) {
    if (r.ok())
        return {};
    if (!r.id.empty())
        return refusalTexts().render(r.id, r.args, russian);
    std::string s = refusalTexts().render(refusalKindId(r.refusal), {}, russian);
    for (const std::string& a : r.args)
        s += " " + a;
    return s;
}

std::string OpResult::text(bool russian) const { return refusalText(*this, russian); }

} // namespace k528::engine
