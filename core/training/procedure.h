// What the student does at the machine, written in the program file as
// comment lines
//
//   ; OPERATOR: PULL:ESTOP PUSH:DRIVES_ON WAIT:1 HOME
//   ; OPERATOR: R12=1000 PROGRAM:1 PUSH:START RUN
//
// («; ОПЕРАТОР:» is the same), the tokens in order over all such lines
// (docs/training-course.md):
//   the K923 keys of `k528 panel` (F1..F8, K1..K12, L1..L4, UP, ESC, ENTER,
//     0..9, SHIFT+KEY …), pressed on the panel model;
//   the machine's buttons: PUSH:NAME (100 ms), HOLD:NAME:S, PUSH:ESTOP,
//     PULL:ESTOP (NAME: DRIVES_ON START STOP RESET X+ X- Z+ Z- RAPID CHUCK);
//   WAIT:S — S seconds of machine time;
//   HOME — F3, then each axis' direction button (ПБТ В "-"), X first, each
//     cycle to its end;
//   RUN — until the program ends or a message stops it; at M00 «Пуск» is
//     pressed again after a second (an operator at the machine);
//   PROGRAM:N — F1, ACK, the digits of N, ENTER (the program of АВТОМАТ);
//   R<n>=<v> — F2, MODE to screen 3 (R-parameters), PAR, n, ENTER, v, ENTER;
//   HANDWHEEL:X|Z|OFF, STEP:1|10|100 (the multiplier), TURN:±N (detents);
//   OVERRIDE:PCT — the override selector (or the K923's L key of that step);
//   NEWWHEEL — the grinder's NEW WHEEL (R207 = R204); DOOR:OPEN, DOOR:CLOSE.
// A file without OPERATOR lines gets the standard procedure `k528 run`
// follows: PULL:ESTOP PUSH:DRIVES_ON WAIT:1 HOME PROGRAM:<first> PUSH:START RUN.
#pragma once

#include "machine/equipment.h"
#include "panel/keys.h"
#include "training/texts.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace k528::training {

struct ProcedureStep {
    enum class Kind {
        Key, Push, Hold, EstopPush, EstopPull, Wait, Home, Run, Program, Preset,
        Handwheel, HandwheelStep, Turn, Override, NewWheel, DoorOpen, DoorClose,
    };
    Kind kind = Kind::Wait;
    panel::KeyPress key{panel::Key::Esc};
    machine::Button button = machine::Button::CycleStart;
    std::int64_t ms = 0;    // Hold, Wait
    std::int64_t value = 0; // Program: number; Preset: value; Turn: detents; Override: percent;
                            // HandwheelStep: 0..2; Handwheel: 0 off, 1 X, 2 Z
    int r = 0;              // Preset
    int line = 0;           // where it is written (0: the standard procedure)
    std::string token;      // as written
};

struct Procedure {
    std::vector<ProcedureStep> steps;
    bool standard = true; // no OPERATOR lines: the standard procedure
};

// A token that is not a step: its line and text, and why.
struct ProcedureError {
    int line = 0;
    std::string token;
    Text why;
};

// The OPERATOR lines of a program file; `errors` gets every bad token
// (the steps keep the good ones). Without OPERATOR lines: the standard
// procedure for program `program`.
Procedure readProcedure(std::string_view fileText, int program, std::vector<ProcedureError>& errors);
Procedure standardProcedure(int program);

// The steps as one line of tokens (what a student would write).
std::string formatProcedure(const Procedure& p);

} // namespace k528::training
