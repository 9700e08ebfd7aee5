// Oscillation of one axis (table 5, Gx81 / Gx80; presets of screen УСТ 7,
// R184..R191 for X, R192..R199 for Z):
//
//   Gx81 starts it: the axis travels between two reverse points at the
//   oscillation speed while the program goes on with the next frames.
//   At each reverse point it waits ЗАДЕРЖКА РЕВЕРСА (R187/R195, ms). With
//   -/+РЕВЕРС ТОЧНО (R188/R189, R196/R197) = 1 it reverses only once it
//   stands inside ДОПУСК ПОЗ at that point; with 0 as soon as its setpoint
//   arrives (the following error is not waited for).
//   Gx80 asks it to stop: after the stroke in progress it makes ХОДЫ
//   ВЫХАЖИВАНИЯ (R191/R199) full strokes, then goes on to the ТОЧКА
//   ЗАВЕРШЕНИЯ (R190/R198: 0 = the reverse point where the spark-out ends,
//   1 = the "-" point, 2 = the "+" point) and stops there. The frame with
//   Gx80 waits for the stop.
#pragma once

#include "axis/servo.h"

#include <cstdint>

namespace k528::engine {

struct OscillationPresets {
    std::int64_t reverseDelayMs = 0;
    bool exactMinus = false, exactPlus = false;
    int endPoint = 0; // 0 any, 1 "-", 2 "+"
    int sparkOut = 0; // full strokes after Gx80
};

class Oscillation {
public:
    enum class Phase : std::uint8_t { Off, Travel, Reverse, Paused };

    // Starts between `lo` and `hi` (internal units, machine system), first
    // towards hi if `towardsHi`. False if the servo refused the move.
    bool start(axis::Servo& s, double lo, double hi, double speed, bool towardsHi,
               const OscillationPresets& p);
    // Gx80: spark-out strokes and end point are taken from `p` now.
    void requestStop(const OscillationPresets& p);
    // Ends at once (reset, alarm, end of program): the axis decelerates.
    void abort(axis::Servo& s);
    // A mode change stops the axis; resume() goes on towards the same point.
    void pause(axis::Servo& s);
    bool resume(axis::Servo& s);
    // After the servo's tick.
    void tick(axis::Servo& s, double dtMs);

    bool active() const { return phase_ != Phase::Off; }
    bool stopRequested() const { return stopRequested_; }
    Phase phase() const { return phase_; }
    int strokes() const { return strokes_; } // reverse points reached since start
    double lo() const { return lo_; }
    double hi() const { return hi_; }
    double speed() const { return speed_; }

private:
    bool arrived(const axis::Servo& s) const;
    void atReversePoint(axis::Servo& s);
    bool move(axis::Servo& s);

    Phase phase_ = Phase::Off;
    double lo_ = 0, hi_ = 0, speed_ = 0;
    bool towardsHi_ = true;
    OscillationPresets p_;
    double waitMs_ = 0;
    bool stopRequested_ = false, counting_ = false;
    int sparkLeft_ = 0, strokes_ = 0;
};

} // namespace k528::engine
