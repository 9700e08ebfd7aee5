#include "engine/core.h"

#include "axis/servo.h"
#include "engine/coordinates.h"

#include <algorithm>

namespace k528::engine {

namespace {
// Faults of an axis' position loop and drive (axis::Fault, their messages
// on either axis): they stop both axes.
bool loopFault(int n) {
    for (int f = static_cast<int>(axis::Fault::RegulatorNotEnabled); f <= static_cast<int>(axis::Fault::EncoderStall);
         ++f)
        for (const AxisId a : {AxisId::X, AxisId::Z})
            if (axis::faultMessage(static_cast<axis::Fault>(f), a) == n)
                return true;
    return false;
}

axis::Constants constantsOf(const profile::MachineProfile& p, AxisId a) {
    return axis::Constants::fromC(p.cValues(), a);
}
} // namespace

Core::Core(const profile::MachineProfile& p)
    : profile(p), axes{AxisUnit(AxisId::X, constantsOf(p, AxisId::X)),
                       AxisUnit(AxisId::Z, constantsOf(p, AxisId::Z))} {
    std::copy(p.c.begin(), p.c.end(), c.begin());
    tickMs = std::clamp<std::int64_t>(p.simulation.getInt("tick_ms", 1), 1, 100);
    dtMs = static_cast<double>(tickMs);
    nestingLimit = static_cast<int>(std::clamp<std::int64_t>(
        p.simulation.getInt("nesting_limit", program::kDefaultNestingLimit), 1, 99));
    mhs.setLeadMs(p.simulation.getInt("m_code_lead_ms", 20));
    applyConstants();
}

void Core::applyConstants() {
    for (AxisUnit& a : axes)
        a.configure(axis::Constants::fromC(c, a.id));
    fast.configure(c);
    for (std::size_t k = 0; k < wheelChannel.size(); ++k) {
        const std::int64_t ch = c[c::handwheelChannel(static_cast<int>(k))];
        wheelChannel[k] = ch >= 1 && ch <= kPulseChannels ? static_cast<int>(ch - 1) : -1;
    }
}

std::uint8_t Core::exclusion(int a) const {
    if (programActive(state))
        return programExclusion;
    const std::uint16_t w = words.axisControl(a, 1);
    return static_cast<std::uint8_t>((w >> 4) & 0x0F); // Z1006.4..7 = G50..G53
}

std::int64_t Core::offsetDisc(int a) const {
    return activeOffset(components(r, a), exclusion(a));
}

std::int64_t Core::currentDisc(int a) const {
    return axes[static_cast<std::size_t>(a)].machineDisc() - offsetDisc(a);
}

void Core::stopAllMotion() {
    for (std::size_t i = 0; i < axes.size(); ++i) {
        AxisUnit& a = axes[i];
        if (!a.present)
            continue;
        if (osc[i].active())
            osc[i].abort(a.servo);
        if (a.homing.running())
            a.homing.cancel(a.servo);
        if (a.servo.moving())
            a.servo.stop();
        a.owner = MotionOwner::None;
        a.jogDir = 0;
    }
}

void Core::abortProgram(ProgramState to) {
    for (std::size_t i = 0; i < axes.size(); ++i) {
        AxisUnit& a = axes[i];
        if (osc[i].active())
            osc[i].abort(a.servo);
        if (programMotion(a.owner)) {
            if (a.servo.moving())
                a.servo.stop();
            a.owner = MotionOwner::None;
        }
        a.eraseSignal = 0;
        a.resumeMove = a.resumeWheel = false;
    }
    mhs.cancel(words);
    stopHold = false;
    state = to;
    programEndMs = nowMs;
}

void Core::raise(int n, int program, int line, bool active) {
    alarms.raise(n, active, program, line);
    if (programActive(state))
        abortProgram(ProgramState::Alarm);
    if (loopFault(n))
        stopAllMotion();
}

void Core::conditionChanged(int n, bool on) {
    if (!on) {
        alarms.clear(n);
        return;
    }
    raise(n, 0, 0, true);
}

} // namespace k528::engine
