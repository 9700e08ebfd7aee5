#include "backplot/backplot_widget.h"
#include "workspace/elided_label.h"
#include "window_language.h"

#include "backplot/path_job.h"
#include "backplot/vtk_gl_widget.h"
#include "widgets.h"

#include <QComboBox>
#include <QEvent>
#include <QFutureWatcher>
#include <QLocale>
#include <QProgressBar>
#include <QtConcurrent/QtConcurrentRun>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QMouseEvent>
#include <QSlider>
#include <QSplitter>
#include <QTimer>
#include <QToolButton>
#include <QWheelEvent>
#include <QVBoxLayout>

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleRubberBand2D.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

namespace k528::studio::backplot {

namespace {
// Numbers as the UI's language writes them ("100 000" in Russian), not the
// system's locale.
QLocale uiLocale() {
    return QLocale(russianWindow() ? QLocale::Russian : QLocale::English);
}
} // namespace

namespace {
constexpr double kSpeeds[] = {0.1, 0.5, 1, 2, 5, 10, 100, -1}; // -1: fastest
constexpr int kScrubSteps = 10000;
constexpr int kTickMs = 40;
constexpr double kWheelZoom = 1.2; // a wheel step
} // namespace

BackplotWidget::BackplotWidget(QWidget* parent)
    : QWidget(parent), scene_(std::make_unique<k528::backplot::BackplotScene>()) {
    setObjectName("backplot");
    auto* top = new QHBoxLayout;
    fitButton_ = new QToolButton(this);
    fitButton_->setObjectName("backplot.fit");
    viewCombo_ = new QComboBox(this);
    viewCombo_->setObjectName("backplot.view");
    viewCombo_->addItems({QString(), QString()});
    pickLabel_ = new ElidedLabel(this); // cut, not widening the dock
    pickLabel_->setObjectName("backplot.pick");
    top->addWidget(fitButton_);
    top->addWidget(viewCombo_);
    top->addWidget(pickLabel_, 1);

    gl_ = new VtkGlWidget(this);
    gl_->setObjectName("backplot.gl");
    gl_->setMinimumSize(200, 150);
    gl_->renderWindow()->AddRenderer(scene_->renderer());
    style2d_ = vtkInteractorStyleRubberBand2D::New();
    style3d_ = vtkInteractorStyleTrackballCamera::New();
    gl_->interactor()->SetInteractorStyle(style2d_);

    outsideTitle_ = new QLabel(this);
    outsideTitle_->setWordWrap(true);
    outsideList_ = new QListWidget(this);
    outsideList_->setObjectName("backplot.outside");
    auto* side = new QWidget(this);
    side->setMaximumWidth(240);
    auto* sideLayout = new QVBoxLayout(side);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    sideLayout->addWidget(outsideTitle_);
    sideLayout->addWidget(outsideList_);
    auto* split = new QSplitter(this);
    split->addWidget(gl_);
    split->addWidget(side);
    split->setStretchFactor(0, 5);
    split->setStretchFactor(1, 1);

    auto* bottom = new QHBoxLayout;
    backButton_ = new QToolButton(this);
    backButton_->setObjectName("backplot.stepBack");
    backButton_->setText(QStringLiteral("|◀"));
    playButton_ = new QToolButton(this);
    playButton_->setObjectName("backplot.play");
    playButton_->setCheckable(true);
    forwardButton_ = new QToolButton(this);
    forwardButton_->setObjectName("backplot.stepForward");
    forwardButton_->setText(QStringLiteral("▶|"));
    speedCombo_ = new QComboBox(this);
    speedCombo_->setObjectName("backplot.speed");
    for (double s : kSpeeds)
        speedCombo_->addItem(s > 0 ? QStringLiteral("×%1").arg(s) : QString());
    speedCombo_->setCurrentIndex(2);
    scrub_ = new QSlider(Qt::Horizontal, this);
    scrub_->setObjectName("backplot.scrub");
    scrub_->setRange(0, kScrubSteps);
    scrub_->setValue(kScrubSteps);
    timeLabel_ = new QLabel(this);
    timeLabel_->setObjectName("backplot.time");
    bottom->addWidget(backButton_);
    bottom->addWidget(playButton_);
    bottom->addWidget(forwardButton_);
    bottom->addWidget(speedCombo_);
    bottom->addWidget(scrub_, 1);
    bottom->addWidget(timeLabel_);

    // A long computation's progress and its Cancel (shown after a moment),
    // and what the view says about the path (cut off, cancelled).
    busyRow_ = new QWidget(this);
    busyRow_->setObjectName("backplot.busy");
    auto* busy = new QHBoxLayout(busyRow_);
    busy->setContentsMargins(0, 0, 0, 0);
    busyLabel_ = new ElidedLabel(busyRow_);
    busyBar_ = new QProgressBar(busyRow_);
    busyBar_->setObjectName("backplot.progress");
    busyBar_->setTextVisible(false);
    busyBar_->setMaximumWidth(160);
    cancelButton_ = new QToolButton(busyRow_);
    cancelButton_->setObjectName("backplot.cancel");
    busy->addWidget(busyLabel_, 1);
    busy->addWidget(busyBar_);
    busy->addWidget(cancelButton_);
    busyRow_->hide();
    statusLabel_ = new ElidedLabel(this);
    statusLabel_->setObjectName("backplot.status");
    statusLabel_->setStyleSheet(QStringLiteral("color: #b05000"));
    statusLabel_->hide();

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->addLayout(top);
    layout->addWidget(busyRow_);
    layout->addWidget(statusLabel_);
    layout->addWidget(split, 1);
    layout->addLayout(bottom);

    job_ = new PathJob(this);
    connect(job_, &PathJob::finished, this, &BackplotWidget::pathJobFinished);
    connect(job_, &PathJob::progressed, this, &BackplotWidget::showBusy);
    connect(cancelButton_, &QToolButton::clicked, this, [this] {
        cancelledByUser_ = true;
        job_->cancel();
    });

    liveTimer_ = new QTimer(this);
    liveTimer_->setSingleShot(true);
    connect(liveTimer_, &QTimer::timeout, this, [this] {
        scene_->refreshTool(pw_, ph_);
        liveRendered_ = liveShows();
        sinceLiveRender_.restart();
        gl_->requestRender();
    });
    timer_ = new QTimer(this);
    timer_->setInterval(kTickMs);
    connect(timer_, &QTimer::timeout, this, &BackplotWidget::tickPlayback);
    connect(fitButton_, &QToolButton::clicked, this, &BackplotWidget::fit);
    connect(viewCombo_, &QComboBox::currentIndexChanged, this, [this](int i) {
        setViewMode(i == 1 ? k528::backplot::ViewMode::Solid3D : k528::backplot::ViewMode::XZ);
    });
    connect(playButton_, &QToolButton::toggled, this, [this](bool on) {
        if (on) {
            if (playhead_ < 0 || playhead_ >= scene_->totalSeconds())
                setPlayhead(0);
            timer_->start();
        } else {
            timer_->stop();
        }
        retranslate();
    });
    connect(backButton_, &QToolButton::clicked, this, [this] { stepFrame(-1); });
    connect(forwardButton_, &QToolButton::clicked, this, [this] { stepFrame(1); });
    connect(scrub_, &QSlider::sliderMoved, this, [this](int v) {
        setPlayhead(v >= kScrubSteps ? -1 : scene_->totalSeconds() * v / kScrubSteps);
    });
    connect(gl_, &VtkGlWidget::sizeChanged, this, [this](int w, int h) {
        pw_ = w, ph_ = h;
        scene_->setPixelRatio(gl_->devicePixelRatioF());
        if (!userMoved_) // until the user pans or zooms, the view keeps the whole path
            scene_->fit(pw_, ph_);
        else
            scene_->refresh(pw_, ph_);
    });
    connect(gl_, &VtkGlWidget::interactionStarted, this, [this] { scene_->setInteracting(true); });
    connect(gl_, &VtkGlWidget::interactionEnded, this, [this] {
        userMoved_ = true;
        scene_->setInteracting(false);
        refresh();
    });
    connect(outsideList_, &QListWidget::currentRowChanged, this, [this](int row) {
        if (row < 0)
            return;
        const QListWidgetItem* it = outsideList_->item(row);
        emit lineActivated(it->data(Qt::UserRole).toInt(), it->data(Qt::UserRole + 1).toInt());
        selectLine(it->data(Qt::UserRole).toInt(), it->data(Qt::UserRole + 1).toInt());
    });
    gl_->installEventFilter(this);
    retranslate();
}

BackplotWidget::~BackplotWidget() {
    style2d_->Delete();
    style3d_->Delete();
}

bool BackplotWidget::eventFilter(QObject* o, QEvent* e) {
    if (o == gl_ && e->type() == QEvent::Wheel && scene_->viewMode() == k528::backplot::ViewMode::XZ) {
        // The wheel zooms to the cursor (VTK's 2D style zooms to the centre).
        auto* w = static_cast<QWheelEvent*>(e);
        const double steps = w->angleDelta().y() / 120.0;
        if (steps != 0) {
            const QPointF p = w->position();
            zoomAt(p.x(), p.y(), std::pow(kWheelZoom, steps));
        }
        return true;
    }
    if (o == gl_ && e->type() == QEvent::MouseButtonPress) {
        auto* m = static_cast<QMouseEvent*>(e);
        if (m->button() == Qt::LeftButton)
            pressPos_ = m->position().toPoint();
    } else if (o == gl_ && e->type() == QEvent::MouseMove) {
        auto* m = static_cast<QMouseEvent*>(e);
        if (m->buttons() == Qt::NoButton)
            hoverAt(m->position().toPoint().x(), m->position().toPoint().y());
    } else if (o == gl_ && e->type() == QEvent::MouseButtonRelease) {
        auto* m = static_cast<QMouseEvent*>(e);
        if (m->button() == Qt::LeftButton &&
            (m->position().toPoint() - pressPos_).manhattanLength() <= 3)
            pickAt(pressPos_.x(), pressPos_.y());
    }
    return QWidget::eventFilter(o, e);
}

void BackplotWidget::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) {
        pickLabel_->clear(); // the hint in the new language (a pick names its frame anew)
        retranslate();
    }
    QWidget::changeEvent(e);
}

void BackplotWidget::retranslate() {
    cancelButton_->setText(tr("Cancel"));
    cancelButton_->setToolTip(tr("Stop computing the path (the view keeps what it shows)"));
    if (busyRow_->isVisible())
        showBusy();
    updateStatus();
    fitButton_->setText(tr("Fit"));
    fitButton_->setToolTip(tr("Show the whole path (middle button pans, the wheel zooms)"));
    setItemTexts(viewCombo_, {tr("XZ view"), tr("3D view")});
    speedCombo_->setItemText(speedCombo_->count() - 1, tr("fastest"));
    playButton_->setText(playButton_->isChecked() ? tr("Pause") : tr("Play"));
    backButton_->setToolTip(tr("Previous frame"));
    forwardButton_->setToolTip(tr("Next frame"));
    outsideTitle_->setText(tr("Beyond the software limits"));
    k528::backplot::OverlayTexts t;
    t.segments = tr("%1 segments").toStdString();
    t.diameter = tr("X ⌀ diameter").toStdString();
    t.radius = tr("X radius").toStdString();
    t.mm = tr("%1 mm").toStdString();
    t.micrometres = tr("µm").toStdString();
    scene_->setTexts(t);
    if (pw_ > 1)
        refresh(); // the scale's length in the new words
    if (pickLabel_->text().isEmpty())
        pickLabel_->setText(tr("Click a segment to find its frame"));
    updateOutsideList();
}

void BackplotWidget::showProgram(const profile::MachineProfile& profile,
                                 const program::ProgramStore& store, int number,
                                 const std::optional<stock::Blank>& blank) {
    pendingProgram_ = number;
    cancelledByUser_ = false;
    job_->request(profile, store, number, blank);
}

bool BackplotWidget::computing() const { return job_->busy(); }

QString BackplotWidget::statusText() const { return statusLabel_->isHidden() ? QString() : statusLabel_->text(); }

void BackplotWidget::showBusy() {
    if (!job_->busy()) {
        busyRow_->hide();
        return;
    }
    const PathJob::Progress p = job_->progress();
    // A short one shows no progress at all (counted in frames and legs).
    if (busyRow_->isHidden() && (p.phase == PathJob::Phase::Preview ? p.done : p.total) < PathJob::kShowProgressAfter)
        return;
    const QLocale l = uiLocale();
    busyLabel_->setText(p.phase == PathJob::Phase::Preview
                            ? tr("L%1: computing the path… %2 frames").arg(pendingProgram_).arg(l.toString(p.done))
                            : tr("L%1: cutting the blank… %2 of %3 moves")
                                  .arg(pendingProgram_)
                                  .arg(l.toString(p.done), l.toString(p.total)));
    busyBar_->setRange(0, static_cast<int>(std::max<std::int64_t>(1, p.total)));
    busyBar_->setValue(static_cast<int>(std::min(p.done, p.total)));
    busyRow_->show();
}

void BackplotWidget::pathJobFinished() {
    std::optional<k528::backplot::PreparedPath> r = job_->take();
    if (!job_->busy())
        busyRow_->hide();
    if (!r) {
        if (cancelledByUser_) {
            status_ = {Status::Cancelled, pendingProgram_, 0};
            updateStatus();
        }
        return;
    }
    const bool cutOff = r->path.run.status == engine::PreviewStatus::Limit;
    const int program = r->path.program;
    const std::int64_t frames = r->path.run.frames;
    scene_->setPrepared(std::move(*r));
    // The path of a run on the session's machine (appendLive) stays: it grew
    // while this path was computed and is not drawn again from its start.
    if (!scene_->actual() || scene_->actual() == actual_.get())
        scene_->setActual(actual_ && actual_->result.program == scene_->path().program ? actual_.get() : nullptr);
    playhead_ = -1;
    scrub_->setValue(kScrubSteps);
    updateOutsideList();
    fit();
    status_ = cutOff ? decltype(status_){Status::CutOff, program, frames} : decltype(status_){};
    updateStatus();
    emit pathShown();
}

void BackplotWidget::updateStatus() {
    QString text;
    switch (status_.what) {
    case Status::None:
        break;
    case Status::CutOff:
        text = tr("L%1 does not end within %2 frames (an endless loop?): the path shows those frames")
                   .arg(status_.program)
                   .arg(uiLocale().toString(status_.frames));
        break;
    case Status::Cancelled:
        text = tr("L%1: the path was not computed (cancelled)").arg(status_.program);
        break;
    case Status::Running:
        text = tr("L%1: simulating the run…").arg(status_.program);
        break;
    }
    statusLabel_->setText(text);
    statusLabel_->setToolTip(text);
    statusLabel_->setVisible(!text.isEmpty());
}

void BackplotWidget::showActualRun(const profile::MachineProfile& profile,
                                   const program::ProgramStore& store, int number) {
    // Up to 600 s of machine time at the servo's tick: seconds of work, on a worker.
    auto* watcher = new QFutureWatcher<toolpath::ActualPath>(this);
    const int run = ++actualRuns_;
    connect(watcher, &QFutureWatcher<toolpath::ActualPath>::finished, this, [this, watcher, run] {
        watcher->deleteLater();
        if (run != actualRuns_)
            return; // a newer run was asked for
        status_ = {};
        updateStatus();
        try {
            actual_ = std::make_unique<toolpath::ActualPath>(watcher->result());
        } catch (const std::exception&) {
            return; // the machine cannot run it: the view keeps what it had
        }
        scene_->setActual(actual_.get());
        refresh();
    });
    status_ = {Status::Running, number, 0};
    updateStatus();
    watcher->setFuture(QtConcurrent::run([profile, store, number] {
        engine::RunOptions ro;
        ro.maxSeconds = 600;
        return toolpath::actualPath(profile, store, number, ro, 1.0);
    }));
}

void BackplotWidget::showPath(toolpath::ProgrammedPath path) {
    job_->cancel(); // a path computed meanwhile would replace this one
    status_ = {};
    updateStatus();
    scene_->setPath(std::move(path));
    scene_->setActual(actual_ && actual_->result.program == scene_->path().program ? actual_.get()
                                                                                    : nullptr);
    playhead_ = -1;
    scrub_->setValue(kScrubSteps);
    updateOutsideList();
    fit();
}

void BackplotWidget::updateOutsideList() {
    outsideList_->clear();
    int shown = 0;
    for (const toolpath::Segment& s : scene_->path().segments) {
        if (!s.outside)
            continue;
        if (++shown > 1000)
            break;
        // «ВНЕ ГРАНИЦ» is the NC-200's own text (the panel's language).
        auto* it = new QListWidgetItem(QStringLiteral("ВНЕ ГРАНИЦ  L%1 N%2  ").arg(s.program).arg(s.n) +
                                       tr("line %1").arg(s.line));
        it->setData(Qt::UserRole, s.program);
        it->setData(Qt::UserRole + 1, s.line);
        outsideList_->addItem(it);
    }
}

void BackplotWidget::zoomAt(double x, double y, double factor) {
    const qreal dpr = devicePixelRatioF();
    scene_->zoomAt(x * dpr, ph_ - y * dpr, factor, pw_, ph_);
    userMoved_ = true;
    refresh();
}

void BackplotWidget::fit() {
    userMoved_ = false;
    scene_->fit(pw_, ph_);
    gl_->requestRender();
}

void BackplotWidget::refresh() {
    scene_->refresh(pw_, ph_);
    gl_->requestRender();
}

void BackplotWidget::setViewMode(k528::backplot::ViewMode m) {
    scene_->setViewMode(m);
    gl_->interactor()->SetInteractorStyle(m == k528::backplot::ViewMode::XZ ? style2d_ : style3d_);
    if (viewCombo_->currentIndex() != (m == k528::backplot::ViewMode::XZ ? 0 : 1))
        viewCombo_->setCurrentIndex(m == k528::backplot::ViewMode::XZ ? 0 : 1);
    fit();
}

void BackplotWidget::setFindings(const std::vector<k528::backplot::BackplotScene::FindingMarker>& markers) {
    if (markers == scene_->findings())
        return;
    scene_->setFindings(markers);
    refresh();
}

void BackplotWidget::highlightFinding(int program, int line, double z, double x) {
    scene_->highlightFinding(k528::backplot::BackplotScene::FindingMarker{program, line, z, x});
    refresh();
}

void BackplotWidget::selectLine(int program, int line) {
    scene_->highlightLine(program, line);
    refresh();
}

void BackplotWidget::setPlayhead(double seconds) {
    playhead_ = seconds;
    scene_->setPlayhead(seconds);
    const double total = scene_->totalSeconds();
    const double t = seconds < 0 ? total : seconds;
    timeLabel_->setText(QStringLiteral("%1 / %2 s").arg(t, 0, 'f', 1).arg(total, 0, 'f', 1));
    if (!scrub_->isSliderDown())
        scrub_->setValue(seconds < 0 || total <= 0 ? kScrubSteps
                                                   : static_cast<int>(kScrubSteps * t / total));
    refresh();
}

void BackplotWidget::stepFrame(int dir) {
    const std::size_t n = scene_->path().segments.size();
    if (n == 0)
        return;
    std::size_t k = playhead_ < 0 ? n - 1 : scene_->segmentAt(playhead_);
    if (dir < 0 && k > 0)
        --k;
    else if (dir > 0 && k + 1 < n)
        ++k;
    else if (dir > 0) {
        setPlayhead(-1);
        return;
    }
    // The end of segment k.
    setPlayhead(scene_->segmentStart(k) + scene_->path().segments[k].durationS);
    const toolpath::Segment& s = scene_->path().segments[k];
    pickLabel_->setText(tr("L%1 N%2, line %3").arg(s.program).arg(s.n).arg(s.line));
    emit lineActivated(s.program, s.line);
}

void BackplotWidget::tickPlayback() {
    const double speed = kSpeeds[std::clamp(speedCombo_->currentIndex(), 0, 7)];
    const double total = scene_->totalSeconds();
    double t = playhead_ < 0 ? 0 : playhead_;
    t = speed < 0 ? total : t + speed * kTickMs / 1000.0;
    if (t >= total) {
        setPlayhead(-1);
        playButton_->setChecked(false);
        return;
    }
    setPlayhead(t);
}

void BackplotWidget::appendLive(const toolpath::ActualPath& path, std::size_t from,
                                const std::optional<k528::backplot::BackplotScene::LiveTool>& tool) {
    const bool rewritten = from < scene_->actualPointsShown() || scene_->actual() != &path;
    scene_->appendActual(&path, from);
    scene_->setLiveTool(tool);
    // Rendered at most every kLiveIntervalMs: the latest batch then; not at
    // all when the picture would be the last one again.
    if (liveTimer_->isActive())
        return;
    if (!rewritten && liveShows() == liveRendered_)
        return;
    const qint64 since = sinceLiveRender_.isValid() ? sinceLiveRender_.elapsed() : kLiveIntervalMs;
    liveTimer_->start(static_cast<int>(std::max<qint64>(0, kLiveIntervalMs - since)));
}

BackplotWidget::LiveShown BackplotWidget::liveShows() const {
    LiveShown shown;
    shown.samples = scene_->actualPointsShown();
    if (const auto& tool = scene_->liveTool()) {
        const k528::backplot::ViewWindow vw = scene_->window(pw_, ph_);
        const double perPixel = vw.worldPerPixel > 0 ? vw.worldPerPixel : 1;
        shown.tool = true;
        shown.toolPx = QPoint(static_cast<int>(std::lround(tool->z / perPixel)),
                              static_cast<int>(std::lround(tool->x / perPixel)));
        shown.wheelPx = static_cast<int>(std::lround(tool->wheelMm / perPixel));
        shown.station = tool->station;
    }
    return shown;
}

QString BackplotWidget::pickText() const {
    return pickLabel_->text();
}

long BackplotWidget::hoverAt(int x, int y) {
    const qreal dpr = devicePixelRatioF();
    const long seg = scene_->pick(x * dpr, ph_ - y * dpr, pw_, ph_);
    if (seg >= 0) {
        const toolpath::Segment& s = scene_->path().segments[static_cast<std::size_t>(seg)];
        pickLabel_->setText(tr("L%1 N%2, line %3").arg(s.program).arg(s.n).arg(s.line));
    }
    return seg;
}

long BackplotWidget::pickAt(int x, int y) {
    const qreal dpr = devicePixelRatioF();
    const long seg = scene_->pick(x * dpr, ph_ - y * dpr, pw_, ph_);
    if (seg < 0) {
        pickLabel_->setText(tr("No segment here"));
        return -1;
    }
    const toolpath::Segment& s = scene_->path().segments[static_cast<std::size_t>(seg)];
    pickLabel_->setText(tr("L%1 N%2, line %3").arg(s.program).arg(s.n).arg(s.line));
    selectLine(s.program, s.line);
    emit lineActivated(s.program, s.line);
    return seg;
}

} // namespace k528::studio::backplot
