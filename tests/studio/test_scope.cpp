// The axis oscilloscope (app/studio/scope): its following-error trace of a
// known move matches the engine's reported maximum within one discrete, the
// min/max decimation keeps the peaks, triggers stop the picture, CSV export,
// and a screenshot of the dock.
#include "engine/run.h"
#include "machine/run.h"
#include "machine/simulation.h"
#include "profile/builtin.h"
#include "program/parser.h"
#include "scope/scope_view.h"

#include <QChartView>
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

} // namespace

class TestScope : public QObject {
    Q_OBJECT
private slots:
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
