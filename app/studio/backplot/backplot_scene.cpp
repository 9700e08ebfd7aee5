#include "backplot/backplot_scene.h"
#include "backplot/line_cells.h"

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkLegendScaleActor.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkCoordinate.h>
#include <vtkRenderer.h>
#include <vtkRotationalExtrusionFilter.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTriangleFilter.h>
#include <vtkTextProperty.h>
#include <vtkAxisActor2D.h>
#include <vtkPolyDataNormals.h>
#include <vtkAppendPolyData.h>
#include <vtkCylinderSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

namespace k528::backplot {

namespace {
constexpr const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

struct Layer {
    vtkNew<vtkPolyData> data;
    vtkNew<vtkPolyDataMapper> mapper;
    vtkNew<vtkActor> actor;
    void init(vtkRenderer* r, Rgb c, double width) {
        mapper->SetInputData(data);
        mapper->ScalarVisibilityOff();
        actor->SetMapper(mapper);
        actor->GetProperty()->SetColor(c.r, c.g, c.b);
        actor->GetProperty()->SetLineWidth(static_cast<float>(width));
        actor->GetProperty()->SetLighting(false);
        actor->GetProperty()->SetAmbient(1);
        actor->GetProperty()->SetDiffuse(0);
        r->AddActor(actor);
    }
    // Replaces the contents with lines (4 floats a line) at depth z.
    void lines(const std::vector<float>& v, double z) { setCells(data, v, 2, z); }
    // Replaces the contents with triangles (6 floats a triangle) at depth z.
    void triangles(const std::vector<float>& v, double z) { setCells(data, v, 3, z); }
};
} // namespace

struct BackplotScene::Vtk {
    vtkNew<vtkRenderer> renderer;
    Layer feed, rapid, outside, points, limit, tool, highlight, stock2d, stock3d, stockFill, actual;
    Layer osc, oscTicks, wheel2d, wheel3d, oscSweep;
    Layer findingDisc, findingRing, findingHighlight; // the prove-out's markers, above the path
    vtkNew<vtkCylinderSource> cylinder;
    std::size_t sweepLimit = ~std::size_t{0};
    vtkNew<vtkLookupTable> lut;
    double actualMaxUm = -1; // the lut's top for the actual path (-1: not set since its buffers were made)
    vtkNew<vtkScalarBarActor> bar;
    vtkNew<vtkLegendScaleActor> legend;
    vtkNew<vtkTextActor> warning;
    vtkNew<vtkTextActor> title;
    Layer scaleBar;               // our scale: a bar of a round length ...
    vtkNew<vtkTextActor> scaleText; // ... and its length ("10 mm")
};

BackplotScene::BackplotScene() : v_(std::make_unique<Vtk>()) {
    vtkRenderer* r = v_->renderer;
    r->SetBackground(kBackground.r, kBackground.g, kBackground.b);
    r->SetBackgroundAlpha(1.0); // opaque: the studio shows the frame as an RGB image
    v_->stock3d.init(r, kStockColour, 1);
    v_->stock3d.actor->GetProperty()->SetLighting(true);
    v_->stock3d.actor->GetProperty()->SetAmbient(0.25);
    v_->stock3d.actor->GetProperty()->SetDiffuse(0.8);
    v_->stock3d.actor->SetOrientation(0, 90, 0); // the revolution axis (z) along world x = Z
    v_->stock3d.actor->VisibilityOff();
    v_->stockFill.init(r, kStockColour, 1);
    v_->stockFill.actor->GetProperty()->SetOpacity(0.35);
    v_->stock2d.init(r, kStockColour, 2);
    v_->limit.init(r, kLimitColour, 2);
    v_->actual.init(r, kFeedColour, 2);
    v_->actual.mapper->ScalarVisibilityOn();
    v_->actual.mapper->SetLookupTable(v_->lut);
    v_->actual.mapper->SetScalarModeToUsePointData();
    v_->actual.mapper->UseLookupTableScalarRangeOn();
    v_->feed.init(r, kFeedColour, 2);
    v_->rapid.init(r, kRapidColour, 2);
    v_->outside.init(r, kOutsideColour, 3);
    v_->osc.init(r, kOscillationColour, 2);
    v_->oscTicks.init(r, kOscillationColour, 1);
    v_->points.init(r, kPointColour, 1);
    v_->wheel2d.init(r, kWheelColour, 2);
    v_->wheel3d.init(r, kWheelColour, 1);
    v_->wheel3d.actor->GetProperty()->SetLighting(true);
    v_->wheel3d.actor->GetProperty()->SetAmbient(0.35);
    v_->wheel3d.actor->GetProperty()->SetDiffuse(0.75);
    v_->cylinder->SetResolution(48);
    v_->cylinder->CappingOn();
    v_->wheel3d.mapper->SetInputConnection(v_->cylinder->GetOutputPort());
    v_->wheel3d.actor->SetOrientation(0, 0, 90); // the cylinder's axis (y) along world x = Z
    v_->wheel3d.actor->VisibilityOff();
    v_->oscSweep.init(r, kOscillationColour, 1);
    v_->oscSweep.actor->GetProperty()->SetOpacity(0.3);
    v_->oscSweep.actor->VisibilityOff();
    v_->highlight.init(r, {1, 1, 1}, 4);
    v_->tool.init(r, kToolColour, 2);
    edge_ = std::make_unique<ToolEdge>(r);
    v_->findingDisc.init(r, kFindingColour, 1);
    v_->findingRing.init(r, kFindingColour, 2);
    v_->findingHighlight.init(r, {1, 1, 1}, 2);
    v_->lut->SetHueRange(0.66, 0.0); // blue (0 µm) .. red (largest)
    v_->lut->Build();
    v_->bar->SetLookupTable(v_->lut);
    v_->bar->SetTitle(texts_.micrometres.c_str());
    v_->bar->SetNumberOfLabels(5);
    v_->bar->SetLabelFormat(kDeviationLabelFormat);
    // Placed in pixels by placeOverlays(): a strip of fixed width with its
    // labels beside it, whatever the width of the view.
    v_->bar->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
    v_->bar->GetPosition2Coordinate()->SetCoordinateSystemToDisplay();
    v_->bar->UnconstrainedFontSizeOn();
    v_->bar->SetBarRatio(0.35);
    v_->bar->SetTextPositionToSucceedScalarBar();
    for (vtkTextProperty* t : {v_->bar->GetTitleTextProperty(), v_->bar->GetLabelTextProperty()}) {
        t->SetFontFamily(VTK_FONT_FILE);
        t->SetFontFile(kFont);
        t->SetFontSize(12);
        t->ShadowOff();
        t->ItalicOff();
    }
    v_->bar->VisibilityOff();
    r->AddActor2D(v_->bar);
    // The rulers of the left and bottom edges; the scale is our own bar
    // (VTK's legend says "Scale 1 : 147.603" in English).
    v_->legend->SetLegendVisibility(false);
    v_->legend->SetTopAxisVisibility(false);
    v_->legend->SetTopBorderOffset(kTopBandPx); // the title and «ВНЕ ГРАНИЦ» above the left ruler
    v_->legend->SetBottomBorderOffset(kBottomBandPx); // the scale bar below the bottom ruler
    v_->legend->SetRightAxisVisibility(false);
    v_->legend->SetLabelModeToXYCoordinates();
    for (vtkAxisActor2D* a : {v_->legend->GetLeftAxis(), v_->legend->GetBottomAxis()}) {
        a->GetProperty()->SetColor(0.7, 0.7, 0.7);
        a->SetNumberOfMinorTicks(0);
        // Labels of a fixed size (VTK sizes them to the viewport: 2-5 px in a dock).
        a->UseFontSizeFromPropertyOn();
        a->GetLabelTextProperty()->SetColor(0.8, 0.8, 0.8);
        a->GetLabelTextProperty()->SetFontFamily(VTK_FONT_FILE);
        a->GetLabelTextProperty()->SetFontFile(kFont);
        a->GetLabelTextProperty()->SetFontSize(kSmallTextPx);
        a->GetLabelTextProperty()->ShadowOff();
        a->GetLabelTextProperty()->ItalicOff();
        a->GetLabelTextProperty()->BoldOff();
        a->SetLabelFormat("%.4g");
    }
    v_->legend->GetLegendLabelProperty()->SetColor(0.8, 0.8, 0.8);
    v_->legend->GetLegendTitleProperty()->SetColor(0.8, 0.8, 0.8);
    r->AddViewProp(v_->legend);
    // The title on the first line of the top band, «ВНЕ ГРАНИЦ» on the
    // second (placeOverlays()), both of a fixed size in pixels.
    for (vtkTextActor* t : {v_->warning.GetPointer(), v_->title.GetPointer(), v_->scaleText.GetPointer()}) {
        t->SetTextScaleModeToNone();
        t->GetTextProperty()->SetFontFamily(VTK_FONT_FILE);
        t->GetTextProperty()->SetFontFile(kFont);
        t->GetTextProperty()->SetFontSize(kTextPx);
        t->GetTextProperty()->ShadowOff();
        t->GetTextProperty()->SetVerticalJustificationToTop();
        t->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
        r->AddActor2D(t);
    }
    v_->warning->GetTextProperty()->SetColor(kOutsideColour.r, kOutsideColour.g, kOutsideColour.b);
    v_->title->GetTextProperty()->SetColor(kTitleColour.r, kTitleColour.g, kTitleColour.b);
    v_->scaleText->GetTextProperty()->SetColor(kTitleColour.r, kTitleColour.g, kTitleColour.b);
    v_->scaleText->GetTextProperty()->SetFontSize(kSmallTextPx);
    v_->scaleText->GetTextProperty()->SetJustificationToCentered();
    v_->scaleBar.init(r, kTitleColour, 2);
    r->GetActiveCamera()->ParallelProjectionOn();
}

BackplotScene::~BackplotScene() = default;

vtkRenderer* BackplotScene::renderer() const {
    return v_->renderer;
}

void BackplotScene::setPath(const toolpath::ProgrammedPath& path) {
    setPath(toolpath::ProgrammedPath(path));
}

void BackplotScene::setInteracting(bool on) {
    const bool overlays = !on && mode_ == ViewMode::XZ;
    v_->legend->SetVisibility(overlays);
    v_->scaleBar.actor->SetVisibility(overlays);
    v_->scaleText->SetVisibility(overlays);
    v_->warning->SetVisibility(!on);
    v_->title->SetVisibility(!on);
    v_->bar->SetVisibility(overlays && actual_ != nullptr);
}

void BackplotScene::setPath(toolpath::ProgrammedPath&& path) {
    path_ = std::move(path);
    geom_.build(path_);
    tools_.stations.clear();
    pathChanged();
    buildStock();
}

PreparedPath preparePath(toolpath::ProgrammedPath path, const std::optional<stock::Blank>& blank,
                         const stock::CutProgress& progress) {
    PreparedPath p;
    p.path = std::move(path);
    p.geometry.build(p.path);
    p.blank = blank;
    if (blank) {
        stock::Stock s(*blank);
        if (s.cutPath(p.path, stock::Tool{}, progress))
            p.stock = s.shape();
    }
    return p;
}

void BackplotScene::setPrepared(PreparedPath&& p) {
    path_ = std::move(p.path);
    geom_ = std::move(p.geometry);
    blank_ = p.blank;
    tools_ = std::move(p.tools);
    pathChanged();
    buildStock(p.stock);
}

void BackplotScene::pathChanged() {
    cumulative_.resize(path_.segments.size());
    double t = 0;
    for (std::size_t i = 0; i < path_.segments.size(); ++i)
        cumulative_[i] = t += path_.segments[i].durationS;
    playhead_ = -1;
    v_->sweepLimit = ~std::size_t{0};
    matchFindings();
    buildStatic();
}

void BackplotScene::setFindings(std::vector<FindingMarker> markers) {
    findings_ = std::move(markers);
    matchFindings();
}

void BackplotScene::highlightFinding(const std::optional<FindingMarker>& m) { hlFinding_ = m; }

void BackplotScene::matchFindings() {
    shownFindings_.clear();
    // On the path: within this of a leg of a segment of the finding's line
    // (the finding's place is a point of the same preview's path).
    constexpr double kOnPathMm = 0.05;
    for (const FindingMarker& m : findings_) {
        bool on = false;
        for (const toolpath::Segment& s : path_.segments) {
            if (s.program != m.program || s.line != m.line)
                continue;
            const toolpath::PointMm* p = path_.pointsOf(s);
            for (int i = 0; i < s.pointCount && !on; ++i) {
                const toolpath::PointMm a = p[i > 0 ? i - 1 : 0], b = p[i];
                const double dz = b.z - a.z, dx = b.x - a.x, len2 = dz * dz + dx * dx;
                const double t = len2 > 0 ? std::clamp(((m.z - a.z) * dz + (m.x - a.x) * dx) / len2, 0.0, 1.0) : 0;
                on = std::hypot(a.z + t * dz - m.z, a.x + t * dx - m.x) <= kOnPathMm;
            }
            if (on)
                break;
        }
        if (on)
            shownFindings_.push_back(m);
    }
}

void BackplotScene::buildFindings(double wpp) {
    // A disc of kFindingRadiusPx (16 triangles), a ring 4 px outside it.
    constexpr int kSides = 16;
    const auto ring = [wpp](double cz, double cx, double radiusPx, std::vector<float>& out) {
        const double r = radiusPx * wpp;
        for (int i = 0; i < kSides; ++i) {
            const double a0 = 2 * std::numbers::pi * i / kSides, a1 = 2 * std::numbers::pi * (i + 1) / kSides;
            out.insert(out.end(), {static_cast<float>(cz + r * std::cos(a0)), static_cast<float>(cx + r * std::sin(a0)),
                                   static_cast<float>(cz + r * std::cos(a1)), static_cast<float>(cx + r * std::sin(a1))});
        }
    };
    std::vector<float> disc, rings, hl;
    const double r = kFindingRadiusPx * ratio_ * wpp;
    for (const FindingMarker& m : shownFindings_) {
        for (int i = 0; i < kSides; ++i) {
            const double a0 = 2 * std::numbers::pi * i / kSides, a1 = 2 * std::numbers::pi * (i + 1) / kSides;
            disc.insert(disc.end(), {static_cast<float>(m.z), static_cast<float>(m.x),
                                     static_cast<float>(m.z + r * std::cos(a0)), static_cast<float>(m.x + r * std::sin(a0)),
                                     static_cast<float>(m.z + r * std::cos(a1)), static_cast<float>(m.x + r * std::sin(a1))});
        }
        ring(m.z, m.x, (kFindingRadiusPx + 4) * ratio_, rings);
        if (hlFinding_ && *hlFinding_ == m)
            ring(m.z, m.x, (kFindingRadiusPx + 8) * ratio_, hl);
    }
    v_->findingDisc.triangles(disc, 0.4);
    v_->findingRing.lines(rings, 0.4);
    v_->findingHighlight.lines(hl, 0.4);
}

void BackplotScene::setActual(const toolpath::ActualPath* a) {
    actual_ = a;
    v_->actual.data->Initialize();
    if (!a || a->samples.size() < 2) {
        v_->bar->VisibilityOff();
        return;
    }
    vtkNew<vtkPoints> pts;
    vtkNew<vtkFloatArray> err;
    err->SetName("following_error_um");
    vtkNew<vtkCellArray> lines;
    v_->actual.data->SetPoints(pts);
    v_->actual.data->SetLines(lines);
    v_->actual.data->GetPointData()->SetScalars(err);
    v_->actualMaxUm = -1;
    appendActual(a, 0);
}

void BackplotScene::appendActual(const toolpath::ActualPath* a, std::size_t from) {
    if (a != actual_ || v_->actual.data->GetPoints() == nullptr) {
        setActual(a); // (re)builds the buffers: it appends from 0
        return;
    }
    if (!a)
        return;
    vtkPoints* pts = v_->actual.data->GetPoints();
    auto* err = vtkFloatArray::SafeDownCast(v_->actual.data->GetPointData()->GetScalars());
    vtkCellArray* lines = v_->actual.data->GetLines();
    // Resume where the buffers end (they hold samples [0, shown)).
    const std::size_t shown = static_cast<std::size_t>(pts->GetNumberOfPoints());
    from = std::min(from, shown);
    // The colour scale's top: the largest error drawn (at least 1 µm),
    // followed over the new samples only.
    double maxUm = std::max(1.0, v_->actualMaxUm);
    if (from < shown) { // rewritten samples: rebuild
        pts->SetNumberOfPoints(static_cast<vtkIdType>(from));
        err->SetNumberOfTuples(static_cast<vtkIdType>(from));
        lines->Reset();
        for (std::size_t i = 1; i < from; ++i) {
            const vtkIdType ids[2] = {static_cast<vtkIdType>(i - 1), static_cast<vtkIdType>(i)};
            lines->InsertNextCell(2, ids);
        }
        maxUm = 1.0;
        for (vtkIdType i = 0; i < err->GetNumberOfTuples(); ++i)
            maxUm = std::max(maxUm, static_cast<double>(err->GetValue(i)));
    }
    if (from == a->samples.size() && from == shown)
        return; // nothing new: the buffers (and the picture) stay as they are
    for (std::size_t i = from; i < a->samples.size(); ++i) {
        const toolpath::ActualSample& s = a->samples[i];
        const vtkIdType id = pts->InsertNextPoint(s.z, s.x, 0.2);
        const float um = static_cast<float>(std::hypot(s.errX, s.errZ) * 1000.0);
        err->InsertNextValue(um);
        maxUm = std::max(maxUm, static_cast<double>(um));
        if (id > 0) {
            const vtkIdType ids[2] = {id - 1, id};
            lines->InsertNextCell(2, ids);
        }
    }
    pts->Modified();
    err->Modified();
    lines->Modified();
    v_->actual.data->Modified();
    // The scale (and the µm bar's labels, rebuilt with it) only when its top moved.
    if (maxUm != v_->actualMaxUm) {
        v_->actualMaxUm = maxUm;
        v_->lut->SetTableRange(0, maxUm);
        v_->lut->Build();
    }
    v_->bar->SetVisibility(mode_ == ViewMode::XZ && pts->GetNumberOfPoints() >= 2);
}

std::size_t BackplotScene::actualPointsShown() const {
    vtkPoints* p = v_->actual.data->GetPoints();
    return p ? static_cast<std::size_t>(p->GetNumberOfPoints()) : 0;
}

void BackplotScene::setStock(const std::optional<stock::Blank>& blank) {
    blank_ = blank;
    buildStock();
}

void BackplotScene::buildStatic() {
    // The limit rectangle in the current coordinates of the start.
    std::vector<float> lim;
    const toolpath::AxisLimits& lx = path_.limitX;
    const toolpath::AxisLimits& lz = path_.limitZ;
    if (lx.present && lz.present && lx.on && lz.on) {
        const float x0 = static_cast<float>(lx.minMm - lx.offsetMm),
                    x1 = static_cast<float>(lx.maxMm - lx.offsetMm);
        const float z0 = static_cast<float>(lz.minMm - lz.offsetMm),
                    z1 = static_cast<float>(lz.maxMm - lz.offsetMm);
        lim = {z0, x0, z1, x0, z1, x0, z1, x1, z1, x1, z0, x1, z0, x1, z0, x0};
    }
    v_->limit.lines(lim, -0.1);
    // «ВНЕ ГРАНИЦ» with the frames.
    std::string text;
    int count = 0;
    for (const toolpath::Segment& s : path_.segments)
        if (s.outside) {
            if (count < 8)
                text += (count ? ", L" : " L") + std::to_string(s.program) + " N" + std::to_string(s.n);
            ++count;
        }
    if (count > 8)
        text += " … (" + std::to_string(count) + ")";
    // «ВНЕ ГРАНИЦ» is the NC-200's own text (the panel's language).
    v_->warning->SetInput(count ? ("ВНЕ ГРАНИЦ:" + text).c_str() : "");
    v_->title->SetInput(titleText().c_str());
}

std::string BackplotScene::deviationBarTitle() const {
    const char* t = v_->bar->GetTitle();
    return t ? t : "";
}

void BackplotScene::setTexts(const OverlayTexts& texts) {
    texts_ = texts;
    v_->title->SetInput(titleText().c_str());
    v_->bar->SetTitle(texts_.micrometres.c_str());
}

namespace {
std::string withNumber(std::string format, const std::string& number) {
    const std::size_t at = format.find("%1");
    if (at != std::string::npos)
        format.replace(at, 2, number);
    return format;
}
} // namespace

std::string BackplotScene::titleText() const {
    // Appended piece by piece (GCC 12's false -Wrestrict on a chain of +).
    std::string t = "L";
    t.append(std::to_string(path_.program)).append("  ");
    t.append(withNumber(texts_.segments, std::to_string(path_.segments.size()))).append("  ");
    t.append(path_.diameterX ? texts_.diameter : texts_.radius);
    return t;
}

void BackplotScene::placeOverlays(int w, int h) {
    const auto px = [this](int v) { return static_cast<int>(std::lround(v * ratio_)); };
    for (vtkTextActor* t : {v_->warning.GetPointer(), v_->title.GetPointer()})
        t->GetTextProperty()->SetFontSize(px(kTextPx));
    v_->scaleText->GetTextProperty()->SetFontSize(px(kSmallTextPx));
    for (vtkTextProperty* t : {v_->bar->GetTitleTextProperty(), v_->bar->GetLabelTextProperty(),
                               v_->legend->GetLeftAxis()->GetLabelTextProperty(),
                               v_->legend->GetBottomAxis()->GetLabelTextProperty()})
        t->SetFontSize(px(kSmallTextPx));
    // VTK 9.1 sizes the rulers' labels to the viewport (about 0.015 × font
    // factor × label factor × (w + h)) whatever UseFontSizeFromProperty
    // says: the factor that gives kSmallTextPx.
    for (vtkAxisActor2D* a : {v_->legend->GetLeftAxis(), v_->legend->GetBottomAxis()}) {
        a->SetLabelFactor(1.0);
        a->SetFontFactor(std::clamp(px(kSmallTextPx) / (0.015 * std::max(1, w + h)), 0.1, 2.0));
    }
    v_->legend->SetCornerOffsetFactor(1.0);
    v_->legend->SetTopBorderOffset(px(kTopBandPx));
    v_->legend->SetBottomBorderOffset(px(kBottomBandPx));
    // The top band: the title, «ВНЕ ГРАНИЦ» on the line below it.
    v_->title->SetDisplayPosition(px(8), h - px(6));
    v_->warning->SetDisplayPosition(px(8), h - px(6 + kTextPx + 8));
    // The µm bar: a strip of fixed width at the right, between the bands.
    const int barH = std::max(px(60), h - px(kTopBandPx + kBottomBandPx + 16));
    v_->bar->GetPositionCoordinate()->SetValue(std::max(0, w - px(kRightBarBandPx)), px(kBottomBandPx + 8));
    v_->bar->GetPosition2Coordinate()->SetValue(px(kRightBarBandPx - 8), barH);
    // The scale: a bar of 1, 2 or 5 × 10^k mm, 40..100 px long, in the
    // bottom band at the right.
    scaleBarMm_ = 0;
    if (mode_ != ViewMode::XZ || w < 80) {
        v_->scaleBar.lines({}, 0.4);
        v_->scaleText->SetInput("");
        return;
    }
    const ViewWindow vw = window(w, h);
    const double most = 100 * ratio_ * vw.worldPerPixel;
    const double mag = std::pow(10.0, std::floor(std::log10(most)));
    double len = mag;
    for (double f : {5.0, 2.0, 1.0})
        if (f * mag <= most) {
            len = f * mag;
            break;
        }
    scaleBarMm_ = len;
    const double barPx = len / vw.worldPerPixel;
    const double right = w - px(24), y = px(12), tick = px(5);
    const auto wx = [&](double dx) { return static_cast<float>(vw.x0 + dx * vw.worldPerPixel); };
    const auto wy = [&](double dy) { return static_cast<float>(vw.y0 + dy * vw.worldPerPixel); };
    v_->scaleBar.lines({wx(right - barPx), wy(y), wx(right), wy(y), wx(right - barPx), wy(y), wx(right - barPx),
                        wy(y + tick), wx(right), wy(y), wx(right), wy(y + tick)},
                       0.4);
    char number[32];
    std::snprintf(number, sizeof number, "%g", len);
    v_->scaleText->SetInput(withNumber(texts_.mm, number).c_str());
    v_->scaleText->SetDisplayPosition(static_cast<int>(right - barPx / 2),
                                      static_cast<int>(y + tick + px(kSmallTextPx + 6)));
}

void BackplotScene::zoomAt(double dx, double dy, double factor, int w, int h) {
    if (mode_ != ViewMode::XZ || factor <= 0)
        return;
    const ViewWindow vw = window(w, h);
    const double px = vw.x0 + dx * vw.worldPerPixel, py = vw.y0 + dy * vw.worldPerPixel;
    vtkCamera* cam = v_->renderer->GetActiveCamera();
    double f[3];
    cam->GetFocalPoint(f);
    // The point under the cursor keeps its place: the centre moves towards it.
    const double cx = px - (px - f[0]) / factor, cy = py - (py - f[1]) / factor;
    cam->SetFocalPoint(cx, cy, 0);
    cam->SetPosition(cx, cy, 1000);
    cam->SetParallelScale(std::max(cam->GetParallelScale() / factor, 1e-4));
}

void BackplotScene::buildStock() {
    std::optional<stock::Shape> shape;
    if (blank_) {
        stock::Stock s(*blank_);
        s.cutPath(path_, stock::Tool{});
        shape = s.shape();
    }
    buildStock(shape);
}

void BackplotScene::buildStock(const std::optional<stock::Shape>& shape) {
    if (!blank_ || !shape) {
        v_->stock2d.data->Initialize();
        v_->stock3d.data->Initialize();
        v_->stockFill.data->Initialize();
        return;
    }
    const stock::Shape& s = *shape;
    const double shown = path_.diameterX ? 2.0 : 1.0;
    std::vector<float> outline;
    vtkNew<vtkPoints> pts;
    vtkNew<vtkCellArray> rings;
    for (const stock::Shape::Polygon& poly : s.polygons) {
        std::vector<stock::Ring> all = poly.holes;
        all.insert(all.begin(), poly.outer);
        for (const stock::Ring& ring : all) {
            const vtkIdType first = pts->GetNumberOfPoints();
            rings->InsertNextCell(static_cast<vtkIdType>(ring.size() + 1));
            for (std::size_t k = 0; k < ring.size(); ++k) {
                const stock::PointZR& a = ring[k];
                const stock::PointZR& b = ring[(k + 1) % ring.size()];
                outline.insert(outline.end(), {static_cast<float>(a.z), static_cast<float>(a.r * shown),
                                               static_cast<float>(b.z), static_cast<float>(b.r * shown)});
                pts->InsertNextPoint(a.r, 0, a.z);
                rings->InsertCellPoint(first + static_cast<vtkIdType>(k));
            }
            rings->InsertCellPoint(first);
        }
    }
    v_->stock2d.lines(outline, -0.2);
    {
        vtkNew<vtkPoints> fp;
        vtkNew<vtkCellArray> polys;
        for (const stock::Shape::Polygon& poly : s.polygons) {
            const stock::Ring& ring = poly.outer;
            polys->InsertNextCell(static_cast<vtkIdType>(ring.size()));
            for (const stock::PointZR& q : ring)
                polys->InsertCellPoint(fp->InsertNextPoint(q.z, q.r * shown, -0.3));
        }
        vtkNew<vtkPolyData> pd;
        pd->SetPoints(fp);
        pd->SetPolys(polys);
        vtkNew<vtkTriangleFilter> tri;
        tri->SetInputData(pd);
        tri->Update();
        v_->stockFill.data->DeepCopy(tri->GetOutput());
    }
    vtkNew<vtkPolyData> profile;
    profile->SetPoints(pts);
    profile->SetLines(rings);
    vtkNew<vtkRotationalExtrusionFilter> revolve;
    revolve->SetInputData(profile);
    revolve->SetResolution(8 * (1 - blank_->detail) + 8); // detail -1..-5 -> 24..56
    revolve->SetAngle(360);
    revolve->CappingOff();
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputConnection(revolve->GetOutputPort());
    normals->Update();
    v_->stock3d.data->DeepCopy(normals->GetOutput());
}

void BackplotScene::setViewMode(ViewMode m) {
    mode_ = m;
    const bool solid = m == ViewMode::Solid3D;
    v_->stock3d.actor->SetVisibility(solid);
    v_->stock2d.actor->SetVisibility(!solid);
    v_->stockFill.actor->SetVisibility(!solid);
    v_->limit.actor->SetVisibility(!solid);
    v_->wheel2d.actor->SetVisibility(!solid);
    v_->oscTicks.actor->SetVisibility(!solid);
    v_->wheel3d.actor->SetVisibility(solid && wheelBox_.shown);
    v_->oscSweep.actor->SetVisibility(solid);
    if (solid)
        edge_->show(std::nullopt, 0, 0, 1, false); // the edge is an XZ drawing
    v_->legend->SetVisibility(!solid);
    v_->scaleBar.actor->SetVisibility(!solid);
    v_->scaleText->SetVisibility(!solid);
    v_->bar->SetVisibility(!solid && actual_ != nullptr);
    // In 3D the path is drawn at its radius (the body is revolved in radius).
    const double ys = solid && path_.diameterX ? 0.5 : 1.0;
    for (Layer* l : {&v_->feed, &v_->rapid, &v_->outside, &v_->points, &v_->tool, &v_->highlight,
                     &v_->actual, &v_->osc})
        l->actor->SetScale(1, ys, 1);
    vtkCamera* cam = v_->renderer->GetActiveCamera();
    cam->SetParallelProjection(!solid);
}

ViewWindow BackplotScene::window(int w, int h) const {
    vtkCamera* cam = v_->renderer->GetActiveCamera();
    double f[3];
    cam->GetFocalPoint(f);
    ViewWindow vw;
    if (mode_ == ViewMode::XZ) {
        const double half = cam->GetParallelScale();
        vw.worldPerPixel = 2 * half / std::max(h, 1);
        const double halfW = vw.worldPerPixel * w / 2;
        vw.x0 = f[0] - halfW, vw.x1 = f[0] + halfW, vw.y0 = f[1] - half, vw.y1 = f[1] + half;
    } else {
        const double* b = geom_.bounds();
        vw.x0 = b[0], vw.x1 = b[1], vw.y0 = b[2], vw.y1 = b[3];
        const double d = cam->GetDistance() * std::tan(cam->GetViewAngle() * 3.14159265 / 360) * 2;
        vw.worldPerPixel = d / std::max(h, 1);
    }
    return vw;
}

void BackplotScene::fit(int w, int h) {
    const double* b = geom_.bounds();
    double x0 = b[0], x1 = b[1], y0 = b[2], y1 = b[3];
    const auto grow = [&](double x, double y) {
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    };
    const toolpath::AxisLimits& lx = path_.limitX;
    const toolpath::AxisLimits& lz = path_.limitZ;
    if (lx.present && lz.present && lx.on && lz.on) {
        grow(lz.minMm - lz.offsetMm, lx.minMm - lx.offsetMm);
        grow(lz.maxMm - lz.offsetMm, lx.maxMm - lx.offsetMm);
    }
    if (blank_) {
        grow(std::min(0.0, blank_->outerLengthMm), 0);
        grow(std::max(0.0, blank_->outerLengthMm), blank_->outerDiameterMm * (path_.diameterX ? 1 : 0.5));
    }
    if (!path_.wheel.empty()) { // the wheel where the path ends (its largest diameter)
        double d = 0;
        for (const toolpath::WheelChange& c : path_.wheel)
            d = std::max(d, c.diameterMm);
        const double shown = path_.diameterX ? 2.0 : 1.0;
        grow(path_.end.z + wheelGeom_.widthMm, path_.end.x + (wheelGeom_.inside ? -d : d) * shown);
    }
    vtkCamera* cam = v_->renderer->GetActiveCamera();
    const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    if (mode_ == ViewMode::XZ) {
        // The path in the rectangle the overlay leaves free: the top band
        // (title, «ВНЕ ГРАНИЦ»), the bottom band (ruler, scale), the left
        // ruler's labels, the µm bar at the right.
        const auto px = [this](int v) { return v * ratio_; };
        const double left = px(kLeftBandPx), right = px(actual_ ? kRightBarBandPx : 16),
                     top = px(kTopBandPx + 4), bottom = px(kBottomBandPx + 4);
        const double freeW = std::max(20.0, w - left - right), freeH = std::max(20.0, h - top - bottom);
        const double wpp = std::max({(x1 - x0) / freeW, (y1 - y0) / freeH, 1e-6}) * 1.04;
        const double half = wpp * std::max(h, 1) / 2;
        const double fx = cx - (left - right) / 2 * wpp, fy = cy - (bottom - top) / 2 * wpp;
        cam->SetFocalPoint(fx, fy, 0);
        cam->SetPosition(fx, fy, 1000);
        cam->SetViewUp(0, 1, 0);
        cam->SetParallelScale(std::max(half, 1e-3));
        v_->renderer->ResetCameraClippingRange(fx - 1e6, fx + 1e6, fy - 1e6, fy + 1e6, -10, 10);
    } else {
        const double r = std::max(x1 - x0, y1 - y0);
        cam->SetFocalPoint(cx, 0, 0);
        cam->SetPosition(cx + r * 0.6, r * 0.9, r * 1.6);
        cam->SetViewUp(0, 1, 0);
        v_->renderer->ResetCameraClippingRange();
        v_->renderer->ResetCamera();
    }
    refresh(w, h);
}

void BackplotScene::refresh(int w, int h) {
    placeOverlays(w, h);
    const ViewWindow vw = window(w, h);
    const std::size_t limit = playhead_ < 0 ? path_.segments.size() : segmentAt(playhead_) + 1;
    const LodLines lod = geom_.simplify(vw, limit);
    v_->feed.lines(lod.feed, 0);
    v_->outside.lines(lod.outside, 0.1);
    // Dashes of 8 px with gaps of 5 px.
    std::vector<float> dashes;
    const double on = 8 * vw.worldPerPixel, period = 13 * vw.worldPerPixel;
    for (std::size_t i = 0; i + 3 < lod.rapid.size() && dashes.size() < 4'000'000; i += 4) {
        const double ax = lod.rapid[i], ay = lod.rapid[i + 1], bx = lod.rapid[i + 2], by = lod.rapid[i + 3];
        const double len = std::hypot(bx - ax, by - ay);
        if (len <= 0)
            continue;
        const double ux = (bx - ax) / len, uy = (by - ay) / len;
        for (double s = 0; s < len; s += period) {
            const double e = std::min(s + on, len);
            dashes.insert(dashes.end(), {static_cast<float>(ax + ux * s), static_cast<float>(ay + uy * s),
                                         static_cast<float>(ax + ux * e), static_cast<float>(ay + uy * e)});
        }
    }
    v_->rapid.lines(dashes, 0);
    // Diamonds of 4 px.
    std::vector<float> dia;
    const float d = static_cast<float>(4 * vw.worldPerPixel);
    for (std::size_t i = 0; i + 1 < lod.points.size(); i += 2) {
        const float x = lod.points[i], y = lod.points[i + 1];
        dia.insert(dia.end(), {x - d, y, x, y + d, x, y + d, x + d, y, x + d, y, x, y - d, x, y - d, x - d, y});
    }
    v_->points.lines(dia, 0.05);
    // Oscillation strokes: the stroke and a tick of 6 px at each reverse point.
    v_->osc.lines(lod.oscillation, 0.02);
    std::vector<float> ticks;
    const float tk = static_cast<float>(6 * vw.worldPerPixel);
    for (std::size_t i = 0; i + 3 < lod.oscillation.size() && ticks.size() < 400000; i += 4)
        for (int e = 0; e < 2; ++e) {
            const float x = lod.oscillation[i + 2 * e], y = lod.oscillation[i + 2 * e + 1];
            ticks.insert(ticks.end(), {x, y - tk, x, y + tk});
        }
    v_->oscTicks.lines(ticks, 0.02);
    buildOscillation3d(limit);
    refreshTool(w, h);
    buildFindings(vw.worldPerPixel);
    // The selected line's segments.
    std::vector<float> hl;
    if (hlLine_ > 0)
        for (const toolpath::Segment& s : path_.segments) {
            if (s.line != hlLine_ || s.program != hlProgram_)
                continue;
            const toolpath::PointMm* p = path_.pointsOf(s);
            for (int i = 1; i < s.pointCount && hl.size() < 400000; ++i)
                hl.insert(hl.end(), {static_cast<float>(p[i - 1].z), static_cast<float>(p[i - 1].x),
                                     static_cast<float>(p[i].z), static_cast<float>(p[i].x)});
        }
    v_->highlight.lines(hl, 0.25);
}

void BackplotScene::refreshTool(int w, int h) {
    const ViewWindow vw = window(w, h);
    // The tool: live, or where the playhead is (the end when all is shown), a cross of 8 px.
    double tx = path_.end.z, ty = path_.end.x;
    std::size_t k = path_.segments.empty() ? 0 : path_.segments.size() - 1;
    if (live_) {
        tx = live_->z, ty = live_->x;
    } else if (playhead_ >= 0 && !path_.segments.empty()) {
        k = segmentAt(playhead_);
        const toolpath::Segment& s = path_.segments[k];
        const double t0 = segmentStart(k), dur = s.durationS;
        double f = dur > 0 ? std::clamp((playhead_ - t0) / dur, 0.0, 1.0) : 1.0;
        // Along the legs by length (the legs of a dogleg take their share of time).
        const toolpath::PointMm* p = path_.pointsOf(s);
        double total = 0;
        for (int i = 1; i < s.pointCount; ++i)
            total += std::hypot(p[i].z - p[i - 1].z, p[i].x - p[i - 1].x);
        double want = f * total;
        tx = p[0].z, ty = p[0].x;
        for (int i = 1; i < s.pointCount; ++i) {
            const double l = std::hypot(p[i].z - p[i - 1].z, p[i].x - p[i - 1].x);
            if (want <= l && l > 0) {
                tx = p[i - 1].z + (p[i].z - p[i - 1].z) * want / l;
                ty = p[i - 1].x + (p[i].x - p[i - 1].x) * want / l;
                break;
            }
            want -= l;
            tx = p[i].z, ty = p[i].x;
        }
    }
    const float c = static_cast<float>(8 * vw.worldPerPixel);
    const float fx = static_cast<float>(tx), fy = static_cast<float>(ty);
    v_->tool.lines({fx - c, fy, fx + c, fy, fx, fy - c, fx, fy + c, fx, fy, fx + c, fy + c}, 0.3);
    // The active tool's edge there: the turret's station while live, else the path's at the playhead.
    std::optional<profile::Tool> active;
    if (live_)
        active = live_->station >= 0 ? tools_.atStation(live_->station) : std::nullopt;
    else if (!path_.segments.empty())
        active = tools_.atSegment(k);
    edge_->show(active, tx, ty, path_.diameterX ? 2.0 : 1.0, mode_ == ViewMode::XZ);
    // The wheel there: its outline in XZ, a cylinder in 3D.
    const double d = live_ ? live_->wheelMm : path_.wheelDiameterAt(k);
    const double shown = path_.diameterX ? 2.0 : 1.0; // shown X per mm of radius
    wheelBox_ = {};
    if (d > 0) {
        wheelBox_.shown = true;
        wheelBox_.diameterMm = d;
        wheelBox_.z0 = tx;
        wheelBox_.z1 = tx + wheelGeom_.widthMm;
        wheelBox_.x0 = wheelGeom_.inside ? ty - d * shown : ty;
        wheelBox_.x1 = wheelGeom_.inside ? ty : ty + d * shown;
        const float z0 = static_cast<float>(wheelBox_.z0), z1 = static_cast<float>(wheelBox_.z1);
        const float x0 = static_cast<float>(wheelBox_.x0), x1 = static_cast<float>(wheelBox_.x1);
        const float xc = static_cast<float>((wheelBox_.x0 + wheelBox_.x1) / 2);
        // The outline and the wheel's axis (dash-dotted on a drawing; a line here).
        v_->wheel2d.lines({z0, x0, z1, x0, z1, x0, z1, x1, z1, x1, z0, x1, z0, x1, z0, x0,
                           z0 - static_cast<float>(4 * vw.worldPerPixel), xc,
                           z1 + static_cast<float>(4 * vw.worldPerPixel), xc},
                          0.35);
        // 3D: at its radius (the body of revolution is in radius, world y).
        const double rEdge = ty / shown;
        const double rc = wheelGeom_.inside ? rEdge - d / 2 : rEdge + d / 2;
        if (v_->cylinder->GetRadius() != d / 2 || v_->cylinder->GetHeight() != wheelGeom_.widthMm) {
            v_->cylinder->SetRadius(d / 2);
            v_->cylinder->SetHeight(wheelGeom_.widthMm);
        }
        v_->wheel3d.actor->SetPosition(tx + wheelGeom_.widthMm / 2, rc, 0);
    } else {
        v_->wheel2d.lines({}, 0.35);
    }
    v_->wheel3d.actor->SetVisibility(mode_ == ViewMode::Solid3D && wheelBox_.shown);
}

void BackplotScene::buildOscillation3d(std::size_t limit) {
    if (limit == v_->sweepLimit)
        return;
    v_->sweepLimit = limit;
    // The wheel's swept band over each stroke (the latest 64 up to the
    // playhead): a cylinder from the near to the far reverse point + width.
    vtkNew<vtkAppendPolyData> all;
    int count = 0;
    const double shown = path_.diameterX ? 2.0 : 1.0;
    for (std::size_t i = std::min(limit, path_.segments.size()); i-- > 0 && count < 64;) {
        const toolpath::Segment& s = path_.segments[i];
        if (s.kind != toolpath::SegmentKind::Oscillation)
            continue;
        const double d = path_.wheelDiameterAt(i);
        if (d <= 0)
            continue;
        const toolpath::PointMm* p = path_.pointsOf(s);
        double z0 = p[0].z, z1 = p[0].z, x = p[0].x;
        for (int k = 1; k < s.pointCount; ++k)
            z0 = std::min(z0, p[k].z), z1 = std::max(z1, p[k].z);
        z1 += wheelGeom_.widthMm;
        const double rEdge = x / shown;
        const double rc = wheelGeom_.inside ? rEdge - d / 2 : rEdge + d / 2;
        vtkNew<vtkCylinderSource> cyl;
        cyl->SetResolution(48);
        cyl->SetRadius(d / 2 * 1.002); // just outside the wheel itself
        cyl->SetHeight(z1 - z0);
        vtkNew<vtkTransform> t;
        t->Translate((z0 + z1) / 2, rc, 0);
        t->RotateZ(90);
        vtkNew<vtkTransformPolyDataFilter> tf;
        tf->SetInputConnection(cyl->GetOutputPort());
        tf->SetTransform(t);
        all->AddInputConnection(tf->GetOutputPort());
        ++count;
    }
    if (count == 0) {
        v_->oscSweep.data->Initialize();
        return;
    }
    all->Update();
    v_->oscSweep.data->DeepCopy(all->GetOutput());
}

void BackplotScene::setLiveTool(const std::optional<LiveTool>& t) {
    live_ = t;
}

void BackplotScene::setPlayhead(double seconds) {
    playhead_ = seconds;
}

std::size_t BackplotScene::segmentAt(double seconds) const {
    if (cumulative_.empty())
        return 0;
    const auto it = std::lower_bound(cumulative_.begin(), cumulative_.end(), seconds);
    return std::min<std::size_t>(static_cast<std::size_t>(it - cumulative_.begin()),
                                 cumulative_.size() - 1);
}

long BackplotScene::pick(double dx, double dy, int w, int h) const {
    if (mode_ != ViewMode::XZ)
        return -1;
    const ViewWindow vw = window(w, h);
    const double x = vw.x0 + dx * vw.worldPerPixel, y = vw.y0 + dy * vw.worldPerPixel;
    return geom_.pick(x, y, 5 * vw.worldPerPixel);
}

void BackplotScene::highlightLine(int program, int line) {
    hlProgram_ = program;
    hlLine_ = line;
}

} // namespace k528::backplot
