// Read-only views of the engine's state for displays (K923 panel, desktop,
// `k528 run`). Values as the panel shows them: coordinates in display
// discretes of the axis (format with units::formatDisc), feeds in display
// discretes per minute, the diagnostic ABS/ERR in internal units (2.6).
#pragma once

#include "engine/alarms.h"
#include "engine/types.h"
#include "units/units.h"

#include <cstdint>
#include <string>
#include <vector>

namespace k528::profile {
struct MachineProfile;
}

namespace k528::engine {

struct AxisView {
    AxisId axis = AxisId::X;
    bool present = false;
    units::AxisScale scale;
    bool referenced = false;           // the «X»/«Z» flag of the ПБТ screen
    bool referenceOk = false;          // referenced or АВТ.БЕЗ ПБТ (Z2005.4)
    bool homing = false;               // the reference-point cycle runs
    std::int64_t currentDisc = 0;      // 2.4 current coordinate (R234/R235)
    std::int64_t machineDisc = 0;      // machine system (R232/R233)
    std::int64_t remainingDisc = 0;    // остаток пути (R244/R245)
    std::int64_t feedDiscPerMin = 0;   // current speed (R236/R237)
    bool moving = false;               // '*' on the screens
    int dac = 0;                       // DAC_X
    double errorInternal = 0;          // ERR_X: setpoint − actual, internal units
    double absInternal = 0;            // ABS_X: machine system, internal units
    std::int64_t pulsesPerTick = 0;    // PLS_X
    std::int64_t homeDistanceDisc = 0; // # of the ПБТ screen (R246/R247)
    bool limitPlus = false, limitMinus = false, decelCam = false;
    bool atSoftLimit = false;
    bool loopClosed = false, regulatorOn = false, inPosition = true;
    bool oscillating = false;
    int fault = 0; // message number of a servo fault, 0 none
};

// Where the text of the technological message shown comes from. A view of a
// controller on a line, whose texts are the machine file's, keeps the default.
enum class MessageOrigin : std::uint8_t {
    MachineFile, // the machine file's message #k (the file may give its English)
    Program,     // a program file's own text, loaded over the machine's
    None,        // the memory holds no text #k: the panel shows none
};

struct ProgramView {
    Mode mode = Mode::Manual;
    bool modeFromPlc = false; // Z1000.8-10 != 0: F1..F7 refused
    ProgramState state = ProgramState::Idle;
    int selectedProgram = 0;      // R252
    int mainProgram = 0;          // R250: the program of АВТОМАТ or the manual cycle
    int program = 0;              // R253: executing program/subprogram
    int cycle = 0;                // manual cycle 1..8, 0 = АВТОМАТ program
    int frameIndex = 0;           // index of the current frame in its program
    int frameNumber = 0;          // N (R254), 0 if none
    int line = 0;                 // source line of the current frame
    int nesting = 0;              // R158
    int messageNumber = 0;        // # of the technological message shown
    std::string messageText;      // its text ("" if none)
    MessageOrigin messageOrigin = MessageOrigin::MachineFile; // where the text comes from
    int overridePercent = 100;    // R249
    bool overrideFromPlc = false; // Z1001.11
    bool endOrReset = false;      // Z2000.10
    int mCode = -1;               // M being handed over, -1 none
    std::int64_t framesExecuted = 0;
    bool dataHold = false; // Z1000.6
};

struct AlarmView {
    int number = 0;  // 1..64 (appendix М)
    int axis = -1;   // 0 X, 1 Z, -1 none
    int program = 0; // program and line of a program error, else 0
    int line = 0;
    bool active = false; // the cause is present
    bool latched = true;
    AlarmCategory category = AlarmCategory::Fault;
    std::string textRu; // as the panel shows it, without the number
    std::string textEn;
};

// The message as one line with its number, for every place that shows one
// (the panel's lists, `k528 run` and `k528 path`, the desktop): Russian as
// the panel and table М.1 print it — «37. Ошибка N ДОС» but «39.Ошибка N
// маховика», the blank after the dot where the manual has one — and English
// always with the blank («37. N encoder error»).
std::string alarmText(const AlarmView& a, bool russian);

// The technological message of `v` for a reader of English or Russian: the
// machine file's (v.messageOrigin) in the English `machine` gives for it,
// else the text as the panel shows it — a program's own text stays as
// written, even when it reads as the machine's.
std::string programMessageText(const ProgramView& v, const profile::MachineProfile& machine,
                               bool english);

// The PLC messages as the panel lists them (bit k-1 = message k).
struct PlcMessagesView {
    std::uint32_t alarms = 0;        // shown (latched) machine alarms, Z1900/Z1901
    std::uint32_t alarmsPresent = 0; // their bits now
    std::uint32_t work = 0;          // Z1902/Z1903
    std::uint16_t system = 0;        // shown system messages, Z1307
    std::uint16_t systemPresent = 0;
};

} // namespace k528::engine
