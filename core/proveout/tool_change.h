// The tool change of a K528-05 lathe, in one place: which tool is in use
// and what puts its offsets into effect (docs/engine.md "The tool change").
//
// The K528-05 has no T word and no tool table (manual 2.7.1: a frame holds
// N, G, M, #, L, X, Z, F). A machine indexes its turret by M functions that
// its PLC carries out (the training lathe: M61..M64, the description's
// `tool_change`); the positioner only hands the number over and waits for
// the PLC's answer. The tool's offsets reach the coordinates through one
// component of 2.4, the correction R226/R227 («Коррекция», appendix Л):
// current = machine − … − correction. The PLC cannot write it (its only way
// in is the one-step «подналадка» ±R218/R219 of Z1006.1/.2), so after the M
// function the program copies the station's offset R-parameters into it —
// `R226=R<offset_r>`, `R227=R<offset_r + 1>` (profile/tools.h) — and from
// the next move on the programmed point is that tool's tip. A program that
// does not copy them moves the new tool as if it were the old one: the
// simulated machine does the same, and the prove-out finds where.
#pragma once

#include "profile/tools.h"
#include "proveout/geometry.h"
#include "toolpath/programmed_path.h"

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace k528::proveout {

// The station in use after a frame's M functions, `station` before them: a
// tool-change M of the machine indexes the turret (the last one of the frame
// wins, as the PLC carries them out in order).
int stationAfter(const MachineGeometry& g, const toolpath::MFunctions& f, int station);

// The station in use during each segment of `path` (one per segment), from
// the turret's station at power-on (`g.firstStation`, 0: none known).
std::vector<int> stationsAlong(const toolpath::ProgrammedPath& path, const MachineGeometry& g);

// What the program copies into the correction after indexing to `tool`:
// R226 ← R<rX>, R227 ← R<rZ>, the values of those R-parameters in `r`
// (display discretes; 0 when not set). Nullopt: the tool names no offset
// R-parameters.
struct ToolCorrection {
    int rX = -1, rZ = -1;
    std::int64_t xDisc = 0, zDisc = 0;
};
std::optional<ToolCorrection> correctionOf(const profile::Tool& tool, const std::map<int, std::int64_t>& r);

} // namespace k528::proveout
