// Teach-in (NC-200 §20, «режим обучения»): the position the controller's
// axes are at, written into the program as a frame — what the setter jogged
// to becomes the program's point — or as the computational frame of a preset
// R-parameter whose panel hint names that coordinate (R220 «MX: координата
// X», the diamond's R200, the oscillation's reversal points …). The studio
// takes the position from the controller it shows (simulated or on the line).
#pragma once

#include "catalog/cparams.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace k528::editing {

// "N12 X40.5 Z-5" (canonical: shortest exact decimal to the µm; N omitted
// when `n` is 0, an axis omitted when not given). Empty when neither is.
std::string teachFrame(int n, std::optional<double> xMm, std::optional<double> zMm);

// A preset R-parameter a position may be taught into.
struct TeachTarget {
    int r = 0;
    catalog::Axis axis = catalog::Axis::X;
    bool machineCoordinate = false; // appendix Л says «в системе станка»: the machine coordinate, else the current one
    std::string_view hint;          // the preset screen's line («MX: координата X»)
    std::string_view meaningRu, meaningEn;
};
// Every writable R whose hint names a coordinate of X or Z, by number.
std::vector<TeachTarget> teachTargets();
// "N12 R220=200000": R`r` set to `disc` (discretes of its axis).
std::string teachRFrame(int n, int r, std::int64_t disc);
// The frame number to give a frame inserted after `previous` (0: none):
// previous + 1, 0 when there is none.
int nextFrameNumber(int previous);

} // namespace k528::editing
