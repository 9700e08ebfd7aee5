// The axis oscilloscope (NC-200 23.x «режим осциллографирования»): per axis
// X and Z a chart over the last window of servo ticks — setpoint and
// position (mm, left scale), following error (mm, first right scale) and the
// speed or the DAC code (second right scale) — drawn with Qt Charts from the
// min/max decimation of ScopeBuffer. Triggers (a frame start, an alarm, a
// threshold of |following error|) stop the picture half a window after the
// event; pause; zoom with the mouse while stopped; a cursor that shows the
// values under the mouse; CSV and PNG export. On the simulated machine it
// records every servo tick; on a real controller (read over the link) each
// poll of its live state — positions and following errors at the link's
// rate, which the view says; the DAC is not on the link.
//
// The charts lay themselves out for the room they get: one legend for both
// above them (the right scales are coloured as their traces), side by side
// when that gives each a better shape than one above the other, round ticks
// as many as fit, axis titles only where they fit whole. Below a chart's
// smallest useful size the pane scrolls rather than crush the scales to «…».
#pragma once

#include "scope/scope_buffer.h"

#include <QElapsedTimer>
#include <QWidget>
#include <array>

class QChart;
class QChartView;
class QLineSeries;
class QValueAxis;
class QComboBox;
class QCheckBox;
class QDoubleSpinBox;
class QSpinBox;
class QLabel;
class QPushButton;
class QBoxLayout;

namespace k528::machine {
class Simulation;
}

namespace k528::studio {

class Controller;
class ScopeTrace;

class ScopeView : public QWidget {
    Q_OBJECT
public:
    // The dock redraws the live charts at most this often (15 Hz).
    static constexpr int kLiveIntervalMs = 66;

    explicit ScopeView(QWidget* parent = nullptr);
    ~ScopeView() override;

    // Records every tick of `sim` from now on (its after-tick hook).
    void attach(machine::Simulation& sim);
    void detach();
    // The simulation is gone (its session was destroyed): stop touching it.
    void forget() { sim_ = nullptr; }
    // Records `c`: its simulated machine's every tick, or a real one's every
    // update (its poll). nullptr: nothing.
    void attachController(Controller* c);
    // Samples a second of what is recorded (the servo tick, or the link's poll).
    double sampleRateHz() const { return rateHz_; }
    QLabel* rateLabel() const { return rateLabel_; }

    const ScopeBuffer& buffer() const { return buffer_; }
    bool isPaused() const { return paused_; }
    void setPaused(bool paused);
    void setWindowSeconds(int s);
    int windowSeconds() const { return windowS_; }
    // The points handed to the chart of `axis` for `sig` (after refresh()).
    QList<QPointF> seriesPoints(int axis, ScopeSignal sig) const;
    QChartView* chartView(int axis) const { return views_[static_cast<std::size_t>(axis)]; }
    // The charts side by side (else one above the other).
    bool chartsSideBySide() const;
    // The smallest chart worth drawing: the pane scrolls below it.
    static constexpr int kChartMinWidth = 240, kChartMinHeight = 130;

    enum class Trigger { None, FrameStart, Alarm, Threshold };
    void setTrigger(Trigger t, double thresholdMm = 0.1);

    bool exportCsv(const QString& path) const;
    bool exportPng(const QString& path);
    double framesPerSecond() const { return fps_; }

public slots:
    // Redraws the window that ends at the newest sample (or the frozen one);
    // while hidden only the triggers look at the new samples.
    void refresh();

protected:
    void changeEvent(QEvent* e) override;
    void showEvent(QShowEvent* e) override;
    bool eventFilter(QObject* o, QEvent* e) override;

private:
    struct AxisChart {
        QChart* chart = nullptr;
        QValueAxis *time = nullptr, *mm = nullptr, *error = nullptr, *extra = nullptr;
        // The series hold no points: they give the traces their names, the
        // chart its domains (zoom, mapToValue). The traces draw the points.
        QLineSeries *setpoint = nullptr, *position = nullptr, *followingError = nullptr,
                    *extraSeries = nullptr;
        std::array<ScopeTrace*, 4> traces{}; // setpoint, position, following error, the fourth
        int valueTicks = 4, timeTicks = 6; // most intervals, for the chart's size
    };
    void retranslate();
    // The charts' arrangement for the room of their area, and each chart's
    // ticks and titles for its own size.
    void arrangeCharts();
    void fitChart(int axis);
    // The samples of [t0, t1] (ms), x in seconds after `origin`.
    void draw(std::int64_t t0, std::int64_t t1, std::int64_t origin);
    void checkTrigger();
    void showCursor(int axis, double tS);
    ScopeSignal extraSignal() const;
    void sampleController(); // one sample of a real controller's state
    void sayRate();

    ScopeBuffer buffer_;
    machine::Simulation* sim_ = nullptr;
    Controller* controller_ = nullptr; // a real one (no simulation)
    QMetaObject::Connection updates_;
    QElapsedTimer linkClock_;
    std::int64_t linkFrames_ = 0;
    int lastFrameNumber_ = -1;
    double rateHz_ = 0;
    QLabel* rateLabel_ = nullptr;
    std::array<AxisChart, 2> charts_{};
    std::array<QChartView*, 2> views_{};
    QComboBox *extraBox_ = nullptr, *triggerBox_ = nullptr;
    QDoubleSpinBox* thresholdBox_ = nullptr;
    QSpinBox* windowBox_ = nullptr;
    QCheckBox* pauseBox_ = nullptr;
    QPushButton *csvButton_ = nullptr, *pngButton_ = nullptr;
    QLabel *cursorLabel_ = nullptr, *triggerLabel_ = nullptr, *extraLabel_ = nullptr,
           *windowLabel_ = nullptr;
    std::array<QLabel*, 4> legend_{};
    QWidget* chartsArea_ = nullptr;
    QBoxLayout* chartsLayout_ = nullptr;
    bool paused_ = false;
    int windowS_ = 10;
    std::int64_t shownT0_ = 0, shownT1_ = 0, originMs_ = 0;
    std::int64_t stopAtMs_ = -1, triggeredAtMs_ = -1;
    std::int64_t lastFrames_ = -1;
    std::size_t lastAlarms_ = 0;
    std::size_t checkedUpTo_ = 0; // samples looked at by the threshold trigger
    std::array<QList<QPointF>, 4> lists_;
    // Each chart's columns, kept from frame to frame (a frame reads only its new samples).
    std::array<ScopeDecimator, 2> decimators_;
    QElapsedTimer fpsClock_;
    int fpsFrames_ = 0;
    double fps_ = 0;
    bool zooming_ = false;
};

} // namespace k528::studio
