// The active tool's cutting edge in the backplot's XZ view (no Qt): the
// insert's outline with its nose radius, drawn with the tip's theoretical
// corner at the tool's point — the programmed point is the tip once the
// program copied the station's offsets into the correction (docs/engine.md
// "The tool change") — and the body lying where the tool's orientation says
// (profile/tools.h): a turning or facing tool an 80° insert, a boring bar a
// 55° insert on its bar, a grooving blade as wide as the tool, a drill
// centred on its tip with its 118° point, a threading tool's 60° form.
//
// Radial sizes are drawn as the view shows X: twice on a diameter axis.
// ToolEdge owns its actor and rebuilds its lines only when the tool, its
// point or the view's scale changed.
#pragma once

#include "profile/tools.h"
#include "toolpath/programmed_path.h"

#include <memory>
#include <optional>
#include <vector>

class vtkRenderer;

namespace k528::backplot {

inline constexpr double kInsertEdgeMm = 8; // an insert's edge, drawn (the profile gives no insert size)

// The tools of the machine's stations and the station in use during each
// segment of the path shown (proveout::stationsAlong); empty: no edge.
struct ToolsInUse {
    std::vector<profile::Tool> tools;
    std::vector<int> stations; // one per segment
    // The tool of the station in use at segment `i` (nullopt: none).
    std::optional<profile::Tool> atSegment(std::size_t i) const;
    std::optional<profile::Tool> atStation(int station) const;
};
// The tools of `profile` and their stations along `path` (empty when the
// machine describes no tools, or its tools or description cannot be read:
// the prove-out says why).
ToolsInUse toolsInUse(const profile::MachineProfile& profile, const toolpath::ProgrammedPath& path);

// The outline as line segments (z0, x0, z1, x1 each, world mm as shown) with
// the tip's corner at (tipZ, tipX); `shownPerMm` is X shown per mm of radius
// (2 on a diameter axis). Arcs are `arcSteps` chords.
std::vector<float> toolEdgeLines(const profile::Tool& tool, double tipZ, double tipX, double shownPerMm,
                                 int arcSteps = 8);

class ToolEdge {
public:
    explicit ToolEdge(vtkRenderer* renderer);
    ~ToolEdge();
    // The tool at (z, x) in the XZ view, none when `tool` is empty or the
    // view is not XZ (`visible` false).
    void show(const std::optional<profile::Tool>& tool, double z, double x, double shownPerMm, bool visible);
    bool shown() const { return shown_; }
    const std::optional<profile::Tool>& tool() const { return tool_; } // the one drawn last
    int rebuilds() const { return rebuilds_; } // how often the lines were rebuilt (tests)

private:
    struct Vtk;
    std::unique_ptr<Vtk> v_;
    std::optional<profile::Tool> tool_;
    double z_ = 0, x_ = 0, shownPerMm_ = 0;
    bool shown_ = false;
    int rebuilds_ = 0;
};

} // namespace k528::backplot
