// The grade of an attempt (docs/training-course.md): the student's program
// file run on the simulated machine as the operator would (its OPERATOR
// lines, else the standard procedure), then the finished part compared with
// the drawing — over-cut (material taken inside the least material the
// tolerances allow) and under-cut (material left beyond the most), each
// region's area and depth (µm, normal to the drawing), located at the frame
// that made it —, the collisions, the messages raised, the cycle time
// against the limit, the operator's steps and the machine's state at the
// end. The score is 100 less the deductions, each explained in the
// student's words (ids of training/texts.h) naming the frame and the line.
// Deterministic: the same file gives the same grade, byte for byte in JSON.
//
//   const training::Grader g(*training::findExercise("lathe-03-step"));
//   const training::Grade r = g.grade(text, "ivanov.k528", "Иванов");
//   std::puts(json::dump(training::gradeJson(r)).c_str());
//
// A Grader is immutable once built: grade() may run on many threads at once
// (each attempt has its own simulated machine).
#pragma once

#include "program/diagnostic.h"
#include "training/attempt.h"
#include "proveout/actual.h"
#include "training/drawing.h"
#include "training/exercise.h"
#include "util/json_fwd.h"

#include <string>
#include <string_view>
#include <vector>

namespace k528::training {

// A collision found along the attempt's actual path by the prove-out's rules
// (proveout/rules.h: the same rule ids as `k528 check --profile`).
using proveout::Collision;

// An over-cut or under-cut: the regions one frame made (over-cut: the
// frame whose sweep took most of it; under-cut: the pass that came nearest,
// none when no pass came within reach).
struct Deviation {
    double areaMm2 = 0;
    double depthUm = 0;          // the deepest point's distance to the limit
    stock::PointZR deepest;      // (z, r)
    int program = 0, line = 0, n = 0;
    bool manual = false;         // made by the operator's move
    bool located = false;        // a frame (or the operator) is named
    double distanceMm = 0;       // under-cut: how far the nearest pass stayed
    std::vector<Shape> shapes;
};

struct Deduction {
    std::string category; // overcut undercut collision message not_completed not_started
                          // cycle_time step end_state program_errors procedure
    double points = 0;
    bool fails = false; // the attempt is not passed whatever the score
    int program = 0, line = 0, n = 0;
    Text text;
};

struct StepResult {
    OperatorStep step;
    bool done = false;
    Text text; // what was found
};

struct EndResult {
    EndCheck check;
    bool ok = false;
    std::int64_t found = 0; // R checks: the value at the end
};

struct Grade {
    std::string exercise, file, student;
    int score = 0;
    bool passed = false;
    // completed, alarm, interrupted, timeout, not_started, errors, procedure (no program)
    std::string status;
    double cycleTimeS = 0, limitS = 0;
    std::vector<Deduction> deductions;
    std::vector<Deviation> overcut, undercut;
    std::vector<Collision> collisions;
    std::vector<SeenMessage> messages;
    std::vector<bool> messageAllowed;
    std::vector<StepResult> steps;
    std::vector<EndResult> atEnd;
    std::vector<FaultEvent> faults;
    std::vector<StepNote> notes;
    std::vector<ProcedureError> procedureErrors;
    std::vector<program::Diagnostic> diagnostics; // the file's errors (status errors)
    // What the desktop draws: the blank, the finished part, the drawing and
    // the tool's path (the lathe in the program's coordinates; the grinder's
    // ring in the machine's).
    std::vector<Shape> blank, finished;
    DrawingShapes drawing;
    std::vector<toolpath::ActualSample> path;
};

class Grader {
public:
    // The exercise's own machine.
    explicit Grader(const Exercise& e);
    // Another set of constants for the same machine (a trainer's locked
    // constants for a class).
    Grader(const Exercise& e, profile::MachineProfile machine);

    Grade grade(std::string_view fileText, std::string file, std::string student = {}) const;

    const Exercise& exercise() const { return e_; }
    const DrawingShapes& drawing() const { return drawing_; }
    const profile::MachineProfile& machine() const { return machine_; }

private:
    void prepare();
    const Exercise& e_;
    profile::MachineProfile machine_;
    DrawingShapes drawing_;
};

// The grade as JSON (shared/spec/cli.md `k528 grade`, docs/training-course.md):
// file, student, exercise, score, passed, status, deductions [{points, frame,
// line, program, category, fails, text_ru, text_en, id, args}] and the
// findings; `geometry` adds the blank, the finished part, the drawing and
// the regions.
Json gradeJson(const Grade& g, bool geometry = false);

} // namespace k528::training
