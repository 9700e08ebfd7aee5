// The "proveout" section of the shipped machine descriptions says what the
// machine's PLC does: every M it names as starting a spindle starts it on the
// simulated machine, every M stopping one stops it, every tool change
// indexes the turret to its station (docs/machine-description.md).
#include "machine/run.h"
#include "profile/builtin.h"
#include "program/parser.h"
#include "proveout/geometry.h"

#include <QtTest>

#include <cmath>

using namespace k528;

namespace {

struct Rig {
    explicit Rig(const char* machine, const std::string& program)
        : profile(profile::builtin(machine)), sim(profile) {
        const program::ParseResult parsed = program::parse(program);
        if (parsed.hasErrors())
            qFatal("program: %s", program.c_str());
        machine::SimulationRunMachine rm(sim);
        engine::RunOptions o;
        o.maxSeconds = 120;
        result = engine::runProgram(rm, parsed.store, 1, o);
        sim.advance(10000); // a spindle told to stop (M2 ends the program at once) comes to rest
    }
    double rpm(const std::string& spindle) const {
        for (const machine::SpindleView& s : sim.view().spindles)
            if (s.name == spindle)
                return std::fabs(s.rpm); // reverse turns negative
        return -1;
    }
    profile::MachineProfile profile;
    machine::Simulation sim;
    engine::RunResult result;
};

// The M that starts `spindle` in `g` (the first).
int starter(const proveout::MachineGeometry& g, const std::string& spindle) {
    return g.spindle(spindle)->on.front();
}

} // namespace

class TestProveoutDescription : public QObject {
    Q_OBJECT
private slots:
    void spindlesAndToolChanges() {
        for (const char* machine : {"training-lathe", "grinder-205"}) {
            const proveout::MachineGeometry g = proveout::geometryOf(profile::builtin(machine));
            QVERIFY2(!g.spindles.empty(), machine);
            QVERIFY2(g.spindle(g.cuttingSpindle), machine);
            for (const proveout::SpindleUse& s : g.spindles) {
                for (int on : s.on) {
                    Rig r(machine, "%L1\nN1 M" + std::to_string(on) + "\nN2 G4 X0.5\n");
                    QVERIFY2(r.result.status == engine::RunStatus::Completed,
                             (std::string(machine) + " M" + std::to_string(on)).c_str());
                    QVERIFY2(r.rpm(s.name) > 0, (std::string(machine) + " M" + std::to_string(on) +
                                                 " starts " + s.name)
                                                    .c_str());
                }
                for (int off : s.off) {
                    // Started first (by its own M), then stopped by this one.
                    Rig r(machine, "%L1\nN1 M" + std::to_string(starter(g, s.name)) + "\nN2 M" +
                                       std::to_string(off) + "\n");
                    QVERIFY2(r.rpm(s.name) == 0, (std::string(machine) + " M" +
                                                  std::to_string(off) + " stops " + s.name)
                                                     .c_str());
                }
            }
            for (const auto& [m, station] : g.toolChange) {
                Rig r(machine, "%L1\nN1 M" + std::to_string(m) + "\n");
                QVERIFY2(r.result.status == engine::RunStatus::Completed, machine);
                QCOMPARE(r.sim.view().turretStation, station);
            }
        }
    }

    void lathesChuckAndTurret() {
        const proveout::MachineGeometry g = proveout::geometryOf(profile::builtin("training-lathe"));
        QVERIFY(g.chuck.present && g.turret.present);
        QCOMPARE(g.firstStation, 1);
        QCOMPARE(g.toolChange.size(), std::size_t(4));
        // The soft limit keeps the reference tool 5 mm off the jaws (docs/training-lathe.md).
        QCOMPARE(g.chuck.jawFaceZMm, -120.0);
        const proveout::MachineGeometry grinder = proveout::geometryOf(profile::builtin("grinder-205"));
        QVERIFY(grinder.ring.present && !grinder.chuck.present);
    }

    void badSectionsAreRefused() {
        const auto read = [](const std::string& proveoutJson) {
            const std::string text = R"({"format": 1, "name": "t", "m_functions": [{"m": 3}],
                "equipment": {"spindles": [{"name": "spindle", "rpm": 100}]},
                "proveout": )" + proveoutJson + "}";
            return proveout::readGeometry(plc::readDescription(text, "t.json"));
        };
        QCOMPARE(read(R"({"spindles": [{"name": "spindle", "on": [3]}]})").spindles.size(),
                 std::size_t(1));
        const auto refused = [&](const std::string& json, const char* says) {
            try {
                read(json);
            } catch (const plc::DescriptionError& e) {
                return std::string(e.what()).find(says) != std::string::npos;
            }
            return false;
        };
        QVERIFY(refused(R"({"spindles": [{"name": "wheel", "on": [3]}]})", "not a spindle"));
        QVERIFY(refused(R"({"spindles": [{"name": "spindle", "on": [4]}]})", "M4"));
        QVERIFY(refused(R"({"cutting_spindle": "spindle"})", "not one of the spindles"));
        QVERIFY(refused(R"({"tool_change": [{"m": 3, "station": 1}]})", "no turret"));
        QVERIFY(refused(R"({"chuck": {"jaw_face_z_mm": -1, "jaws": 3}})", "jaws"));
        QVERIFY(refused(R"({"turret": {"z_min_mm": 5, "z_max_mm": 1, "r_min_mm": 0, "r_max_mm": 1}})",
                        "z_min_mm < z_max_mm"));
    }
};

QTEST_APPLESS_MAIN(TestProveoutDescription)
#include "test_description.moc"
