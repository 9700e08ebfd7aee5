#include "engine/ideal_machine.h"
#include "engine/cparams.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace k528::engine {

namespace {

std::string key(AxisId a, const char* name) {
    return std::string(a == AxisId::X ? "x." : "z.") + name;
}

int sign(std::int64_t v, int fallback) {
    return v > 0 ? 1 : (v < 0 ? -1 : fallback);
}

int channelIndex(std::int64_t code) {
    return code >= 1 && code <= 4 ? static_cast<int>(code - 1) : -1;
}

} // namespace

axis::MechanicsSettings mechanicsOf(const profile::MachineProfile& p, AxisId a) {
    const profile::Settings& s = p.simulation;
    const axis::Constants k = axis::Constants::fromC(p.cValues(), a);
    axis::MechanicsSettings m;
    const double lead = s.getDouble(key(a, "screw_lead_mm"), 5.0);
    const double gear = s.getDouble(key(a, "gear_ratio"), 1.0);
    m.screwLeadMm = lead / (gear > 0 ? gear : 1.0);
    m.encoderLines = static_cast<int>(s.getInt(key(a, "encoder_lines"), 2500));
    const double volts = s.getDouble(key(a, "drive_max_volts"), 10.0);
    m.speedPerVoltMmPerMin =
        s.getDouble(key(a, "drive_max_speed_mm_per_min"), 10000.0) / (volts > 0 ? volts : 10.0);
    m.timeConstantMs = s.getDouble(key(a, "drive_time_constant_ms"), 10.0);
    // The drive's current limit must not be what limits the motion the
    // positioner asks for: twice УСКОРЕНИЕ 2 (as slide acceleration), at least 5 m/s².
    const double perSlide = k.scale.diameter ? 2.0 : 1.0;
    const double a2 = units::accelParamToMmPerS2(k.emergencyAccel(), k.scale) / perSlide;
    m.maxAccelMmPerS2 = std::max(5000.0, 2.0 * a2);
    m.brakeAccelMmPerS2 = std::max(8000.0, 2.0 * a2);
    m.encoderWiredInverted = k.encoderInvert; // ЗНАК ДОС compensates the wiring
    m.dacWiredInverted = k.dacInvert;
    return m;
}

AxisPlacement placeAxis(const profile::MachineProfile& p, AxisId a) {
    const profile::Settings& s = p.simulation;
    const axis::Constants k = axis::Constants::fromC(p.cValues(), a);
    const axis::MechanicsSettings m = mechanicsOf(p, a);
    AxisPlacement pl;
    pl.displayPerSlide = k.scale.diameter ? 2.0 : 1.0;
    const double discMm = k.scale.discreteMm();
    const auto slide = [&](std::int64_t disc) {
        return static_cast<double>(disc) * discMm / pl.displayPerSlide;
    };

    // The reference-point cycle (axis/homing.h) in reverse: the reference
    // point ЗНАЧЕНИЕ БТ is СМЕЩЕНИЕ БТ past the zero mark; the mark is found
    // searching from S до поиска 0-метки past the point where the axis left
    // the cam; the cam is left moving in the sign of S конечника БТ.
    const int dir = k.homeNegative ? -1 : 1;
    const int camDir = sign(k.decelCamDisc, dir);
    const int afterCamDir =
        k.beforeZeroSearchDisc != 0 ? sign(k.beforeZeroSearchDisc, camDir) : camDir;
    const int searchDir = sign(k.zeroSearchDisc, afterCamDir);
    pl.zeroMarkMm = slide(k.homeValueDisc - k.homeOffsetDisc);
    double searchMm = 0.3 * m.screwLeadMm; // the mark lies less than one revolution ahead
    if (k.zeroSearchDisc != 0)
        searchMm = std::min(searchMm, 0.5 * std::fabs(slide(k.zeroSearchDisc)));
    const double searchStart = pl.zeroMarkMm - searchDir * searchMm;
    const double leave = searchStart - slide(k.beforeZeroSearchDisc);
    double camLen = k.decelCamDisc != 0 ? 0.75 * std::fabs(slide(k.decelCamDisc)) : 3.0;
    camLen = s.getDouble(key(a, "decel_cam_mm"), camLen);
    if (camDir > 0) {
        pl.camLoMm = leave - camLen;
        pl.camHiMm = leave;
    } else {
        pl.camLoMm = leave;
        pl.camHiMm = leave + camLen;
    }
    // At power-on the slide stands 20 mm before the cam, inside the soft limits.
    const double nearEdge = dir > 0 ? pl.camLoMm : pl.camHiMm;
    pl.startMm = nearEdge - dir * 20.0;
    if (k.softMinusDisc < k.softPlusDisc) {
        const double lo = slide(k.softMinusDisc), hi = slide(k.softPlusDisc);
        if (hi - lo > 2.0)
            pl.startMm = std::clamp(pl.startMm, lo + 1.0, hi - 1.0);
    }
    if (s.has(key(a, "start_mm")))
        pl.startMm = s.getDouble(key(a, "start_mm"), 0) / pl.displayPerSlide;

    // Limit switches: 2 mm of slide beyond the travel (soft limits, cam, mark).
    double lo = std::min({pl.camLoMm, pl.zeroMarkMm, pl.startMm});
    double hi = std::max({pl.camHiMm, pl.zeroMarkMm, pl.startMm});
    if (k.softMinusDisc < k.softPlusDisc) {
        lo = std::min(lo, slide(k.softMinusDisc));
        hi = std::max(hi, slide(k.softPlusDisc));
    }
    pl.limitMinusMm = lo - 2.0;
    pl.limitPlusMm = hi + 2.0;
    if (s.has(key(a, "limit_minus_mm")))
        pl.limitMinusMm = s.getDouble(key(a, "limit_minus_mm"), 0) / pl.displayPerSlide;
    if (s.has(key(a, "limit_plus_mm")))
        pl.limitPlusMm = s.getDouble(key(a, "limit_plus_mm"), 0) / pl.displayPerSlide;
    return pl;
}

IdealMachine::IdealMachine(Positioner& controller) : c_(controller) {
    const profile::MachineProfile& p = c_.profile();
    const std::span<const std::int64_t> cv = c_.c();
    for (int i = 0; i < kAxisCount; ++i) {
        const AxisId a = axisAt(i);
        Axis& x = axes_[static_cast<std::size_t>(i)];
        x.present = profile::axisPresent(p, i == 0 ? catalog::Axis::X : catalog::Axis::Z);
        if (!x.present)
            continue;
        x.place = placeAxis(p, a);
        axis::MechanicsSettings m = mechanicsOf(p, a);
        m.zeroMarkPhaseMm = x.place.zeroMarkMm;
        m.startSlideMm = x.place.startMm;
        x.mech.emplace(m);
        x.encoderChannel = channelIndex(cv[c::ofAxis(c::EncoderChannelX, i)]);
        x.dacChannel = channelIndex(cv[c::ofAxis(c::DacChannelX, i)]);
    }
    for (int i = 0; i < kAxisCount; ++i) {
        Axis& x = axes_[static_cast<std::size_t>(i)];
        for (int n = 0; n < 8; ++n) {
            const std::int64_t fn = cv[c::fastInput(i, n)];
            const FastFunction f = fn >= 1 && fn < kFastFunctionCount
                                       ? static_cast<FastFunction>(fn)
                                       : FastFunction::None;
            x.inputFn[static_cast<std::size_t>(n)] = f;
            x.inputLevel[static_cast<std::size_t>(n)] = fastActiveLevel(i, f);
            if (f != FastFunction::None)
                x.wiredFunctions |= 1u << static_cast<unsigned>(f);
        }
    }
    wheelChannel_ = {channelIndex(cv[c::Handwheel1Channel]), channelIndex(cv[c::Handwheel2Channel])};
    const std::int64_t pulseMs = p.simulation.getInt("plc.pulse_ms", 20);
    pulseTicks_ =
        static_cast<int>(std::max<std::int64_t>(1, (pulseMs + c_.tickMs() - 1) / c_.tickMs()));
    mAckDelayMs_ = p.simulation.getInt("plc.m_ack_delay_ms", 40);
    sensors();
}

void IdealMachine::setJog(AxisId a, int dir, bool rapid) {
    ax(a).jogDir = dir > 0 ? 1 : (dir < 0 ? -1 : 0);
    ax(a).jogRapid = rapid;
}

void IdealMachine::setHandwheel(AxisId a, int wheel, bool on, bool multiplier, bool drf) {
    const std::size_t k = static_cast<std::size_t>(wheel - 1);
    ax(a).wheelOn[k] = on;
    ax(a).wheelMult[k] = multiplier;
    ax(a).wheelDrf[k] = drf;
}

void IdealMachine::setPlcAlarm(int k, bool on) {
    c_.words().setBit(ZBit{static_cast<std::uint16_t>(z::AlarmMessagesFirst + (k - 1) / 16),
                           static_cast<std::uint8_t>((k - 1) % 16)},
                      on);
}
void IdealMachine::setPlcWork(int k, bool on) {
    c_.words().setBit(ZBit{static_cast<std::uint16_t>(z::WorkMessagesFirst + (k - 1) / 16),
                           static_cast<std::uint8_t>((k - 1) % 16)},
                      on);
}
void IdealMachine::setPlcSystem(int k, bool on) {
    c_.words().setBit(
        ZBit{static_cast<std::uint16_t>(z::SystemMessagesWord), static_cast<std::uint8_t>(k - 1)},
        on);
}

double IdealMachine::slideMm(AxisId a) const {
    const Axis& x = axes_[static_cast<std::size_t>(axisIndex(a))];
    return x.mech ? x.mech->slideMm() : 0.0;
}
bool IdealMachine::camPressed(AxisId a) const {
    const double s = slideMm(a);
    const AxisPlacement& p = placement(a);
    return s >= p.camLoMm && s <= p.camHiMm;
}
bool IdealMachine::limitPlusPressed(AxisId a) const {
    return slideMm(a) >= placement(a).limitPlusMm;
}
bool IdealMachine::limitMinusPressed(AxisId a) const {
    return slideMm(a) <= placement(a).limitMinusMm;
}

void IdealMachine::sensors() {
    MachineIo& io = c_.io();
    // Pulse channels: encoders and handwheels as the constants wire them.
    for (const Axis& x : axes_) {
        if (!x.present || x.encoderChannel < 0)
            continue;
        PulseChannel& ch = io.pulse[static_cast<std::size_t>(x.encoderChannel)];
        ch.count = x.mech->encoderCount();
        ch.line1Ok = x.mech->channelOk(1);
        ch.line2Ok = x.mech->channelOk(2);
        ch.zeroMark = x.mech->zeroMarkCrossed();
        ch.zeroMarkCount = x.mech->zeroMarkCount();
    }
    for (int k = 0; k < 2; ++k)
        if (wheelChannel_[static_cast<std::size_t>(k)] >= 0)
            io.pulse[static_cast<std::size_t>(wheelChannel_[static_cast<std::size_t>(k)])].count =
                wheelCount_[static_cast<std::size_t>(k)];

    // Switches: through a fast input of that function, else the PLC bit.
    InterfaceWords& w = c_.words();
    for (int i = 0; i < kAxisCount; ++i) {
        const AxisId a = axisAt(i);
        const Axis& x = axes_[static_cast<std::size_t>(i)];
        const double s = x.present ? x.mech->slideMm() : 0.0;
        const bool cam = x.present && s >= x.place.camLoMm && s <= x.place.camHiMm;
        const bool limPlus = x.present && s >= x.place.limitPlusMm;
        const bool limMinus = x.present && s <= x.place.limitMinusMm;
        std::uint8_t inputs = 0;
        for (int n = 0; n < 8; ++n) {
            const FastFunction f = x.inputFn[static_cast<std::size_t>(n)];
            bool active = false;
            switch (f) {
            case FastFunction::DriveReady:
                active = x.present && x.driveReady;
                break;
            case FastFunction::LimitPlus:
                active = limPlus;
                break;
            case FastFunction::LimitMinus:
                active = limMinus;
                break;
            case FastFunction::DecelCam:
                active = cam;
                break;
            case FastFunction::Erase1:
            case FastFunction::Erase2:
            case FastFunction::Erase3:
            case FastFunction::Erase4:
                active = x.signal[static_cast<std::size_t>(static_cast<int>(f) -
                                                           static_cast<int>(FastFunction::Erase1))];
                break;
            case FastFunction::None:
                continue; // an unused input reads 0
            case FastFunction::Reset:
            case FastFunction::DisplayMode:
                active = false;
                break;
            }
            if (active == x.inputLevel[static_cast<std::size_t>(n)])
                inputs = static_cast<std::uint8_t>(inputs | (1u << n));
        }
        io.fastInputs[static_cast<std::size_t>(i)] = inputs;
        const auto wired = [&](FastFunction f) {
            return (x.wiredFunctions >> static_cast<unsigned>(f)) & 1u;
        };
        w.setBit(z::decelCam(a), cam && !wired(FastFunction::DecelCam));
        w.setBit(z::limitPlus(a), limPlus && !wired(FastFunction::LimitPlus));
        w.setBit(z::limitMinus(a), limMinus && !wired(FastFunction::LimitMinus));
        for (int n = 1; n <= 4; ++n)
            w.setBit(z::eraseSignal(a, n),
                     x.signal[static_cast<std::size_t>(n - 1)] &&
                         !wired(static_cast<FastFunction>(static_cast<int>(FastFunction::Erase1) +
                                                          n - 1)));
    }
}

void IdealMachine::plcScan() {
    InterfaceWords& w = c_.words();
    w.setBit(z::EmergencyStopOk, !estop_);
    w.setBit(z::FeedEnable, feedEnable_);
    w.setBit(z::StartEnable, startEnable_);
    w.setBit(z::Start, startPulse_ > 0);
    w.setBit(z::Stop, stopPulse_ > 0);
    w.setBit(z::Reset, resetPulse_ > 0);
    w.setBit(z::DataHold, dataHold_);
    w.setBit(z::AckFaults, ackPulse_ > 0);
    w.setField(z::ModeCodeWord, z::ModeCodeFirst, z::ModeCodeWidth,
               static_cast<unsigned>(modeCode_ & 7));
    countDown(startPulse_);
    countDown(stopPulse_);
    countDown(resetPulse_);
    countDown(ackPulse_);

    // M functions: acknowledge the strobe after the delay, drop with it.
    if (w.bit(z::MStrobe)) {
        if (strobeSince_ < 0)
            strobeSince_ = c_.timeMs();
        const bool due = autoAckM_ ? c_.timeMs() - strobeSince_ >= mAckDelayMs_ : manualAck_;
        if (due && !w.bit(z::MAcknowledge)) {
            w.setBit(z::MAcknowledge, true);
            mLog_.push_back(static_cast<int>(w.field(z::MCodeWord, z::MCodeFirst, z::MCodeWidth)));
            manualAck_ = false;
        }
    } else {
        strobeSince_ = -1;
        w.setBit(z::MAcknowledge, false);
    }

    // Z1001: cycles, R150, override.
    for (int n = 1; n <= 8; ++n) {
        int& pulse = cyclePulse_[static_cast<std::size_t>(n - 1)];
        w.setBit(z::startCycle(n), pulse > 0);
        countDown(pulse);
    }
    w.setBit(z::R150Bit, r150_);
    w.setBit(z::OverrideFromPlc, overrideCode_.has_value());
    if (overrideCode_)
        w.setField(z::OverrideCodeWord, z::OverrideCodeFirst, z::OverrideCodeWidth,
                   static_cast<unsigned>(std::clamp(*overrideCode_, 0, 10)));

    // Axis control words.
    for (int i = 0; i < kAxisCount; ++i) {
        const AxisId a = axisAt(i);
        const Axis& x = axes_[static_cast<std::size_t>(i)];
        w.setBit(z::loopOff(a), x.loopOff);
        w.setBit(z::regulatorEnable(a), x.present && x.regulator);
        w.setBit(z::axisFeedEnable(a), x.feed);
        w.setBit(z::accel2(a), x.accel2);
        w.setBit(z::jogPlus(a), x.jogDir > 0);
        w.setBit(z::jogMinus(a), x.jogDir < 0);
        w.setBit(z::rapid(a), x.jogRapid);
        for (int k = 1; k <= 2; ++k) {
            w.setBit(z::handwheelOn(a, k), x.wheelOn[static_cast<std::size_t>(k - 1)]);
            w.setBit(z::handwheelMult(a, k), x.wheelMult[static_cast<std::size_t>(k - 1)]);
            w.setBit(z::handwheelDrf(a, k), x.wheelDrf[static_cast<std::size_t>(k - 1)]);
        }
        w.setBit(z::encoderOn(a), x.present);
    }
}

void IdealMachine::tick() {
    plcScan();
    sensors();
    c_.tick();
    const MachineIo& io = c_.io();
    const double dt = static_cast<double>(c_.tickMs());
    for (int i = 0; i < kAxisCount; ++i) {
        Axis& x = axes_[static_cast<std::size_t>(i)];
        if (!x.present)
            continue;
        x.mech->setDacCode(x.dacChannel >= 0 ? io.dac[static_cast<std::size_t>(x.dacChannel)] : 0);
        x.mech->setDriveEnabled(io.regulatorEnable[static_cast<std::size_t>(i)] && x.driveReady);
        x.mech->tick(dt);
    }
}

void IdealMachine::advance(std::int64_t ms) {
    const std::int64_t ticks = (ms + c_.tickMs() - 1) / c_.tickMs();
    for (std::int64_t i = 0; i < ticks; ++i)
        tick();
}

bool IdealMachine::runUntil(const std::function<bool()>& done, std::int64_t maxMs) {
    const std::int64_t end = c_.timeMs() + maxMs;
    while (c_.timeMs() < end) {
        tick();
        if (done())
            return true;
    }
    return false;
}

} // namespace k528::engine
