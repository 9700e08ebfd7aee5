// The machine constants of the K528-05: the 152 C-parameter definitions of
// appendix Е, table Е.1 (numbers, panel names, descriptions, units, ranges,
// addresses in the positioner).
//
// Parameters 1..52 describe axis X, 53..104 axis Z with the same layout
// (C(n + 52) is the Z counterpart of X's C(n)), 105..152 are common.
// Ranges are the ones printed in table Е.1; where the table prints none the
// range is our decision, listed in docs/machine-constants.md and in the
// definition's `note`.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace k528::catalog {

inline constexpr int kCParamCount = 152;
// Offset from an X parameter to its Z counterpart (C5 -> C57).
inline constexpr int kAxisBlock = 52;

enum class Axis { X, Z, Common };

// "X", "Z" or "" for common parameters.
std::string_view axisName(Axis a);

enum class Kind {
    Flag,     // 0 or 1
    Integer,  // a number in its unit
    Code,     // an enumeration (channel, fast-input function, override code)
    Reserved, // «Резерв»: no meaning, value 0
};

enum class Unit {
    None,            // reserved parameters
    Flag,            // 0/1
    ChannelCode,     // 1..4: module and channel (N ДОС, N ЦАП, N M1/M2)
    MotionDiscretes, // discretes of slide motion (L ИМП.ДОС, КОМП.ЛЮФТА, МНОЖИТ.)
    Discretes,       // display discretes of the axis (coordinates, homing distances)
    EncoderPulses,     // encoder pulses after ×4 (N ИМП.ДОС)
    DiscretesPerPulse, // motion discretes per handwheel pulse (МНОЖИТ.М1/М2)
    Ms,                // milliseconds
    Accel,             // 25600·A/Kd, A in m/s² (formulas 2 and 3 of parameter 22)
    GainKs,            // speed gain Ks
    GainKe,            // error gain Ke
    DacUnits,          // DAC codes: 2047 = +10 V
    InternalUnits,     // ½ discrete of motion (note * of table Е.1)
    Speed,             // 10·discretes/min
    FastInputFunction, // function number of tables Е.1.1 / Е.1.2
    OverrideCode,      // 0..10 -> 0..100 % (table 3)
    ProgramNumber,     // 0..99
};

// Short unit text: Russian, English, and an ASCII-ish symbol used in CSV.
std::string_view unitRu(Unit u);
std::string_view unitEn(Unit u);
std::string_view unitSymbol(Unit u);
std::string_view kindName(Kind k); // "flag", "integer", "code", "reserved"

// Where a parameter lives in the positioner's memory (column «Адрес в БП»).
enum class AddressForm {
    None,     // not printed (reserved parameters)
    Bit,      // Z4100.3
    Word,     // Z4101
    LowByte,  // Z4202, Мл.байт
    HighByte, // Z4202, Ст.байт
    TwoWords, // Z4124, Z4125: a 32-bit value in two consecutive words
};

struct Address {
    AddressForm form = AddressForm::None;
    int word = 0; // e.g. 4100 for Z4100
    int bit = 0;  // for AddressForm::Bit
    // As the manual prints it: "Z4100.3", "Z4101", "Z4202, Мл.байт", "Z4124, Z4125", "".
    std::string text() const;
    // English: "Z4100.3", "Z4101", "Z4202 low byte", "Z4124, Z4125".
    std::string textEn() const;
};

struct CParamDef {
    int number;
    Axis axis;
    Kind kind;
    Unit unit;
    std::int64_t min;
    std::int64_t max;
    Address address;
    std::string_view name;          // panel name, table Е.1 (≤ 20 characters)
    std::string_view nameEn;        // our English panel name
    std::string_view descriptionRu; // the table's text, markup removed
    std::string_view descriptionEn; // our translation
    std::string_view hintRu;        // explanatory line (≤ 20 characters) or ""
    std::string_view hintEn;
    std::string_view note; // OCR fixes and range decisions (English) or ""

    bool inRange(std::int64_t v) const { return v >= min && v <= max; }
    bool reserved() const { return kind == Kind::Reserved; }
    // "C022"
    std::string key() const;
};

// All 152 definitions in number order: cParams()[i].number == i + 1.
std::span<const CParamDef> cParams();

// The definition of C-parameter `number` (1..152); throws std::out_of_range.
const CParamDef& cParam(int number);
// nullptr when `number` is not 1..152.
const CParamDef* findCParam(int number) noexcept;

// The other axis' counterpart of an axis parameter (5 -> 57, 57 -> 5), 0 for common ones.
int counterpart(int number);

// The number of X parameter `xNumber` (1..52) on `axis` (X: itself, Z: +52).
constexpr int axisParam(int xNumber, Axis axis) {
    return axis == Axis::Z ? xNumber + kAxisBlock : xNumber;
}

// Looks a parameter up by its panel name on one axis (axis ignored for common
// names). Case-insensitive; Latin and Cyrillic look-alike letters (K/К, M/М,
// X/Х, ...) are the same, as they are on the panel.
const CParamDef* findCParamByName(std::string_view name, Axis axis);

// Named X numbers (use axisParam() for Z) and common numbers, so code does not
// spell magic numbers.
namespace c {
inline constexpr int kAxisPresent = 1;         // НАЛИЧ.ОСИ
inline constexpr int kEncoderSign = 2;         // ЗНАК ДОС
inline constexpr int kDacSign = 3;             // ЗНАК ЦАП
inline constexpr int kDiscrete0001 = 4;        // 0.0001
inline constexpr int kDiscrete001 = 5;         // 0.001
inline constexpr int kDiscrete01 = 6;          // 0.01
inline constexpr int kDiameter = 7;            // ИНД.ДИАМЕТР
inline constexpr int kAutoWithoutHoming = 8;   // АВТ.БЕЗ ПБТ
inline constexpr int kHomeMinus = 9;           // ПБТ В "-"
inline constexpr int kSoftLimitsOn = 10;       // ВКЛ.ПРГ.КОН
inline constexpr int kWheel1Sign = 11;         // ЗНАК М1
inline constexpr int kWheel2Sign = 12;         // ЗНАК М2
inline constexpr int kAdjustOn = 13;           // ВКЛ.ПОДНАЛ.
inline constexpr int kEncoderCheckAtRest = 14; // Контр.ДОС в останове
inline constexpr int kEncoderChannel = 17;     // N ДОС
inline constexpr int kDacChannel = 18;         // N ЦАП
inline constexpr int kEncoderL = 19;           // L ИМП.ДОС
inline constexpr int kEncoderN = 20;           // N ИМП.ДОС
inline constexpr int kEncoderCheckMs = 21;     // T контроля ДОС
inline constexpr int kAccel1 = 22;             // УСКОРЕНИЕ 1
inline constexpr int kAccel2 = 23;             // УСКОРЕНИЕ 2
inline constexpr int kWheel1Mult = 24;         // МНОЖИТ.М1
inline constexpr int kWheel2Mult = 25;         // МНОЖИТ.М2
inline constexpr int kKs = 26;                 // К(СКОР)
inline constexpr int kKe = 27;                 // К(ОШИБ)
inline constexpr int kDacLimit = 28;           // ПРЕДЕЛ ЦАП
inline constexpr int kDacMax = 29;             // МАКС.ЦАП
inline constexpr int kMaxError = 30;           // МАКС.ОШИБКА
inline constexpr int kPosTolerance = 31;       // ДОПУСК ПОЗ.
inline constexpr int kCheckDelayMs = 32;       // ЗАДЕРЖКА КП
inline constexpr int kClampTolerance = 33;     // ДОПУСК КП
inline constexpr int kDriftComp = 34;          // КОМП.ДРЕЙФА
inline constexpr int kBacklash = 35;           // КОМП.ЛЮФТА
inline constexpr int kRegBlockDelayMs = 36;    // ЗАДЕРЖКА БР
inline constexpr int kBeforeZeroSearch = 37;   // S до поиска 0-метки
inline constexpr int kZeroSearch = 38;         // S поиска 0-метки
inline constexpr int kHomeOffset = 39;         // СМЕЩЕНИЕ БТ
inline constexpr int kFeedNormal = 40;         // F ОБЫЧНАЯ
inline constexpr int kFeedRapid = 41;          // F УСКОРЕН.
inline constexpr int kFeedAutoRapid = 42;      // F УСК.АВТ.
inline constexpr int kFeedHomeStart = 43;      // F СТАРТ БТ
inline constexpr int kFeedHomeCreep = 44;      // F ОТКЛ.БТ
inline constexpr int kHomeValue = 45;          // ЗНАЧЕНИЕ БТ
inline constexpr int kLimitMinus = 46;         // -ОГРАНИЧЕН
inline constexpr int kLimitPlus = 47;          // +ОГРАНИЧЕН
inline constexpr int kHomeCamLength = 48;      // S конечника БТ
inline constexpr int kWheel1Channel = 105;     // N M1
inline constexpr int kWheel2Channel = 106;     // N M2
inline constexpr int kFastInputX1 = 107;       // N Б.ВХ. X1 .. X8 = 107..114
inline constexpr int kFastInputZ1 = 115;       // N Б.ВХ. Z1 .. Z8 = 115..122
inline constexpr int kEscResets = 123;
inline constexpr int kEscAcksMachine = 124;
inline constexpr int kEscAcksSystem = 125;
inline constexpr int kOverrideL1 = 139;   // Корректор по L1 .. L4 = 139..142
inline constexpr int kManualCycle1 = 143; // N ручного цикла 1 .. 8 = 143..150
} // namespace c

} // namespace k528::catalog
