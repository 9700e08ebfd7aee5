#include "db/explain.h"

#include "catalog/cparams.h"
#include "profile/calculator.h"
#include "profile/validate.h"
#include "units/units.h"

#include <cmath>
#include <cstdio>

namespace k528::db {

namespace cat = k528::catalog;
namespace cc = k528::catalog::c;

namespace {

// Fixed decimals, trailing zeros (and a trailing point) removed.
std::string num(double v, int decimals) {
    return units::formatTrimmed(v, decimals);
}

struct Text {
    Lang lang;
    std::string operator()(std::string_view ru, std::string_view en) const {
        return std::string(lang == Lang::Ru ? ru : en);
    }
};

} // namespace

std::string_view fastInputFunction(int function, bool zAxis, Lang lang) {
    // Tables Е.1.1 and Е.1.2 (the functions 1..6 are the same).
    static constexpr std::string_view kRu[] = {
        "Сброс системы в исходное состояние",
        "Ось в режиме индикации",
        "Готовность привода оси",
        "Ограничение перемещения в «+»",
        "Ограничение перемещения в «-»",
        "Торможение перед опорной точкой",
    };
    static constexpr std::string_view kEn[] = {
        "Reset the system to the initial state",
        "Axis in display mode",
        "Axis drive ready",
        "Travel limit in «+»",
        "Travel limit in «-»",
        "Deceleration before the reference point",
    };
    static constexpr std::string_view kXRu[] = {
        "Стирание остатка пути – сигнал 1 (от реле касания)",
        "Стирание остатка пути – сигнал 2 (от ПАК «черновой припуск снят»)",
        "Стирание остатка пути – сигнал 3 (от ПАК «чистовой припуск снят»)",
        "Стирание остатка пути – сигнал 4 (от ПАК «размер»)",
    };
    static constexpr std::string_view kXEn[] = {
        "Erase the distance to go – signal 1 (touch relay)",
        "Erase the distance to go – signal 2 (gauge: rough allowance removed)",
        "Erase the distance to go – signal 3 (gauge: finish allowance removed)",
        "Erase the distance to go – signal 4 (gauge: size reached)",
    };
    static constexpr std::string_view kZRu[] = {
        "Стирание остатка пути – сигнал 1 (торможение при осевой ориентации)",
        "Стирание остатка пути – сигнал 2 (конец осевой ориентации)",
        "Стирание остатка пути – сигнал 3 (переориентация при осевой ориентации)",
    };
    static constexpr std::string_view kZEn[] = {
        "Erase the distance to go – signal 1 (deceleration in axial orientation)",
        "Erase the distance to go – signal 2 (end of axial orientation)",
        "Erase the distance to go – signal 3 (re-orientation in axial orientation)",
    };
    const bool ru = lang == Lang::Ru;
    if (function >= 1 && function <= 6)
        return ru ? kRu[function - 1] : kEn[function - 1];
    if (!zAxis && function >= 7 && function <= 10)
        return ru ? kXRu[function - 7] : kXEn[function - 7];
    if (zAxis && function >= 7 && function <= 9)
        return ru ? kZRu[function - 7] : kZEn[function - 7];
    return {};
}

std::string programTitle(std::string_view text) {
    const auto end = text.find('\n');
    const std::string_view first = text.substr(0, end);
    if (!profile::programHeaderNumber(first))
        return {};
    const auto open = first.find('(');
    const auto close = first.rfind(')');
    if (open == std::string_view::npos || close == std::string_view::npos || close < open)
        return {};
    return std::string(first.substr(open + 1, close - open - 1));
}

std::string explainCValue(const profile::MachineProfile& p, int number, Lang lang) {
    const cat::CParamDef& d = cat::cParam(number);
    const std::int64_t v = p.cValue(number);
    const Text t{lang};
    const bool axisParam = d.axis != cat::Axis::Common;
    const cat::Axis axis = axisParam ? d.axis : cat::Axis::X;
    const units::AxisScale s = profile::axisScale(p, axis);
    const int x = axisParam && d.axis == cat::Axis::Z ? number - cat::kAxisBlock : number;
    const std::string mm = t(" мм", " mm");
    const std::string dia = s.diameter ? t(" на диаметр", " on the diameter") : "";
    const auto value = [&](int xn) { return profile::axisValue(p, axis, xn); };

    switch (d.unit) {
    case cat::Unit::None:
        return t("резерв", "reserved");
    case cat::Unit::Flag:
        return v == 1 ? t("да", "yes") : v == 0 ? t("нет", "no") : "";
    case cat::Unit::ChannelCode: {
        if (v < 1 || v > 4)
            return t("нет такого канала", "no such channel");
        if (x == cc::kDacChannel)
            return t("канал " + std::to_string(v) + " модуля СМ32.03",
                     "channel " + std::to_string(v) + " of the CM32.03 module");
        const int module = v <= 2 ? 1 : 2, channel = v % 2 == 1 ? 1 : 2;
        return t(std::to_string(module) + "-й модуль СР34.23, канал " + std::to_string(channel),
                 "CP34.23 module " + std::to_string(module) + ", channel " +
                     std::to_string(channel));
    }
    case cat::Unit::MotionDiscretes:
    case cat::Unit::EncoderPulses:
        if (x == cc::kEncoderL || x == cc::kEncoderN) {
            const std::int64_t l = value(cc::kEncoderL), n = value(cc::kEncoderN);
            if (n <= 0 || l <= 0)
                return "L/N = " + std::to_string(l) + "/" + std::to_string(n);
            return "L/N = " + std::to_string(l) + "/" + std::to_string(n) + ": " +
                   num(static_cast<double>(l) / static_cast<double>(n) * s.discreteMm(), 7) + mm +
                   t(" на импульс ДОС", " per encoder pulse");
        }
        return "= " + num(static_cast<double>(v) * s.discreteMm(), 4) + mm;
    case cat::Unit::DiscretesPerPulse:
        if (v == 0)
            return t("маховик не действует на ось", "the handwheel does not move the axis");
        return "= " + num(static_cast<double>(v) * s.discreteMm(), 4) + mm +
               t(" на импульс маховика", " per handwheel pulse");
    case cat::Unit::Discretes:
        return "= " + units::formatDisc(v, s) + mm + dia;
    case cat::Unit::Ms:
        if (v == 0 && x == cc::kEncoderCheckMs)
            return t("контроль не производится", "no check");
        return "= " + num(static_cast<double>(v) / 1000.0, 3) + t(" с", " s");
    case cat::Unit::Accel: {
        if (v == 0)
            return x == cc::kAccel2 ? t("0: как УСКОРЕНИЕ 1", "0: as ACCELERATION 1")
                                    : t("нет ускорения: ось не разгонится",
                                        "no acceleration: the axis cannot start");
        std::string r = "= " + num(units::accelParamToMPerS2(v, s), 4) + t(" м/с²", " m/s²");
        if (x == cc::kAccel1) {
            const auto sum = profile::calc::summarizeAxis(p, axis);
            if (sum.runUpToAutoRapidMs > 0)
                r += t("; разгон до F УСК.АВТ. за ", "; run-up to F AUTO RAPID in ") +
                     num(sum.runUpToAutoRapidMs, 0) + t(" мс", " ms");
        }
        return r;
    }
    case cat::Unit::GainKs:
    case cat::Unit::GainKe:
        return {};
    case cat::Unit::DacUnits:
        return "= " + num(static_cast<double>(v) * 10.0 / 2047.0, 2) + t(" В", " V");
    case cat::Unit::InternalUnits:
        return "= " + num(static_cast<double>(v) * s.internalMotionMm(), 5) + mm;
    case cat::Unit::Speed:
        return "= " + num(units::speedParamToMmPerMin(v, s), 4) + t(" мм/мин", " mm/min");
    case cat::Unit::FastInputFunction: {
        if (v == 0)
            return t("вход не используется", "input not used");
        const auto f = fastInputFunction(static_cast<int>(v), number >= cc::kFastInputZ1, lang);
        return f.empty() ? t("нет такой функции", "no such function") : std::string(f);
    }
    case cat::Unit::OverrideCode:
        if (v < 0 || v > 10)
            return t("нет такого кода", "no such code");
        return "= " + std::to_string(units::overrideCodeToPercent(static_cast<int>(v))) + " %";
    case cat::Unit::ProgramNumber: {
        if (v == 0)
            return t("цикл не задан", "cycle not defined");
        const auto it = p.programs.find(static_cast<int>(v));
        if (it == p.programs.end())
            return "L" + std::to_string(v) +
                   t(": программы нет (сообщение 45)", ": no such program (message 45)");
        const std::string title = programTitle(it->second);
        return "L" + std::to_string(v) + (title.empty() ? "" : " (" + title + ")");
    }
    }
    return {};
}

} // namespace k528::db
