#include "scope/scope_view.h"

#include "controller/controller.h"
#include "controller/simulated_machine.h"
#include "machine/simulation.h"
#include "workspace/flow_layout.h"
#include "widgets.h"

#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFile>
#include <QFileDialog>
#include <QGraphicsItem>
#include <QPainter>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineSeries>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPushButton>
#include <QResizeEvent>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QVBoxLayout>
#include <QValueAxis>
#include <algorithm>
#include <cmath>
#include <limits>

namespace k528::studio {

// One trace drawn onto its chart as Qt Charts draws a line series (the same
// mapping of values to the plot area, a line from point to point, clipped to
// the plot area), without the series' work on every change of its points:
// QLineSeries::replace strokes the whole outline of the line for mouse
// hit-testing, which took three quarters of a live frame for 8 traces of
// 2 points a pixel column (bench_scope); the scope has no use for it.
class ScopeTrace : public QGraphicsItem {
public:
    ScopeTrace(QChart* chart, QValueAxis* x, QValueAxis* y, const QColor& colour)
        : QGraphicsItem(chart), chart_(chart), x_(x), y_(y), pen_(colour) {
        pen_.setWidthF(1.0);
        setZValue(kSeriesZ);
        QObject::connect(chart, &QChart::plotAreaChanged, chart, [this] { prepareGeometryChange(); });
    }
    void setPoints(const QList<QPointF>& points) {
        points_ = points;
        update();
    }
    const QList<QPointF>& points() const { return points_; }
    QRectF boundingRect() const override { return chart_->plotArea(); }
    void paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) override {
        const QRectF area = chart_->plotArea();
        const double dx = x_->max() - x_->min(), dy = y_->max() - y_->min();
        if (points_.size() < 2 || !(dx > 0) || !(dy > 0))
            return;
        const double sx = area.width() / dx, sy = area.height() / dy;
        lines_.resize(points_.size() - 1);
        QPointF prev;
        for (qsizetype i = 0; i < points_.size(); ++i) {
            const QPointF p(area.left() + (points_[i].x() - x_->min()) * sx,
                            area.top() + area.height() - (points_[i].y() - y_->min()) * sy);
            if (i > 0)
                lines_[i - 1] = QLineF(prev, p);
            prev = p;
        }
        painter->save();
        painter->setClipRect(area);
        painter->setPen(pen_);
        painter->setBrush(Qt::NoBrush);
        painter->drawLines(lines_.constData(), static_cast<int>(lines_.size()));
        painter->restore();
    }

private:
    // Above the grid and the scales, where Qt Charts puts its series.
    static constexpr double kSeriesZ = 4;
    QChart* chart_;
    QValueAxis *x_, *y_;
    QPen pen_;
    QList<QPointF> points_;
    QList<QLineF> lines_; // (its memory reused from paint to paint)
};

namespace {

// The traces' colours: setpoint, position, following error, the fourth.
const std::array<QColor, 4> kColours = {QColor(40, 90, 200), QColor(20, 150, 60),
                                        QColor(200, 40, 40), QColor(150, 100, 20)};

// Round ticks for a range of `span`: an interval of 1, 2 or 5 × 10^n, at
// most `most` of them, labelled with the decimals it needs.
double roundStep(double span, int most) {
    const double raw = span / std::max(1, most);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * magnitude >= raw * (1 - 1e-9))
            return m * magnitude;
    return 10 * magnitude;
}

// The top of the range asked of setRangeAndTicks (the axis's is a hair above).
double askedMax(const QValueAxis* axis) {
    const QVariant asked = axis->property("k528.max");
    return asked.isValid() ? asked.toDouble() : axis->max();
}

// Sets the axis's range [lo, hi] with round ticks anchored at 0, at most
// `most`. A wider range takes its wider interval first, a narrower one its
// range first: the axis never holds a range of millions of its ticks.
void setRangeAndTicks(QValueAxis* axis, double lo, double hi, int most) {
    const double span = hi - lo;
    if (!(span > 0) || !std::isfinite(span))
        return;
    const double step = roundStep(span, most);
    const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
    const QString format = QStringLiteral("%.%1f").arg(decimals);
    const bool dynamic = axis->tickType() == QValueAxis::TicksDynamic;
    const bool stepFirst = !dynamic || step > axis->tickInterval();
    const auto setStep = [&] {
        if (axis->tickInterval() != step) {
            axis->setTickInterval(step);
            // A hair above 0: the tick at 0 (summed up from the first in
            // steps of a binary fraction) is never labelled «-0.0».
            axis->setTickAnchor(step * 1e-6);
        }
        if (!dynamic)
            axis->setTickType(QValueAxis::TicksDynamic);
    };
    if (stepFirst)
        setStep();
    // The range a hair wider than asked: a tick on its end (0 s, the newest
    // sample) is drawn although it sits a hair above 0.
    const double top = hi + step * 1e-5;
    axis->setProperty("k528.max", hi);
    if (axis->min() != lo || axis->max() != top)
        axis->setRange(lo, top);
    if (!stepFirst)
        setStep();
    if (axis->labelFormat() != format)
        axis->setLabelFormat(format);
}

// The y range of `axis` for the points: kept while the data fill at least
// 40 % of it and stay inside (no relayout of the chart each frame), else
// the data's range with a margin, at least `leastSpan` (a still machine's
// zeros are not drawn to a ten-thousandth of a millimetre); round ticks, at
// most `most`.
void fitAxis(QValueAxis* axis, int most, double leastSpan, const QList<QPointF>& a,
             const QList<QPointF>* b = nullptr) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const QList<QPointF>* l : {&a, b})
        if (l)
            for (const QPointF& p : *l) {
                lo = std::min(lo, p.y());
                hi = std::max(hi, p.y());
            }
    if (!(lo <= hi)) {
        lo = -1;
        hi = 1;
    }
    if (hi - lo < leastSpan) {
        const double mid = (lo + hi) / 2;
        lo = mid - leastSpan / 2;
        hi = mid + leastSpan / 2;
    }
    const double curLo = axis->min(), curHi = askedMax(axis), span = hi - lo;
    if (lo >= curLo && hi <= curHi && span >= 0.4 * (curHi - curLo)) {
        setRangeAndTicks(axis, curLo, curHi, most); // the ticks for the chart's size
        return;
    }
    const double pad = span * 0.15;
    setRangeAndTicks(axis, lo - pad, hi + pad, most);
}

} // namespace

ScopeView::ScopeView(QWidget* parent) : QWidget(parent) {
    setObjectName("scope");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    // The controls wrap onto more rows in a narrow dock (one row of them
    // once widened the window past the screen).
    auto* bar = new FlowLayout;
    pauseBox_ = new QCheckBox(this);
    pauseBox_->setObjectName("scope.pause");
    windowLabel_ = new QLabel(this);
    windowBox_ = new QSpinBox(this);
    windowBox_->setObjectName("scope.window");
    windowBox_->setRange(1, 60);
    windowBox_->setValue(windowS_);
    extraLabel_ = new QLabel(this);
    extraBox_ = new QComboBox(this);
    extraBox_->setObjectName("scope.extra");
    extraBox_->addItems({QString(), QString()});
    triggerLabel_ = new QLabel(this);
    triggerBox_ = new QComboBox(this);
    triggerBox_->setObjectName("scope.trigger");
    triggerBox_->addItems({QString(), QString(), QString(), QString()});
    thresholdBox_ = new QDoubleSpinBox(this);
    thresholdBox_->setObjectName("scope.threshold");
    thresholdBox_->setDecimals(3);
    thresholdBox_->setRange(0.001, 100);
    thresholdBox_->setValue(0.1);
    csvButton_ = new QPushButton(this);
    csvButton_->setObjectName("scope.csv");
    pngButton_ = new QPushButton(this);
    pngButton_->setObjectName("scope.png");
    bar->addWidget(pauseBox_);
    bar->addGroup({windowLabel_, windowBox_});
    bar->addGroup({extraLabel_, extraBox_});
    bar->addGroup({triggerLabel_, triggerBox_, thresholdBox_});
    bar->addWidget(csvButton_);
    bar->addWidget(pngButton_);
    layout->addLayout(bar);
    // One legend for both charts (in a chart it took a third of its width).
    auto* legend = new FlowLayout(nullptr, 14, 2);
    for (std::size_t i = 0; i < legend_.size(); ++i) {
        legend_[i] = new QLabel(this);
        legend_[i]->setObjectName(QStringLiteral("scope.legend.%1").arg(i));
        legend_[i]->setTextFormat(Qt::RichText);
        legend->addWidget(legend_[i]);
    }
    layout->addLayout(legend);
    chartsArea_ = new QWidget(this);
    chartsArea_->setObjectName("scope.charts");
    chartsLayout_ = new QBoxLayout(QBoxLayout::TopToBottom, chartsArea_);
    chartsLayout_->setContentsMargins(0, 0, 0, 0);
    chartsLayout_->setSpacing(4);
    chartsArea_->installEventFilter(this);
    layout->addWidget(chartsArea_, 1);

    for (int a = 0; a < 2; ++a) {
        AxisChart& c = charts_[static_cast<std::size_t>(a)];
        c.chart = new QChart;
        c.chart->setMargins(QMargins(2, 2, 2, 2));
        c.chart->setAnimationOptions(QChart::NoAnimation);
        c.chart->setDropShadowEnabled(false);
        c.chart->setBackgroundRoundness(0);
        c.chart->legend()->hide();
        QFont titleFont = font();
        titleFont.setBold(true);
        c.chart->setTitleFont(titleFont);
        c.time = new QValueAxis(c.chart);
        c.mm = new QValueAxis(c.chart);
        c.error = new QValueAxis(c.chart);
        c.extra = new QValueAxis(c.chart);
        c.chart->addAxis(c.time, Qt::AlignBottom);
        c.chart->addAxis(c.mm, Qt::AlignLeft);
        c.chart->addAxis(c.error, Qt::AlignRight);
        c.chart->addAxis(c.extra, Qt::AlignRight);
        const auto add = [&](QLineSeries*& s, QValueAxis* y, const QColor& colour) {
            s = new QLineSeries(c.chart);
            // Raster, not Qt Charts' OpenGL series: under llvmpipe (Xvfb) the
            // OpenGL overlay measured 4 frames/s against 60 (bench/run scope).
            s->setUseOpenGL(false);
            QPen pen(colour);
            pen.setWidthF(1.0);
            s->setPen(pen);
            c.chart->addSeries(s);
            s->attachAxis(c.time);
            s->attachAxis(y);
        };
        add(c.setpoint, c.mm, kColours[0]);
        add(c.position, c.mm, kColours[1]);
        add(c.followingError, c.error, kColours[2]);
        add(c.extraSeries, c.extra, kColours[3]);
        c.traces = {new ScopeTrace(c.chart, c.time, c.mm, kColours[0]),
                    new ScopeTrace(c.chart, c.time, c.mm, kColours[1]),
                    new ScopeTrace(c.chart, c.time, c.error, kColours[2]),
                    new ScopeTrace(c.chart, c.time, c.extra, kColours[3])};
        // The right scales in their trace's colour (the legend names them).
        for (auto [axis, colour] :
             {std::pair{c.error, kColours[2]}, std::pair{c.extra, kColours[3]}}) {
            axis->setLinePenColor(colour);
            axis->setLabelsColor(colour);
            axis->setGridLineVisible(false);
            axis->setTitleVisible(false);
        }
        auto* view = new QChartView(c.chart, chartsArea_);
        view->setObjectName(a == 0 ? "scope.chart.X" : "scope.chart.Z");
        view->setRenderHint(QPainter::Antialiasing, false);
        view->setViewportUpdateMode(QGraphicsView::FullViewportUpdate);
        view->setMouseTracking(true);
        view->viewport()->installEventFilter(this);
        view->installEventFilter(this); // its size: its ticks and titles
        view->setMinimumSize(kChartMinWidth, kChartMinHeight);
        views_[static_cast<std::size_t>(a)] = view;
        chartsLayout_->addWidget(view, 1);
        connect(c.time, &QValueAxis::rangeChanged, this, [this](qreal lo, qreal hi) {
            if (!zooming_ && paused_)
                draw(originMs_ + std::llround(lo * 1000), originMs_ + std::llround(hi * 1000),
                     originMs_);
        });
    }
    rateLabel_ = new QLabel(this);
    rateLabel_->setObjectName("scope.rate");
    rateLabel_->setWordWrap(true);
    layout->insertWidget(1, rateLabel_);
    cursorLabel_ = new QLabel(this);
    cursorLabel_->setObjectName("scope.cursor");
    cursorLabel_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    cursorLabel_->setWordWrap(true);
    layout->addWidget(cursorLabel_);

    connect(pauseBox_, &QCheckBox::toggled, this, &ScopeView::setPaused);
    connect(windowBox_, &QSpinBox::valueChanged, this, &ScopeView::setWindowSeconds);
    connect(extraBox_, &QComboBox::currentIndexChanged, this, [this] {
        retranslate();
        refresh();
    });
    connect(triggerBox_, &QComboBox::currentIndexChanged, this, [this](int i) {
        setTrigger(static_cast<Trigger>(i), thresholdBox_->value());
    });
    connect(csvButton_, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export CSV"), "scope.csv",
                                                          tr("CSV (*.csv)"));
        if (!path.isEmpty() && !exportCsv(path))
            QMessageBox::warning(this, tr("Export CSV"), tr("Cannot write %1").arg(path));
    });
    connect(pngButton_, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export PNG"), "scope.png",
                                                          tr("PNG (*.png)"));
        if (!path.isEmpty() && !exportPng(path))
            QMessageBox::warning(this, tr("Export PNG"), tr("Cannot write %1").arg(path));
    });
    retranslate();
    fpsClock_.start();
}

ScopeView::~ScopeView() { detach(); }

void ScopeView::attach(machine::Simulation& sim) {
    detach();
    sim_ = &sim;
    buffer_.clear();
    const engine::Positioner* ctl = &sim.controller();
    sim.setAfterTick([this, ctl] {
        if (!paused_)
            buffer_.record(*ctl);
    });
}

void ScopeView::detach() {
    if (sim_)
        sim_->setAfterTick({});
    sim_ = nullptr;
    disconnect(updates_);
    controller_ = nullptr;
}

void ScopeView::attachController(Controller* c) {
    detach();
    buffer_.clear();
    stopAtMs_ = triggeredAtMs_ = -1;
    checkedUpTo_ = 0;
    lastFrames_ = -1;
    if (c && c->simulated()) {
        attach(c->simulated()->simulation());
        rateHz_ = 1000.0 / static_cast<double>(std::max<std::int64_t>(1, sim_->controller().tickMs()));
    } else if (c) {
        controller_ = c;
        linkClock_.start();
        linkFrames_ = 0;
        lastFrameNumber_ = -1;
        rateHz_ = c->capabilities().liveRateHz;
        updates_ = connect(c, &Controller::sampled, this, &ScopeView::sampleController);
        connect(c, &QObject::destroyed, this, [this, c] {
            if (controller_ == c)
                detach();
        });
    }
    // The DAC code is the simulated machine's: the link's map has none.
    if (auto* m = qobject_cast<QStandardItemModel*>(extraBox_->model()))
        if (QStandardItem* dac = m->item(1)) {
            dac->setEnabled(!controller_);
            if (controller_ && extraBox_->currentIndex() == 1)
                extraBox_->setCurrentIndex(0);
        }
    sayRate();
    refresh();
}

void ScopeView::sampleController() {
    if (!controller_ || paused_)
        return;
    const ControllerState& st = controller_->state();
    if (!st.connected) // a lost line: no samples (its last ones stay)
        return;
    machine::TraceSample s;
    s.tMs = linkClock_.elapsed();
    if (buffer_.size() > 0 && s.tMs <= buffer_.last().tMs)
        return;
    for (std::size_t i = 0; i < 2; ++i) {
        const engine::AxisView& v = st.axes[i];
        machine::TraceAxisSample& a = s.axes[i];
        const double dpm = static_cast<double>(v.scale.discretesPerMm());
        const double ipd = static_cast<double>(v.scale.internalPerDisc());
        if (!(dpm > 0) || !(ipd > 0))
            continue;
        a.positionMm = static_cast<double>(v.currentDisc) / dpm;
        a.followingErrorMm = v.errorInternal / ipd / dpm;
        a.setpointMm = a.positionMm + a.followingErrorMm; // error = setpoint − position
        if (buffer_.size() > 0) {
            const machine::TraceSample& prev = buffer_.last();
            const double minutes = static_cast<double>(s.tMs - prev.tMs) / 60000.0;
            a.velocityMmMin = (a.setpointMm - prev.axes[i].setpointMm) / minutes;
        }
    }
    if (st.program.frameNumber != lastFrameNumber_) {
        if (lastFrameNumber_ >= 0)
            ++linkFrames_;
        lastFrameNumber_ = st.program.frameNumber;
    }
    buffer_.add(s);
    // The rate measured over the samples of the last 5 s.
    const std::size_t first = buffer_.lowerBound(s.tMs - 5000);
    if (buffer_.size() - first >= 3)
        rateHz_ = static_cast<double>(buffer_.size() - first - 1) * 1000.0 /
                  static_cast<double>(s.tMs - buffer_.at(first).tMs);
    sayRate();
}

void ScopeView::sayRate() {
    if (!rateLabel_)
        return;
    const QString text =
        controller_ ? tr("Live at %1 samples a second: the link's poll of the controller's positions and following "
                         "errors (the setpoint is position + error; no DAC on the link).")
                          .arg(rateHz_, 0, 'f', 1)
        : sim_ ? tr("Every servo tick of the simulated machine (%1 samples a second).").arg(rateHz_, 0, 'f', 0)
               : QString();
    if (rateLabel_->text() != text)
        rateLabel_->setText(text);
}

void ScopeView::setPaused(bool paused) {
    if (paused_ == paused)
        return;
    paused_ = paused;
    pauseBox_->setChecked(paused);
    for (QChartView* v : views_)
        v->setRubberBand(paused ? QChartView::HorizontalRubberBand : QChartView::NoRubberBand);
    if (!paused) {
        stopAtMs_ = triggeredAtMs_ = -1;
        checkedUpTo_ = buffer_.size();
    }
    refresh();
}

void ScopeView::setWindowSeconds(int s) {
    windowS_ = std::clamp(s, 1, 60);
    windowBox_->setValue(windowS_);
    refresh();
}

void ScopeView::setTrigger(Trigger t, double thresholdMm) {
    triggerBox_->setCurrentIndex(static_cast<int>(t));
    thresholdBox_->setValue(thresholdMm);
    stopAtMs_ = triggeredAtMs_ = -1;
    checkedUpTo_ = buffer_.size();
    lastFrames_ = -1;
    lastAlarms_ = sim_ ? sim_->controller().alarms().size() : controller_ ? controller_->state().alarms.size() : 0;
}

ScopeSignal ScopeView::extraSignal() const {
    return extraBox_->currentIndex() == 1 ? ScopeSignal::Dac : ScopeSignal::Velocity;
}

void ScopeView::checkTrigger() {
    if ((!sim_ && !controller_) || buffer_.size() == 0 || stopAtMs_ >= 0)
        return;
    const auto t = static_cast<Trigger>(triggerBox_->currentIndex());
    const std::int64_t now = buffer_.last().tMs;
    bool fired = false;
    if (t == Trigger::FrameStart) {
        const std::int64_t frames = sim_ ? sim_->controller().framesExecuted() : linkFrames_;
        fired = lastFrames_ >= 0 && frames != lastFrames_;
        lastFrames_ = frames;
    } else if (t == Trigger::Alarm) {
        const std::size_t n = sim_ ? sim_->controller().alarms().size() : controller_->state().alarms.size();
        fired = n > lastAlarms_;
        lastAlarms_ = n;
    } else if (t == Trigger::Threshold) {
        const double limit = thresholdBox_->value();
        checkedUpTo_ = std::min(checkedUpTo_, buffer_.size());
        for (std::size_t i = checkedUpTo_; i < buffer_.size() && !fired; ++i)
            for (const machine::TraceAxisSample& a : buffer_.at(i).axes)
                if (std::fabs(a.followingErrorMm) > limit) {
                    fired = true;
                    break;
                }
        checkedUpTo_ = buffer_.size();
    }
    if (fired) {
        triggeredAtMs_ = now;
        stopAtMs_ = now + windowS_ * 500;
    }
}

void ScopeView::refresh() {
    if (!paused_) {
        checkTrigger();
        if (stopAtMs_ >= 0 && buffer_.size() > 0 && buffer_.last().tMs >= stopAtMs_) {
            setPaused(true);
            return;
        }
    }
    // Hidden (the dock closed, or a tab behind another: Qt moves such a dock
    // out of sight without hiding it): the triggers keep watching, the
    // picture is drawn when it shows again (showEvent, the dock's
    // visibilityChanged).
    if (!isVisible() || visibleRegion().isEmpty())
        return;
    if (buffer_.size() == 0) {
        draw(-windowS_ * 1000, 0, 0);
        return;
    }
    const std::int64_t t1 =
        paused_ && stopAtMs_ >= 0 ? std::min(stopAtMs_, buffer_.last().tMs) : buffer_.last().tMs;
    draw(t1 - windowS_ * 1000, t1, t1);
}

void ScopeView::draw(std::int64_t t0, std::int64_t t1, std::int64_t origin) {
    shownT0_ = t0;
    shownT1_ = t1;
    originMs_ = origin;
    const ScopeSignal extra = extraSignal();
    for (int a = 0; a < 2; ++a) {
        AxisChart& c = charts_[static_cast<std::size_t>(a)];
        const int columns = std::max(50, static_cast<int>(c.chart->plotArea().width()));
        const ScopeSignal sigs[4] = {ScopeSignal::Setpoint, ScopeSignal::Position,
                                     ScopeSignal::FollowingError, extra};
        QList<QPointF>* outs[4] = {&lists_[0], &lists_[1], &lists_[2], &lists_[3]};
        decimators_[static_cast<std::size_t>(a)].decimate(buffer_, a, sigs, 4, t0, t1, columns, outs, origin);
        // The least spans: 10 µm of position, 2 µm of error, 10 mm/min or
        // 10 codes of the fourth trace.
        fitAxis(c.mm, c.valueTicks, 0.01, lists_[0], &lists_[1]);
        fitAxis(c.error, c.valueTicks, 0.002, lists_[2]);
        fitAxis(c.extra, c.valueTicks, 10, lists_[3]);
        for (std::size_t k = 0; k < c.traces.size(); ++k)
            c.traces[k]->setPoints(lists_[k]);
        // The time axis: seconds before the window's end (0): live, its range
        // and labels stay put and only the traces move.
        const double x0 = static_cast<double>(t0 - origin) / 1000.0,
                     x1 = static_cast<double>(t1 - origin) / 1000.0;
        zooming_ = true;
        setRangeAndTicks(c.time, x0, x1, c.timeTicks);
        zooming_ = false;
    }
    ++fpsFrames_;
    if (fpsClock_.elapsed() >= 1000) {
        fps_ = fpsFrames_ * 1000.0 / static_cast<double>(fpsClock_.restart());
        fpsFrames_ = 0;
    }
}

QList<QPointF> ScopeView::seriesPoints(int axis, ScopeSignal sig) const {
    const AxisChart& c = charts_[static_cast<std::size_t>(axis)];
    switch (sig) {
    case ScopeSignal::Setpoint: return c.traces[0]->points();
    case ScopeSignal::Position: return c.traces[1]->points();
    case ScopeSignal::FollowingError: return c.traces[2]->points();
    default: return extraSignal() == sig ? c.traces[3]->points() : QList<QPointF>{};
    }
}

bool ScopeView::exportCsv(const QString& path) const {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return false;
    f.write(QByteArray::fromStdString(machine::traceCsvHeader() + "\n"));
    for (std::size_t i = buffer_.lowerBound(shownT0_); i < buffer_.lowerBound(shownT1_ + 1); ++i)
        f.write(QByteArray::fromStdString(machine::traceCsvRow(buffer_.at(i)) + "\n"));
    return f.error() == QFileDevice::NoError;
}

bool ScopeView::exportPng(const QString& path) { return grab().save(path, "PNG"); }

void ScopeView::showCursor(int axis, double tS) {
    const std::size_t i = buffer_.lowerBound(originMs_ + std::llround(tS * 1000));
    if (i >= buffer_.size())
        return;
    const machine::TraceSample& s = buffer_.at(i);
    const machine::TraceAxisSample& v = s.axes[static_cast<std::size_t>(axis)];
    cursorLabel_->setText(tr("%1  t = %2 s  setpoint %3 mm  position %4 mm  speed %5 mm/min  "
                             "following error %6 mm  DAC %7")
                              .arg(axis == 0 ? "X" : "Z")
                              .arg(s.tMs / 1000.0, 0, 'f', 3)
                              .arg(v.setpointMm, 0, 'f', 4)
                              .arg(v.positionMm, 0, 'f', 4)
                              .arg(v.velocityMmMin, 0, 'f', 1)
                              .arg(v.followingErrorMm, 0, 'f', 4)
                              .arg(v.dac));
}

bool ScopeView::chartsSideBySide() const {
    return chartsLayout_->direction() == QBoxLayout::LeftToRight;
}

void ScopeView::arrangeCharts() {
    const double w = chartsArea_->width(), h = chartsArea_->height();
    if (w <= 0 || h <= 0)
        return;
    // How far a chart of cw × ch is from 2:1, a trace's natural shape.
    const auto off = [](double cw, double ch) {
        return std::fabs(std::log(cw / std::max(1.0, ch) / 2.0));
    };
    const double stackedOff = off(w, h / 2), sideOff = off(w / 2, h);
    const bool side = chartsSideBySide();
    // Switched only when the other is clearly better (no flapping).
    bool want = side ? stackedOff >= sideOff * 0.8 : sideOff < stackedOff * 0.8;
    if (w < 2 * kChartMinWidth + chartsLayout_->spacing())
        want = false;
    if (want != side)
        chartsLayout_->setDirection(want ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom);
}

void ScopeView::fitChart(int axis) {
    AxisChart& c = charts_[static_cast<std::size_t>(axis)];
    const QChartView* v = views_[static_cast<std::size_t>(axis)];
    const int w = v->width(), h = v->height();
    const QFontMetrics labels(c.time->labelsFont()), titles(c.time->titleFont());
    // The plot's room inside the scales (three of labels).
    const int plotW = w - 3 * (labels.horizontalAdvance(QStringLiteral("-000.000")) + 8) - 8;
    // The time axis's title where the plot keeps its room below it and the
    // title fits whole along it.
    const bool timeTitle = h >= kChartMinHeight + 2 * titles.height() &&
                           plotW >= titles.horizontalAdvance(c.time->titleText()) + 8;
    if (c.time->isTitleVisible() != timeTitle)
        c.time->setTitleVisible(timeTitle);
    const int plotH = h - 2 * labels.height() - (timeTitle ? titles.height() + 4 : 0) -
                      QFontMetrics(c.chart->titleFont()).height() - 16;
    c.valueTicks = std::clamp(plotH / (2 * labels.height()), 1, 8);
    c.timeTicks =
        std::clamp(plotW / (labels.horizontalAdvance(QStringLiteral("-00.0")) + 28), 2, 12);
    for (QValueAxis* a : {c.mm, c.error, c.extra, c.time})
        setRangeAndTicks(a, a->min(), askedMax(a), a == c.time ? c.timeTicks : c.valueTicks);
}

bool ScopeView::eventFilter(QObject* o, QEvent* e) {
    if (e->type() == QEvent::Resize) {
        if (o == chartsArea_)
            arrangeCharts();
        for (int a = 0; a < 2; ++a)
            if (o == views_[static_cast<std::size_t>(a)])
                fitChart(a);
    }
    if (e->type() == QEvent::MouseMove)
        for (int a = 0; a < 2; ++a)
            if (o == views_[static_cast<std::size_t>(a)]->viewport()) {
                const auto* me = static_cast<QMouseEvent*>(e);
                const QPointF v = charts_[static_cast<std::size_t>(a)].chart->mapToValue(
                    me->position(), charts_[static_cast<std::size_t>(a)].setpoint);
                showCursor(a, v.x());
            }
    return QWidget::eventFilter(o, e);
}

void ScopeView::showEvent(QShowEvent* e) {
    QWidget::showEvent(e);
    refresh();
}

void ScopeView::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) {
        cursorLabel_->clear(); // the hint in the new language; values come with the next move
        retranslate();
    }
    QWidget::changeEvent(e);
}

void ScopeView::retranslate() {
    pauseBox_->setText(tr("Pause"));
    windowLabel_->setText(tr("Window, s"));
    extraLabel_->setText(tr("Fourth trace"));
    extraBox_->setItemText(0, tr("Speed, mm/min"));
    extraBox_->setItemText(1, tr("DAC code"));
    extraBox_->setItemData(1, controller_ ? tr("The link's map carries no DAC code: the simulated machine's only")
                                          : QString(),
                           Qt::ToolTipRole);
    sayRate();
    triggerLabel_->setText(tr("Trigger"));
    setItemTexts(triggerBox_, {tr("Free running"), tr("Frame start"), tr("Alarm"), tr("|Following error| over, mm")});
    csvButton_->setText(tr("Export CSV…"));
    pngButton_->setText(tr("Export PNG…"));
    const bool dac = extraSignal() == ScopeSignal::Dac;
    const QString names[4] = {
        tr("Setpoint, mm"), tr("Position, mm"), tr("Following error, mm (right scale)"),
        dac ? tr("DAC code (right scale)") : tr("Speed, mm/min (right scale)")};
    for (std::size_t i = 0; i < legend_.size(); ++i)
        legend_[i]->setText(QStringLiteral("<span style=\"color:%1\">&#9632;</span>&nbsp;%2")
                                .arg(kColours[i].name(), names[i].toHtmlEscaped()));
    for (int a = 0; a < 2; ++a) {
        AxisChart& c = charts_[static_cast<std::size_t>(a)];
        // The axis in the chart's title: a vertical scale's title takes more
        // room than Qt Charts leaves for it and cuts the scale's labels to «…».
        c.chart->setTitle(a == 0 ? tr("Axis X") : tr("Axis Z"));
        c.time->setTitleText(tr("Time before the newest sample, s"));
        c.setpoint->setName(names[0]);
        c.position->setName(names[1]);
        c.followingError->setName(names[2]);
        c.extraSeries->setName(names[3]);
        fitChart(a); // the titles' widths changed
    }
    if (cursorLabel_->text().isEmpty())
        cursorLabel_->setText(tr("Move the mouse over a chart to read the values."));
}

} // namespace k528::studio
