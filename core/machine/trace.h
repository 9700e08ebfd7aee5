// The trace recorder: the axes of the simulated machine sampled at every
// servo tick — setpoint, position, speed, following error and DAC code per
// axis — for `k528 run --trace FILE.csv` (docs/engine.md) and the desktop's
// oscilloscope. Coordinates as the panel shows them (the current system, × 2
// on a diameter axis); following error = setpoint − position. No clock: it
// records what the simulation's ticks give.
#pragma once

#include "engine/positioner.h"
#include "engine/run.h"
#include "machine/simulation.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace k528::machine {

struct TraceAxisSample {
    double setpointMm = 0;
    double positionMm = 0;
    double velocityMmMin = 0; // speed of the setpoint, signed
    double followingErrorMm = 0;
    int dac = 0;
};

struct TraceSample {
    std::int64_t tMs = 0;
    std::array<TraceAxisSample, 2> axes{}; // X, Z
};

// One sample of `ctl` now; `previous` (the sample a tick before, or null)
// gives the sign and size of the setpoint's speed.
TraceSample sampleAxes(const engine::Positioner& ctl, const TraceSample* previous);

// "t_ms,X_setpoint_mm,...,Z_dac" and one row.
std::string traceCsvHeader();
std::string traceCsvRow(const TraceSample& s);

// Samples every tick of a Simulation (Simulation::setAfterTick) into a
// callback-free buffer and/or a CSV file.
class TraceRecorder {
public:
    // Keeps at most `keep` samples in memory (0: none); writes every row to
    // `csv` when it is not null (the caller owns and closes the file).
    explicit TraceRecorder(std::size_t keep = 0, std::FILE* csv = nullptr);
    // Starts recording every tick of `sim` (replaces its after-tick hook).
    void attach(Simulation& sim);
    void record(const engine::Positioner& ctl);

    const std::vector<TraceSample>& samples() const { return samples_; }
    std::int64_t rows() const { return rows_; }
    // The largest |following error| of axis 0 (X) / 1 (Z) over every row, mm.
    double maxAbsFollowingErrorMm(int axis) const {
        return maxError_[static_cast<std::size_t>(axis)];
    }
    bool writeFailed() const { return writeFailed_; }

private:
    std::size_t keep_;
    std::FILE* csv_;
    std::vector<TraceSample> samples_;
    TraceSample last_;
    bool haveLast_ = false;
    std::int64_t rows_ = 0;
    std::array<double, 2> maxError_{};
    bool writeFailed_ = false;
};

// machine::runProgram (machine/run.h) with every tick recorded by `trace`.
engine::RunResult runProgramTraced(const profile::MachineProfile& profile,
                                   const program::ProgramStore& programs, int number,
                                   const engine::RunOptions& options, TraceRecorder& trace);

} // namespace k528::machine
