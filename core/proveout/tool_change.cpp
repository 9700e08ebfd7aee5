#include "proveout/tool_change.h"

namespace k528::proveout {

int stationAfter(const MachineGeometry& g, const toolpath::MFunctions& f, int station) {
    for (int k = 0; k < f.count; ++k)
        if (const auto t = g.toolChange.find(f.codes[static_cast<std::size_t>(k)]); t != g.toolChange.end())
            station = t->second;
    return station;
}

std::vector<int> stationsAlong(const toolpath::ProgrammedPath& path, const MachineGeometry& g) {
    std::vector<int> out(path.segments.size(), 0);
    int station = g.firstStation;
    std::size_t m = 0;
    for (std::size_t i = 0; i < path.segments.size(); ++i) {
        for (; m < path.mFunctions.size() && path.mFunctions[m].segment <= i; ++m)
            station = stationAfter(g, path.mFunctions[m], station);
        out[i] = station;
    }
    return out;
}

std::optional<ToolCorrection> correctionOf(const profile::Tool& tool, const std::map<int, std::int64_t>& r) {
    if (tool.offsetR < 0)
        return std::nullopt;
    ToolCorrection c;
    c.rX = tool.offsetR;
    c.rZ = tool.offsetR + 1;
    if (const auto it = r.find(c.rX); it != r.end())
        c.xDisc = it->second;
    if (const auto it = r.find(c.rZ); it != r.end())
        c.zDisc = it->second;
    return c;
}

} // namespace k528::proveout
