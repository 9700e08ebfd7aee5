#include "toolpath/actual_path.h"

#include "machine/run.h"
#include "machine/simulation.h"

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

bool sampleOf(const engine::Controller& c, ActualSample& s) {
    if (!engine::programActive(c.state()))
        return false;
    s = ActualSample{};
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
    }
    const engine::ProgramView p = c.programView();
    s.program = p.program;
    s.line = p.line;
    s.n = p.frameNumber;
    return true;
}

void SamplingRunMachine::tick() {
    m_.tick();
    ActualSample s;
    if (!sampleOf(m_.controller(), s))
        return;
    path_.maxErrorUm = std::max({path_.maxErrorUm, std::fabs(s.errX) * 1000.0, std::fabs(s.errZ) * 1000.0});
    d_.add(s);
}

LiveActualPath::LiveActualPath(double toleranceUm)
    : toleranceUm_(toleranceUm), path_(std::make_unique<ActualPath>()) {
    path_->toleranceUm = toleranceUm;
    decimator_ = std::make_unique<Decimator>(toleranceUm, path_->samples);
}

LiveActualPath::~LiveActualPath() {
    detach();
}

void LiveActualPath::attach(machine::Simulation& sim) {
    detach();
    sim_ = &sim;
    const engine::Controller* c = &sim.controller();
    observer_ = sim.addTickObserver([this, c] { observe(*c); });
}

void LiveActualPath::detach() {
    if (sim_)
        sim_->removeTickObserver(observer_);
    sim_ = nullptr;
    observer_ = 0;
}

void LiveActualPath::observe(const engine::Controller& c) {
    ActualSample s;
    if (!sampleOf(c, s)) {
        if (active_)
            endPending_ = true;
        active_ = false;
        return;
    }
    if (!active_) { // a new run: what is pending belongs to the old one
        if (!pending_.empty() || endPending_)
            flush();
        restartPending_ = true;
        active_ = true;
    }
    pending_.push_back(s);
}

LiveActualPath::Batch LiveActualPath::flush() {
    Batch b;
    if (restartPending_) {
        b.restarted = true;
        restartPending_ = false;
        endPending_ = false;
        path_ = std::make_unique<ActualPath>();
        path_->toleranceUm = toleranceUm_;
        decimator_ = std::make_unique<Decimator>(toleranceUm_, path_->samples);
        program_ = pending_.empty() ? 0 : pending_.front().program;
    }
    b.firstNew = path_->samples.size();
    b.raw = pending_.size();
    for (const ActualSample& s : pending_) {
        path_->maxErrorUm =
            std::max({path_->maxErrorUm, std::fabs(s.errX) * 1000.0, std::fabs(s.errZ) * 1000.0});
        decimator_->add(s);
    }
    pending_.clear();
    if (endPending_) { // the run ended: its last sample too
        decimator_->finish();
        endPending_ = false;
    }
    path_->rawSamples = decimator_->raw();
    b.added = path_->samples.size() - b.firstNew;
    return b;
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
