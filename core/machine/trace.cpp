#include "machine/trace.h"

#include "machine/run.h"
#include "units/units.h"

#include <cmath>

namespace k528::machine {

TraceSample sampleAxes(const engine::Positioner& ctl, const TraceSample* previous) {
    TraceSample s;
    s.tMs = ctl.timeMs();
    for (int i = 0; i < engine::kAxisCount; ++i) {
        const engine::AxisView v = ctl.axisView(engine::axisAt(i));
        TraceAxisSample& a = s.axes[static_cast<std::size_t>(i)];
        if (!v.present)
            continue;
        // The current system = the machine system + the offset the panel
        // applies (both in display discretes); the actual slide at internal
        // resolution.
        const double offsetDisc = static_cast<double>(v.currentDisc - v.machineDisc);
        const double positionDisc = units::internalToDisc(v.absInternal, v.scale) + offsetDisc;
        const double errorDisc = units::internalToDisc(v.errorInternal, v.scale);
        a.positionMm = units::fractionalDiscToMm(positionDisc, v.scale);
        a.followingErrorMm = units::fractionalDiscToMm(errorDisc, v.scale);
        a.setpointMm = a.positionMm + a.followingErrorMm;
        a.dac = v.dac;
        if (previous && s.tMs > previous->tMs) {
            const double dtMin = static_cast<double>(s.tMs - previous->tMs) / 60000.0;
            a.velocityMmMin =
                (a.setpointMm - previous->axes[static_cast<std::size_t>(i)].setpointMm) / dtMin;
        }
    }
    return s;
}

std::string traceCsvHeader() {
    std::string h = "t_ms";
    for (const char* axis : {"X", "Z"})
        for (const char* col :
             {"_setpoint_mm", "_position_mm", "_velocity_mm_min", "_following_error_mm", "_dac"})
            h += std::string(",") + axis + col;
    return h;
}

std::string traceCsvRow(const TraceSample& s) {
    char buf[64];
    std::string row = std::to_string(s.tMs);
    for (const TraceAxisSample& a : s.axes) {
        std::snprintf(buf, sizeof buf, ",%.5f,%.5f,%.3f,%.5f,%d", a.setpointMm, a.positionMm,
                      a.velocityMmMin, a.followingErrorMm, a.dac);
        row += buf;
    }
    return row;
}

TraceRecorder::TraceRecorder(std::size_t keep, std::FILE* csv) : keep_(keep), csv_(csv) {
    if (csv_ && std::fprintf(csv_, "%s\n", traceCsvHeader().c_str()) < 0)
        writeFailed_ = true;
}

void TraceRecorder::attach(Simulation& sim) {
    const engine::Positioner* ctl = &sim.controller();
    sim.setAfterTick([this, ctl] { record(*ctl); });
}

void TraceRecorder::record(const engine::Positioner& ctl) {
    const TraceSample s = sampleAxes(ctl, haveLast_ ? &last_ : nullptr);
    for (std::size_t i = 0; i < 2; ++i)
        maxError_[i] = std::max(maxError_[i], std::fabs(s.axes[i].followingErrorMm));
    if (csv_ && !writeFailed_ && std::fprintf(csv_, "%s\n", traceCsvRow(s).c_str()) < 0)
        writeFailed_ = true;
    if (keep_ > 0) {
        if (samples_.size() >= keep_)
            samples_.erase(samples_.begin(),
                           samples_.begin() + static_cast<std::ptrdiff_t>(samples_.size() / 2));
        samples_.push_back(s);
    }
    last_ = s;
    haveLast_ = true;
    ++rows_;
}

engine::RunResult runProgramTraced(const profile::MachineProfile& profile,
                                   const program::ProgramStore& programs, int number,
                                   const engine::RunOptions& options, TraceRecorder& trace) {
    Simulation sim(profile);
    trace.attach(sim);
    SimulationRunMachine machine(sim);
    engine::RunResult r = engine::runProgram(machine, programs, number, options);
    sim.setAfterTick({});
    return r;
}

} // namespace k528::machine
