// The R-parameter map of the K528-05 (section 2.5, appendix Л, the preset
// screens of section 2.6.5).
//
// R0..R149 belong to the user. R150..R299 are reserved by the system; appendix
// Л gives the meaning of most of R150..R262, R232..R262 are read-only. The
// preset groups «УСТАНОВОЧНЫЕ ДАННЫЕ 1..9» are the screens УСТ 1..9 of the
// ПРЕДУСТАНОВКИ mode. Values are signed 32-bit integers; coordinates are in
// display discretes of their axis, feeds in discretes per minute.
#pragma once

#include "catalog/cparams.h"

#include <cstdint>
#include <string_view>

namespace k528::catalog {

inline constexpr int kRParamCount = 300;    // R0..R299
inline constexpr int kRUserLast = 149;      // R0..R149: user parameters
inline constexpr int kRReadOnlyFirst = 232; // R232..R262: read only
inline constexpr int kRReadOnlyLast = 262;
inline constexpr std::int64_t kRMin = -2147483648LL;
inline constexpr std::int64_t kRMax = 2147483647LL;

enum class RAccess {
    User,       // R0..R149
    System,     // reserved with a meaning, writable (presets, offsets)
    ReadOnly,   // R232..R262: the controller writes them
    Unassigned, // reserved, no meaning printed
};

enum class RUnit {
    Number,        // plain number (user parameters, counters, codes)
    Flag,          // 0/1
    DiscX,         // display discretes of axis X
    DiscZ,         // display discretes of axis Z
    DiscXPerMin,   // discretes of X per minute (a feed of X)
    DiscZPerMin,   // discretes of Z per minute (a feed of Z)
    Ms,            // milliseconds (shown as seconds with 3 decimals)
    DacUnits,      // DAC code
    Pulses,        // encoder pulses
    ProgramNumber, // 1..99
    FrameNumber,   // 1..999
};

std::string_view rUnitRu(RUnit u);
std::string_view rUnitEn(RUnit u);
// X for DiscX / DiscXPerMin, Z for the Z ones, Common otherwise.
Axis rUnitAxis(RUnit u);

struct RParamDef {
    int number;
    RAccess access;
    RUnit unit;
    int group;                  // 1..9: «УСТАНОВОЧНЫЕ ДАННЫЕ n», 0: none
    std::string_view meaningRu; // appendix Л (or the preset screen), "" if unassigned
    std::string_view meaningEn;
    std::string_view panelHint; // explanatory line of the preset screen, "" if none
    std::string_view note;      // decisions and sources (English), "" if none

    bool readOnly() const { return access == RAccess::ReadOnly; }
    bool user() const { return access == RAccess::User; }
    bool reserved() const { return access != RAccess::User; }
};

// The definition of R`number` (0..299); throws std::out_of_range.
const RParamDef& rParam(int number);
const RParamDef* findRParam(int number) noexcept;

// «КООРД.И СМЕЩЕНИЯ», «ИСХОДНОЕ», ... for groups 1..9 ("" otherwise).
std::string_view rGroupNameRu(int group);
std::string_view rGroupNameEn(int group);

} // namespace k528::catalog
