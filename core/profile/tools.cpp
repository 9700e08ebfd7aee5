#include "profile/tools.h"

#include <algorithm>
#include <array>

namespace k528::profile {

namespace {

struct KindName {
    ToolKind kind;
    std::string_view name;
};
constexpr std::array<KindName, 6> kKinds{{{ToolKind::Turning, "turning"},
                                          {ToolKind::Facing, "facing"},
                                          {ToolKind::Grooving, "grooving"},
                                          {ToolKind::Boring, "boring"},
                                          {ToolKind::Drill, "drill"},
                                          {ToolKind::Threading, "threading"}}};

constexpr std::array<std::string_view, 9> kKeys{"kind",      "name",     "name.en",      "tip_radius_mm",
                                                "orientation", "width_mm", "height_mm",
                                                "max_depth_mm", "offset_r"};

std::string key(int station, std::string_view k) {
    return "tool." + std::to_string(station) + "." + std::string(k);
}

bool outside(ToolKind k) {
    return k != ToolKind::Boring && k != ToolKind::Drill;
}

} // namespace

std::string_view toolKindName(ToolKind k) {
    for (const KindName& n : kKinds)
        if (n.kind == k)
            return n.name;
    return "";
}

std::optional<ToolKind> parseToolKind(std::string_view s) {
    for (const KindName& n : kKinds)
        if (n.name == s)
            return n.kind;
    return std::nullopt;
}

std::string Tool::orientation() const {
    return std::string(zDirection > 0 ? "+z" : "-z") + (xDirection > 0 ? "+x" : "-x");
}

namespace {
// "simulation <key>: <what>".
Problem setting(const std::string& key, Problem what) {
    Problem p = problem("setting.value", {key});
    p.within.push_back(std::move(what));
    return p;
}
} // namespace

std::vector<Tool> tools(const MachineProfile& p) {
    std::vector<Tool> out;
    for (int st = 1; st <= kMaxToolStations; ++st) {
        if (!p.simulation.has(key(st, "kind")))
            continue;
        Tool t;
        t.station = st;
        const auto fail = [&](std::string_view k, std::string id, std::vector<std::string> args = {}) {
            throw ToolError(setting(key(st, k), problem(std::move(id), std::move(args))));
        };
        const std::string kind = p.simulation.getString(key(st, "kind"), "");
        const auto k = parseToolKind(kind);
        if (!k)
            fail("kind", "tool.kind", {kind});
        t.kind = *k;
        t.name = p.simulation.getString(key(st, "name"), "");
        try {
            t.tipRadiusMm = p.simulation.getDouble(key(st, "tip_radius_mm"), 0);
            t.widthMm = p.simulation.getDouble(key(st, "width_mm"), outside(t.kind) ? 3 : 150);
            t.heightMm = p.simulation.getDouble(key(st, "height_mm"), outside(t.kind) ? 1000 : 10);
            t.maxDepthMm = p.simulation.getDouble(key(st, "max_depth_mm"), 0);
            t.offsetR = static_cast<int>(p.simulation.getInt(key(st, "offset_r"), -1));
        } catch (const SettingError& e) {
            throw ToolError(problem("tool.value", {e.what()}));
        }
        const std::string o =
            p.simulation.getString(key(st, "orientation"), t.kind == ToolKind::Boring ? "+z-x" : "+z+x");
        if (o.size() != 4 || (o[0] != '+' && o[0] != '-') || o[1] != 'z' ||
            (o[2] != '+' && o[2] != '-') || o[3] != 'x')
            fail("orientation", "tool.orientation", {o});
        t.zDirection = o[0] == '+' ? 1 : -1;
        t.xDirection = o[2] == '+' ? 1 : -1;
        if (t.tipRadiusMm < 0 || t.tipRadiusMm > 50)
            fail("tip_radius_mm", "tool.tip-radius");
        if (t.widthMm <= 0 || t.widthMm > 1000)
            fail("width_mm", "tool.size");
        if (t.heightMm <= 0 || t.heightMm > 1000)
            fail("height_mm", "tool.size");
        if (t.maxDepthMm < 0 || t.maxDepthMm > 100)
            fail("max_depth_mm", "tool.depth");
        if (t.offsetR != -1 && (t.offsetR < 0 || t.offsetR > 148 || t.offsetR + 1 > 149))
            fail("offset_r", "tool.offset");
        out.push_back(t);
    }
    for (const auto& [k, v] : p.simulation.entries()) {
        if (k.rfind("tool.", 0) != 0)
            continue;
        const std::size_t dot = k.find('.', 5);
        const std::string st = k.substr(5, dot == std::string::npos ? std::string::npos : dot - 5);
        const auto n = parseInt(st);
        if (!n || *n < 1 || *n > kMaxToolStations || dot == std::string::npos)
            throw ToolError(setting(k, problem("tool.key")));
        const std::string_view field = std::string_view(k).substr(dot + 1);
        if (std::find(kKeys.begin(), kKeys.end(), field) == kKeys.end())
            throw ToolError(setting(k, problem("tool.field", {std::string(field)})));
        if (!p.simulation.has(key(static_cast<int>(*n), "kind")))
            throw ToolError(setting(k, problem("tool.no-kind", {st})));
    }
    return out;
}

void setTool(MachineProfile& p, const Tool& t) {
    for (std::string_view k : kKeys)
        if (k != "name.en") // the name's English (english.h) stays with the station
            p.simulation.erase(key(t.station, k));
    p.simulation.set(key(t.station, "kind"), toolKindName(t.kind));
    if (!t.name.empty())
        p.simulation.set(key(t.station, "name"), t.name);
    p.simulation.setDouble(key(t.station, "tip_radius_mm"), t.tipRadiusMm);
    p.simulation.set(key(t.station, "orientation"), t.orientation());
    p.simulation.setDouble(key(t.station, "width_mm"), t.widthMm);
    p.simulation.setDouble(key(t.station, "height_mm"), t.heightMm);
    p.simulation.setDouble(key(t.station, "max_depth_mm"), t.maxDepthMm);
    if (t.offsetR >= 0)
        p.simulation.setInt(key(t.station, "offset_r"), t.offsetR);
}

std::optional<Tool> toolAt(const std::vector<Tool>& tools, int station) {
    for (const Tool& t : tools)
        if (t.station == station)
            return t;
    return std::nullopt;
}

ToolOffsets toolOffsets(const Tool& t, const MachineProfile& p,
                        const std::map<int, std::int64_t>& extraR) {
    ToolOffsets o;
    if (t.offsetR < 0)
        return o;
    const auto value = [&](int n) -> std::int64_t {
        if (const auto it = extraR.find(n); it != extraR.end())
            return it->second;
        if (const auto it = p.r.find(n); it != p.r.end())
            return it->second;
        return 0;
    };
    o.xMm = units::discToMm(value(t.offsetR), axisScale(p, catalog::Axis::X));
    o.zMm = units::discToMm(value(t.offsetR + 1), axisScale(p, catalog::Axis::Z));
    return o;
}

} // namespace k528::profile
