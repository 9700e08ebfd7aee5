// Frame builders the editor's masters call: each takes the fields
// of one kind of frame, builds the model's Frame and gives its canonical
// text through the formatter (formatFrame), with the problems the parser
// and the validator find in it. `problems` empty = the frame may be
// inserted; re-parsing `text` gives the same frame (a test checks it).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "program/diagnostic.h"
#include "program/gfunctions.h"
#include "program/model.h"

namespace k528::program {

struct BuiltFrame {
    Frame frame;
    std::string text;                  // canonical, without comments
    std::vector<Diagnostic> problems;  // parser + validator rules of the frame itself
    bool ok() const { return !hasErrors(problems); }
};

// The fields every frame has.
struct FrameHead {
    bool skip = false;
    int n = 0; // 0 = no frame number
};

// ISO motion frame: up to 3 G, up to 3 M, #k, L p, X, FX, Z, FZ.
struct IsoFields {
    FrameHead head;
    std::vector<int> g;
    std::vector<int> m;
    int message = 0; // 0 = none
    int call = 0;    // 0 = none
    std::optional<Value> x, fx, z, fz;
};
BuiltFrame buildIso(const IsoFields& f);

// G04 X<seconds>.
BuiltFrame buildDwell(FrameHead head, Decimal seconds);

// L<p> (a subprogram call), optionally with M-functions.
BuiltFrame buildCall(FrameHead head, int program, std::vector<int> m = {});

// Gx81 (start) / Gx80 (stop) oscillation of one axis: stroke and speed on start.
BuiltFrame buildOscillation(FrameHead head, Axis axis, bool start, std::optional<Decimal> strokeMm = {},
                            std::optional<Decimal> feedMmPerMin = {});

// Gx36..Gx39: move an axis until signal 1..4.
BuiltFrame buildMoveUntilSignal(FrameHead head, Axis axis, int signal, Decimal targetMm, Decimal feedMmPerMin);

// R<target>=<a>[<op><b>].
BuiltFrame buildCompute(FrameHead head, int target, Operand a, ArithOp op = ArithOp::None, Operand b = {});

// IF R<r>>0 GOTO <target>.
BuiltFrame buildIfGoto(FrameHead head, int r, int target);

// GOTO <target>.
BuiltFrame buildGoto(FrameHead head, int target);

// "#k=text" of the %MESSAGES section, with its problems (length, characters).
struct BuiltMessage {
    std::string text;
    std::vector<Diagnostic> problems;
    bool ok() const { return !hasErrors(problems); }
};
BuiltMessage buildMessage(int number, const std::string& text);

// Problems of one frame's text read on its own: syntax, ranges, combinations.
// Rules that need the rest of the file (jump targets, calls, message
// table, subprogram ends) are left to the file's validation.
std::vector<Diagnostic> frameProblems(const std::string& frameText);

} // namespace k528::program
