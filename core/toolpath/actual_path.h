// The actual path: sampled from the simulation of a run — the same
// machine as `k528 run` (machine/run.h) — every tick while the program is
// active: the actual position of X and Z in current coordinates (mm as the
// panel shows them) and the following error (setpoint − actual, mm).
//
// Decimation (documented bound): a sample is dropped only if the polyline
// through the kept samples passes within `toleranceUm` of its position AND
// the following error interpolated linearly in time between the kept
// neighbours is within `toleranceUm` of its own. A corner (a direction
// change larger than the tolerance over the samples since the last kept one)
// therefore always keeps its sample. The first and last samples are kept; a
// new frame (N/line) keeps its first sample.
#pragma once

#include "engine/forwarding_run_machine.h"
#include "toolpath/programmed_path.h"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace k528::machine {
class Simulation;
}

namespace k528::toolpath {

struct ActualSample {
    double tMs = 0;
    double x = 0, z = 0;       // actual position, current coordinates, mm
    double errX = 0, errZ = 0; // following error, mm
    int program = 0, line = 0, n = 0;
    // What moves the axes: a program's G00 (Rapid) or G01 (Feed); `manual`
    // for the operator's motion outside a program (jog, handwheel, the
    // reference-point cycle). A change of either starts a new frame of the
    // decimation, so each kept stretch has one kind.
    SegmentKind kind = SegmentKind::Feed;
    bool manual = false;
};

// Streaming decimator of samples (the bound above), O(1) a sample: instead
// of measuring every sample since the last kept one against each new chord,
// each sample narrows the chords that may still replace it — directions
// from the last kept sample within asin(tol / distance) of its own (so it
// lies within tol of the chord's line), a chord at least as long as the
// farthest of them (so within tol of the chord itself), and slopes of the
// following error in time within ±tol of it. A sample is dropped only when
// the new chord meets all of them: the bound holds (it may keep a few more
// samples than an exhaustive test would).
class Decimator {
public:
    explicit Decimator(double toleranceUm, std::vector<ActualSample>& out)
        : tol_(toleranceUm / 1000.0), out_(out) {}
    void add(const ActualSample& s);
    void finish(); // keeps the last sample
    std::size_t raw() const { return raw_; }

private:
    bool fits(const ActualSample& end) const;
    void restart();                       // a new kept sample: no constraints
    void constrain(const ActualSample& s); // s joins the dropped-so-far
    double tol_;
    std::vector<ActualSample>& out_;
    ActualSample last_;      // the latest sample since the last kept one
    std::size_t pending_ = 0; // samples since the last kept one
    std::size_t raw_ = 0;
    bool haveRef_ = false;
    double ref_ = 0, lo_ = 0, hi_ = 0; // chord direction interval, radians relative to ref_
    double farthest_ = 0;              // of the pending samples from the kept one
    double exLo_ = 0, exHi_ = 0, ezLo_ = 0, ezHi_ = 0; // following-error slopes, mm/ms
    static constexpr std::size_t kMaxWindow = 512;
};

struct ActualPath {
    std::vector<ActualSample> samples;
    std::size_t rawSamples = 0;
    double toleranceUm = 1.0;
    double maxErrorUm = 0; // largest |following error| sampled, µm
    engine::RunResult result;
};

// A RunMachine decorator that samples after each tick.
class SamplingRunMachine final : public engine::ForwardingRunMachine {
public:
    SamplingRunMachine(engine::RunMachine& inner, Decimator& d, ActualPath& path)
        : ForwardingRunMachine(inner), d_(d), path_(path) {}
    void tick() override;

private:
    Decimator& d_;
    ActualPath& path_;
};

// The sample of `c` now: actual position and following error in current
// coordinates (mm as the panel shows them), program/N/line. Returns false
// when no program is active (nothing to sample).
bool sampleOf(const engine::Positioner& c, ActualSample& s);
// The same from what a view of any controller shows (a real one read over
// the link: the current position in discretes as its panel shows them, the
// following error), at time `tMs` of the caller's clock.
bool sampleOfViews(const engine::ProgramView& p, std::span<const engine::AxisView> axes, double tMs,
                   ActualSample& s);

// The actual path of a machine that runs in real time (the studio's
// session) growing live. attach() observes every tick of the Simulation
// (Simulation::addTickObserver); a tick with a program active only copies
// its sample into a buffer, so the machine is not slowed. flush(), once per
// UI frame, passes the batch through the Decimator (the bound above) into
// path().samples. A new run (a program becomes active after none was)
// starts a new path.
class LiveActualPath {
public:
    explicit LiveActualPath(double toleranceUm = 1.0);
    ~LiveActualPath();
    LiveActualPath(const LiveActualPath&) = delete;
    LiveActualPath& operator=(const LiveActualPath&) = delete;

    void attach(machine::Simulation& sim);
    void detach();
    // The Simulation is gone (destroyed first): forget it without detaching.
    void abandon() { sim_ = nullptr; }
    // The per-tick observer (attach() installs it; tests may call it).
    void observe(const engine::Positioner& c);
    // The same for a sample taken elsewhere (a real controller's live
    // positions, read over the link): null when no program is active.
    void observe(const ActualSample* sample);

    struct Batch {
        bool restarted = false;  // a new run began: path() was cleared first
        std::size_t firstNew = 0; // path().samples[firstNew..] are new
        std::size_t added = 0;    // kept samples added by this flush
        std::size_t raw = 0;      // ticks sampled since the last flush
    };
    Batch flush();
    const ActualPath& path() const { return *path_; }
    bool running() const { return active_; }
    // The program of the current or last run (the first sample's), 0 none.
    int program() const { return program_; }

private:
    double toleranceUm_;
    machine::Simulation* sim_ = nullptr;
    int observer_ = 0;
    std::unique_ptr<ActualPath> path_;
    std::unique_ptr<Decimator> decimator_;
    std::vector<ActualSample> pending_;
    bool active_ = false, restartPending_ = false, endPending_ = false;
    int program_ = 0;
};

// Runs the program on the simulated machine (as `k528 run`) and samples it.
// Throws what machine::runProgram throws (bad machine description, override).
ActualPath actualPath(const profile::MachineProfile& profile, const program::ProgramStore& programs,
                      int number, const engine::RunOptions& options, double toleranceUm = 1.0);

} // namespace k528::toolpath
