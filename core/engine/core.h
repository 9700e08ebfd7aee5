// The state the engine's parts share (internal to core/engine): constants,
// interface words and machine I/O, the two axes, R-parameters, messages,
// mode and program state, plus the few actions every part needs (raise a
// message, abort a program, stop motion). The Positioner (positioner.h) owns
// one Core and runs the parts over it in a fixed order each tick.
#pragma once

#include "engine/alarms.h"
#include "engine/axis_unit.h"
#include "engine/cparams.h"
#include "engine/fast_inputs.h"
#include "engine/interface_words.h"
#include "engine/m_handshake.h"
#include "engine/machine_io.h"
#include "engine/oscillation.h"
#include "engine/rparams.h"
#include "engine/types.h"
#include "profile/profile.h"
#include "program/model.h"

#include <array>
#include <cstdint>

namespace k528::engine {

class ProgramOutput; // engine/program_output.h

struct Core {
    explicit Core(const profile::MachineProfile& p);

    // --- actions --------------------------------------------------------
    // Raises message n (latched until acknowledged; `active` while its cause
    // lasts, else an event). Any message stops a program that is under way
    // (state Alarm); a fault of an axis' loop or drive also stops the other axis.
    void raise(int n, int program = 0, int line = 0, bool active = false);
    // Raises or clears a condition message (active while `on`); a new one
    // has the effects of raise().
    void condition(int n, bool on) {
        if (on != alarms.active(n))
            conditionChanged(n, on);
    }
    void conditionChanged(int n, bool on);
    // Stops every motion a program started and ends the program in `to`.
    void abortProgram(ProgramState to);
    // Decelerates every moving axis (alarm, emergency).
    void stopAllMotion();
    // Re-reads the axis constants, fast-input functions and settings from c.
    void applyConstants();

    // Exclusions in effect for axis a (G50..G53 in a program, else Z1006.4-7).
    std::uint8_t exclusion(int a) const;
    // The sum of the offsets in effect for axis a (zero offset, dressing,
    // correction, DRF less the exclusions), discretes: current = machine - sum.
    std::int64_t offsetDisc(int a) const;
    std::int64_t currentDisc(int a) const;

    // --- data -----------------------------------------------------------
    profile::MachineProfile profile;
    std::array<std::int64_t, kCCount + 1> c{};
    std::int64_t tickMs = 1;
    double dtMs = 1.0;
    std::int64_t nowMs = 0;
    bool powered = false;
    int nestingLimit = program::kDefaultNestingLimit;

    InterfaceWords words;
    MachineIo io;
    std::array<AxisUnit, kAxisCount> axes;
    std::array<Oscillation, kAxisCount> osc{};
    RStore r;
    AlarmRegistry alarms;
    PlcMessages plc;
    FastInputMap fast;
    // The pulse channel (0..3) of handwheel 1 and 2 (C105/C106), -1: none.
    std::array<int, 2> wheelChannel{-1, -1};
    MHandshake mhs;
    program::ProgramStore store;
    // Where the interpreter's frames go (engine/program_output.h): the
    // machine, the preview's instant axes, or the machine under the editor's
    // debugger; the Positioner sets it, never null while it runs.
    ProgramOutput* out = nullptr;
    // The preview's output is set: the axes are placed by the interpreter
    // and their servos do not tick (engine/preview.h).
    bool instantAxes = false;

    // Mode.
    Mode mode = Mode::Manual;
    Mode panelMode = Mode::Manual;
    bool modeFromPlc = false;

    // Program.
    ProgramState state = ProgramState::Idle;
    ProgramState resumeState = ProgramState::Running; // what «Пуск» returns to after «Стоп»
    bool endOrReset = false;                          // Z2000.10
    bool stopHold = false;                            // «Стоп»: feed held on program motion
    int cycle = 0;                 // manual cycle 1..8 being run, 0 = a program of АВТОМАТ
    Mode programMode = Mode::Auto; // the mode the active program belongs to
    std::uint8_t programExclusion = 0; // G50..G53 (modal, group 6)
    int messageNumber = 0;             // # of the current frame (stays until a new one)
    std::int64_t framesExecuted = 0;
    std::int64_t programStartMs = -1, programEndMs = -1;

    // Feed override.
    int panelOverrideCode = 10; // last L1..L4 code (100 % at power-on)
    int overridePercent = 100;

    // Edges: last tick's inputs.
    std::uint16_t lastZ1000 = 0, lastZ1001 = 0;
    std::array<std::uint16_t, kAxisCount> lastAxisWord0{}, lastAxisWord1{}, lastAxisWord2{};
    bool lastFastReset = false;
    std::int64_t lastPanelWrite = 0;
};

} // namespace k528::engine
