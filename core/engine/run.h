// A headless run of a program, as `k528 run` does it (shared/spec/cli.md) and
// as the benchmark and the tests drive it:
//   switch the machine on; load the programs into the store (over the
//   profile's own); preset R-parameters; home every present axis that needs
//   it (АВТ.БЕЗ ПБТ = 0), X first, unless told not to; АВТОМАТ, select the
//   program, «Пуск»; run until the end of the program (M02/M30 or its last
//   frame), a message that stops it, or the time limit. An M00 is continued
//   with «Пуск» after `m0WaitS` (an operator at the machine).
//
// The run is written against RunMachine — what an operator does at the
// machine — so that it drives the simulated machine of core/machine (what
// `k528 run` uses, machine/run.h) and the engine's ideal machine (its test
// double, below) the same way.
#pragma once

#include "engine/positioner.h"
#include "engine/ideal_machine.h"
#include "engine/views.h"
#include "profile/profile.h"
#include "program/model.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace k528::engine {

struct RunOptions {
    std::map<int, std::int64_t> rPresets; // checked by the caller (writable R, 32-bit)
    bool home = true;
    int overridePercent = 100; // one of the override steps
    double maxSeconds = 3600;  // program time limit, from «Пуск»
    double m0WaitS = 0;        // operator's delay before «Пуск» after M00
    // Start from a frame (engine/start_point.h; preview_run.h findStartPoint):
    // «Пуск» starts the program before this frame with its state rebuilt.
    std::optional<StartPoint> from;
};

// Blocked: the program never started — the machine did not get ready, a
// reference-point cycle did not start, or «Пуск» was not taken; the result's
// blockedBy says why (docs/engine.md). Never a silent timeout.
enum class RunStatus { Completed, Alarm, Timeout, Blocked };
// "completed", "alarm", "timeout", "blocked"
std::string_view runStatusName(RunStatus s);

// One reason a run did not start: a PLC message shown on the panel, or a
// signal of the PLC interface that holds «Пуск» back.
struct RunBlocker {
    // "plc_alarm", "plc_work", "plc_system" (number = k, text = the profile's
    // text); "emergency_stop", "start_enable", "mode" (Z1000 signals),
    // "drives" (not ready), "homing" (a cycle did not start), "start"
    // («Пуск» not seen).
    std::string source;
    int number = 0;
    std::string textRu; // as the panel shows it / the manual names the signal
    std::string textEn;
};
// "A05 Круг изношен" / "Z1000.2 «Деблокировка пуска программы» = 0": one line.
std::string describeBlocker(const RunBlocker& b, bool russian);

struct RunAxis {
    bool present = false;
    units::AxisScale scale;
    std::int64_t currentDisc = 0;
    std::int64_t machineDisc = 0;
    // The largest |following error| from «Пуск» to the end, display discretes.
    double maxFollowingErrorDisc = 0;
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
    ModalState modal;            // the program's modal state at the end
    std::vector<RunBlocker> blockedBy; // status Blocked: why, most direct first
};

// The machine around a Positioner, as the run uses it: time, and the
// operator's gestures at the machine's control panel.
class RunMachine {
public:
    virtual ~RunMachine() = default;
    virtual Positioner& controller() = 0;
    virtual void tick() = 0;
    // Switches the machine on and waits (ticking) until it is ready to move:
    // false if it is not within `maxMs`.
    virtual bool switchOn(std::int64_t maxMs) = 0;
    // Sets the feed override the operator would choose (a code 0..10).
    virtual void setOverrideCode(int code) = 0;
    // The push-button of direction `dir` of axis `a`, pressed and released
    // as an operator starts the reference-point cycle in ПБТ.
    virtual void startReferenceCycle(AxisId a, int dir) = 0;
    // «Пуск» on the machine's panel; startHeld() while the press lasts.
    virtual void pressStart() = 0;
    virtual bool startHeld() const = 0;
    // M codes handed to the PLC so far, in order.
    virtual std::vector<int> mFunctions() const = 0;
};

// The reference-point cycles, as an operator does them in ПБТ and as `k528
// run` and the test rigs all do them (one procedure): ПРИВЯЗКА К БАЗОВОЙ
// ТОЧКЕ selected, then for every present axis not yet referenced that needs
// it (АВТ.БЕЗ ПБТ = 0), X first (as an operator retracts X before Z), the
// push-button of the direction C9/C61 (ПБТ В "-") is pressed; the cycle must
// start within kHomingStartMs (else Blocked, blockedBy says why), then it
// ends by itself — referenced, or 40/41 when the cam or the mark is missing,
// the axis stopping at a limit switch at the latest (an hour of machine time
// is only a guard: Timeout). A message latched during the cycles (one
// latched before is not counted) ends them: Alarm.
struct HomingResult {
    RunStatus status = RunStatus::Completed; // Completed: every axis that needs it is referenced
    double timeS = 0;                        // machine time the cycles took
    std::vector<RunBlocker> blockedBy;       // status Blocked
};
inline constexpr std::int64_t kHomingStartMs = 1000;
inline constexpr std::int64_t kHomingGuardMs = 3600 * 1000;
HomingResult homeAxes(RunMachine& machine);

// Why a program (or a cycle) does not start: what the panel shows (the
// PLC's messages) and the signals of Z1000 that hold «Пуск» back; `what`,
// the step that did not happen, comes last.
std::vector<RunBlocker> startBlockers(const Positioner& ctl, RunBlocker what);

// The engine's ideal machine (engine/ideal_machine.h) as a RunMachine, over
// a Positioner and IdealMachine the caller owns (the rigs; runProgram below).
class IdealRunMachine final : public RunMachine {
public:
    IdealRunMachine(Positioner& ctl, IdealMachine& m) : ctl_(ctl), m_(m) {}
    Positioner& controller() override { return ctl_; }
    void tick() override;
    bool switchOn(std::int64_t maxMs) override;
    void setOverrideCode(int code) override;
    void startReferenceCycle(AxisId a, int dir) override;
    void pressStart() override;
    bool startHeld() const override;
    std::vector<int> mFunctions() const override;

private:
    Positioner& ctl_;
    IdealMachine& m_;
};

// Runs program `number` of `programs` (merged over the profile's programs
// and messages) on `machine`, whose controller is fresh (not powered on).
RunResult runProgram(RunMachine& machine, const program::ProgramStore& programs, int number,
                     const RunOptions& options);

// The same on the engine's ideal machine and minimal PLC (engine/ideal_machine.h),
// the engine's test double. `k528 run` uses the simulated machine (machine/run.h).
RunResult runProgram(const profile::MachineProfile& profile, const program::ProgramStore& programs,
                     int number, const RunOptions& options);

} // namespace k528::engine
