// core/toolpath and `k528 path`: exact corner coordinates from the
// engine's preview, and the actual path of a run against the following error.
#include "cli_runner.h"
#include "profile/builtin.h"
#include "program/parser.h"
#include "machine/run.h"
#include "rig/watched_run.h"
#include "machine/simulation.h"
#include "toolpath/actual_path.h"
#include "toolpath/programmed_path.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace k528;

namespace {

QJsonObject pathJson(const QByteArray& program, QStringList extra = {}) {
    QTemporaryDir dir;
    const QString file = dir.filePath("p.k528");
    QFile f(file);
    f.open(QIODevice::WriteOnly);
    f.write(program);
    f.close();
    QStringList args{"path", "--json"};
    args << extra << file;
    const CliResult r = runK528(args);
    if (r.exitCode != 0 && r.exitCode != 1)
        qWarning() << r.err << r.out;
    return QJsonDocument::fromJson(r.out.toUtf8()).object();
}

// The points of segment i as "x,z x,z ..." (mm, shortest form).
QString points(const QJsonObject& o, int i) {
    QStringList out;
    for (const QJsonValue& p : o["segments"].toArray()[i].toObject()["points"].toArray())
        out << QString::number(p.toArray()[0].toDouble(), 'g', 10) + "," +
                   QString::number(p.toArray()[1].toDouble(), 'g', 10);
    return out.join(' ');
}

} // namespace

class TestToolpath : public QObject {
    Q_OBJECT
private slots:
    void absoluteAndIncremental() {
        // X is a diameter axis: FX in mm of diameter per minute.
        const QJsonObject o = pathJson("%L1\n"
                                       "N1 G1 X20 FX100\n"
                                       "N2 G91 X10 FX100 Z-5 FZ100\n"
                                       "N3 G90 X0 Z0 FZ100\n");
        QCOMPARE(o["status"].toString(), QString("completed"));
        QCOMPARE(o["segments"].toArray().size(), 3);
        QCOMPARE(points(o, 0), QString("0,0 20,0"));
        // X 10 at 100 = 6 s, Z 5 at 100 = 3 s: Z arrives first, X at 25.
        QCOMPARE(points(o, 1), QString("20,0 25,-5 30,-5"));
        // back: X 30 at 100 = 18 s, Z 5 at 100 = 3 s.
        QCOMPARE(points(o, 2), QString("30,-5 25,0 0,0"));
        QCOMPARE(o["segments"].toArray()[1].toObject()["n"].toInt(), 2);
        QCOMPARE(o["segments"].toArray()[1].toObject()["line"].toInt(), 3);
        QCOMPARE(o["segments"].toArray()[1].toObject()["kind"].toString(), QString("feed"));
    }
    void doglegUnequalFeeds() {
        const QJsonObject o = pathJson("%L1\nN1 G1 X40 FX200 Z-30 FZ100\n");
        // X 40 at 200 = 12 s, Z 30 at 100 = 18 s: X arrives first, Z at -20.
        QCOMPARE(points(o, 0), QString("0,0 40,-20 40,-30"));
        const QJsonObject feed = o["segments"].toArray()[0].toObject()["feed_mm_min"].toObject();
        QCOMPARE(feed["X"].toDouble(), 200.0);
        QCOMPARE(feed["Z"].toDouble(), 100.0);
    }
    void rapidDoglegAtEachAxisRapid() {
        // G00: each axis at its F УСК.АВТ. (C42, C94: 10 discretes/min).
        const QJsonObject o = pathJson("%L1\nN1 G0 X60 Z-60\n",
                                       {"--param", "42=300000", "--param", "94=600000"});
        // X 60 at 3000 = 1.2 s, Z 60 at 6000 = 0.6 s: Z first, X at 30.
        QCOMPARE(points(o, 0), QString("0,0 30,-60 60,-60"));
        QCOMPARE(o["segments"].toArray()[0].toObject()["kind"].toString(), QString("rapid"));
        QVERIFY(o["segments"].toArray()[0].toObject()["feed_mm_min"].toObject()["X"].isNull());
    }
    void subprogramsLoopsAndRTargets() {
        const QJsonObject o = pathJson("%L1\n"
                                       "N1 R1=15000\n"
                                       "N2 G1 X=R1 FX100\n"
                                       "N3 R2=3\n"
                                       "N4 L2\n"
                                       "N5 R2=R2-1\n"
                                       "N6 IF R2>0 GOTO 4\n"
                                       "N7 M30\n"
                                       "%L2\n"
                                       "N1 G91 G1 Z-1.5 FZ50\n"
                                       "N2 G90 M17\n");
        QCOMPARE(o["status"].toString(), QString("completed"));
        const QJsonArray segs = o["segments"].toArray();
        QCOMPARE(segs.size(), 4);
        QCOMPARE(points(o, 0), QString("0,0 15,0"));
        QCOMPARE(points(o, 1), QString("15,0 15,-1.5"));
        QCOMPARE(points(o, 3), QString("15,-3 15,-4.5"));
        QCOMPARE(segs[3].toObject()["program"].toInt(), 2);
        QCOMPARE(segs[3].toObject()["line"].toInt(), 10);
        QCOMPARE(o["end"].toObject()["Z"].toDouble(), -4.5);
        QCOMPARE(o["frames"].toInt(), 3 + 3 * 5 + 1); // N1..N3, 3 × (N4, L2 N1, N2, N5, N6), N7
    }
    void setPositionAndSkip() {
        const QJsonObject o = pathJson("%L1\n"
                                       "N1 G192 X50\n"
                                       "/N2 G1 X99 FX100\n"
                                       "N3 G1 X60 FX100\n"
                                       "N4 G4 X1.5\n"
                                       "N5 G192 X10\n"
                                       "N6 G1 Z-5 FZ100\n");
        const QJsonArray segs = o["segments"].toArray();
        QCOMPARE(segs.size(), 2); // the skipped frame draws nothing
        QCOMPARE(points(o, 1), QString("10,0 10,-5")); // X stands where Gx92 put it
        QCOMPARE(points(o, 0), QString("50,0 60,0"));
        QCOMPARE(segs[0].toObject()["n"].toInt(), 3);
        const QJsonArray dw = o["dwells"].toArray();
        QCOMPARE(dw.size(), 1);
        QCOMPARE(dw[0].toObject()["seconds"].toDouble(), 1.5);
        QCOMPARE(dw[0].toObject()["at"].toArray()[0].toDouble(), 60.0);
    }
    void outsideTheSoftLimits() {
        // training-lathe: X -4..272 (diameter), Z -115..295 (C46/C47, C98/C99).
        const QJsonObject o = pathJson("%L1\nN1 G0 X100\nN7 G0 X300\nN8 G0 X100 Z-200\nN9 G0 Z0\n"
                                       "N10 G0 X300\nN11 G0 Z5\n");
        QCOMPARE(o["status"].toString(), QString("completed"));
        const QJsonArray segs = o["segments"].toArray();
        QCOMPARE(segs[0].toObject()["outside"].toBool(), false);
        QCOMPARE(segs[1].toObject()["outside"].toBool(), true);
        QCOMPARE(segs[2].toObject()["outside"].toBool(), true);
        QCOMPARE(segs[3].toObject()["outside"].toBool(), true); // starts at Z-200
        QCOMPARE(segs[5].toObject()["outside"].toBool(), true); // Z moves, X stands beyond
        const QJsonArray w = o["warnings"].toArray();
        QCOMPARE(w.size(), 5);
        QCOMPARE(w[0].toObject()["n"].toInt(), 7);
        QCOMPARE(w[0].toObject()["text_ru"].toString(), QString::fromUtf8("ВНЕ ГРАНИЦ"));
        QCOMPARE(o["limits"].toObject()["X"].toArray()[1].toDouble(), 272.0);
        QCOMPARE(o["limits"].toObject()["Z"].toArray()[0].toDouble(), -115.0);
    }
    void endlessProgramStopsAtTheFrameLimit() {
        const QJsonObject o =
            pathJson("%L1\nN1 G91 G1 Z1 FZ1000\nN2 GOTO 1\n", {"--max-frames", "1000"});
        QCOMPARE(o["status"].toString(), QString("limit"));
        QVERIFY(o["frames"].toInt() >= 1000);
        QVERIFY(o["segments"].toArray().size() >= 500);
    }
    void plainOutput() {
        QTemporaryDir dir;
        QFile f(dir.filePath("p.k528"));
        f.open(QIODevice::WriteOnly);
        f.write("%L1\nN1 G0 X300\n");
        f.close();
        const CliResult r = runK528({"path", f.fileName()});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(QString::fromUtf8("L1 N1 line 2 rapid  X0 Z0 -> X300 Z0  ВНЕ ГРАНИЦ")), qPrintable(r.out));
        QVERIFY(r.out.contains("status completed"));
    }
    // The preview's output in program order for a reader of the path
    // (collision checks, a start from a frame): each frame's M functions and
    // message before its motion or dwell, each naming the segment it precedes.
    void mFunctionsAndMessagesInProgramOrder() {
        const profile::MachineProfile prof = profile::builtin("training-lathe");
        const auto parsed = program::parse("%L1\nN1 G0 X60 Z5 M3 M8\nN2 #1 G4 X1.5 M5\n"
                                           "N3 G1 X40 FX200 M9\nN4 M30\n%MESSAGES\n#1=ДОВОДКА\n");
        QVERIFY(!parsed.hasErrors());
        const toolpath::ProgrammedPath p = toolpath::programmedPath(prof, parsed.store, 1);
        QCOMPARE(p.run.status, engine::PreviewStatus::Completed);
        QCOMPARE(p.segments.size(), std::size_t(2));
        QCOMPARE(p.mFunctions.size(), std::size_t(4)); // N1, N2, N3, N4
        const auto codes = [&](std::size_t i) {
            QStringList c;
            for (int k = 0; k < p.mFunctions[i].count; ++k)
                c << QString::number(p.mFunctions[i].codes[static_cast<std::size_t>(k)]);
            return c.join(' ');
        };
        QCOMPARE(codes(0), QString("3 8"));
        QCOMPARE(p.mFunctions[0].segment, 0u); // before N1's move
        QCOMPARE(p.mFunctions[0].n, 1);
        QCOMPARE(codes(1), QString("5"));
        QCOMPARE(p.mFunctions[1].segment, 1u); // after N1's move, before N3's
        QCOMPARE(codes(2), QString("9"));
        QCOMPARE(p.mFunctions[2].segment, 1u);
        QCOMPARE(codes(3), QString("30"));
        QCOMPARE(p.mFunctions[3].segment, 2u);
        QCOMPARE(p.messages.size(), std::size_t(1));
        QCOMPARE(p.messages[0].number, 1);
        QCOMPARE(p.messages[0].line, 3);
        QCOMPARE(p.messages[0].segment, 1u);
        QCOMPARE(p.dwells.size(), std::size_t(1));
        QCOMPARE(p.dwells[0].segment, 1u);
        QCOMPARE(p.dwells[0].seconds, 1.5);
    }
    void actualPathDiffersByTheFollowingError() {
        const profile::MachineProfile prof = profile::builtin("training-lathe");
        const program::ParseResult parsed =
            program::parse("%L1\nN1 G1 X40 FX2000 Z-30 FZ1000\nN2 G1 X20 FX2000\n");
        QVERIFY(!parsed.hasErrors());
        engine::RunOptions ro;
        const toolpath::ActualPath a = toolpath::actualPath(prof, parsed.store, 1, ro, 1.0);
        QCOMPARE(a.result.status, engine::RunStatus::Completed);
        QVERIFY(a.rawSamples > a.samples.size() * 5); // decimated
        QVERIFY(a.maxErrorUm > 10);                    // the servo lags at these feeds
        // Ends where the program ends (within ДОПУСК ПОЗ), and while moving the
        // following error is what the engine reports: actual + error = setpoint
        // lies on the programmed leg X (Z standing at -30 in frame 2).
        const toolpath::ActualSample& last = a.samples.back();
        QVERIFY(std::fabs(last.x - 20) < 0.02);
        QVERIFY(std::fabs(last.z + 30) < 0.02);
        bool sawLag = false;
        for (const toolpath::ActualSample& s : a.samples)
            if (s.n == 2 && std::fabs(s.errX) > 0.01) {
                sawLag = true;
                QVERIFY(std::fabs(s.z + s.errZ + 30) < 1e-6); // Z setpoint stays at -30
                QVERIFY(s.x + s.errX <= 40 + 1e-6 && s.x + s.errX >= 20 - 1e-6);
            }
        QVERIFY(sawLag);
        // The programmed path of the same program.
        const toolpath::ProgrammedPath p = toolpath::programmedPath(prof, parsed.store, 1);
        QCOMPARE(p.segments.size(), std::size_t(2));
    }
    void livePathGrowsWithTheRun() {
        // The session's way: every tick observed, a flush every 16 ticks (a UI
        // frame at 60 Hz): the path grows batch by batch and ends as the
        // offline actual path of the same run, sample for sample.
        const profile::MachineProfile prof = profile::builtin("training-lathe");
        const program::ParseResult parsed =
            program::parse("%L1\nN1 G1 X40 FX2000 Z-30 FZ1000\nN2 G1 X20 FX2000\n");
        QVERIFY(!parsed.hasErrors());
        engine::RunOptions ro;
        const toolpath::ActualPath offline = toolpath::actualPath(prof, parsed.store, 1, ro, 1.0);
        machine::Simulation sim(prof);
        toolpath::LiveActualPath live(1.0);
        live.attach(sim);
        std::vector<std::size_t> sizes;
        int restarts = 0;
        const auto flush = [&] {
            const toolpath::LiveActualPath::Batch b = live.flush();
            restarts += b.restarted;
            if (b.raw > 0)
                sizes.push_back(live.path().samples.size());
            QCOMPARE(b.firstNew + b.added, live.path().samples.size());
        };
        testrig::WatchedSimulationRun frames(sim, [&, ticks = 0]() mutable {
            if (++ticks % 16 == 0)
                flush();
        });
        const engine::RunResult r = engine::runProgram(frames, parsed.store, 1, ro);
        QCOMPARE(r.status, engine::RunStatus::Completed);
        flush();
        QVERIFY(!live.running());
        QCOMPARE(live.program(), 1);
        QCOMPARE(restarts, 1);
        QVERIFY(sizes.size() > 20); // it grew over many frames
        QVERIFY(std::is_sorted(sizes.begin(), sizes.end()));
        QVERIFY(sizes.front() < sizes.back() / 4);
        const toolpath::ActualPath& a = live.path();
        QCOMPARE(a.rawSamples, offline.rawSamples);
        QCOMPARE(a.samples.size(), offline.samples.size());
        for (std::size_t i = 0; i < a.samples.size(); ++i) {
            QCOMPARE(a.samples[i].tMs, offline.samples[i].tMs);
            QCOMPARE(a.samples[i].x, offline.samples[i].x);
            QCOMPARE(a.samples[i].z, offline.samples[i].z);
            QCOMPARE(a.samples[i].errX, offline.samples[i].errX);
        }
        QCOMPARE(a.maxErrorUm, offline.maxErrorUm);
        live.detach();
        sim.advance(50); // no observer left
        QCOMPARE(live.flush().raw, std::size_t(0));
    }
};

QTEST_APPLESS_MAIN(TestToolpath)
#include "test_toolpath.moc"
