// A machine profile: everything that makes one K528-05 installation — the
// machine constants C1..C152, R-parameter presets, control programs, the
// technological messages, the PLC message texts and the simulation settings.
//
// A value object: copy it, compare it, store it. Its text form is the
// machine file (.k528m, profile/text_format.h); the built-in profiles are
// loaded with profile/builtin.h. Nothing here checks values: validate()
// (profile/validate.h) does, and the machine-file reader rejects a file whose
// values break their definitions.
#pragma once

#include "catalog/cparams.h"
#include "catalog/messages.h"
#include "profile/settings.h"
#include "units/units.h"

#include <array>
#include <cstdint>
#include <map>
#include <span>
#include <string>

namespace k528::profile {

struct MachineProfile {
    std::string name;  // identifier: a-z 0-9 . _ - (e.g. "grinder-205")
    std::string title; // one line for people

    // C-parameter n is c[n] (n = 1..152); c[0] is unused and stays 0, so the
    // array can be handed to code that indexes by number (axis::Constants::fromC).
    std::array<std::int64_t, catalog::kCParamCount + 1> c{};

    // R-parameter presets: number (0..299) -> value (signed 32-bit). Only
    // listed parameters are preset.
    std::map<int, std::int64_t> r;

    // Control programs: number (1..99) -> the program's text in the program
    // language (shared/spec/program-language.md), a whole file of its own,
    // usually starting with its header «%L<n> (title)». Stored verbatim, not
    // parsed here. Lines end with "\n".
    std::map<int, std::string> programs;

    // Technological messages #1..99 (≤ 20 characters, shown while a frame
    // with #k runs).
    std::map<int, std::string> messages;

    // PLC message texts (≤ 40 characters): alarm 1..32 (Z1900/Z1901), work
    // 1..32 (Z1902/Z1903), system 1..16 (Z1307).
    std::map<int, std::string> plcAlarm;
    std::map<int, std::string> plcWork;
    std::map<int, std::string> plcSystem;

    Settings simulation;

    // C-parameter access by number; throws std::out_of_range outside 1..152.
    std::int64_t cValue(int number) const;
    void setC(int number, std::int64_t value);
    // All values indexed by number (size 153, element 0 unused).
    std::span<const std::int64_t> cValues() const { return c; }

    std::map<int, std::string>& plcTexts(catalog::PlcGroup g);
    const std::map<int, std::string>& plcTexts(catalog::PlcGroup g) const;

    bool operator==(const MachineProfile&) const = default;
};

// The value of X-parameter `xNumber` (1..52) for `axis` (Z: C(xNumber + 52)).
std::int64_t axisValue(const MachineProfile& p, catalog::Axis axis, int xNumber);

// НАЛИЧ.ОСИ of the axis is 1.
bool axisPresent(const MachineProfile& p, catalog::Axis axis);

// The axis' display discrete (C4..6 / C56..58) and diameter display (C7 /
// C59). When not exactly one discrete flag is set (a profile validate()
// reports with message 15), the smallest set one is taken, 0.001 mm if none.
units::AxisScale axisScale(const MachineProfile& p, catalog::Axis axis);

// Values indexed by number, all 0 (for building profiles).
using CValues = std::array<std::int64_t, catalog::kCParamCount + 1>;

} // namespace k528::profile
