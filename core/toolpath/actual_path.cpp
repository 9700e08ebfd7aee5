#include "toolpath/actual_path.h"

#include "machine/run.h"
#include "machine/simulation.h"

#include <algorithm>
#include <cmath>

namespace k528::toolpath {

namespace {
constexpr double kPi = 3.14159265358979323846;
double wrap(double a) { // to (-pi, pi]
    while (a > kPi)
        a -= 2 * kPi;
    while (a <= -kPi)
        a += 2 * kPi;
    return a;
}
} // namespace

void Decimator::restart() {
    pending_ = 0;
    haveRef_ = false;
    lo_ = -kPi, hi_ = kPi;
    farthest_ = 0;
    exLo_ = ezLo_ = -1e300;
    exHi_ = ezHi_ = 1e300;
}

void Decimator::constrain(const ActualSample& s) {
    const ActualSample& a = out_.back();
    const double dx = s.x - a.x, dz = s.z - a.z;
    const double d = std::hypot(dx, dz);
    farthest_ = std::max(farthest_, d);
    if (d > tol_) {
        const double phi = std::atan2(dx, dz);
        if (!haveRef_) {
            haveRef_ = true;
            ref_ = phi;
        }
        const double rel = wrap(phi - ref_);
        const double w = std::asin(tol_ / d);
        lo_ = std::max(lo_, rel - w);
        hi_ = std::min(hi_, rel + w);
    }
    const double dt = s.tMs - a.tMs;
    if (dt > 0) {
        exLo_ = std::max(exLo_, (s.errX - tol_ - a.errX) / dt);
        exHi_ = std::min(exHi_, (s.errX + tol_ - a.errX) / dt);
        ezLo_ = std::max(ezLo_, (s.errZ - tol_ - a.errZ) / dt);
        ezHi_ = std::min(ezHi_, (s.errZ + tol_ - a.errZ) / dt);
    } else { // the same moment as the kept one: its error must match it
        if (std::fabs(s.errX - a.errX) > tol_ || std::fabs(s.errZ - a.errZ) > tol_)
            exLo_ = 1, exHi_ = -1; // nothing fits
    }
    last_ = s;
    ++pending_;
}

bool Decimator::fits(const ActualSample& e) const {
    if (pending_ == 0)
        return true;
    const ActualSample& a = out_.back();
    const double dx = e.x - a.x, dz = e.z - a.z;
    const double d = std::hypot(dx, dz);
    if (d <= tol_) {
        if (farthest_ > tol_) // a short chord: the pending samples must lie near the kept one
            return false;
    } else {
        if (farthest_ > d)
            return false;
        if (haveRef_) {
            const double rel = wrap(std::atan2(dx, dz) - ref_);
            if (rel < lo_ || rel > hi_)
                return false;
        }
    }
    const double dt = e.tMs - a.tMs;
    if (dt <= 0)
        return false;
    const double sx = (e.errX - a.errX) / dt, sz = (e.errZ - a.errZ) / dt;
    return sx >= exLo_ && sx <= exHi_ && sz >= ezLo_ && sz <= ezHi_;
}

void Decimator::add(const ActualSample& s) {
    ++raw_;
    if (out_.empty()) {
        out_.push_back(s);
        restart();
        return;
    }
    const ActualSample& b = out_.back();
    const bool newFrame = s.line != b.line || s.n != b.n || s.program != b.program ||
                          s.kind != b.kind || s.manual != b.manual;
    if (newFrame || pending_ >= kMaxWindow || !fits(s)) {
        if (pending_ > 0) {
            out_.push_back(last_); // the last sample that fitted
            restart();
        }
        if (newFrame) {
            out_.push_back(s);
            restart();
            return;
        }
    }
    constrain(s);
}

void Decimator::finish() {
    if (pending_ > 0)
        out_.push_back(last_);
    restart();
}
bool sampleOf(const engine::Positioner& c, ActualSample& s) {
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
    s.kind = c.modal().rapid ? SegmentKind::Rapid : SegmentKind::Feed;
    return true;
}

bool sampleOfViews(const engine::ProgramView& p, std::span<const engine::AxisView> axes, double tMs,
                   ActualSample& s) {
    if (!engine::programActive(p.state))
        return false;
    s = ActualSample{};
    s.tMs = tMs;
    double* pos[2] = {&s.x, &s.z};
    double* err[2] = {&s.errX, &s.errZ};
    for (std::size_t i = 0; i < axes.size() && i < 2; ++i) {
        const engine::AxisView& v = axes[i];
        if (!v.present)
            continue;
        const double dpm = static_cast<double>(v.scale.discretesPerMm());
        const double ipd = static_cast<double>(v.scale.internalPerDisc());
        *pos[i] = static_cast<double>(v.currentDisc) / dpm;
        *err[i] = v.errorInternal / ipd / dpm;
    }
    s.program = p.program;
    s.line = p.line;
    s.n = p.frameNumber;
    return true;
}

void SamplingRunMachine::tick() {
    ForwardingRunMachine::tick();
    ActualSample s;
    if (!sampleOf(controller(), s))
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
    const engine::Positioner* c = &sim.controller();
    observer_ = sim.addTickObserver([this, c] { observe(*c); });
}

void LiveActualPath::detach() {
    if (sim_)
        sim_->removeTickObserver(observer_);
    sim_ = nullptr;
    observer_ = 0;
}

void LiveActualPath::observe(const engine::Positioner& c) {
    ActualSample s;
    observe(sampleOf(c, s) ? &s : nullptr);
}

void LiveActualPath::observe(const ActualSample* sample) {
    if (!sample) {
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
    pending_.push_back(*sample);
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
