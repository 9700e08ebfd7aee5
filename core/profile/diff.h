// Differences between two machine profiles: two machines, or two revisions of
// one machine. Every C-parameter, R preset, program, message, PLC text and
// simulation setting that differs, old -> new, in a fixed order.
#pragma once

#include "profile/profile.h"

#include <optional>
#include <string>
#include <vector>

namespace k528::profile {

enum class DiffSection { Machine, C, R, Program, Message, PlcMessage, Simulation };

std::string_view diffSectionName(DiffSection s); // "machine", "c", "r", ...

struct Change {
    DiffSection section;
    std::string key;   // "name", "C022", "R204", "L11", "#3", "A01", "x.kv"
    std::string label; // panel name or meaning ("УСКОРЕНИЕ 1"), may be empty
    std::optional<std::string> before; // nullopt: absent in the first profile
    std::optional<std::string> after;  // nullopt: absent in the second profile

    bool operator==(const Change&) const = default;
};

// Changes turning `a` into `b`, ordered: machine (name, title), C by number,
// R by number, programs, messages, PLC texts (A, W, S), simulation settings
// (keys in `a`'s order, then keys only `b` has, in `b`'s order; a key that
// only moved is not a change).
std::vector<Change> diff(const MachineProfile& a, const MachineProfile& b);

// Readable text, one line per change:
//   C022 УСКОРЕНИЕ 1: 2000 -> 2133
//   R204 ДИАМЕТР НОВ.КРУГА: (none) -> 20000
// Programs show a line diff below their line ("  - old line", "  + new line").
std::string formatDiff(const std::vector<Change>& changes);

// Line differences of two texts (longest common subsequence): each line of
// the result is "  <line>", "- <line>" or "+ <line>". Equal texts give "".
std::string lineDiff(const std::string& before, const std::string& after);

} // namespace k528::profile
