// The actual path (issue 12): sampled from the simulation of a run — the same
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

#include "engine/run.h"

#include <cstdint>
#include <vector>

namespace k528::toolpath {

struct ActualSample {
    double tMs = 0;
    double x = 0, z = 0;       // actual position, current coordinates, mm
    double errX = 0, errZ = 0; // following error, mm
    int program = 0, line = 0, n = 0;
};

// Streaming decimator of samples (the bound above).
class Decimator {
public:
    explicit Decimator(double toleranceUm, std::vector<ActualSample>& out)
        : tol_(toleranceUm / 1000.0), out_(out) {}
    void add(const ActualSample& s);
    void finish(); // keeps the last sample
    std::size_t raw() const { return raw_; }

private:
    bool fits(const ActualSample& end) const;
    double tol_;
    std::vector<ActualSample>& out_;
    std::vector<ActualSample> window_; // samples since the last kept one
    std::size_t raw_ = 0;
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
class SamplingRunMachine final : public engine::RunMachine {
public:
    SamplingRunMachine(engine::RunMachine& inner, Decimator& d, ActualPath& path)
        : m_(inner), d_(d), path_(path) {}
    engine::Controller& controller() override { return m_.controller(); }
    void tick() override;
    bool switchOn(std::int64_t maxMs) override { return m_.switchOn(maxMs); }
    void setOverrideCode(int code) override { m_.setOverrideCode(code); }
    void startReferenceCycle(engine::AxisId a, int dir) override { m_.startReferenceCycle(a, dir); }
    void pressStart() override { m_.pressStart(); }
    bool startHeld() const override { return m_.startHeld(); }
    std::vector<int> mFunctions() const override { return m_.mFunctions(); }

private:
    engine::RunMachine& m_;
    Decimator& d_;
    ActualPath& path_;
};

// Runs the program on the simulated machine (as `k528 run`) and samples it.
// Throws what machine::runProgram throws (bad machine description, override).
ActualPath actualPath(const profile::MachineProfile& profile, const program::ProgramStore& programs,
                      int number, const engine::RunOptions& options, double toleranceUm = 1.0);

} // namespace k528::toolpath
