#include "session/core_texts.h"

#include "db/error.h"
#include "engine/refusal_texts.h"
#include "engine/types.h"
#include "db/notes.h"
#include "plc/description_texts.h"
#include "plc/json_reader.h"
#include "window_language.h"
#include "profile/calculator.h"
#include "profile/cutting.h"
#include "profile/problem.h"
#include "profile/tools.h"
#include "proveout/proveout.h"
#include "profile/validate.h"
#include "profile/text_format.h"
#include "session/database_texts.h"
#include "session/shop_database.h"
#include "session/translated_texts.h"
#include "util/input_file.h"

#include <QCoreApplication>

#include <optional>
#include <string>
#include <vector>

namespace k528::studio {

namespace {

// core/profile/problem.cpp's catalog, each text marked for the translators.
const TranslatedText kProblems[] = {
        {"file.cannot-read", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "cannot read the file: %1")},
        {"file.cannot-create", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "cannot create the file")},
        {"file.cannot-write", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "cannot write the file")},
        {"file.utf8", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "not valid UTF-8")},
        {"file.bom", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "column %1: U+FEFF (byte-order mark), an invisible character; a byte-order mark may stand only at the very start of the file (files joined with `cat`?) — remove it")},
        {"file.twice", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1 is given twice (first on line %2)")},
        {"file.header-bracket", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "section header without ']': %1")},
        {"file.end-without-program", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "[end program] without [program N]")},
        {"file.unknown-section", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "unknown section [%1] (known: machine, c, r, program N, messages, plc-messages, simulation)")},
        {"file.program-number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "[program N]: N must be a number 1..99, not '%1'")},
        {"file.program-empty", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program %1 is empty")},
        {"file.program-bracket", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "a program line may not start with '[' (missing [end program] for program %1 of line %2?)")},
        {"file.program-unended", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program %1 has no [end program]")},
        {"file.outside-section", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "line outside any section: %1")},
        {"file.no-equals", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "expected key=value: %1")},
        {"file.machine-key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "unknown key '%1' in [machine] (format, name, title)")},
        {"file.format-nan", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "format: '%1' is not a number")},
        {"file.format-unknown", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "format %1 is not one this program reads (%2)")},
        {"file.c-key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "unknown key '%1' in [c] (C001..C152)")},
        {"file.r-key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "unknown key '%1' in [r] (R0..R299)")},
        {"file.not-integer", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1: '%2' is not a whole number")},
        {"file.english-alone", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1 without its Russian %2 (an English text stands beside its Russian)")},
        {"file.english-place", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1 is written beside its Russian text: %2=")},
        {"file.message-key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "expected #k=text in [messages], not '%1'")},
        {"file.message-number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "message number %1 is outside #1..#99")},
        {"file.plc-key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "expected A01..A32, W01..W32 or S01..S16 in [plc-messages], not '%1'")},
        {"file.plc-number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "PLC message '%1': the number must be 1..%2")},
        {"file.no-machine", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "no [machine] section")},
        {"file.no-format", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "[machine] has no format=%1")},
        {"file.no-name", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "[machine] has no name=")},
        {"file.no-c", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "no [c] section (the 152 machine constants)")},
        {"file.c-lacks", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "[c] lacks %1 (all 152 are required)")},
        {"file.c-lacks-more", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "[c] lacks %1 and %2 more (all 152 are required)")},
        {"builtin.unknown", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "no built-in profile of this name (built-in: %1)")},
        {"builtin.none-given", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "no profile given (built-in: %1)")},
        {"builtin.neither", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "neither a built-in profile (%1) nor a machine file")},
        {"csv.header", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the first line must be the header '%1'")},
        {"csv.fields", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "expected 5 fields (number;axis;name;value;unit), found %1")},
        {"csv.number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "number '%1' is not a C-parameter 1..152")},
        {"csv.axis", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1 belongs to axis '%2', the row says '%3'")},
        {"csv.twice", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1 is given twice")},
        {"csv.value", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1: value '%2' is not a whole number")},
        {"csv.empty", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "empty: no header line")},
        {"csv.missing", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1 is missing (all 152 are required)")},
        {"csv.quote-open", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "a quoted field is not closed")},
        {"csv.quote-text", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text after a closing quote")},
        {"name.empty", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "name is empty")},
        {"name.long", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "name longer than 64 characters")},
        {"name.start", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "name '%1' does not start with a-z or 0-9")},
        {"name.char", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "name '%1' has a character other than a-z, 0-9, '-', '_', '.'")},
        {"title", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "title: %1")},
        {"text.empty", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text is empty")},
        {"text.utf8", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text is not valid UTF-8")},
        {"text.control", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text has a control character or line break")},
        {"text.long", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text has %1 characters, more than %2")},
        {"text.trailing-blank", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text ends with a blank")},
        {"text.leading-blank", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "text starts with a blank")},
        {"c.none", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "no C-parameter %1 (1..152)")},
        {"c.range", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1 = %2 is outside the range %3 of «%4»")},
        {"r.none", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "no R-parameter %1 (0..299)")},
        {"r.read-only", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "R%1 is read-only (R232..R262): it cannot be preset")},
        {"r.range", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "R%1 = %2 is outside the 32-bit range")},
        {"program.number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program number %1 is outside 1..99")},
        {"program.empty", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: empty")},
        {"program.utf8", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: not valid UTF-8")},
        {"program.no-line-break", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: the text does not end with a line break")},
        {"program.carriage-return", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: carriage return in the text (lines end with LF)")},
        {"program.bracket", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: line %2 starts with '[' (reserved for machine-file sections)")},
        {"program.header", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: line %2 is the header of program L%3 (one program per entry)")},
        {"program.messages", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: line %2: %MESSAGES belongs to the machine file's [messages] section")},
        {"program.blank", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "program L%1: only blank lines")},
        {"message.number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "technological message number %1 is outside 1..99")},
        {"message.text", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "message #%1: %2")},
        {"plc.number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "PLC message %1 is outside 1..%2")},
        {"plc.text", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "PLC message %1: %2")},
        {"setting.key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "simulation: %1")},
        {"setting.value", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "simulation %1: %2")},
        {"key.empty", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "empty key")},
        {"key.long", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "key longer than 64 characters")},
        {"key.start", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "key '%1' does not start with a letter a-z")},
        {"key.char", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "key '%1' has a character other than a-z, 0-9, '_', '.'")},
        {"value.utf8", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value is not valid UTF-8")},
        {"value.long", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value longer than 200 characters")},
        {"value.lines", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value spans lines")},
        {"value.control", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value has a control character")},
        {"value.semicolon", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value has a ';' (starts a comment in machine files)")},
        {"value.blank", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value starts or ends with a blank")},
        {"value.range", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value %1 is outside %2..%3")},
        {"value.integer", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value '%1' is not a whole number")},
        {"value.number", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value '%1' is not a number")},
        {"value.bool", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "value '%1' is not true/false")},
        {"line.form", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "line '%1' is not tcp://HOST:PORT/UNIT or serial:DEVICE?baud=115200&parity=none&address=1")},
        {"line.unit", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "line '%1': the unit id after '/' is a station address 1..247")},
        {"line.host-port", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "line '%1': no HOST:PORT after tcp:// (tcp://HOST:PORT/UNIT)")},
        {"line.port", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "line '%1': the port after the host is 1..65535")},
        {"line.host", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "line '%1': '%2' is not a host name or address")},
        {"line.device", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "line '%1': no device after serial: (serial:DEVICE?baud=115200&parity=none&address=1)")},
        {"line.baud", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "line '%1': baud is a rate in bit/s, 1200..4000000")},
        {"line.parity", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "line '%1': parity is none, even or odd")},
        {"line.stop-bits", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "line '%1': stop_bits is 1 or 2")},
        {"line.address", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "line '%1': address is a station address 1..247")},
        {"line.key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "line '%1': '%2' is not a setting of a serial line (baud, parity, stop_bits, address)")},
        {"tool.kind", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "'%1' is not a tool kind (turning, facing, grooving, boring, drill, threading)")},
        {"tool.value", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1")},
        {"tool.orientation", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "'%1' is not one of +z+x, -z+x, +z-x, -z-x")},
        {"tool.tip-radius", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "needs 0..50 mm")},
        {"tool.size", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "needs more than 0, at most 1000 mm")},
        {"tool.depth", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "needs 0..100 mm (0: no limit)")},
        {"tool.offset", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "needs a user R-parameter 0..148 (X there, Z in the next)")},
        {"tool.key", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "a tool key is tool.<station 1..8>.<key>")},
        {"tool.field", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "'%1' is not a key of a tool")},
        {"tool.no-kind", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the tool of station %1 has no kind (tool.%1.kind)")},
        {"check.incomplete", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Incomplete set of C-parameters")},
        {"check.range", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "%1 %5 = %3 is outside %4")},
        {"check.axis-discrete", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Axis %1: exactly one display discrete must be set (%2), %3 set")},
        {"check.axis-ratio", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Axis %1: L/N = %2/%3 is above 1: one encoder pulse is more than a discrete, the axis cannot position finer than a pulse")},
        {"check.dac-max-zero", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Axis %1: DAC MAX = 0: the drive gets no voltage")},
        {"check.dac-limit-below", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Axis %1: DAC LIMIT %2 is below DAC MAX %3: message %4 at full speed")},
        {"check.dac-limit-margin", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Axis %1: DAC LIMIT %2 is not 15-20 %% above DAC MAX %3 (recommended %4...%5)")},
        {"check.accel-zero", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Axis %1: ACCELERATION 1 = 0")},
        {"check.feed-zero", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Axis %1: %3 = 0: the axis will not move")},
        {"check.homing-speed-zero", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Axis %1: a homing speed is zero, yet programs need the axis homed")},
        {"check.homing-creep", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Axis %1: F HOME CREEP is above F HOME START")},
        {"check.limits-order", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Axis %1: -LIMIT %2 is not below +LIMIT %3")},
        {"check.home-outside", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Axis %1: HOME VALUE %2 is outside the soft limits %3...%4")},
        {"check.fast-input-twice", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Axis %1: function %2 is assigned to two fast inputs")},
        {"check.no-axis", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "No axis is present (AXIS PRESENT = 0)")},
        {"check.encoders-channel", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Both encoders are on channel %1 (%4)")},
        {"check.wheel-encoder-channel", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "A handwheel and an encoder are on channel %1 (%4)")},
        {"check.drives-channel", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Both drives are on DAC channel %1 (%4)")},
        {"check.wheels-channel", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Both handwheels are on channel %1")},
        {"check.manual-cycle", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Manual cycle %1: program L%2 does not exist")},
        {"check.setting-unknown", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Simulation setting %1 is not in the registry (a typo?)")},
        {"calc.vmax", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Vmax must be a positive number")},
        {"calc.run-up", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the run-up time must be a positive number")},
        {"calc.braking", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the braking distance must be a positive number")},
        {"calc.acceleration", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the acceleration must be a positive number")},
        {"calc.umax", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Umax must be a positive number")},
        {"calc.kv", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "Kv must be a positive number")},
        {"calc.screw-lead", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the screw lead must be a positive number")},
        {"calc.gear-ratio", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the gear ratio must be a positive number")},
        {"calc.encoder-lines", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the encoder must have at least one line")},
        {"calc.lead-discretes", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the screw lead %1 mm is not a whole number of discretes (%2 mm)")},
        {"calc.gear-fraction", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the gear ratio %1 is not a fraction with a denominator up to 100000")},
        {"calc.speed", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "a speed must be zero or positive")},
        {"calc.feed-reach", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the fastest feed %1 mm/min is above what the drive reaches at DAC MAX (%2 mm/min)")},
        {"cutting.cutting-speed", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the cutting speed must be a positive number")},
        {"cutting.diameter", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the diameter must be a positive number")},
        {"cutting.spindle-speed", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the spindle speed must be a positive number")},
        {"cutting.feed", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the feed per revolution must be a positive number")},
        {"cutting.wheel-diameter", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the wheel's diameter must be a positive number")},
        {"cutting.wheel-speed", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the wheel's speed must be a positive number")},
        {"cutting.no-r207", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the machine presets no R207 (the wheel's diameter)")},
        {"cutting.no-offset", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "tool %1 has no offset R-parameters (tool.%1.offset_r)")},
        {"cutting.not-numbers", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "the measured size and the drawing's must be numbers")},
        {"cutting.r-range", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "R%1 would leave the R-parameter range")},
        {"cutting.no-tool", QT_TRANSLATE_NOOP("k528::studio::CoreTexts", "no tool at station %1")},
};

// core/db/notes.cpp's catalog: the notes core and the desktop write.
const TranslatedText kNotes[] = {
        {"seed", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "built-in profile %1 (first start)")},
        {"created", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "created")},
        {"set", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "set %1")},
        {"changed", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "changed %1")},
        {"changed-more", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "changed %1 and %2 more")},
        {"changed-order", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "changed order of simulation settings")},
        {"import", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "import %1")},
        {"studio.import", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "import %1 (K528 Studio)")},
        {"studio.loaded", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "the machine as K528 Studio loaded it")},
        {"studio.kept", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "kept from the simulated controller's memory (K528 Studio)")},
        {"studio.editor", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "programs and messages from the editor (K528 Studio)")},
        {"studio.set", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "set %1 = %2 (K528 Studio)")},
        {"studio.undo", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "undo: %1")},
        {"studio.presets", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "presets %1 (K528 Studio)")},
        {"studio.lock", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "constants locked for the class %1 (trainer)")},
        {"studio.unlock", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "constants unlocked (trainer; were locked for %1)")},
        {"trial", QT_TRANSLATE_NOOP("k528::studio::RevisionNotes", "trial part: T%1 %2 measured %3 for %4: R%5 %6 -> %7")},
};

// core/proveout's findings (proveout::texts()), each text marked for the translators.
const TranslatedText kFindings[] = {
        {"rapid-into-material", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A rapid (G00) enters the material of the blank: X%1 Z%2")},
        {"rapid-into-material.dogleg", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A rapid (G00) enters the material at its dogleg: axis %3 arrives first (X%1 Z%2), although both end points are outside the blank")},
        {"rapid-into-material.ring", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A rapid (G00) takes the wheel into the ring's material: X%1 Z%2")},
        {"tool-into-chuck.jaws", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "Tool T%3 runs into the chuck's jaws: X%1 Z%2")},
        {"tool-into-chuck.body", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "Tool T%3 runs into the chuck's body: X%1 Z%2")},
        {"turret-into-chuck.jaws", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "The turret runs into the chuck's jaws (tool T%3 at X%1 Z%2)")},
        {"turret-into-chuck.body", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "The turret runs into the chuck's body (tool T%3 at X%1 Z%2)")},
        {"feed-spindle-stopped", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A feed into the material with the spindle stopped: X%1 Z%2")},
        {"feed-wheel-stopped", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A feed into the ring's material with the wheel stopped: X%1 Z%2")},
        {"manual-into-material", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A manual move takes the tool into the material of the blank: X%1 Z%2")},
        {"cut-too-deep", QT_TRANSLATE_NOOP("k528::studio::ProveoutTexts", "A cut %1 mm deep, deeper than tool T%2 takes (%3 mm)")},
};

// core/plc/description_texts.cpp's catalog (what is wrong with a machine
// description), each text marked for the translators.
const TranslatedText kDescriptions[] = {
        {"json.twice", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "appears twice")},
        {"json.syntax", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "JSON syntax error: line %2, column %3")},
        {"json.expected-object", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "expected an object, found %1")},
        {"json.unknown-key", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "unknown key (known here: %1)")},
        {"json.missing", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "is missing")},
        {"json.expected-array", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "expected an array, found %1")},
        {"json.expected-string", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "expected a string, found %1")},
        {"json.expected-integer", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "expected a whole number, found %1")},
        {"json.outside", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "%1 is outside %2..%3")},
        {"json.expected-number", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "expected a number, found %1")},
        {"json.expected-bool", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "expected true or false, found %1")},
        {"type.null", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "null")},
        {"type.boolean", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "true/false")},
        {"type.number", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "a number")},
        {"type.string", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "a string")},
        {"type.array", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "an array")},
        {"type.object", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "an object")},
        {"type.other", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "?")},
        {"name.invalid", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1' is not a valid name (letters, digits and '_', starting with a letter or '_', at most 40)")},
        {"name.reserved", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1' is reserved (a keyword or a built-in signal)")},
        {"name.key", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1' is reserved for the K923 keys K1..K12")},
        {"name.address", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1' looks like an interface address (Z<word>.<bit>)")},
        {"format", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "this program reads format 1")},
        {"empty", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "is empty")},
        {"module.twice", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "module place %1 appears twice")},
        {"module.none", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "no module at place %1 in \"modules\"")},
        {"contact", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1': use \"no\" (normally open) or \"nc\" (normally closed)")},
        {"timer.one", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "a timer needs exactly one of on_delay_ms, off_delay_ms, pulse_ms")},
        {"timer.delay", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "a delay belongs to a timer: {\"timer\": \"name\", \"on_delay_ms\": ..., \"when\": ...}")},
        {"rung.one", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "a rung has exactly one of \"out\", \"set\", \"reset\", \"timer\"")},
        {"m.twice", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "M%1 is described twice")},
        {"m.timeout", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "timeout_ms and timeout_alarm go together")},
        {"unknown-m", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "give either \"acknowledge\": true or \"alarm\": k (hold the frame, raise alarm k)")},
        {"override.step", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "%1 % is not an override step (0 1 2 5 10 20 35 50 75 90 100)")},
        {"key.twice", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "K%1 is bound twice")},
        {"key.action", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "a key needs an action: set, reset, toggle or pulse")},
        {"led.twice", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "the LEDs of K%1 are described twice")},
        {"message.twice", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "message %1 has two conditions here")},
        {"slot.unknown", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "not a signal of the positioner interface (known: %1, mode, override, bits)")},
        {"override.code", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "needs the four code bits, least significant first")},
        {"bits.word", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "only the free words Z1011..Z1013 are written here; the bits of Z1000..Z1010 have names (see slot keys)")},
        {"slot.same-bit", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "writes the same bit as %1")},
        {"file.cannot-read", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "cannot read the file")},
        {"file.unknown-machine", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "no such machine description (built in: %1; or give a .json file)")},
        {"plc.name-used", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "the name '%1' is already used (%2)")},
        {"plc.built-in", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "built in")},
        {"plc.unknown-signal", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "unknown signal '%1'")},
        {"plc.not-logic", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "%1 is not written by the logic (only Z1000..Z1013 are; messages, LEDs and keys have their own sections)")},
        {"plc.z1000-11", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "Z1000.11 (M acknowledged) is written by segment 0")},
        {"plc.mode-code", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "%1 is the mode code, written by positioner.mode")},
        {"plc.override-code", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "%1 belongs to the override code, written by positioner.override")},
        {"plc.not-writable", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1' cannot be written: only outputs, flags and bits Z1000..Z1013 can (it is declared at %2)")},
        {"plc.coil-twice", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1' already has a coil (each signal has one)")},
        {"plc.slot-coil", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "%1 already has a coil in the logic")},
        {"plc.pulse-coil", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1' is pulsed by an action and also has a coil")},
        {"condition", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "column %1: %3 in \"%2\"")},
        {"expr.empty", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "empty condition")},
        {"expr.unexpected", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "unexpected '%1'")},
        {"expr.deep", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "condition nested too deeply (more than %1 levels)")},
        {"expr.keyword", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1' is a keyword, not a signal")},
        {"expr.paren", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "missing ')'")},
        {"expr.early", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "the condition ends too early")},
        {"expr.paren-after", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "missing ')' after the signal of %1")},
        {"equipment.detents", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "needs three values: x1, x10, x100 positions")},
        {"equipment.spindle-name", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1': a spindle is \"spindle\", \"wheel\" or \"work\"")},
        {"equipment.spindle-twice", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "spindle '%1' appears twice")},
        {"equipment.pump-name", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1': a pump is \"coolant\", \"lube\", \"hydraulics\" or \"air\"")},
        {"equipment.pump-twice", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "pump '%1' appears twice")},
        {"equipment.ring-size", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "the size must be larger than the blank's bore (internal grinding)")},
        {"equipment.grinding-spindles", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "grinding needs the spindles \"wheel\" and \"work\"")},
        {"equipment.grinding-chuck", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "grinding needs a chuck (the ring is changed while it is open)")},
        {"equipment.unknown-signal", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "unknown machine signal '%1'")},
        {"signal.not-sensor", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1' is not a sensor of this machine (%2)")},
        {"signal.not-actuator", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1' is not an actuator of this machine (%2)")},
        {"signal.driven-twice", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1' is driven by another output too")},
        {"proveout.not-m", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "M%1 is not one of the description's m_functions")},
        {"proveout.not-spindle", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1' is not a spindle of the equipment")},
        {"proveout.on-off", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "M%1 both starts and stops the spindle")},
        {"proveout.cutting-spindle", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "'%1' is not one of the spindles listed here")},
        {"proveout.tool-twice", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "M%1 changes the tool twice")},
        {"proveout.no-turret", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "the equipment has no turret")},
        {"proveout.turret-box", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "the turret's box needs z_min_mm < z_max_mm and r_min_mm < r_max_mm")},
        {"expr.name-missing", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "a signal name is missing at the end")},
        {"expr.name-expected", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "expected a signal name, found '%1'")},
        {"expr.needs-paren", QT_TRANSLATE_NOOP("k528::studio::DescriptionTexts", "%1 needs a signal in parentheses: %1(name)")},
};

// core/engine/refusal_texts.cpp's catalog (why the controller refused an
// operator function), each text marked for the translators.
const TranslatedText kRefusals[] = {
        {"kind.mode-from-plc", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "the PLC sets the mode")},
        {"kind.wrong-mode", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "not in this mode")},
        {"kind.program-active", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "a program is active")},
        {"kind.read-only", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "read-only parameter")},
        {"kind.no-parameter", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "no such parameter")},
        {"kind.out-of-range", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "value out of range")},
        {"kind.no-program", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "no such program")},
        {"kind.axis-absent", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "the axis is not present")},
        {"kind.no-key", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "no such key")},
        {"kind.not-powered", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "the controller is off")},
        {"mode-key", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "F%1 selects no mode")},
        {"mode-from-plc", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "the PLC sets the mode (Z1000.8-10 = %1)")},
        {"override-key", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "override keys are L1..L4, not L%1")},
        {"program-number", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "program numbers are 1..99, not %1")},
        {"r-number", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "R-parameters are R0..R299, not R%1")},
        {"r-read-only", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "R%1 is read only (R232..R262)")},
        {"r-range", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "%1 is outside -2147483648..2147483647")},
        {"program-executing", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "a program is executing")},
        {"program-active", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "a program is active (running or held)")},
        {"c-number", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "C-parameters are 1..152, not %1")},
        {"c-range", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "%1 = %2 is outside the range %3 of «%4»")},
        {"c-mode", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "C-parameters are edited in РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ (F5)")},
        {"c-count", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "153 values expected (C1..C152 at 1..152)")},
        {"c-load-mode", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "C-parameters are loaded from the PC in УПРАВЛЕНИЕ ДАННЫМИ (F7)")},
        {"clear-mode", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "memory is cleared in УПРАВЛЕНИЕ ДАННЫМИ (F7)")},
        {"axis-absent", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "axis %1 is not present")},
        {"set-actual-mode", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "the current value is set in ПРЕДУСТАНОВКИ (F4)")},
        {"zero-offset-range", QT_TRANSLATE_NOOP("k528::studio::RefusalTexts", "the zero offset would leave the 32-bit range")},
};

// util/system_texts.h's catalog: a file that cannot be read or written, the
// system's reason, an MQTT broker's address that is not one.
const TranslatedText kSystem[] = {
        {"io.cannot-open", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "cannot open %1: %2")},
        {"io.cannot-read", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "cannot read %1: %2")},
        {"io.cannot-write", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "cannot write %1: %2")},
        {"io.cannot-read-stdin", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "cannot read standard input: %1")},
        {"io.cannot-write-stdout", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "cannot write standard output: %1")},
        {"io.directory", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "it is a directory")},
        {"io.not-regular", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "it is %1, not a regular file (k528 reads program and machine files only)")},
        {"io.kind.directory", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "a directory")},
        {"io.kind.character-device", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "a character device")},
        {"io.kind.block-device", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "a block device")},
        {"io.kind.fifo", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "a FIFO (named pipe)")},
        {"io.kind.socket", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "a socket")},
        {"io.kind.other", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "a special file")},
        {"io.too-large", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "it is larger than %1 MiB, the most k528 reads (a K528-05 holds at most 99 programs of 999 frames, about 3 MB of text)")},
        {"io.no-memory", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "not enough memory")},
        {"io.write-directory", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "it is a directory; give a file name")},
        {"io.write-kind", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "it is not a regular file, a FIFO or a character device")},
        {"io.create-in-folder", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "cannot create a file in its folder %1: %2")},
        {"io.not-open", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "it is not open")},
        {"io.write-failed", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "a write failed")},
        {"mqtt.url-scheme", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "'%1' is not mqtt://HOST[:PORT] (plain MQTT; TLS is not supported)")},
        {"mqtt.url-port", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "'%1': the port is 1..65535")},
        {"mqtt.url-host", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "'%1': no host name or address after mqtt://")},
        {"errno.EPERM", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Operation not permitted")},
        {"errno.ENOENT", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "No such file or directory")},
        {"errno.EINTR", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Interrupted system call")},
        {"errno.EIO", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Input/output error")},
        {"errno.ENXIO", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "No such device or address")},
        {"errno.EBADF", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Bad file descriptor")},
        {"errno.EAGAIN", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Resource temporarily unavailable")},
        {"errno.ENOMEM", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Cannot allocate memory")},
        {"errno.EACCES", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Permission denied")},
        {"errno.EBUSY", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Device or resource busy")},
        {"errno.EEXIST", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "File exists")},
        {"errno.EXDEV", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Invalid cross-device link")},
        {"errno.ENODEV", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "No such device")},
        {"errno.ENOTDIR", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Not a directory")},
        {"errno.EISDIR", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Is a directory")},
        {"errno.EINVAL", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Invalid argument")},
        {"errno.ENFILE", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Too many open files in system")},
        {"errno.EMFILE", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Too many open files")},
        {"errno.ETXTBSY", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Text file busy")},
        {"errno.EFBIG", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "File too large")},
        {"errno.ENOSPC", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "No space left on device")},
        {"errno.ESPIPE", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Illegal seek")},
        {"errno.EROFS", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Read-only file system")},
        {"errno.EMLINK", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Too many links")},
        {"errno.EPIPE", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Broken pipe")},
        {"errno.ENAMETOOLONG", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "File name too long")},
        {"errno.ELOOP", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Too many levels of symbolic links")},
        {"errno.ENOTEMPTY", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Directory not empty")},
        {"errno.EDQUOT", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Disk quota exceeded")},
        {"errno.ESTALE", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Stale file handle")},
        {"errno.EOVERFLOW", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Value too large for defined data type")},
        {"errno.ENOTSUP", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Operation not supported")},
        {"errno.ECONNREFUSED", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Connection refused")},
        {"errno.ETIMEDOUT", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "Connection timed out")},
        {"errno.other", QT_TRANSLATE_NOOP("k528::studio::SystemTexts", "%2 (error %1)")},
};

const TranslatedTexts kProblemTexts("k528::studio::CoreTexts", kProblems);
const TranslatedTexts kSystemTexts("k528::studio::SystemTexts", kSystem);
const TranslatedTexts kNoteTexts("k528::studio::RevisionNotes", kNotes);
const TranslatedTexts kFindingTexts("k528::studio::ProveoutTexts", kFindings);
const TranslatedTexts kDescriptionTexts("k528::studio::DescriptionTexts", kDescriptions);
const TranslatedTexts kRefusalTexts("k528::studio::RefusalTexts", kRefusals);

QString fromStd(const std::string& s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

} // namespace

bool hasProblemText(std::string_view id) { return kProblemTexts.has(id); }

bool hasSystemText(std::string_view id) { return kSystemTexts.has(id); }

QString systemText(const util::Message& m) {
    return sayWithin({&kSystemTexts}, m.id, m.args, m.within,
                     [](const util::Message& w) { return systemText(w); },
                     [&] { return fromStd(util::systemText(m, false)); });
}

bool hasNoteText(std::string_view id) { return kNoteTexts.has(id); }

bool hasDescriptionText(std::string_view id) { return kDescriptionTexts.has(id); }

QString descriptionProblemText(const profile::Problem& p) {
    return sayWithin({&kDescriptionTexts}, p.id, p.args, p.within,
                     [](const profile::Problem& w) { return descriptionProblemText(w); },
                     [&] { return fromStd(plc::descriptionText(p, false)); });
}

QString descriptionErrorText(const plc::DescriptionError& e) {
    const QString what = descriptionProblemText(e.problem());
    if (e.path().empty())
        return QCoreApplication::translate("k528::studio::CoreTexts", "%1: %2").arg(fromStd(e.source()), what);
    return QCoreApplication::translate("k528::studio::DescriptionTexts", "%1: %2: %3")
        .arg(fromStd(e.source()), fromStd(e.path()), what);
}

bool hasFindingText(std::string_view id) { return kFindingTexts.has(id); }

QString findingText(const proveout::Finding& f) {
    if (const std::optional<QString> text = kFindingTexts.text(f.text, f.args))
        return *text;
    return fromStd(f.message(false)); // an id without a translation: core's English
}

QString refusalText(engine::Refusal r) {
    return kRefusalTexts.text(engine::refusalKindId(r), {}).value_or(QString());
}

bool hasRefusalText(std::string_view id) { return kRefusalTexts.has(id); }

QString refusalText(const engine::OpResult& r) {
    if (r.ok())
        return {};
    if (const std::optional<QString> text = kRefusalTexts.text(r.id, r.args))
        return *text;
    return refusalText(r.refusal); // an id without a translation: the refusal's kind
}

QString revisionNoteText(const std::string& summary) {
    const std::optional<db::Note> note = db::readNote(summary);
    if (!note)
        return fromStd(summary); // a user's own words
    std::vector<std::string> args = note->args;
    if (note->id == "studio.undo")
        for (std::string& a : args)
            a = revisionNoteText(a).toStdString(); // the note undone
    if (const std::optional<QString> text = kNoteTexts.text(note->id, args))
        return *text;
    return fromStd(summary);
}

QString problemText(const profile::Problem& p) {
    // The system's texts too: a machine file's reason why it cannot be read.
    return sayWithin({&kProblemTexts, &kSystemTexts}, p.id, p.args, p.within,
                     [](const profile::Problem& w) { return problemText(w); }, [&] { return fromStd(p.text()); });
}

QString fileErrorText(const profile::FileError& e) {
    const QString what = problemText(e.problem());
    const QString source = fromStd(e.source());
    if (source.isEmpty())
        return what;
    if (e.line() > 0)
        return QCoreApplication::translate("k528::studio::CoreTexts", "%1, line %2: %3")
            .arg(source, QString::number(e.line()), what);
    return QCoreApplication::translate("k528::studio::CoreTexts", "%1: %2").arg(source, what);
}

QString coreErrorText(const std::exception& e) {
    if (const auto* f = dynamic_cast<const profile::FileError*>(&e))
        return fileErrorText(*f);
    if (const auto* d = dynamic_cast<const plc::DescriptionError*>(&e))
        return descriptionErrorText(*d);
    if (const auto* c = dynamic_cast<const profile::cutting::CuttingError*>(&e))
        return problemText(c->problem);
    if (const auto* c = dynamic_cast<const profile::calc::CalcError*>(&e))
        return problemText(c->problem);
    if (const auto* t = dynamic_cast<const profile::ToolError*>(&e))
        return problemText(t->problem());
    if (const auto* v = dynamic_cast<const db::ValidationError*>(&e); v && !v->problem().empty())
        return databaseText(v->catalogText()) + QStringLiteral(" ") + problemText(v->problem());
    if (const auto* v = dynamic_cast<const db::ValidationError*>(&e); v && !v->findings().empty()) {
        // The head by the database's catalog id; the cross-checks' findings
        // a line each, by their problems' ids.
        QString text = databaseText(v->catalogText());
        for (const profile::Finding& f : v->findings()) {
            QString line = fromStd(f.subject);
            if (f.message)
                line += QCoreApplication::translate("k528::studio::CoreTexts", " (message %1)").arg(*f.message);
            text += QStringLiteral("\n") + line + QStringLiteral(": ") + problemText(f.problem);
        }
        return text;
    }
    return databaseErrorText(e);
}

bool readTextFile(const QString& path, std::string& text, QString& error) {
    util::Message m;
    if (util::readInputFile(path.toStdString(), text, m))
        return true;
    // Core's reason (util/system_texts.h) in the window's language, the system's too.
    error = QCoreApplication::translate("k528::studio::CoreTexts", "%1 cannot be read: %2")
                .arg(path, m.within.empty() ? systemText(m) : systemText(m.within.front()));
    return false;
}

} // namespace k528::studio
