// The axis oscilloscope (app/studio/scope): its following-error trace of a
// known move matches the engine's reported maximum within one discrete, the
// min/max decimation keeps the peaks, the live decimation kept from frame to
// frame draws what a fresh one does, triggers stop the picture, CSV export,
// and a screenshot of the dock.
#include "engine/run.h"
#include "language.h"
#include "machine/run.h"
#include "machine/simulation.h"
#include "profile/builtin.h"
#include "program/parser.h"
#include "rig/widgets.h"
#include "scope/scope_view.h"

#include <QChartView>
#include <QGraphicsTextItem>
#include <QScrollArea>
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>

using namespace k528;
using namespace k528::studio;

namespace {

program::ProgramStore parse(const char* text) {
    program::ParseOptions o;
    return program::parse(text, o).store;
}

double maxAbs(const QList<QPointF>& pts) {
    double m = 0;
    for (const QPointF& p : pts)
        m = std::max(m, std::fabs(p.y()));
    return m;
}

profile::MachineProfile lathe() {
    profile::MachineProfile p = profile::builtin("training-lathe");
    p.setC(8, 1); // АВТ.БЕЗ ПБТ: the program runs without the reference cycles
    p.setC(60, 1);
    return p;
}

// The texts the chart draws (its scales' labels and titles) that Qt Charts
// cut to «…» for want of room, and how many it shows whole.
QStringList cutTexts(QChartView* view, int* whole) {
    QStringList cut;
    *whole = 0;
    for (QGraphicsItem* item : view->scene()->items()) {
        auto* t = dynamic_cast<QGraphicsTextItem*>(item);
        if (!t || !t->isVisible() || t->toPlainText().isEmpty())
            continue;
        const QString text = t->toPlainText();
        if (text.contains(QStringLiteral("...")) || text.contains(QChar(0x2026)))
            cut << text;
        else
            ++*whole;
    }
    return cut;
}

} // namespace

class TestScope : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY(setLanguage("ru")); } // the longer texts

    void followingErrorMatchesTheEngine() {
        machine::Simulation sim(lathe());
        ScopeView view;
        view.resize(1100, 700);
        view.show();
        view.attach(sim);
        machine::SimulationRunMachine m(sim);
        engine::RunOptions options;
        options.home = false;
        const engine::RunResult r =
            engine::runProgram(m, parse("%L1\nN1 G1 Z-20 FZ6000\nN2 G0 X40\n"), 1, options);
        QCOMPARE(r.status, engine::RunStatus::Completed);
        view.setPaused(true);
        view.setWindowSeconds(10); // the whole run (under 3 s) in the window
        QVERIFY(view.buffer().size() > 1000);
        QVERIFY(view.buffer().size() < 60000);
        for (int a = 0; a < 2; ++a) {
            const double engineMm = units::fractionalDiscToMm(r.axes[static_cast<std::size_t>(a)].maxFollowingErrorDisc,
                                                    r.axes[static_cast<std::size_t>(a)].scale);
            const QList<QPointF> pts = view.seriesPoints(a, ScopeSignal::FollowingError);
            QVERIFY(!pts.isEmpty());
            // What the chart holds (min/max per pixel column once the window
            // has more samples than 4 a column) keeps the peak.
            QVERIFY(pts.size() <= static_cast<qsizetype>(view.buffer().size()));
            QVERIFY2(engineMm > 0.01, "the move lags");
            QVERIFY2(std::fabs(maxAbs(pts) - engineMm) <= 0.001,
                     qPrintable(QString("axis %1: scope %2 engine %3").arg(a).arg(maxAbs(pts)).arg(engineMm)));
        }
        // The end position as the run reports it.
        QVERIFY(std::fabs(view.buffer().last().axes[1].positionMm + 20.0) < 0.01);
        QTemporaryDir dir;
        const QString csv = dir.filePath("scope.csv");
        QVERIFY(view.exportCsv(csv));
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.readLine().startsWith("t_ms,X_setpoint_mm"));
        const QString shots = QStringLiteral(K528_BINARY_DIR "/screenshots");
        QDir().mkpath(shots);
        QVERIFY(view.exportPng(shots + "/scope.png"));
    }

    void decimationKeepsPeaks() {
        ScopeBuffer b(60000);
        for (int t = 1; t <= 60000; ++t) {
            machine::TraceSample s;
            s.tMs = t;
            s.axes[0].followingErrorMm = (t == 31234) ? 0.5 : std::sin(t / 100.0) * 0.01;
            b.add(s);
        }
        QList<QPointF> out;
        b.decimate(0, ScopeSignal::FollowingError, 1, 60000, 800, out);
        QVERIFY(out.size() <= 800 * 2 + 2);
        QCOMPARE(maxAbs(out), 0.5);
        // A full ring drops the oldest.
        machine::TraceSample s;
        s.tMs = 60001;
        b.add(s);
        QCOMPARE(b.size(), std::size_t(60000));
        QCOMPARE(b.at(0).tMs, std::int64_t(2));
    }

    // The live chart keeps its columns from frame to frame and reads only the
    // new samples (ScopeDecimator): after every frame its points are those
    // of a decimation of the whole window from scratch. Samples arrive in
    // uneven chunks, at times with gaps (a link's poll), the ring drops its
    // oldest inside the window, and the width, the window, the signals and
    // a cleared buffer change what is kept.
    void liveDecimationIsAFreshOne() {
        ScopeBuffer b(5000);
        std::array<ScopeDecimator, 2> live; // one per chart, as the view keeps them
        std::uint32_t seed = 12345;
        auto next = [&seed](std::uint32_t below) {
            seed = seed * 1664525u + 1013904223u;
            return (seed >> 8) % below;
        };
        std::int64_t t = 1000;
        int columns = 487;      // not a divisor of the window: columns of 12 and 13 samples
        std::int64_t window = 6000; // longer than the ring holds
        ScopeSignal sigs[4] = {ScopeSignal::Setpoint, ScopeSignal::Position, ScopeSignal::FollowingError,
                               ScopeSignal::Velocity};
        std::array<QList<QPointF>, 4> got, want;
        QList<QPointF>* gotOut[4] = {&got[0], &got[1], &got[2], &got[3]};
        QList<QPointF>* wantOut[4] = {&want[0], &want[1], &want[2], &want[3]};
        int decimatedFrames = 0;
        for (int frame = 0; frame < 700; ++frame) {
            if (frame == 250)
                columns = 300; // the chart was resized
            if (frame == 330)
                window = 2500; // a shorter window
            if (frame == 400)
                sigs[3] = ScopeSignal::Dac; // the fourth trace changed
            if (frame == 470)
                b.clear(); // attached to another machine: a few samples drawn each, then columns again
            const std::uint32_t chunk = frame % 9 == 0 ? next(400) : next(70); // ms of samples
            for (std::uint32_t k = 0; k < chunk; ++k) {
                t += frame >= 550 && next(4) == 0 ? 1 + next(30) : 1;
                machine::TraceSample s;
                s.tMs = t;
                for (auto& a : s.axes) {
                    // Coarse values: equal minima and maxima in a column
                    // (the first of them is drawn), and now and then a peak.
                    a.setpointMm = static_cast<double>(next(7));
                    a.positionMm = std::sin(static_cast<double>(t) / 300.0);
                    a.followingErrorMm = next(500) == 0 ? 0.5 : static_cast<double>(next(5)) * 0.001;
                    a.velocityMmMin = static_cast<double>(next(3)) * 100.0;
                    a.dac = static_cast<double>(next(20000)) - 10000.0;
                }
                b.add(s);
            }
            if (b.size() == 0)
                continue;
            const std::int64_t t1 = b.last().tMs, t0 = t1 - window;
            for (int axis = 0; axis < 2; ++axis) {
                live[static_cast<std::size_t>(axis)].decimate(b, axis, sigs, 4, t0, t1, columns, gotOut, t1);
                b.decimate(axis, sigs, 4, t0, t1, columns, wantOut, t1);
                for (int k = 0; k < 4; ++k) {
                    qsizetype i = 0;
                    while (i < got[k].size() && i < want[k].size() && got[k][i].x() == want[k][i].x() &&
                           got[k][i].y() == want[k][i].y())
                        ++i;
                    if (i == got[k].size() && i == want[k].size())
                        continue;
                    const auto point = [i](const QList<QPointF>& l) {
                        return i < l.size() ? QString("(%1, %2)").arg(l[i].x()).arg(l[i].y()) : QString("none");
                    };
                    QFAIL(qPrintable(QString("frame %1 axis %2 trace %3: %4 points, fresh %5; point %6 %7, fresh %8")
                                         .arg(frame)
                                         .arg(axis)
                                         .arg(k)
                                         .arg(got[k].size())
                                         .arg(want[k].size())
                                         .arg(i)
                                         .arg(point(got[k]))
                                         .arg(point(want[k]))));
                }
                if (axis == 0 && want[0].size() < static_cast<qsizetype>(b.size()))
                    ++decimatedFrames;
            }
        }
        QVERIFY2(decimatedFrames > 500, qPrintable(QString::number(decimatedFrames))); // not mostly raw points
    }

    // The charts lay themselves out for the room they get: in a shop PC's
    // pane, a desk's, a wide and low one and the smallest, no scale's label
    // or title is cut to «…», each value scale keeps at least two labels;
    // a wide low pane puts the charts side by side; below the smallest
    // useful chart the pane scrolls instead of crushing them.
    void chartsFitTheirRoom_data() {
        QTest::addColumn<QSize>("size");
        QTest::addColumn<bool>("sideBySide");
        QTest::newRow("shop PC's tab 560x620") << QSize(560, 620) << false;
        QTest::newRow("desk's pane 800x440") << QSize(800, 440) << true;
        QTest::newRow("4K pane 1600x900") << QSize(1600, 900) << false;
        QTest::newRow("narrow 300x700") << QSize(300, 700) << false;
        QTest::newRow("low 1100x260") << QSize(1100, 260) << true;
    }
    void chartsFitTheirRoom() {
        QFETCH(QSize, size);
        QFETCH(bool, sideBySide);
        machine::Simulation sim(lathe());
        QScrollArea pane; // as in its dock
        pane.setWidgetResizable(true);
        auto* view = new ScopeView;
        pane.setWidget(view);
        pane.resize(size);
        pane.show();
        QVERIFY(QTest::qWaitForWindowExposed(&pane));
        view->attach(sim);
        // A still machine (its zeros), then a move.
        for (const bool moved : {false, true}) {
            if (moved) {
                machine::SimulationRunMachine m(sim);
                engine::RunOptions options;
                options.home = false;
                engine::runProgram(m, parse("%L1\nN1 G1 Z-20 FZ6000\nN2 G0 X40\n"), 1, options);
            } else {
                sim.advance(2000);
            }
            for (int i = 0; i < 3; ++i) {
                view->refresh();
                QCoreApplication::sendPostedEvents();
                QTest::qWait(30);
            }
            QCOMPARE(view->chartsSideBySide(), sideBySide);
            for (int a = 0; a < 2; ++a) {
                QChartView* chart = view->chartView(a);
                QVERIFY(chart->width() >= ScopeView::kChartMinWidth);
                QVERIFY(chart->height() >= ScopeView::kChartMinHeight);
                int whole = 0;
                const QStringList cut = cutTexts(chart, &whole);
                QVERIFY2(cut.isEmpty(), qPrintable(QStringLiteral("%1x%2 axis %3%4: %5")
                                                       .arg(size.width())
                                                       .arg(size.height())
                                                       .arg(a)
                                                       .arg(moved ? "" : " (still)")
                                                       .arg(cut.join(" | "))));
                // Three value scales and the time scale, two labels each at least.
                QVERIFY2(whole >= 8, qPrintable(QString::number(whole)));
                // The live window ends at 0 s, labelled.
            bool zero = false;
            for (QGraphicsItem* item : chart->scene()->items())
                if (auto* t = dynamic_cast<QGraphicsTextItem*>(item); t && t->isVisible())
                    zero = zero || t->toPlainText() == "0";
            QVERIFY2(zero, "no label 0 at the window's end");
            // Round values: no «-0.0» of a sum of binary fractions.
                for (QGraphicsItem* item : chart->scene()->items())
                    if (auto* t = dynamic_cast<QGraphicsTextItem*>(item); t && t->isVisible())
                        QVERIFY2(
                            !QRegularExpression("^-0(\\.0*)?$").match(t->toPlainText()).hasMatch(),
                            qPrintable(t->toPlainText()));
            }
        }
        K528_VERIFY_SHOT(pane.grab(), QStringLiteral("scope-%1x%2.png").arg(size.width()).arg(size.height()));
        // Below the charts' smallest size: the pane scrolls.
        if (size.height() < 2 * ScopeView::kChartMinHeight + 120 && !sideBySide)
            QVERIFY(view->height() > pane.viewport()->height());
    }

    // An alarm trigger: the picture stops half a window after the message.
    void alarmTriggerStops() {
        machine::Simulation sim(lathe());
        ScopeView view;
        view.attach(sim);
        view.setWindowSeconds(2);
        sim.advance(500);
        view.setTrigger(ScopeView::Trigger::Alarm);
        view.refresh();
        QVERIFY(!view.isPaused());
        sim.inject(machine::FaultSpec(machine::Fault::EmergencyStop));
        const std::int64_t injected = sim.timeMs();
        for (int i = 0; i < 400 && !view.isPaused(); ++i) {
            sim.advance(16);
            view.refresh();
        }
        QVERIFY(view.isPaused());
        const std::int64_t stoppedAt = view.buffer().last().tMs;
        QVERIFY(stoppedAt >= injected + 1000 && stoppedAt <= injected + 1100);
        sim.advance(500); // paused: nothing more is recorded
        QCOMPARE(view.buffer().last().tMs, stoppedAt);
    }
};

QTEST_MAIN(TestScope)
#include "test_scope.moc"
