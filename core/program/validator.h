// The rules of program-language.md over a ProgramStore: ranges and counts,
// the combinations the K528-05 refuses (appendix М messages 33..64), jumps
// and frame numbers, subprogram calls across programs, and — when a
// machine's constants are given — software limits, feeds, axes and
// discretes (warnings).
//
// validate() checks a whole store. The editor, which re-checks one program
// on every keystroke, keeps a CallGraph of the store, updates it with the
// edited program and calls validateProgram() for that program only.
#pragma once

#include <array>
#include <bitset>
#include <optional>
#include <vector>

#include "program/diagnostic.h"
#include "program/model.h"
#include "program/parser.h"

namespace k528::program {

// The constants of one axis of the machine a program is meant for (from the
// machine's C-parameters). Coordinates are in programmed millimetres: on a
// diameter axis (C7/C59 ИНД.ДИАМЕТР) X is programmed as a diameter, and so
// are its limits.
struct AxisLimits {
    bool present = true;            // C1/C53 НАЛИЧ.ОСИ
    bool diameter = false;          // C7/C59 ИНД.ДИАМЕТР
    bool softLimits = false;        // C10/C62 ВКЛ.ПРГ.КОН
    Decimal minMm;                  // C46/C98 -ОГРАНИЧЕН, in mm (machine system)
    Decimal maxMm;                  // C47/C99 +ОГРАНИЧЕН, in mm (machine system)
    // The coordinate components between the program's (current) system and
    // the machine system, in mm (R-parameter presets, app. Л): machine =
    // programmed + zero offset + dressing sum + correction + handwheel
    // offset, each left out while G53 / G52 / G51 / G50 is active.
    Decimal zeroOffsetMm;           // R228 / R229
    Decimal dressingMm;             // R224 / R225
    Decimal correctionMm;           // R226 / R227
    Decimal handwheelMm;            // R230 / R231 (DRF)
    std::optional<Decimal> maxFeedMmPerMin; // C42/C94 F УСК.АВТ., in mm/min
    std::optional<int> decimals;    // digits of the display discrete (C4..6/C56..58): 4, 3 or 2
};

struct MachineLimits {
    AxisLimits x;
    AxisLimits z;
};

struct ValidateOptions {
    // Subprogram nesting limit (message 48): a profile setting, 8 by default.
    // The main program is level 0; each active L call adds one level, so
    // with a limit of 8 eight nested calls are allowed.
    int nestingLimit = kDefaultNestingLimit;
    // The machine the programs are meant for; nullopt = check the language only.
    std::optional<MachineLimits> machine;
};

// Subprogram calls of a store: who calls whom, from which frame. Build once
// for a store; after editing one program call update() with it.
class CallGraph {
public:
    struct Call {
        int callee = 0;     // the L number as written (may be out of range)
        int frameIndex = 0; // the calling frame in the caller's `frames`
    };

    CallGraph() = default;
    explicit CallGraph(const ProgramStore& store);

    void update(const Program& program);
    void remove(int number);

    // Calls made by program `number` (empty if it makes none or does not exist).
    const std::vector<Call>& callsFrom(int number) const;
    // True if some program of the store calls `number` (so it is a subprogram).
    bool isCalled(int number) const;
    // Number of the programs that call `number`.
    int callerCount(int number) const;

private:
    std::array<std::vector<Call>, kMaxPrograms + 1> calls_{};
    std::array<std::bitset<kMaxPrograms + 1>, kMaxPrograms + 1> edges_{}; // edges_[caller][callee]
};

// Every rule over every program of the store, plus the message table.
// Sorted by line and column.
std::vector<Diagnostic> validate(const ProgramStore& store, const ValidateOptions& options = {});

// The rules of one program (including the ones that look at other programs:
// calls, nesting, whether it is a subprogram), given the store's call graph.
std::vector<Diagnostic> validateProgram(const ProgramStore& store, int number, const CallGraph& graph,
                                        const ValidateOptions& options = {});

// The rules of the message table alone (length, characters).
std::vector<Diagnostic> validateMessages(const MessageTable& table);

// Parse and validate in one call: the store and all diagnostics, sorted.
struct CheckResult {
    ProgramStore store;
    std::vector<Diagnostic> diagnostics;
    bool syntaxErrors = false; // the parser reported errors (the text cannot be formatted)
    bool hasErrors() const { return program::hasErrors(diagnostics); }
};
CheckResult check(std::string_view text, const ParseOptions& parseOptions = {},
                  const ValidateOptions& options = {});

} // namespace k528::program
