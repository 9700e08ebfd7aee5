// The training run of the profile-guided optimisation of the tick
// (cmake/K528Pgo.cmake, docs/engine.md "Speed"). The sub-build compiles the
// tick's modules instrumented, links this program and runs it once; the
// profile it leaves then guides the optimisation of those modules in the
// real build. It drives the tick as `k528 run` and the workstation do: the
// sample programs on their machines (the positioner, the simulated PLC
// running the machine description, the plant), the engine benchmark's long
// two-axis program on the training lathe, and an idle machine with its
// drives on. Nothing here is measured; a run that does not complete fails
// the build, since its profile would not be the usual path.
//
// pgo_train [IDLE_TICKS]
#include "engine/run.h"
#include "machine/run.h"
#include "machine/simulation.h"
#include "profile/builtin.h"
#include "program/parser.h"
#include "resources/embedded.h"

#include "engine_program.h"

#include <cstdio>
#include <cstdlib>
#include <string>

using namespace k528;

namespace {

bool run(const char* machineName, std::string_view text, const char* what) {
    const program::ParseResult parsed = program::parse(text);
    if (parsed.hasErrors()) {
        std::fprintf(stderr, "pgo_train: %s does not parse\n", what);
        return false;
    }
    const engine::RunResult r = machine::runProgram(profile::builtin(machineName), parsed.store, 1,
                                                    engine::RunOptions{});
    std::printf("pgo_train: %-28s on %-15s %s, %.1f s of machine time\n", what, machineName,
                std::string(engine::runStatusName(r.status)).c_str(), r.timeS + r.homeTimeS);
    return r.status == engine::RunStatus::Completed;
}

} // namespace

int main(int argc, char** argv) {
    const long long idleTicks = argc > 1 ? std::atoll(argv[1]) : 200000;
    bool ok = true;
    const struct {
        const char* machine;
        const char* sample;
    } samples[] = {{"training-lathe", "samples/lathe-shaft.k528"},
                   {"training-lathe", "samples/lathe-grooves.k528"},
                   {"grinder-205", "samples/grinder-bore-205.k528"}};
    for (const auto& s : samples) {
        const auto text = resources::find(s.sample);
        ok = text && run(s.machine, *text, s.sample) && ok;
    }
    const std::string benchmarkProgram = bench::engineProgram(50);
    ok = run("training-lathe", benchmarkProgram, "the benchmark program") && ok;

    machine::Simulation sim(profile::builtin("training-lathe"));
    machine::SimulationRunMachine m(sim);
    sim.powerOn();
    ok = m.switchOn(10000) && ok;
    sim.advance(idleTicks);
    std::printf("pgo_train: idle on training-lathe, %lld ticks\n", idleTicks);
    return ok ? 0 : 1;
}
