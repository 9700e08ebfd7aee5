// The backplot scene in VTK (no Qt: the studio's dock and `k528 plot` draw the
// same scene): the lathe view with Z horizontal and X vertical (X as the
// machine shows it: diameter or radius), feed solid and rapid dashed in
// distinct colours (OpenGL2 has no stipple: dashes are separate cells),
// segments beyond the software limits highlighted, programmed points as
// diamonds, the tool, the limit rectangle (C46/C47, C98/C99, drawn in the
// current coordinates of the start), a scale legend with rulers, the actual
// path coloured by following error with a legend in µm, and the stock: its
// half profile in XZ, revolved (vtkRotationalExtrusionFilter) in the 3D view.
//
// Level of detail: path_geometry.h simplifies for the camera; the scene's
// polydata are static buffers rebuilt only by refresh() (after a zoom or
// pan ends, or when the playhead moves), so interaction renders a few
// thousand cells whatever the size of the program.
#pragma once

#include "backplot/path_geometry.h"
#include "backplot/tool_edge.h"
#include "stock/stock.h"
#include "toolpath/actual_path.h"
#include "toolpath/programmed_path.h"

#include <memory>
#include <string>
#include <vector>
#include <optional>

class vtkRenderer;

namespace k528::backplot {

struct Rgb {
    double r, g, b;
};
// The scene's colours (tests check pixels against them).
inline constexpr Rgb kBackground{0.10, 0.11, 0.13};
inline constexpr Rgb kFeedColour{0.15, 0.85, 0.25};
inline constexpr Rgb kRapidColour{1.00, 0.70, 0.00};
inline constexpr Rgb kOutsideColour{1.00, 0.15, 0.15};
inline constexpr Rgb kLimitColour{0.30, 0.55, 1.00};
inline constexpr Rgb kPointColour{0.90, 0.90, 0.90};
inline constexpr Rgb kToolColour{1.00, 0.20, 1.00};
inline constexpr Rgb kStockColour{0.45, 0.47, 0.52};
inline constexpr Rgb kOscillationColour{0.20, 0.85, 0.95};
inline constexpr Rgb kWheelColour{0.85, 0.78, 0.60};
inline constexpr Rgb kTitleColour{0.85, 0.85, 0.85}; // the title, the scale bar and its length
inline constexpr Rgb kFindingColour{1.00, 0.00, 0.00}; // a prove-out finding's marker (a red disc)

// The overlay's sizes in pixels (at the window's DPI): texts do not shrink
// with the view, the bands keep the rulers clear of the texts.
inline constexpr int kTextPx = 14;      // the title, «ВНЕ ГРАНИЦ»
inline constexpr int kSmallTextPx = 12; // rulers, the scale's length, the µm bar
inline constexpr int kTopBandPx = 54;   // two lines of text above the left ruler
inline constexpr int kBottomBandPx = 60; // the scale bar below the bottom ruler
inline constexpr int kLeftBandPx = 56;   // the left ruler's labels
inline constexpr int kRightBarBandPx = 96; // the µm bar of an actual path

// The overlay's words in the caller's language; "%1" stands for a number.
// English by default (`k528 plot`); the studio sets them through tr().
// The deviation bar's labels: printf's format (394, 12.5, 0.25; VTK's own
// "%-#6.3g" would say «394.»).
inline constexpr const char* kDeviationLabelFormat = "%.4g";

struct OverlayTexts {
    std::string segments = "%1 segments";
    std::string diameter = "X \xE2\x8C\x80 diameter"; // X ⌀ diameter
    std::string radius = "X radius";
    std::string mm = "%1 mm";
    std::string micrometres = "\xC2\xB5m"; // the deviation bar's title
};

// The grinding wheel as the view draws it: a cylinder of R207's diameter
// (ProgrammedPath::wheel; 0: no wheel) whose axis is parallel to Z. The
// programmed point is the wheel's working edge at its −Z face (as the lathe
// tool's cutting corner, stock.h): the wheel extends `widthMm` along +Z and,
// on an internal grinder (`inside`, grinder-205: the edge grinds the bore),
// its diameter towards the work's axis; outside: away from it. R-parameters
// give no width: 10 mm is the view's default (a setting, not a measurement).
struct WheelGeometry {
    double widthMm = 10.0;
    bool inside = true;
};

enum class ViewMode { XZ, Solid3D };

// A path made ready for the scene away from it (any thread, no VTK): the
// geometry built and the blank cut by the path. The studio prepares a path
// on a worker (backplot/path_job.h) and hands it to setPrepared(): the GUI
// thread then only fills VTK's buffers.
struct PreparedPath {
    toolpath::ProgrammedPath path;
    PathGeometry geometry;
    std::optional<stock::Blank> blank;
    std::optional<stock::Shape> stock; // the blank as the path leaves it; none: no blank, or the cut was stopped
    ToolsInUse tools; // the machine's tools and the station along the path (toolsInUse); empty: no tool edge
};
// Builds the geometry and cuts the blank; `progress` as Stock::cutPath's
// (false stops the cut: `stock` stays empty).
PreparedPath preparePath(toolpath::ProgrammedPath path, const std::optional<stock::Blank>& blank,
                         const stock::CutProgress& progress = {});

class BackplotScene {
public:
    BackplotScene();
    ~BackplotScene();
    vtkRenderer* renderer() const;

    void setPath(const toolpath::ProgrammedPath& path);
    void setPath(toolpath::ProgrammedPath&& path);
    // A path and its stock prepared elsewhere (preparePath).
    void setPrepared(PreparedPath&& prepared);
    // The overlay's words (the title, the scale's length); shown at the next refresh.
    void setTexts(const OverlayTexts& texts);
    const OverlayTexts& texts() const { return texts_; }
    // Device pixels per pixel of the overlay's sizes (2 on a 2× HiDPI screen).
    void setPixelRatio(double ratio) { ratio_ = ratio > 0 ? ratio : 1; }
    // What the title says now ("L1  5 segments  X ⌀ diameter").
    std::string titleText() const;
    // The deviation bar's title now («µm», «мкм»).
    std::string deviationBarTitle() const;
    // The scale bar's length now, in mm (0: none, the 3D view).
    double scaleBarMm() const { return scaleBarMm_; }
    // While the user pans or zooms: the 2D overlays (rulers, texts) are
    // hidden — they are rebuilt every frame and cost more than the path.
    void setInteracting(bool on);
    void setActual(const toolpath::ActualPath* actual); // null: none
    const toolpath::ActualPath* actual() const { return actual_; }
    // The same path grown since the last call: samples [from, size) are
    // appended to the buffers (a different path or from 0: setActual).
    void appendActual(const toolpath::ActualPath* actual, std::size_t from);
    std::size_t actualPointsShown() const;
    // The live tool (a run on the session's machine): the cross and the
    // wheel there, instead of the playhead's; nullopt: the playhead's.
    struct LiveTool {
        double z = 0, x = 0;     // current coordinates, mm as shown
        double wheelMm = 0;      // R207 now, 0 none
        int station = -1;        // the turret's station now (0 indexing); -1 unknown: no tool edge
    };
    void setLiveTool(const std::optional<LiveTool>& t);
    const std::optional<LiveTool>& liveTool() const { return live_; }
    void setWheelGeometry(const WheelGeometry& g) { wheelGeom_ = g; }
    // The tools whose edge is drawn at the tool's point (tool_edge.h); a new
    // path (setPath) clears the stations, setPrepared brings its own.
    void setToolsInUse(ToolsInUse tools) { tools_ = std::move(tools); }
    const ToolEdge& toolEdge() const { return *edge_; }
    const WheelGeometry& wheelGeometry() const { return wheelGeom_; }
    // Where the wheel is drawn now (world Z0..Z1 × shown X0..X1), empty when none.
    struct WheelBox {
        bool shown = false;
        double z0 = 0, z1 = 0, x0 = 0, x1 = 0, diameterMm = 0;
    };
    WheelBox wheelBox() const { return wheelBox_; }
    void setStock(const std::optional<stock::Blank>& blank); // cut by the path when shown
    const toolpath::ProgrammedPath& path() const { return path_; }
    const PathGeometry& geometry() const { return geom_; }

    void setViewMode(ViewMode m);
    ViewMode viewMode() const { return mode_; }
    // Camera to the whole path, limits and stock; window size in pixels.
    void fit(int widthPx, int heightPx);
    // Rebuilds the level of detail for the current camera (call after
    // zoom/pan ends and after the window resized).
    void refresh(int widthPx, int heightPx);

    // Playback: the path drawn up to time `seconds` from the start (the tool
    // there); a negative time shows all.
    void setPlayhead(double seconds);
    double totalSeconds() const { return cumulative_.empty() ? 0 : cumulative_.back(); }
    // The start time of segment i (step by frame).
    double segmentStart(std::size_t i) const { return i == 0 ? 0 : cumulative_[i - 1]; }
    std::size_t segmentAt(double seconds) const;

    // Display (pixels, origin bottom-left) -> world; the segment under it within 5 px, -1 none.
    long pick(double displayX, double displayY, int widthPx, int heightPx) const;
    // The prove-out's findings (proveout.h) as red markers at their places:
    // a disc of kFindingRadiusPx and a ring round it. A marker is drawn
    // only where the path shown passes its place on a segment of its frame's
    // line (the findings of another program, or of another text of this
    // one, are not this path's). Drawn at the next refresh.
    struct FindingMarker {
        int program = 0, line = 0;
        double z = 0, x = 0; // the place (world Z, X as shown)
        bool operator==(const FindingMarker&) const = default;
    };
    static constexpr int kFindingRadiusPx = 6;
    void setFindings(std::vector<FindingMarker> markers);
    const std::vector<FindingMarker>& findings() const { return findings_; }
    // The markers drawn (those on the path shown).
    const std::vector<FindingMarker>& findingsShown() const { return shownFindings_; }
    // A white ring round the marker at (z, x) of (program, line); nullopt: none.
    void highlightFinding(const std::optional<FindingMarker>& m);
    // Highlights the segments of one source line (0: none).
    void highlightLine(int program, int line);
    int highlightedProgram() const { return hlProgram_; }
    int highlightedLine() const { return hlLine_; }

    // XZ view: zooms by `factor` (> 1 closer) keeping the world point under
    // display pixel (x, y; origin bottom-left) where it is: zoom to the cursor.
    void zoomAt(double displayX, double displayY, double factor, int widthPx, int heightPx);

    // World coordinates (Z, X) of the window's centre and the size of a pixel.
    ViewWindow window(int widthPx, int heightPx) const;
    // Rebuilds only the tool and the wheel (cheap: every live frame).
    void refreshTool(int widthPx, int heightPx);

private:
    struct Vtk;
    std::unique_ptr<Vtk> v_;
    toolpath::ProgrammedPath path_;
    PathGeometry geom_;
    std::vector<double> cumulative_;
    std::optional<stock::Blank> blank_;
    const toolpath::ActualPath* actual_ = nullptr;
    ViewMode mode_ = ViewMode::XZ;
    double playhead_ = -1;
    int hlProgram_ = 0, hlLine_ = 0;
    WheelGeometry wheelGeom_;
    WheelBox wheelBox_;
    std::optional<LiveTool> live_;
    ToolsInUse tools_;
    std::unique_ptr<ToolEdge> edge_;
    OverlayTexts texts_;
    std::vector<FindingMarker> findings_, shownFindings_;
    std::optional<FindingMarker> hlFinding_;
    void matchFindings(); // shownFindings_ from findings_ and path_
    void buildFindings(double worldPerPixel);
    double scaleBarMm_ = 0;
    double ratio_ = 1;
    // The texts, the scale bar and the µm bar in pixels for a w × h view.
    void placeOverlays(int widthPx, int heightPx);
    void buildStatic();
    void buildOscillation3d(std::size_t limit);
    void buildStock(); // cuts blank_ by path_ here
    void buildStock(const std::optional<stock::Shape>& shape);
    void pathChanged(); // after path_ and geom_ changed
};

} // namespace k528::backplot
