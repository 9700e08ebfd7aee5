#include "toolpath/actual_path.h"

#include "machine/run.h"

#include <algorithm>
#include <cmath>

namespace k528::toolpath {

namespace {
double distToSegment(double px, double pz, double ax, double az, double bx, double bz) {
    const double dx = bx - ax, dz = bz - az;
    const double len2 = dx * dx + dz * dz;
    double t = len2 > 0 ? ((px - ax) * dx + (pz - az) * dz) / len2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    const double qx = ax + t * dx - px, qz = az + t * dz - pz;
    return std::sqrt(qx * qx + qz * qz);
}
} // namespace

bool Decimator::fits(const ActualSample& e) const {
    const ActualSample& a = out_.back();
    const double span = e.tMs - a.tMs;
    for (const ActualSample& s : window_) {
        if (distToSegment(s.x, s.z, a.x, a.z, e.x, e.z) > tol_)
            return false;
        const double f = span > 0 ? (s.tMs - a.tMs) / span : 0;
        if (std::fabs(a.errX + f * (e.errX - a.errX) - s.errX) > tol_ ||
            std::fabs(a.errZ + f * (e.errZ - a.errZ) - s.errZ) > tol_)
            return false;
    }
    return true;
}

void Decimator::add(const ActualSample& s) {
    ++raw_;
    if (out_.empty()) {
        out_.push_back(s);
        return;
    }
    const bool newFrame = s.line != out_.back().line || s.n != out_.back().n ||
                          s.program != out_.back().program;
    if (newFrame || window_.size() >= kMaxWindow || !fits(s)) {
        if (!window_.empty()) {
            out_.push_back(window_.back()); // the last sample that fitted
            window_.clear();
        }
        if (newFrame) {
            out_.push_back(s);
            return;
        }
    }
    window_.push_back(s);
}

void Decimator::finish() {
    if (!window_.empty())
        out_.push_back(window_.back());
    window_.clear();
}

void SamplingRunMachine::tick() {
    m_.tick();
    const engine::Controller& c = m_.controller();
    if (!engine::programActive(c.state()))
        return;
    ActualSample s;
    s.tMs = static_cast<double>(c.timeMs());
    double* pos[2] = {&s.x, &s.z};
    double* err[2] = {&s.errX, &s.errZ};
    for (int i = 0; i < engine::kAxisCount; ++i) {
        const engine::AxisView v = c.axisView(engine::axisAt(i));
        if (!v.present)
            continue;
        const double dpm = static_cast<double>(v.scale.discretesPerMm());
        const double ipd = static_cast<double>(v.scale.internalPerDisc());
        const double offsetDisc = static_cast<double>(v.machineDisc - v.currentDisc);
        *pos[i] = (v.absInternal / ipd - offsetDisc) / dpm;
        *err[i] = v.errorInternal / ipd / dpm;
        path_.maxErrorUm = std::max(path_.maxErrorUm, std::fabs(*err[i]) * 1000.0);
    }
    const engine::ProgramView p = c.programView();
    s.program = p.program;
    s.line = p.line;
    s.n = p.frameNumber;
    d_.add(s);
}

ActualPath actualPath(const profile::MachineProfile& profile, const program::ProgramStore& programs,
                      int number, const engine::RunOptions& options, double toleranceUm) {
    ActualPath path;
    path.toleranceUm = toleranceUm;
    Decimator d(toleranceUm, path.samples);
    machine::Simulation sim(profile);
    machine::SimulationRunMachine inner(sim);
    SamplingRunMachine sampling(inner, d, path);
    path.result = engine::runProgram(sampling, programs, number, options);
    d.finish();
    path.rawSamples = d.raw();
    return path;
}

} // namespace k528::toolpath
