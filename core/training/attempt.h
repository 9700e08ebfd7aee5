// One attempt at an exercise on the simulated machine: the student's
// programs loaded over the machine's, the setter's R-parameters set, the
// student's procedure (training/procedure.h) done step by step at the
// machine's panel and the K923, the exercise's faults injected when their
// time or frame comes and cleared when their end comes. Every tick is
// watched (a tick observer of machine::Simulation): the tool's motion as
// the slides really moved (decimated within 1 µm, toolpath::Decimator),
// what moved it (a program's G00/G01, the operator), the spindle, the
// program's starts and ends, the messages (msglog::Recorder), the grinder's
// bore where the wheel covered the ring. Deterministic: the same exercise,
// programs and procedure give the same record, bit for bit.
#pragma once

#include "db/message_log.h"
#include "engine/run.h"
#include "profile/profile.h"
#include "program/model.h"
#include "proveout/rules.h"
#include "toolpath/actual_path.h"
#include "training/exercise.h"
#include "training/procedure.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace k528::training {

struct SpindleChange {
    double tMs = 0;
    bool running = false;
};

// A message the attempt raised (positioner 1..64, PLC alarm or system message).
struct SeenMessage {
    db::MessageSource source = db::MessageSource::Positioner;
    int number = 0;
    std::string code; // "11", "A27", "S01"
    std::string textRu, textEn;
    int program = 0, line = 0;
    double tMs = 0;
    bool acknowledgeable = true;
    bool acknowledged = false;
};

// A fault of the exercise as it happened.
struct FaultEvent {
    std::string id; // machine::faultText's id
    std::vector<std::string> args;
    double injectedMs = -1, clearedMs = -1; // -1: not (yet)
    int program = 0, line = 0, n = 0;     // the frame it came in (0: none)
};

// One band of the grinder's ring (machine Z): the bore there and the frame
// that ground it last.
struct BandCell {
    double zMm = 0;     // the band's left end
    double boreMm = 0;  // its bore diameter
    bool ground = false;
    int program = 0, line = 0, n = 0;
};

// The grinder's wheel moved into the ring where grinding does not take it:
// at rapid, or at feed with the wheel standing (proveout::materialRule).
struct RingContact {
    proveout::Rule rule = proveout::Rule::RapidIntoMaterial; // the prove-out's rule it breaks
    int program = 0, line = 0, n = 0;
    double edgeMm = 0, boreMm = 0, zMm = 0;
};

// A step of the procedure that did not do what it says (a refused key
// sequence, a homing that did not end, a program that did not start).
struct StepNote {
    int line = 0;
    std::string token;
    Text text;
};

struct AttemptRecord {
    // The tool's motion: the lathe's in the program's coordinates of the
    // set-up (X as a diameter), the grinder's in the machine's.
    std::vector<toolpath::ActualSample> path;
    std::vector<SpindleChange> spindle; // the (main / wheel) spindle running, from the start
    // The program: started at all, first «Пуск» seen, last end, state at the end.
    int starts = 0;
    double firstStartMs = -1, lastEndMs = -1, endMs = 0;
    engine::ProgramState endState = engine::ProgramState::Idle;
    int endProgram = 0, endLine = 0, endN = 0;
    std::vector<engine::RunBlocker> blockedBy; // a RUN that found the program not started
    std::array<std::int32_t, 300> rAtBegin{}, rAtFirstStart{}, rAtEnd{};
    std::array<bool, 2> referencedAtFirstStart{}, referencedAtEnd{};
    std::array<double, 2> currentAtEndMm{}; // X, Z as the panel shows them
    std::vector<SeenMessage> messages;      // in the order they came
    std::vector<FaultEvent> faults;
    bool wheelChanged = false;
    bool spindlesStoppedAtEnd = true, coolantOffAtEnd = true, gaugeOutAtEnd = true;
    // The grinder.
    std::vector<BandCell> bands;
    double bandMm = 0.1;
    double blankBoreMm = 0; // the ring's bore before the attempt
    std::vector<RingContact> ringContacts;
    std::vector<StepNote> notes;
    bool guardHit = false; // the attempt's machine time ran out
};

struct AttemptInput {
    const Exercise* exercise = nullptr;
    profile::MachineProfile profile;  // the exercise's machine (with a class's locked constants)
    program::ProgramStore programs;   // the student's file
    Procedure procedure;
};

// The machine of an exercise: its built-in profile with the setter's
// R-parameters.
profile::MachineProfile exerciseProfile(const Exercise& e);

// Runs the attempt. Throws plc::DescriptionError for a broken machine
// description (never for a shipped one).
AttemptRecord runAttempt(const AttemptInput& in);

} // namespace k528::training
