// Basic types of the positioner engine: axes, modes (manual 2.6), program
// states, and the refusal codes of the operator functions.
#pragma once

#include "axis/constants.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace k528::engine {

using axis::AxisId;

inline constexpr int kAxisCount = 2;
constexpr int axisIndex(AxisId a) {
    return static_cast<int>(a);
}
constexpr AxisId axisAt(int i) {
    return i == 0 ? AxisId::X : AxisId::Z;
}

// The working modes of 2.6, numbered as their keys F1..F7 and as the PLC's
// mode code Z1000.8-10 (1..7).
enum class Mode : std::uint8_t {
    Auto = 1,      // АВТОМАТ <F1>
    Manual = 2,    // РУЧНОЙ <F2>
    Reference = 3, // ПРИВЯЗКА К БАЗОВОЙ ТОЧКЕ <F3>
    SetActual = 4, // ПРЕДУСТАНОВКИ / установка фактического значения <F4>
    MachineData = 5, // РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ <F5>
    ProgramEdit = 6, // РЕДАКТИРОВАНИЕ УП <F6>
    DataControl = 7, // УПРАВЛЕНИЕ ДАННЫМИ <F7>
};

constexpr int modeKey(Mode m) {
    return static_cast<int>(m);
}
constexpr bool validModeKey(int f) {
    return f >= 1 && f <= 7;
}
// Screen tag of the first LCD line: «АВТ», «РУЧ», «ПБТ», «УСТ», «ПАР», «РЕД», «УПР».
std::string_view modeTagRu(Mode m);
std::string_view modeNameRu(Mode m); // «АВТОМАТ», «РУЧНОЙ», ...
std::string_view modeNameEn(Mode m); // "automatic", "manual", ...

// What the interpreter is doing (one value for the panel and Z2000).
enum class ProgramState : std::uint8_t {
    Idle,        // no program (after power-on or «Сброс»)
    Running,     // executing frames or a motion
    Dwell,       // G04
    WaitingM,    // M function handed to the PLC, waiting for its acknowledgement
    M0,          // stopped by M00, waiting for «Пуск»
    Interrupted, // «Стоп» or a mode change; «Пуск» continues
    Ended,       // M02/M30 or the end of the main program; «Пуск» restarts
    Alarm,       // stopped by a message; «Пуск» starts again from the top
};
std::string_view programStateName(ProgramState s); // "idle", "running", ...
// Running, Dwell or WaitingM: the program is being executed.
constexpr bool executing(ProgramState s) {
    return s == ProgramState::Running || s == ProgramState::Dwell || s == ProgramState::WaitingM;
}
// A program is under way (executing, or held by M00 / «Стоп»).
constexpr bool programActive(ProgramState s) {
    return executing(s) || s == ProgramState::M0 || s == ProgramState::Interrupted;
}

// Why an operator function was refused.
enum class Refusal : std::uint8_t {
    None,
    ModeFromPlc,     // the PLC imposes the mode (Z1000.8-10 != 0)
    WrongMode,       // the function belongs to another mode
    ProgramActive,   // not while a program runs or is held
    ReadOnly,        // R232..R262
    NoSuchParameter, // number outside the table
    ValueOutOfRange, // value outside the parameter's range
    NoSuchProgram,   // program number not in the store (or outside 1..99)
    AxisAbsent,      // НАЛИЧ.ОСИ = 0
    NoSuchKey,       // L1..L4, F1..F7
    NotPowered,      // before powerOn()
};

// An operator function's answer: accepted, or refused with why as an id of
// refusal_texts.h and its arguments (the value and the limit).
struct OpResult {
    Refusal refusal = Refusal::None;
    std::string id;
    std::vector<std::string> args;

    bool ok() const { return refusal == Refusal::None; }
    // Why, in Russian or English (refusal_texts.h; "" when accepted).
    std::string text(bool russian = false) const;
    static OpResult accepted() { return {}; }
    static OpResult refused(Refusal r, std::string id, std::vector<std::string> args = {}) {
        return {r, std::move(id), std::move(args)};
    }
};

} // namespace k528::engine
