#include "catalog/cparams.h"

#include "util/utf8.h"

#include <stdexcept>
#include <string>

namespace k528::catalog {

std::string_view axisName(Axis a) {
    switch (a) {
    case Axis::X:
        return "X";
    case Axis::Z:
        return "Z";
    case Axis::Common:
        return "";
    }
    return "";
}

std::string_view unitRu(Unit u) {
    switch (u) {
    case Unit::None:
        return "";
    case Unit::Flag:
        return "флаг 0/1";
    case Unit::ChannelCode:
        return "код канала 1...4";
    case Unit::MotionDiscretes:
        return "дискреты перемещения";
    case Unit::Discretes:
        return "дискреты индикации";
    case Unit::EncoderPulses:
        return "импульсы ДОС (x4)";
    case Unit::DiscretesPerPulse:
        return "дискрет на импульс";
    case Unit::Ms:
        return "мс";
    case Unit::Accel:
        return "25600*A/Кд (A в м/с²)";
    case Unit::GainKs:
        return "коэффициент Ks";
    case Unit::GainKe:
        return "коэффициент Ke";
    case Unit::DacUnits:
        return "единицы ЦАП (2047 = 10 В)";
    case Unit::InternalUnits:
        return "внутрисистемные единицы (1/2 дискреты)";
    case Unit::Speed:
        return "10*дискрет/мин";
    case Unit::FastInputFunction:
        return "функция (табл. Е.1.1, Е.1.2)";
    case Unit::OverrideCode:
        return "код корректора 0...10";
    case Unit::ProgramNumber:
        return "номер УП";
    }
    return "";
}

std::string_view unitEn(Unit u) {
    switch (u) {
    case Unit::None:
        return "";
    case Unit::Flag:
        return "flag 0/1";
    case Unit::ChannelCode:
        return "channel code 1...4";
    case Unit::MotionDiscretes:
        return "motion discretes";
    case Unit::Discretes:
        return "display discretes";
    case Unit::EncoderPulses:
        return "encoder pulses (x4)";
    case Unit::DiscretesPerPulse:
        return "discretes per pulse";
    case Unit::Ms:
        return "ms";
    case Unit::Accel:
        return "25600*A/Kd (A in m/s²)";
    case Unit::GainKs:
        return "gain Ks";
    case Unit::GainKe:
        return "gain Ke";
    case Unit::DacUnits:
        return "DAC units (2047 = 10 V)";
    case Unit::InternalUnits:
        return "internal units (1/2 discrete)";
    case Unit::Speed:
        return "10*discretes/min";
    case Unit::FastInputFunction:
        return "function (tables E.1.1, E.1.2)";
    case Unit::OverrideCode:
        return "override code 0...10";
    case Unit::ProgramNumber:
        return "program number";
    }
    return "";
}

std::string_view unitSymbol(Unit u) {
    switch (u) {
    case Unit::None:
        return "";
    case Unit::Flag:
        return "flag";
    case Unit::ChannelCode:
        return "channel";
    case Unit::MotionDiscretes:
        return "disc";
    case Unit::Discretes:
        return "disc";
    case Unit::EncoderPulses:
        return "pulses";
    case Unit::DiscretesPerPulse:
        return "disc/pulse";
    case Unit::Ms:
        return "ms";
    case Unit::Accel:
        return "25600*A/Kd";
    case Unit::GainKs:
        return "Ks";
    case Unit::GainKe:
        return "Ke";
    case Unit::DacUnits:
        return "dac";
    case Unit::InternalUnits:
        return "internal";
    case Unit::Speed:
        return "10*disc/min";
    case Unit::FastInputFunction:
        return "function";
    case Unit::OverrideCode:
        return "override";
    case Unit::ProgramNumber:
        return "program";
    }
    return "";
}

std::string_view kindName(Kind k) {
    switch (k) {
    case Kind::Flag:
        return "flag";
    case Kind::Integer:
        return "integer";
    case Kind::Code:
        return "code";
    case Kind::Reserved:
        return "reserved";
    }
    return "";
}

// (Strings are built with append: GCC 12 at -O3 reports a false -Wrestrict for
// chains of operator+ on short strings.)
std::string Address::text() const {
    std::string s = "Z";
    s += std::to_string(word);
    switch (form) {
    case AddressForm::None:
        return "";
    case AddressForm::Bit:
        s += '.';
        s += std::to_string(bit);
        return s;
    case AddressForm::Word:
        return s;
    case AddressForm::LowByte:
        s += ", Мл.байт";
        return s;
    case AddressForm::HighByte:
        s += ", Ст.байт";
        return s;
    case AddressForm::TwoWords:
        s += ", Z";
        s += std::to_string(word + 1);
        return s;
    }
    return "";
}

std::string Address::textEn() const {
    std::string s = "Z";
    s += std::to_string(word);
    switch (form) {
    case AddressForm::LowByte:
        s += " low byte";
        return s;
    case AddressForm::HighByte:
        s += " high byte";
        return s;
    default:
        return text();
    }
}

std::string CParamDef::key() const {
    const std::string n = std::to_string(number);
    std::string s = "C";
    s.append(3 - std::min<std::size_t>(3, n.size()), '0');
    s += n;
    return s;
}

const CParamDef* findCParam(int number) noexcept {
    if (number < 1 || number > kCParamCount)
        return nullptr;
    return &cParams()[static_cast<std::size_t>(number - 1)];
}

const CParamDef& cParam(int number) {
    const CParamDef* d = findCParam(number);
    if (!d)
        throw std::out_of_range("no C-parameter " + std::to_string(number) + " (1..152)");
    return *d;
}

int counterpart(int number) {
    if (number >= 1 && number <= kAxisBlock)
        return number + kAxisBlock;
    if (number > kAxisBlock && number <= 2 * kAxisBlock)
        return number - kAxisBlock;
    return 0;
}

namespace {

// Upper case, Latin look-alikes turned Cyrillic, spaces dropped: the panel
// shows «K» and «К» alike, and the manual's OCR mixes them.
std::string foldName(std::string_view s) {
    std::string out;
    for (char32_t cp : utf8::decode(utf8::toUpper(s))) {
        switch (cp) {
        case U' ':
        case U'\t':
            continue;
        case U'A':
            cp = U'А';
            break;
        case U'B':
            cp = U'В';
            break;
        case U'C':
            cp = U'С';
            break;
        case U'E':
            cp = U'Е';
            break;
        case U'H':
            cp = U'Н';
            break;
        case U'K':
            cp = U'К';
            break;
        case U'M':
            cp = U'М';
            break;
        case U'O':
            cp = U'О';
            break;
        case U'P':
            cp = U'Р';
            break;
        case U'T':
            cp = U'Т';
            break;
        case U'X':
            cp = U'Х';
            break;
        case U'Y':
            cp = U'У';
            break;
        case U'Ё':
            cp = U'Е';
            break;
        default:
            break;
        }
        utf8::append(out, cp);
    }
    return out;
}

struct Alias {
    std::string_view name;
    int number;
};
// Names other tables of the manual use for the same parameters (table Ж).
constexpr Alias kAliases[] = {
    {"ОТМ=СБРОС", 123},
    {"ОТМ=КВИТ.Н.", 124},
    {"ОТМ=КВИТ.С.", 125},
    {"S кончика БТ", 48},   // C48's printed name, asked for Z
    {"S конечника БТ", 48}, // C100's printed name, asked for X
};

} // namespace

const CParamDef* findCParamByName(std::string_view name, Axis axis) {
    const std::string key = foldName(name);
    if (key.empty())
        return nullptr;
    const CParamDef* found = nullptr;
    for (const CParamDef& d : cParams()) {
        if (d.reserved() || foldName(d.name) != key)
            continue;
        if (d.axis == Axis::Common || d.axis == axis)
            return &d;
        if (!found)
            found = &d;
    }
    if (found && axis == Axis::Common)
        return found; // an axis name asked without an axis: X's
    for (const Alias& a : kAliases) {
        if (foldName(a.name) == key) {
            const CParamDef& d = cParam(a.number);
            return d.axis == Axis::Common
                       ? &d
                       : &cParam(axisParam(a.number, axis == Axis::Z ? Axis::Z : Axis::X));
        }
    }
    return nullptr;
}

} // namespace k528::catalog
