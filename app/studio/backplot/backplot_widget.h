// The backplot view: the VTK scene (backplot_scene.h) in our own
// QOpenGLWidget bridge, with fit, pan (middle button), zoom (wheel, right
// button), the XZ and 3D views, playback (play/pause, speed ×0.1…×100 and
// fastest, scrub by time, step by frame), picking (a click names the frame
// and line of the segment under the cursor and asks the editor to go there),
// the list of segments «ВНЕ ГРАНИЦ», and the actual path of a simulated run
// coloured by following error.
#pragma once

#include "backplot/backplot_scene.h"

#include <QElapsedTimer>
#include <QPoint>
#include <QWidget>

#include <memory>
#include <optional>

class QComboBox;
class QLabel;
class QListWidget;
class QProgressBar;
class QSlider;
class QTimer;
class QToolButton;
class vtkInteractorStyle;

namespace k528::studio::backplot {

class VtkGlWidget;
class PathJob;

class BackplotWidget : public QWidget {
    Q_OBJECT
public:
    // The live path of a run is drawn at most this often (10 Hz): the scene
    // takes every batch, the OpenGL view renders the latest — and only when
    // the picture changed (the path grew, or the tool moved a pixel or more).
    // Each render is a whole VTK frame read back from llvmpipe on a PC
    // without a GPU driver: at 20 Hz the training workspace spent a third
    // of a core drawing a slide that moves a few pixels a frame.
    static constexpr int kLiveIntervalMs = 100;

    explicit BackplotWidget(QWidget* parent = nullptr);
    ~BackplotWidget() override;

    // Computes the programmed path of program `number` (the engine's
    // preview) and the blank cut by it on a worker (path_job.h) and shows
    // them when done (pathShown); a newer call cancels the one under way.
    // The window goes on meanwhile; a long one shows its progress and a
    // Cancel button. `blank` is the stock, if the file keeps one.
    void showProgram(const profile::MachineProfile& profile, const program::ProgramStore& store,
                     int number, const std::optional<stock::Blank>& blank = std::nullopt);
    // Whether a path is being computed.
    bool computing() const;
    // What the view says about the path beside it ("", or the preview cut
    // off at PathJob::kMaxFrames, a cancelled computation, a run under way).
    QString statusText() const;
    // Runs the program on the simulated machine (on a worker) and overlays
    // the actual path when it is done.
    void showActualRun(const profile::MachineProfile& profile, const program::ProgramStore& store,
                       int number);
    void showPath(toolpath::ProgrammedPath path);
    // A run on the session's machine, once per UI frame: the actual path
    // grown from sample `from` (a new path or 0: drawn anew) and the tool
    // where the machine stands (nullopt: the run ended, the playhead's again).
    void appendLive(const toolpath::ActualPath& path, std::size_t from,
                    const std::optional<k528::backplot::BackplotScene::LiveTool>& tool);

    k528::backplot::BackplotScene& scene() { return *scene_; }
    VtkGlWidget* glWidget() const { return gl_; }
    void fit();
    // XZ: zooms by `factor` (> 1 closer) about widget point (x, y) from the
    // top-left: what is under the cursor stays there (the wheel does this).
    void zoomAt(double x, double y, double factor);
    void setViewMode(k528::backplot::ViewMode m);
    // Selects the segments of a source line (the editor's cursor).
    void selectLine(int program, int line);
    // The prove-out's findings as red markers at their places (those on
    // the path shown, BackplotScene::setFindings); drawn again only when
    // they changed.
    void setFindings(const std::vector<k528::backplot::BackplotScene::FindingMarker>& markers);
    // A white ring round the marker of a finding (a Problems entry activated).
    void highlightFinding(int program, int line, double z, double x);
    // Picks at widget pixel (x, y from the top-left); the segment or -1.
    // A click: names it, highlights its line and emits lineActivated.
    long pickAt(int x, int y);
    // The segment under the cursor (hover): names it only.
    long hoverAt(int x, int y);
    QString pickText() const;
    void changeEvent(QEvent* e) override;
    bool eventFilter(QObject* o, QEvent* e) override;

signals:
    void lineActivated(int program, int line);
    // A path computed by showProgram() is shown.
    void pathShown();

private:
    void retranslate();
    void refresh();
    void setPlayhead(double seconds);
    void stepFrame(int dir);
    void tickPlayback();
    void updateOutsideList();
    void pathJobFinished();
    void showBusy();
    void updateStatus(); // statusLabel_ from status_, in the UI's language

    std::unique_ptr<k528::backplot::BackplotScene> scene_;
    std::unique_ptr<toolpath::ActualPath> actual_;
    VtkGlWidget* gl_ = nullptr;
    QToolButton *fitButton_ = nullptr, *playButton_ = nullptr, *backButton_ = nullptr,
                *forwardButton_ = nullptr;
    QComboBox *viewCombo_ = nullptr, *speedCombo_ = nullptr;
    QSlider* scrub_ = nullptr;
    QLabel *timeLabel_ = nullptr, *pickLabel_ = nullptr, *outsideTitle_ = nullptr;
    QListWidget* outsideList_ = nullptr;
    PathJob* job_ = nullptr;
    QWidget* busyRow_ = nullptr; // progress and Cancel, while a long job runs
    QLabel *statusLabel_ = nullptr, *busyLabel_ = nullptr;
    QProgressBar* busyBar_ = nullptr;
    QToolButton* cancelButton_ = nullptr;
    int pendingProgram_ = 0;
    // What statusLabel_ says (kept as data: it is said again after a language switch).
    enum class Status { None, CutOff, Cancelled, Running };
    struct {
        Status what = Status::None;
        int program = 0;
        std::int64_t frames = 0;
    } status_;
    bool cancelledByUser_ = false;
    int actualRuns_ = 0; // simulated runs under way
    QTimer* timer_ = nullptr;
    QTimer* liveTimer_ = nullptr;      // the next live render, when one is due
    QElapsedTimer sinceLiveRender_;
    // What a live render shows: the path's samples, the tool's pixel, its
    // wheel and station (a frame that changes none of them is not rendered).
    struct LiveShown {
        std::size_t samples = 0;
        bool tool = false;
        QPoint toolPx;
        int wheelPx = 0, station = -1;
        bool operator==(const LiveShown&) const = default;
    };
    LiveShown liveShows() const;
    LiveShown liveRendered_;
    vtkInteractorStyle* style2d_ = nullptr;
    vtkInteractorStyle* style3d_ = nullptr;
    double playhead_ = -1;
    int pw_ = 1, ph_ = 1;
    bool userMoved_ = false; // panned or zoomed since the last fit
    QPoint pressPos_;
};

} // namespace k528::studio::backplot
