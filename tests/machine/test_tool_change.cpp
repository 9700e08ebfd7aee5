// The tool change on the simulated training lathe as the K528-05 does it
// (docs/engine.md "The tool change"): M61..M64 make the PLC index the turret,
// the program copies the station's offset R-parameters into the correction
// R226/R227, and the same programmed point is then the new tool's tip — the
// slide stands off by exactly the difference of the two tools' offsets.
// Without the copy the machine has nothing to apply: the slide goes where it
// went for the old tool (no tool table), and the prove-out's station says
// which tool is really there.
#include "engine/rparams.h"
#include "rig/machine_rig.h"
#include "profile/tools.h"
#include "proveout/tool_change.h"
#include "toolpath/programmed_path.h"

using namespace k528;
using namespace k528::testrig;

namespace {

// After the tool change at X250 Z200 to station `station`, to X100 Z50 (both
// axes from above: the servo's rest error is the same on every run).
std::string changeAndMove(int station, bool copyOffsets) {
    std::string t = "%L5\nN1 G0 X250 Z200\nN2 M6" + std::to_string(station) + "\n";
    if (copyOffsets) {
        const int r = 100 + 2 * (station - 1); // tool.N.offset_r of the training lathe
        t += "N3 R226=R" + std::to_string(r) + "\nN4 R227=R" + std::to_string(r + 1) + "\n";
    }
    return t + "N5 G0 X100 Z50\nN6 M30\n";
}

struct End {
    std::int64_t machineX = 0, machineZ = 0, currentX = 0, currentZ = 0, r226 = 0, r227 = 0;
    int station = 0;
};

End run(const std::string& text) {
    MachineRig r;
    End e;
    if (!r.drivesOn() || !r.home())
        return e;
    r.load(text);
    if (!r.start(5) || !r.runToEnd(120000) || r.c().state() != ProgramState::Ended)
        return e;
    e.machineX = r.c().axisView(X).machineDisc;
    e.machineZ = r.c().axisView(Z).machineDisc;
    e.currentX = r.c().axisView(X).currentDisc;
    e.currentZ = r.c().axisView(Z).currentDisc;
    e.r226 = r.c().rValues()[engine::r::CorrectionX];
    e.r227 = r.c().rValues()[engine::r::CorrectionX + 1];
    e.station = r.sim->view().turretStation;
    return e;
}

} // namespace

class TestToolChange : public QObject {
    Q_OBJECT
    profile::MachineProfile lathe_ = profile::builtin("training-lathe");

    std::int64_t preset(int n) const {
        const auto it = lathe_.r.find(n);
        return it == lathe_.r.end() ? 0 : it->second;
    }

private slots:
    void theSamePointIsEachToolsTip_data() {
        QTest::addColumn<int>("station");
        for (int s = 2; s <= 4; ++s)
            QTest::addRow("T%d", s) << s;
    }
    void theSamePointIsEachToolsTip() {
        QFETCH(int, station);
        const End one = run(changeAndMove(1, true));
        const End other = run(changeAndMove(station, true));
        QCOMPARE(one.station, 1);
        QCOMPARE(other.station, station);
        // The program's coordinates are the same point: where the tip is.
        QCOMPARE(other.currentX, one.currentX);
        QCOMPARE(other.currentZ, one.currentZ);
        QVERIFY(std::llabs(one.currentX - 100000) <= 10 && std::llabs(one.currentZ - 50000) <= 10);
        // The correction holds the station's offsets, read from the R-parameters the tool names.
        const std::vector<profile::Tool> tools = profile::tools(lathe_);
        const auto tool1 = proveout::correctionOf(*profile::toolAt(tools, 1), lathe_.r);
        const auto toolN = proveout::correctionOf(*profile::toolAt(tools, station), lathe_.r);
        QVERIFY(tool1 && toolN);
        QCOMPARE(toolN->rX, 100 + 2 * (station - 1));
        QCOMPARE(toolN->xDisc, preset(toolN->rX));
        QCOMPARE(other.r226, toolN->xDisc);
        QCOMPARE(other.r227, toolN->zDisc);
        // The slide stands off by exactly the difference of the offsets.
        QCOMPARE(other.machineX - one.machineX, toolN->xDisc - tool1->xDisc);
        QCOMPARE(other.machineZ - one.machineZ, toolN->zDisc - tool1->zDisc);
        QVERIFY(other.machineX - one.machineX != 0 || other.machineZ - one.machineZ != 0);
    }

    // The K528-05 has no tool table: M62 alone indexes the turret and leaves
    // the correction as it was, so the slide goes where it went for tool 1.
    void withoutTheCopyTheSlideGoesWhereItWentForTheOldTool() {
        const End one = run(changeAndMove(1, true));
        const End bare = run(changeAndMove(2, false));
        QCOMPARE(bare.station, 2);
        QCOMPARE(bare.r226, std::int64_t(0));
        QCOMPARE(bare.r227, std::int64_t(0));
        QCOMPARE(bare.machineX, one.machineX);
        QCOMPARE(bare.machineZ, one.machineZ);
    }

    // The station in use along the preview: the description's M functions
    // from the turret's station at power-on; the last of a frame wins.
    void stationsAlongThePreview() {
        const program::ParseResult p = program::parse(
            "%L5\nN1 G0 X250 Z200\nN2 M63\nN3 G0 X200\nN4 M8 M62\nN5 G0 Z150\nN6 M64 M61 G0 X150\nN7 M30\n");
        QVERIFY(!p.hasErrors());
        const toolpath::ProgrammedPath path = toolpath::programmedPath(lathe_, p.store, 5);
        const std::vector<int> st = proveout::stationsAlong(path, proveout::geometryOf(lathe_));
        QCOMPARE(st.size(), path.segments.size());
        std::vector<std::pair<int, int>> byFrame; // (N, station)
        for (std::size_t i = 0; i < st.size(); ++i)
            byFrame.emplace_back(path.segments[i].n, st[i]);
        QCOMPARE(byFrame, (std::vector<std::pair<int, int>>{{1, 1}, {3, 3}, {5, 2}, {6, 1}}));
        // A machine without a turret: no station at all.
        proveout::MachineGeometry none;
        for (int s : proveout::stationsAlong(path, none))
            QCOMPARE(s, 0);
    }
};

QTEST_APPLESS_MAIN(TestToolChange)
#include "test_tool_change.moc"
