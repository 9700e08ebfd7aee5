// A training exercise as data (docs/training-course.md): what the student
// is told (title, task and hints in Russian and English), the machine, the
// blank (NC-200's UCG) or the grinder's ring, the drawing of the finished
// part with its tolerances (a half-profile, the bore of a ring, or the part
// the reference program makes), the limits (cycle time, the messages
// allowed), the faults injected for training (at a time or a frame), what
// the student must do at the machine (homing, presets, acknowledging, a
// position, a new wheel), what the machine must be left like, and the
// reference program that scores 100. One JSON file per exercise in
// resources/exercises/ (embedded); a course (course.json) orders them.
//
// readExercise() checks every key and value and names the first wrong one
// ("drawing.contour[2].d: expected a number"); nothing is guessed.
#pragma once

#include "machine/simulation.h"
#include "stock/stock.h"
#include "training/texts.h"

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace k528::training {

// An exercise or course file that cannot be read: "<source>: <path>: <why>",
// the why an id of exercise_texts.h and its arguments; what() is English.
class ExerciseError : public std::runtime_error {
public:
    // A message without an id (the JSON parser's own words).
    ExerciseError(std::string source, std::string message)
        : std::runtime_error(source + ": " + message), message_(std::move(message)),
          source_(std::move(source)) {}
    // `at`: the key's path in the document ("" for the file itself, nullopt
    // for none), `id` and `args` the catalog's.
    ExerciseError(std::string source, std::optional<std::string> at, std::string id,
                  std::vector<std::string> args = {});
    const std::string& source() const { return source_; }
    // What is wrong, in English, after the source.
    const std::string& message() const { return message_; }
    const std::string& textId() const { return id_; }
    const std::vector<std::string>& textArgs() const { return args_; }
    // The whole error in a language ("<source>: <path>: <why>").
    std::string text(bool russian) const;

private:
    std::string message_, source_;
    std::optional<std::string> at_;
    std::string id_;
    std::vector<std::string> args_;
};

// Deviations of a size in mm: [lower, upper]. For a diameter (a cylinder,
// the bore) of the diameter; for a face or a cone of its place along its
// normal, + being more material (docs/training-course.md).
struct Tolerance {
    double lowerMm = -0.1, upperMm = 0.1;
    bool operator==(const Tolerance&) const = default;
};

// A point of the drawing's outer contour, (z, diameter) in the program's
// coordinates; `tol` belongs to the element from the previous point to this one.
struct ContourPoint {
    double zMm = 0, dMm = 0;
    std::optional<Tolerance> tol; // none: the drawing's general tolerance
    bool operator==(const ContourPoint&) const = default;
};

struct Drawing {
    enum class Kind {
        None,      // nothing is machined (homing and jogging)
        Contour,   // the outer half-profile of a turned part
        Reference, // the part the reference program makes, within `tolerance`
        Bore,      // the bore of the grinder's ring
    };
    Kind kind = Kind::None;
    std::vector<ContourPoint> contour; // from the right face on the axis round to the left end on the axis
    Tolerance tolerance;               // general (Contour), uniform (Reference)
    double boreMm = 0;                 // Bore: the diameter and its tolerance
    Tolerance boreTol;
};

// The chuck of the lathe in the program's coordinates: its face, its
// diameter, and the jaws that grip the blank from the face to the blank's
// left end, `jawHeightMm` above its surface.
struct Chuck {
    double faceZMm = -120, diameterMm = 160, jawLengthMm = 20, jawHeightMm = 15;
};

// The grinder's ring and wheel in the machine's coordinates: the ring lies
// between ringZ, the wheel covers [Z, Z + width] (its far face at the
// programmed Z); the bore grows where the wheel covers the ring.
struct Ring {
    double zMinMm = 120, zMaxMm = 135;
    double outerMm = 31.5;
    double wheelWidthMm = 20;
};

// A frame of a program: L<program> N<n>.
struct FrameAt {
    int program = 0, n = 0;
    bool operator==(const FrameAt&) const = default;
};

struct FaultInjection {
    machine::FaultSpec fault;
    std::optional<double> atS;      // seconds after the program first started
    std::optional<FrameAt> atFrame; // when the program first reaches this frame
    // What ends it: never; the slide moved off the switch (`moveOffMm` of
    // slide away from the side it was hit); a time.
    enum class Until { Never, MovedOff, Time };
    Until until = Until::Never;
    double forS = 0;
    double moveOffMm = 1.0;
};

struct OperatorStep {
    enum class Kind {
        Home,        // both axes referenced before the program is started
        Preset,      // R<r> = value at the first «Пуск» (set on РУЧ screen 3)
        Acknowledge, // every message raised is acknowledged by the end
        Position,    // the tool ends at X, Z within tolerance (current coordinates)
        NewWheel,    // the grinder's wheel was changed (NEW WHEEL)
        Completed,   // the program ran to its end
    };
    Kind kind = Kind::Completed;
    int r = 0;
    std::int64_t value = 0;
    double xMm = 0, zMm = 0, toleranceMm = 0;
};
std::string_view stepName(OperatorStep::Kind k); // "home", "preset", ...

struct EndCheck {
    enum class Kind { SpindleStopped, CoolantOff, GaugeOut, RDelta, RValue };
    Kind kind = Kind::SpindleStopped;
    int r = 0;
    std::int64_t value = 0; // RValue: the value; RDelta: the change from the start
};
std::string_view endCheckName(EndCheck::Kind k); // "spindle_stopped", ...

struct Limits {
    double cycleTimeS = 0;                  // 0: none
    std::vector<std::string> alarmsAllowed; // "11", "A27", "44"
};

// Points of the deductions (docs/training-course.md); an exercise may change them.
struct Scoring {
    int passScore = 70;
    double overcutBase = 15, overcutPerMm = 40, overcutCap = 40;   // per frame's regions
    double undercutBase = 10, undercutPerMm = 40, undercutCap = 30; // per frame's regions
    double rapidIntoMaterial = 30, toolIntoChuck = 50, cutWithoutSpindle = 30, jogIntoMaterial = 20;
    double alarm = 10, alarmCap = 30;
    double notCompleted = 40;
    double cycleTimePerPercent = 0.5, cycleTimeCap = 15;
    double operatorStep = 15;
    double endCheck = 5;
    double programErrors = 100;
};

struct Bilingual {
    std::string ru, en;
    const std::string& in(Language l) const { return l == Language::Ru ? ru : en; }
};

struct Exercise {
    std::string id;      // the file's name without .json
    std::string machine; // a built-in profile: "training-lathe", "grinder-205"
    Bilingual title, task;
    std::vector<Bilingual> hints;
    // The lathe's blank: UCG as written, the blank it gives, and where its
    // part zero lies in the program's Z.
    std::string ucg;
    std::optional<stock::Blank> blank;
    double blankZMm = 0;
    stock::Tool tool;
    Chuck chuck;
    std::optional<Ring> ring; // the grinder
    Drawing drawing;
    std::map<int, std::int64_t> setupR; // the setter's R-parameters before the attempt
    std::vector<FaultInjection> faults;
    std::vector<OperatorStep> steps;
    std::vector<EndCheck> atEnd;
    Limits limits;
    Scoring scoring;
    std::string reference; // the reference program file (its text)
    std::string given;     // the program handed out with the task ("" none)

    bool lathe() const { return blank.has_value(); }
    bool grinder() const { return ring.has_value(); }
};

// Reads one exercise (JSON). `id` names it (the file's name without
// .json); `source` names the text in errors. Throws ExerciseError.
Exercise readExercise(std::string_view text, std::string_view id, std::string_view source);

struct Course {
    std::string id;
    Bilingual title;
    std::vector<std::string> exercises; // ids, in order
};
Course readCourse(std::string_view text, std::string_view source);

// The shipped course and its exercises (resources/exercises/, embedded).
const Course& starterCourse();
// Every shipped exercise in the course's order. Throws ExerciseError if a
// shipped file is broken (a test reads them all).
const std::vector<Exercise>& shippedExercises();
// A shipped exercise by id, nullptr if none.
const Exercise* findExercise(std::string_view id);

} // namespace k528::training
