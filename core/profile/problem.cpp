#include "profile/problem.h"

#include <array>

namespace k528::profile {

namespace {

// The English of every problem; the desktop's translations follow these ids.
constexpr std::array kTexts = {
    // reading a file
    ProblemText{"file.cannot-read", "cannot read the file: %1"},
    ProblemText{"file.cannot-create", "cannot create the file"},
    ProblemText{"file.cannot-write", "cannot write the file"},
    ProblemText{"file.utf8", "not valid UTF-8"},
    ProblemText{"file.bom", "column %1: U+FEFF (byte-order mark), an invisible character; a byte-order mark may "
                            "stand only at the very start of the file (files joined with `cat`?) — remove it"},
    ProblemText{"file.twice", "%1 is given twice (first on line %2)"},
    ProblemText{"file.header-bracket", "section header without ']': %1"},
    ProblemText{"file.end-without-program", "[end program] without [program N]"},
    ProblemText{"file.unknown-section",
                "unknown section [%1] (known: machine, c, r, program N, messages, plc-messages, simulation)"},
    ProblemText{"file.program-number", "[program N]: N must be a number 1..99, not '%1'"},
    ProblemText{"file.program-empty", "program %1 is empty"},
    ProblemText{"file.program-bracket",
                "a program line may not start with '[' (missing [end program] for program %1 of line %2?)"},
    ProblemText{"file.program-unended", "program %1 has no [end program]"},
    ProblemText{"file.outside-section", "line outside any section: %1"},
    ProblemText{"file.no-equals", "expected key=value: %1"},
    ProblemText{"file.machine-key", "unknown key '%1' in [machine] (format, name, title)"},
    ProblemText{"file.format-nan", "format: '%1' is not a number"},
    ProblemText{"file.format-unknown", "format %1 is not one this program reads (%2)"},
    ProblemText{"file.c-key", "unknown key '%1' in [c] (C001..C152)"},
    ProblemText{"file.r-key", "unknown key '%1' in [r] (R0..R299)"},
    ProblemText{"file.not-integer", "%1: '%2' is not a whole number"},
    ProblemText{"file.message-key", "expected #k=text in [messages], not '%1'"},
    ProblemText{"file.message-number", "message number %1 is outside #1..#99"},
    ProblemText{"file.plc-key", "expected A01..A32, W01..W32 or S01..S16 in [plc-messages], not '%1'"},
    ProblemText{"file.plc-number", "PLC message '%1': the number must be 1..%2"},
    ProblemText{"file.no-machine", "no [machine] section"},
    ProblemText{"file.no-format", "[machine] has no format=%1"},
    ProblemText{"file.no-name", "[machine] has no name="},
    ProblemText{"file.no-c", "no [c] section (the 152 machine constants)"},
    ProblemText{"file.c-lacks", "[c] lacks %1 (all 152 are required)"},
    ProblemText{"file.c-lacks-more", "[c] lacks %1 and %2 more (all 152 are required)"},
    // built-in profiles
    ProblemText{"builtin.unknown", "no built-in profile of this name (built-in: %1)"},
    ProblemText{"builtin.none-given", "no profile given (built-in: %1)"},
    ProblemText{"builtin.neither", "neither a built-in profile (%1) nor a machine file"},
    // a constants CSV
    ProblemText{"csv.header", "the first line must be the header '%1'"},
    ProblemText{"csv.fields", "expected 5 fields (number;axis;name;value;unit), found %1"},
    ProblemText{"csv.number", "number '%1' is not a C-parameter 1..152"},
    ProblemText{"csv.axis", "%1 belongs to axis '%2', the row says '%3'"},
    ProblemText{"csv.twice", "%1 is given twice"},
    ProblemText{"csv.value", "%1: value '%2' is not a whole number"},
    ProblemText{"csv.empty", "empty: no header line"},
    ProblemText{"csv.missing", "%1 is missing (all 152 are required)"},
    ProblemText{"csv.quote-open", "a quoted field is not closed"},
    ProblemText{"csv.quote-text", "text after a closing quote"},
    // items
    ProblemText{"name.empty", "name is empty"},
    ProblemText{"name.long", "name longer than 64 characters"},
    ProblemText{"name.start", "name '%1' does not start with a-z or 0-9"},
    ProblemText{"name.char", "name '%1' has a character other than a-z, 0-9, '-', '_', '.'"},
    ProblemText{"title", "title: %1"},
    ProblemText{"text.empty", "text is empty"},
    ProblemText{"text.utf8", "text is not valid UTF-8"},
    ProblemText{"text.control", "text has a control character or line break"},
    ProblemText{"text.long", "text has %1 characters, more than %2"},
    ProblemText{"text.trailing-blank", "text ends with a blank"},
    ProblemText{"text.leading-blank", "text starts with a blank"},
    ProblemText{"c.none", "no C-parameter %1 (1..152)"},
    ProblemText{"c.range", "%1 = %2 is outside the range %3 of «%4»"},
    ProblemText{"r.none", "no R-parameter %1 (0..299)"},
    ProblemText{"r.read-only", "R%1 is read-only (R232..R262): it cannot be preset"},
    ProblemText{"r.range", "R%1 = %2 is outside the 32-bit range"},
    ProblemText{"program.number", "program number %1 is outside 1..99"},
    ProblemText{"program.empty", "program L%1: empty"},
    ProblemText{"program.utf8", "program L%1: not valid UTF-8"},
    ProblemText{"program.no-line-break", "program L%1: the text does not end with a line break"},
    ProblemText{"program.carriage-return", "program L%1: carriage return in the text (lines end with LF)"},
    ProblemText{"program.bracket", "program L%1: line %2 starts with '[' (reserved for machine-file sections)"},
    ProblemText{"program.header", "program L%1: line %2 is the header of program L%3 (one program per entry)"},
    ProblemText{"program.messages", "program L%1: line %2: %MESSAGES belongs to the machine file's [messages] section"},
    ProblemText{"program.blank", "program L%1: only blank lines"},
    ProblemText{"message.number", "technological message number %1 is outside 1..99"},
    ProblemText{"message.text", "message #%1: %2"},
    ProblemText{"plc.number", "PLC message %1 is outside 1..%2"},
    ProblemText{"plc.text", "PLC message %1: %2"},
    // simulation settings
    ProblemText{"setting.key", "simulation: %1"},
    ProblemText{"setting.value", "simulation %1: %2"},
    ProblemText{"key.empty", "empty key"},
    ProblemText{"key.long", "key longer than 64 characters"},
    ProblemText{"key.start", "key '%1' does not start with a letter a-z"},
    ProblemText{"key.char", "key '%1' has a character other than a-z, 0-9, '_', '.'"},
    ProblemText{"value.utf8", "value is not valid UTF-8"},
    ProblemText{"value.long", "value longer than 200 characters"},
    ProblemText{"value.lines", "value spans lines"},
    ProblemText{"value.control", "value has a control character"},
    ProblemText{"value.semicolon", "value has a ';' (starts a comment in machine files)"},
    ProblemText{"value.blank", "value starts or ends with a blank"},
    ProblemText{"value.range", "value %1 is outside %2..%3"},
    ProblemText{"value.integer", "value '%1' is not a whole number"},
    ProblemText{"value.number", "value '%1' is not a number"},
    ProblemText{"value.bool", "value '%1' is not true/false"},
    ProblemText{"value.line", "%1"}, // the link line's own check (line.h)
    // a tool's settings (tool.N.*)
    ProblemText{"tool.kind", "'%1' is not a tool kind (turning, facing, grooving, boring, drill, threading)"},
    ProblemText{"tool.value", "%1"}, // a value of the wrong type (SettingError's words)
    ProblemText{"tool.orientation", "'%1' is not one of +z+x, -z+x, +z-x, -z-x"},
    ProblemText{"tool.tip-radius", "needs 0..50 mm"},
    ProblemText{"tool.size", "needs more than 0, at most 1000 mm"},
    ProblemText{"tool.depth", "needs 0..100 mm (0: no limit)"},
    ProblemText{"tool.offset", "needs a user R-parameter 0..148 (X there, Z in the next)"},
    ProblemText{"tool.key", "a tool key is tool.<station 1..8>.<key>"},
    ProblemText{"tool.field", "'%1' is not a key of a tool"},
    ProblemText{"tool.no-kind", "the tool of station %1 has no kind (tool.%1.kind)"},
    // a database's refusal of an edit its machine cannot hold (db/error.h)
    ProblemText{"machine.item", "machine %1: %2"},
    // the constants calculator's inputs (calculator.h)
    ProblemText{"calc.vmax", "Vmax must be a positive number"},
    ProblemText{"calc.run-up", "the run-up time must be a positive number"},
    ProblemText{"calc.braking", "the braking distance must be a positive number"},
    ProblemText{"calc.acceleration", "the acceleration must be a positive number"},
    ProblemText{"calc.umax", "Umax must be a positive number"},
    ProblemText{"calc.kv", "Kv must be a positive number"},
    ProblemText{"calc.screw-lead", "the screw lead must be a positive number"},
    ProblemText{"calc.gear-ratio", "the gear ratio must be a positive number"},
    ProblemText{"calc.encoder-lines", "the encoder must have at least one line"},
    ProblemText{"calc.lead-discretes", "the screw lead %1 mm is not a whole number of discretes (%2 mm)"},
    ProblemText{"calc.gear-fraction", "the gear ratio %1 is not a fraction with a denominator up to 100000"},
    ProblemText{"calc.speed", "a speed must be zero or positive"},
    ProblemText{"calc.feed-reach", "the fastest feed %1 mm/min is above what the drive reaches at DAC MAX (%2 mm/min)"},
    // the cutting data and the trial part (cutting.h)
    ProblemText{"cutting.cutting-speed", "the cutting speed must be a positive number"},
    ProblemText{"cutting.diameter", "the diameter must be a positive number"},
    ProblemText{"cutting.spindle-speed", "the spindle speed must be a positive number"},
    ProblemText{"cutting.feed", "the feed per revolution must be a positive number"},
    ProblemText{"cutting.wheel-diameter", "the wheel's diameter must be a positive number"},
    ProblemText{"cutting.wheel-speed", "the wheel's speed must be a positive number"},
    ProblemText{"cutting.no-r207", "the machine presets no R207 (the wheel's diameter)"},
    ProblemText{"cutting.no-offset", "tool %1 has no offset R-parameters (tool.%1.offset_r)"},
    ProblemText{"cutting.not-numbers", "the measured size and the drawing's must be numbers"},
    ProblemText{"cutting.r-range", "R%1 would leave the R-parameter range"},
    ProblemText{"cutting.no-tool", "no tool at station %1"},
};

} // namespace

std::span<const ProblemText> problemTexts() { return kTexts; }

std::string_view problemEnglish(std::string_view id) {
    for (const ProblemText& t : kTexts)
        if (t.id == id)
            return t.en;
    return {};
}

Problem problem(std::string id, std::vector<std::string> args) {
    Problem p;
    p.id = std::move(id);
    p.args = std::move(args);
    return p;
}

std::string Problem::text() const {
    if (id.empty())
        return {};
    std::vector<std::string> all = args;
    for (const Problem& w : within)
        all.push_back(w.text());
    const std::string_view en = problemEnglish(id);
    return fillPattern(en.empty() ? std::string_view(id) : en, all);
}

} // namespace k528::profile
