// A headless run of a program on the ideal machine, as `k528 run` does it
// (shared/spec/cli.md) and as the benchmark and the tests drive it:
//   power on; load the programs into the store (over the profile's own);
//   preset R-parameters; home every present axis that needs it (АВТ.БЕЗ
//   ПБТ = 0), X first, unless told not to; АВТОМАТ, select the program,
//   «Пуск»; run until the end of the program (M02/M30 or its last frame),
//   a message that stops it, or the time limit. An M00 is continued with
//   «Пуск» after `m0WaitS` (an operator at the machine).
#pragma once

#include "engine/views.h"
#include "profile/profile.h"
#include "program/model.h"

#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace k528::engine {

struct RunOptions {
    std::map<int, std::int64_t> rPresets; // checked by the caller (writable R, 32-bit)
    bool home = true;
    int overridePercent = 100; // one of the override steps
    double maxSeconds = 3600;  // program time limit, from «Пуск»
    double m0WaitS = 0;        // operator's delay before «Пуск» after M00
};

enum class RunStatus { Completed, Alarm, Timeout };
std::string_view runStatusName(RunStatus s); // "completed", "alarm", "timeout"

struct RunAxis {
    bool present = false;
    units::AxisScale scale;
    std::int64_t currentDisc = 0;
    std::int64_t machineDisc = 0;
};

struct RunResult {
    RunStatus status = RunStatus::Completed;
    std::vector<AlarmView> alarms;
    double timeS = 0;     // from «Пуск» to the end
    double homeTimeS = 0; // reference-point cycles
    std::int64_t frames = 0;
    std::array<RunAxis, 2> axes{};
    std::array<std::int32_t, 300> r{};
    // Where it stopped.
    ProgramState state = ProgramState::Idle;
    int program = 0, frameNumber = 0, line = 0;
    int messageNumber = 0;
    std::string messageText;
    std::vector<int> mFunctions; // M codes handed to the PLC, in order
};

// Runs program `number` of `programs` (merged over the profile's programs
// and messages) on `profile`. The profile's C-parameters are used as given.
RunResult runProgram(const profile::MachineProfile& profile, const program::ProgramStore& programs,
                     int number, const RunOptions& options);

} // namespace k528::engine
