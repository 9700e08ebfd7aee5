// A servo coupled to its mechanics, ticked at 1 ms: the closed loop of one
// axis as the engine runs it. Constants of appendix Ж (grinder 205), axis Z.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>

#include "axis/mechanics.h"
#include "axis/servo.h"

namespace k528::testrig {

// Appendix Ж, table Ж.1, C53..C100 (axis Z), written out independently.
inline axis::Constants grinderZ() {
    std::array<std::int64_t, 153> c{};
    const std::int64_t z[] = {1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 3, 2, 1, 2, 2500, 4445, 17780, 0, 5,
                              131, 13, 2395, 2047, 1000, 10, 800, 20, 0, 0, 400, 0, 0, 0, 500000, 600000, 500000,
                              5000, 500, 190000, -1000, 200000, 0};
    for (int i = 0; i < 48; ++i)
        c[static_cast<std::size_t>(53 + i)] = z[i];
    return axis::Constants::fromC(c, axis::AxisId::Z);
}

// Mechanics of the grinder's Z: 5 mm per motor revolution, 2500 lines,
// 5 V at 10 m/min (2000 mm/min per volt), 4 ms speed-loop lag.
inline axis::MechanicsSettings grinderZMechanics() {
    axis::MechanicsSettings m;
    m.screwLeadMm = 5.0;
    m.encoderLines = 2500;
    m.speedPerVoltMmPerMin = 2000.0;
    m.timeConstantMs = 4.0;
    m.maxAccelMmPerS2 = 3000.0;
    m.startSlideMm = 100.0;
    return m;
}

struct AxisLoop {
    axis::Servo servo;
    axis::Mechanics mech;
    axis::ServoInputs in;
    std::int64_t timeMs = 0;
    double maxAbsError = 0;

    explicit AxisLoop(const axis::Constants& k = grinderZ(),
                      const axis::MechanicsSettings& m = grinderZMechanics())
        : servo(axis::AxisId::Z, k), mech(m) {
        step(); // first contact: an incremental encoder reads 0 at power-on
        // As after the reference-point cycle: machine system = slide position.
        servo.setActualValue(mm(m.startSlideMm));
    }

    void step() {
        in.encoderCount = mech.encoderCount();
        in.channel1Ok = mech.channelOk(1);
        in.channel2Ok = mech.channelOk(2);
        in.zeroMark = mech.zeroMarkCrossed();
        in.zeroMarkCount = mech.zeroMarkCount();
        servo.tick(in, 1.0);
        mech.setDacCode(servo.dac());
        mech.setDriveEnabled(servo.regulatorOn());
        mech.tick(1.0);
        ++timeMs;
        if (servo.moving())
            maxAbsError = std::max(maxAbsError, std::fabs(servo.followingError()));
    }
    // Runs until `done` or `limitMs`; returns the ms it took (or -1).
    std::int64_t runUntil(const std::function<bool()>& done, std::int64_t limitMs) {
        const std::int64_t t0 = timeMs;
        while (timeMs - t0 < limitMs) {
            step();
            if (done())
                return timeMs - t0;
        }
        return -1;
    }
    void run(std::int64_t ms) {
        for (std::int64_t i = 0; i < ms; ++i)
            step();
    }
    // mm <-> internal units of Z (0.001 mm discrete, radius: 2000 per mm)
    static double mm(double v) { return v * 2000.0; }
};

} // namespace k528::testrig
