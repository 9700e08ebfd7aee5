#include "machine/simulation.h"
#include "engine/cparams.h"

#include "catalog/messages.h"
#include "engine/rparams.h"
#include "plc/description.h"
#include "profile/builtin.h"
#include "util/json.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace k528::machine {

namespace {

constexpr std::string_view kFaultNames[kFaultCount] = {"encoder_channel_break",
                                                       "drive_not_ready",
                                                       "limit_switch",
                                                       "emergency_stop",
                                                       "dac_limit",
                                                       "plc_module_failure",
                                                       "lost_link",
                                                       "spindle_drive",
                                                       "spindle_overheat",
                                                       "pump_overload",
                                                       "chuck_pressure",
                                                       "turret_jam",
                                                       "gauge_fault",
                                                       "positioner_module",
                                                       "k923",
                                                       "plc_stopped"};

int channelIndex(std::int64_t code) {
    return code >= 1 && code <= 4 ? static_cast<int>(code - 1) : -1;
}

const char* axisLetter(AxisId a) {
    return a == AxisId::X ? "X" : "Z";
}

bool axisFault(Fault f) {
    return f == Fault::EncoderChannelBreak || f == Fault::DriveNotReady ||
           f == Fault::LimitSwitch || f == Fault::DacLimit;
}

} // namespace

std::string_view faultName(Fault f) {
    return kFaultNames[static_cast<int>(f)];
}

FaultText faultText(const FaultSpec& f) {
    const std::string ax = axisLetter(f.axis);
    const std::string id(faultName(f.kind));
    switch (f.kind) {
    case Fault::EncoderChannelBreak:
        return {id, {ax, std::to_string(f.detail)}};
    case Fault::DriveNotReady:
    case Fault::DacLimit:
        return {id, {ax}};
    case Fault::LimitSwitch:
        return {id, {ax, f.detail < 0 ? "-" : "+"}};
    case Fault::PlcModuleFailure:
        return {id, {std::to_string(f.detail)}};
    case Fault::SpindleDrive:
    case Fault::SpindleOverheat:
    case Fault::PumpOverload:
        return {id, {f.equipment}, true};
    case Fault::PositionerModule: {
        static constexpr std::string_view parts[] = {"?",           "pulse_module_1", "pulse_module_2",
                                                     "dac_module",  "comm_module",    "panel_link",
                                                     "memory"};
        const int d = f.detail >= 1 && f.detail <= kPositionerPartCount ? f.detail : 0;
        return {id + "." + std::string(parts[d]), {}};
    }
    case Fault::K923: {
        static constexpr std::string_view parts[] = {"?", "plc_link", "positioner_link", "ram",
                                                     "resident"};
        const int d = f.detail >= 1 && f.detail <= kK923PartCount ? f.detail : 0;
        return {id + "." + std::string(parts[d]), {}};
    }
    case Fault::EmergencyStop:
    case Fault::LostLink:
    case Fault::ChuckPressure:
    case Fault::TurretJam:
    case Fault::GaugeFault:
    case Fault::PlcStopped:
        break;
    }
    return {id, {}};
}

std::string describeFault(const FaultSpec& f, bool russian) { return faultTextIn(faultText(f), russian); }

// ---------------------------------------------------------------------------
// Construction

plc::MachineDescription Simulation::descriptionFor(const profile::MachineProfile& p) {
    if (const auto m = p.simulation.find("machine"); m && !m->empty())
        return plc::loadDescription(*m);
    if (plc::descriptionExists(p.name))
        return plc::loadDescription(p.name);
    return plc::loadDescription("generic");
}

Simulation::Simulation(const profile::MachineProfile& profile) {
    build(profile, descriptionFor(profile));
}

Simulation::Simulation(const profile::MachineProfile& profile,
                       const plc::MachineDescription& description) {
    build(profile, description);
}

Simulation::Simulation(std::string_view profileNameOrPath) {
    const profile::MachineProfile p = profile::load(profileNameOrPath);
    build(p, descriptionFor(p));
}

Simulation::~Simulation() = default;

void Simulation::build(const profile::MachineProfile& p, const plc::MachineDescription& d) {
    ctl_ = std::make_unique<engine::Positioner>(p);
    const std::span<const std::int64_t> cv = ctl_->c();

    // Equipment first (its signals), then the axes' and the drives' signals.
    const Json noEquipment = Json::object(); // a description not read from a document
    eq_ = buildEquipment(
        plc::JsonNode(d.equipment ? *d.equipment : noEquipment, d.source, "equipment"), signals_);
    drivesPowerAct_ = signals_.addActuator("drives.power", "feed drives main contactor");
    drivesOnSig_ = signals_.addSensor("drives.on", "feed drives main contactor closed");
    for (int i = 0; i < engine::kAxisCount; ++i) {
        const AxisId a = engine::axisAt(i);
        AxisPlant& x = axes_[static_cast<std::size_t>(i)];
        const std::string n = i == 0 ? "x" : "z";
        x.camSig =
            signals_.addSensor(n + ".cam", "deceleration cam before the reference point pressed");
        x.limPlusSig = signals_.addSensor(n + ".limit_plus", "limit switch + hit");
        x.limMinusSig = signals_.addSensor(n + ".limit_minus", "limit switch - hit");
        x.readySig = signals_.addSensor(n + ".drive_ready", "feed drive ready");
        x.present = profile::axisPresent(p, i == 0 ? catalog::Axis::X : catalog::Axis::Z);
        if (x.present) {
            x.place = engine::placeAxis(p, a);
            axis::MechanicsSettings m = engine::mechanicsOf(p, a);
            m.zeroMarkPhaseMm = x.place.zeroMarkMm;
            m.startSlideMm = x.place.startMm;
            x.mech.emplace(m);
            x.encoderChannel = channelIndex(cv[engine::c::ofAxis(engine::c::EncoderChannelX, i)]);
            x.dacChannel = channelIndex(cv[engine::c::ofAxis(engine::c::DacChannelX, i)]);
        }
        for (int k = 0; k < 8; ++k) {
            const std::int64_t fn = cv[engine::c::fastInput(i, k)];
            const engine::FastFunction f = fn >= 1 && fn < engine::kFastFunctionCount
                                               ? static_cast<engine::FastFunction>(fn)
                                               : engine::FastFunction::None;
            x.inputFn[static_cast<std::size_t>(k)] = f;
            x.inputLevel[static_cast<std::size_t>(k)] = engine::fastActiveLevel(i, f);
        }
    }
    wheelChannel_ = {channelIndex(cv[engine::c::Handwheel1Channel]), channelIndex(cv[engine::c::Handwheel2Channel])};

    // The grinding wheel as the setter left it: R207 its diameter, R204 a new one.
    if (eq_.grinding) {
        Grinding::Settings gs = eq_.grinding->settings();
        const units::AxisScale sx = profile::axisScale(p, catalog::Axis::X);
        const double disc = sx.discreteMm();
        if (const auto it = p.r.find(engine::r::WheelCurrent); it != p.r.end())
            gs.wheelMm = static_cast<double>(it->second) * disc;
        if (const auto it = p.r.find(engine::r::WheelNew); it != p.r.end()) {
            const double r204 = static_cast<double>(it->second) * disc;
            if (std::fabs(r204 - gs.newWheelMm) > 1e-9)
                warnings_.push_back("R204 (new wheel " + json::formatDouble(r204) +
                                    " mm) differs from the machine's new wheel (" +
                                    json::formatDouble(gs.newWheelMm) + " mm)");
        }
        // Machine X is the edge's diameter when the wheel has the diameter it
        // had when the dressing sum R224 was zero.
        double r224 = 0;
        if (const auto it = p.r.find(engine::r::DressingSumX); it != p.r.end())
            r224 = static_cast<double>(it->second) * disc;
        eq_.grinding->setWheel(gs.wheelMm, gs.wheelMm + r224);
    }

    // The PLC and its wiring.
    plc_ = std::make_unique<plc::Plc>(d);
    const auto listOf = [](const std::vector<Signals::Entry>& v) {
        std::string s;
        for (const Signals::Entry& e : v)
            s += (s.empty() ? "" : ", ") + e.name;
        return s;
    };
    for (int i = 0; i < plc_->inputCount(); ++i) {
        const plc::InputDef& in = d.inputs[static_cast<std::size_t>(i)];
        const auto s = signals_.findSensor(in.signal);
        if (!s)
            throw plc::DescriptionError(d.source, in.path + ".signal",
                                        profile::problem("signal.not-sensor", {in.signal, listOf(signals_.sensorList())}));
        inputs_.push_back({i, *s, in.normallyClosed});
    }
    for (int i = 0; i < plc_->outputCount(); ++i) {
        const plc::OutputDef& out = d.outputs[static_cast<std::size_t>(i)];
        const auto s = signals_.findActuator(out.signal);
        if (!s)
            throw plc::DescriptionError(
                d.source, out.path + ".signal",
                profile::problem("signal.not-actuator", {out.signal, listOf(signals_.actuatorList())}));
        for (const Wire& w : outputs_)
            if (w.signal == *s)
                throw plc::DescriptionError(d.source, out.path + ".signal",
                                            profile::problem("signal.driven-twice", {out.signal}));
        outputs_.push_back({i, *s, false});
    }

    // PLC message texts come from the profile ([plc-messages]).
    std::set<int> alarms, work;
    for (const plc::MessageDef& m : d.alarms)
        alarms.insert(m.k);
    for (const plc::MessageDef& m : d.work)
        work.insert(m.k);
    for (const plc::InterlockDef& il : d.interlocks) {
        if (il.alarm)
            alarms.insert(il.alarm);
        if (il.work)
            work.insert(il.work);
    }
    for (const plc::MFunctionDef& f : d.mFunctions) {
        if (f.waitWork)
            work.insert(f.waitWork);
        if (f.timeoutAlarm)
            alarms.insert(f.timeoutAlarm);
    }
    if (d.unknownM.alarm)
        alarms.insert(d.unknownM.alarm);
    for (int k : alarms)
        if (!p.plcAlarm.count(k))
            warnings_.push_back(d.source + " raises machine alarm " + std::to_string(k) + " (" +
                                catalog::plcMessageAddress(catalog::PlcGroup::Alarm, k) +
                                "), which has no text A" + (k < 10 ? "0" : "") + std::to_string(k) +
                                " in profile " + p.name);
    for (int k : work)
        if (!p.plcWork.count(k))
            warnings_.push_back(d.source + " shows work message " + std::to_string(k) + " (" +
                                catalog::plcMessageAddress(catalog::PlcGroup::Work, k) +
                                "), which has no text W" + (k < 10 ? "0" : "") + std::to_string(k) +
                                " in profile " + p.name);
    for (const plc::ModuleDef& m : d.modules)
        if (!p.plcSystem.count(m.place + 1))
            warnings_.push_back("module place " + std::to_string(m.place) +
                                " has no system message text S" + (m.place < 9 ? "0" : "") +
                                std::to_string(m.place + 1) + " in profile " + p.name);

    senseDrives(0);
}

// ---------------------------------------------------------------------------
// Time

void Simulation::powerOn() {
    ctl_->powerOn();
}

// The sensors of the drives and the axes: the drives' contactor and ready
// contacts, the axis switches (readPlant looks at these when a fault changed
// an axis, the PLC switched the contactor or the ready delay runs).
void Simulation::senseDrives(std::int64_t nowMs) {
    const bool power = signals_.actuator(drivesPowerAct_);
    if (power && drivesPowerSinceMs_ < 0)
        drivesPowerSinceMs_ = nowMs;
    else if (!power)
        drivesPowerSinceMs_ = -1;
    signals_.setSensor(drivesOnSig_, power);
    const bool powered =
        power && nowMs - drivesPowerSinceMs_ >= static_cast<std::int64_t>(eq_.drivesReadyDelayMs);
    for (AxisPlant& x : axes_) {
        // No drive: its ready contact is bridged in the cabinet.
        x.ready = x.present ? powered && !x.driveFault : powered;
        signals_.setSensor(x.readySig, x.ready);
        if (x.present)
            senseSwitches(x);
    }
    sensedPower_ = power;
    sensedDelayMs_ = eq_.drivesReadyDelayMs;
    // While the ready delay runs, time alone changes the ready contacts.
    senseAll_ = power && !powered;
}

// The cam and the limit switches of a present axis at its slide's position,
// and the stretch of positions around it that passes no switch point.
void Simulation::senseSwitches(AxisPlant& x) {
    const double s = x.mech->slideMm();
    const engine::AxisPlacement& p = x.place;
    signals_.setSensor(x.camSig, s >= p.camLoMm && s <= p.camHiMm);
    signals_.setSensor(x.limPlusSig, s >= p.limitPlusMm || x.stuckLimit > 0);
    signals_.setSensor(x.limMinusSig, s <= p.limitMinusMm || x.stuckLimit < 0);
    // Every switch compares s with one of these points (>= or <=): on either
    // side of all of them the readings stay. On a point (or not a number)
    // the stretch is empty and the next tick looks again.
    double lo = -HUGE_VAL, hi = HUGE_VAL;
    for (const double t : {p.camLoMm, p.camHiMm, p.limitPlusMm, p.limitMinusMm}) {
        if (t < s)
            lo = std::max(lo, t);
        else if (t > s)
            hi = std::min(hi, t);
        else
            lo = hi = s;
    }
    x.switchLoMm = lo;
    x.switchHiMm = hi;
}

// The health of the positioner's modules and the PLC link (faults), and the
// channels the plant writes, which a failed module or a fault changes.
void Simulation::refreshIoWiring() {
    engine::MachineIo& io = ctl_->io();
    const auto broken = [&](PositionerPart p) {
        return (brokenParts_ >> (static_cast<int>(p) - 1)) & 1u;
    };
    // A failed CP34.23 counts no more: both its channels stand still.
    const auto live = [&](int channel) {
        return channel >= 0 &&
               !broken(channel < 2 ? PositionerPart::PulseModule1 : PositionerPart::PulseModule2);
    };
    io.pulseModule1Ok = !broken(PositionerPart::PulseModule1);
    io.pulseModule2Ok = !broken(PositionerPart::PulseModule2);
    io.dacModuleOk = !broken(PositionerPart::DacModule);
    io.commModuleOk = !broken(PositionerPart::CommModule);
    io.panelLinkOk = !broken(PositionerPart::PanelLink);
    io.memoryOk = !broken(PositionerPart::Memory);
    io.plcLinkOk = !lostLink_;
    for (AxisPlant& x : axes_) {
        x.encoderOut = x.present && live(x.encoderChannel) ? x.encoderChannel : -1;
        x.dacIn = io.dacModuleOk ? x.dacChannel : -1; // a failed CM32.03 gives 0 V
    }
    wheelOverEncoder_ = false;
    for (std::size_t k = 0; k < 2; ++k) {
        wheelOut_[k] = live(wheelChannel_[k]) ? wheelChannel_[k] : -1; // the pendant is always there
        for (const AxisPlant& x : axes_)
            wheelOverEncoder_ = wheelOverEncoder_ || (wheelOut_[k] >= 0 && wheelOut_[k] == x.encoderOut);
    }
}

// Every input of the positioner from the plant: after a fault, which may
// change any of them or their wiring.
void Simulation::writeAllInputs() {
    ioStale_ = false;
    refreshIoWiring();
    engine::MachineIo& io = ctl_->io();
    for (const AxisPlant& x : axes_) {
        if (x.encoderOut < 0)
            continue;
        engine::PulseChannel& ch = io.pulse[static_cast<std::size_t>(x.encoderOut)];
        ch.count = x.mech->encoderCount() + x.glitchCounts;
        ch.line1Ok = x.mech->channelOk(1);
        ch.line2Ok = x.mech->channelOk(2);
        ch.zeroMark = x.mech->zeroMarkCrossed();
        ch.zeroMarkCount = x.mech->zeroMarkCount() + x.glitchCounts;
    }
    eq_.pendant->takeWheelTurned();
    writeHandwheels(io);
}

// After the encoders: a handwheel wired to an encoder's channel wins.
void Simulation::writeHandwheels(engine::MachineIo& io) const {
    for (std::size_t k = 0; k < 2; ++k)
        if (wheelOut_[k] >= 0)
            io.pulse[static_cast<std::size_t>(wheelOut_[k])].count =
                eq_.pendant->wheelCount(static_cast<int>(k) + 1);
}

// The inputs that follow the sensors: the fast inputs of both CP34.23
// modules (as C107..C122 wire them) and the PLC's input terminals.
void Simulation::writeSensorInputs() {
    engine::MachineIo& io = ctl_->io();
    for (int i = 0; i < engine::kAxisCount; ++i) {
        const AxisPlant& x = axes_[static_cast<std::size_t>(i)];
        std::uint8_t inputs = 0;
        for (int n = 0; n < 8; ++n) {
            const engine::FastFunction f = x.inputFn[static_cast<std::size_t>(n)];
            bool active = false;
            switch (f) {
            case engine::FastFunction::None:
                continue; // an unused input reads 0
            case engine::FastFunction::Reset:
                active = signals_.sensor(eq_.resetSource);
                break;
            case engine::FastFunction::DisplayMode:
                active = false;
                break;
            case engine::FastFunction::DriveReady:
                active = signals_.sensor(x.readySig);
                break;
            case engine::FastFunction::LimitPlus:
                active = signals_.sensor(x.limPlusSig);
                break;
            case engine::FastFunction::LimitMinus:
                active = signals_.sensor(x.limMinusSig);
                break;
            case engine::FastFunction::DecelCam:
                active = signals_.sensor(x.camSig);
                break;
            case engine::FastFunction::Erase1:
            case engine::FastFunction::Erase2:
            case engine::FastFunction::Erase3:
            case engine::FastFunction::Erase4:
                active = signals_.sensor(
                    eq_.eraseSource[static_cast<std::size_t>(i)][static_cast<std::size_t>(
                        static_cast<int>(f) - static_cast<int>(engine::FastFunction::Erase1))]);
                break;
            }
            if (active == x.inputLevel[static_cast<std::size_t>(n)])
                inputs = static_cast<std::uint8_t>(inputs | (1u << n));
        }
        io.fastInputs[static_cast<std::size_t>(i)] = inputs;
    }
    for (const Wire& w : inputs_)
        plc_->setInput(w.plcIndex, signals_.sensor(w.signal) != w.inverted);
}

// Steps 1 and 2 of a tick: the sensors of the axes and drives and the
// positioner's inputs from the plant as the last tick left it — the same as
// looking at all of them, looking only where something can have changed.
inline void Simulation::readPlant(std::int64_t nowMs) {
    if (senseAll_ || eq_.drivesReadyDelayMs != sensedDelayMs_)
        senseDrives(nowMs);
    if (ioStale_)
        writeAllInputs();
    engine::MachineIo& io = ctl_->io();
    bool encoders = false;
    for (AxisPlant& x : axes_) {
        if (!x.present)
            continue;
        // The drives' contacts read as they did: only a slide that left the
        // stretch between its switch points can change a switch.
        const double s = x.mech->slideMm();
        if (!(s > x.switchLoMm && s < x.switchHiMm))
            senseSwitches(x);
        // An encoder's outputs change only in a tick of its drive that was
        // not quiet, and then only the count and the zero mark: the line
        // monitoring changes with a fault (writeAllInputs).
        if (x.encoderOut >= 0 && !x.mech->quiet()) {
            engine::PulseChannel& ch = io.pulse[static_cast<std::size_t>(x.encoderOut)];
            ch.count = x.mech->encoderCount() + x.glitchCounts;
            ch.zeroMark = x.mech->zeroMarkCrossed();
            if (ch.zeroMark) // a mark's count is new only with the mark
                ch.zeroMarkCount = x.mech->zeroMarkCount() + x.glitchCounts;
            encoders = true;
        }
    }
    if (eq_.pendant->takeWheelTurned() || (encoders && wheelOverEncoder_))
        writeHandwheels(io);
    if (signals_.takeChanged())
        writeSensorInputs();
}

// Step 5: the positioner's outputs to the drives and slides, the PLC's
// outputs to the equipment; time advances by dtMs.
inline void Simulation::actuate(double dtMs) {
    const engine::MachineIo& io = ctl_->io();
    for (int i = 0; i < engine::kAxisCount; ++i) {
        AxisPlant& x = axes_[static_cast<std::size_t>(i)];
        if (!x.present)
            continue;
        x.mech->setDacCode(x.dacIn >= 0 ? io.dac[static_cast<std::size_t>(x.dacIn)] : 0);
        x.mech->setDriveEnabled(io.regulatorEnable[static_cast<std::size_t>(i)] && x.ready);
        x.mech->tick(dtMs);
    }
    if (signals_.takeEquipmentAwake()) {
        for (auto& s : eq_.spindles)
            s->tick(dtMs);
        for (auto& p : eq_.pumps)
            p->tick(dtMs);
        if (eq_.chuck)
            eq_.chuck->tick(dtMs);
        if (eq_.turret)
            eq_.turret->tick(dtMs);
        if (eq_.door)
            eq_.door->tick();
    }
    if (eq_.grinding)
        eq_.grinding->tick(dtMs, machineMm(AxisId::X), machineMm(AxisId::Z));
}

void Simulation::tick() {
    if (!ctl_->poweredOn())
        ctl_->powerOn();
    const std::int64_t now = ctl_->timeMs();
    if (!releases_.empty()) {
        for (std::size_t i = 0; i < releases_.size();) {
            if (releases_[i].atMs <= now) {
                const Button b = releases_[i].button;
                releases_.erase(releases_.begin() + static_cast<std::ptrdiff_t>(i));
                eq_.pendant->release(b, now);
            } else {
                ++i;
            }
        }
    }
    eq_.pendant->tick(now);
    readPlant(now);
    engine::InterfaceWords& w = ctl_->words();
    if (!lostLink_)
        plc_->readPositioner(w);
    if (plc_->scanDue(now)) {
        plc_->scan(now);
        for (const Wire& o : outputs_)
            signals_.setActuator(o.signal, plc_->output(o.plcIndex));
        // The drives' contactor is one of them (senseDrives).
        if (signals_.actuator(drivesPowerAct_) != sensedPower_)
            senseAll_ = true;
        if (!lostLink_)
            plc_->writePositioner(w);
    }
    ctl_->tick();
    actuate(static_cast<double>(ctl_->tickMs()));
    if (afterTick_)
        afterTick_();
    for (const auto& o : tickObservers_)
        o.second();
}

int Simulation::addTickObserver(std::function<void()> f) {
    tickObservers_.emplace_back(nextObserver_, std::move(f));
    return nextObserver_++;
}

void Simulation::removeTickObserver(int id) {
    std::erase_if(tickObservers_, [id](const auto& o) { return o.first == id; });
}

void Simulation::advance(std::int64_t ms) {
    const std::int64_t ticks = (ms + tickMs() - 1) / tickMs();
    for (std::int64_t i = 0; i < ticks; ++i)
        tick();
}

bool Simulation::runUntil(const std::function<bool()>& done, std::int64_t maxMs) {
    const std::int64_t end = timeMs() + maxMs;
    while (timeMs() < end) {
        tick();
        if (done())
            return true;
    }
    return false;
}

// ---------------------------------------------------------------------------
// The operator

void Simulation::press(Button b) {
    eq_.pendant->press(b, timeMs());
}

void Simulation::release(Button b) {
    eq_.pendant->release(b, timeMs());
    releases_.erase(std::remove_if(releases_.begin(), releases_.end(),
                                   [b](const TimedRelease& r) { return r.button == b; }),
                    releases_.end());
}

void Simulation::pressFor(Button b, std::int64_t ms) {
    press(b);
    releases_.push_back({b, timeMs() + std::max<std::int64_t>(ms, 1)});
}

bool Simulation::buttonDown(Button b) const {
    return eq_.pendant->down(b);
}

void Simulation::pressEmergencyStop() {
    eq_.pendant->setEmergencyStop(true);
}

void Simulation::releaseEmergencyStop() {
    eq_.pendant->setEmergencyStop(false);
}

bool Simulation::emergencyStopPressed() const {
    return eq_.pendant->emergencyStop();
}

bool Simulation::hasHandwheel() const {
    return eq_.pendant->settings().handwheel;
}

void Simulation::selectHandwheel(HandwheelAxis a) {
    eq_.pendant->selectWheelAxis(a);
}

void Simulation::selectHandwheelMultiplier(int step) {
    eq_.pendant->selectWheelMultiplier(step);
}

void Simulation::turnHandwheel(std::int64_t detents) {
    eq_.pendant->turn(detents);
}

std::int64_t Simulation::handwheelDiscretesPerDetent(int step) const {
    const Pendant& p = *eq_.pendant;
    const AxisId a = p.wheelAxis() == HandwheelAxis::Z ? AxisId::Z : AxisId::X;
    const int i = engine::axisIndex(a);
    const int wheel = p.settings().wheelOfAxis[static_cast<std::size_t>(i)];
    step = std::clamp(step, 0, 2);
    const axis::Constants k = axis::Constants::fromC(ctl_->c(), a);
    const std::int64_t mult = step == 0 ? 1 : (wheel == 1 ? k.handwheel1Mult : k.handwheel2Mult);
    // One pulse is one discrete of motion: 2 internal units.
    const std::int64_t internal =
        2 * mult * p.settings().pulsesPerDetent[static_cast<std::size_t>(step)];
    return internal / std::max<std::int64_t>(1, k.scale.internalPerDisc());
}

bool Simulation::hasOverrideSwitch() const {
    return eq_.pendant->settings().overrideSwitch;
}

void Simulation::setOverrideSwitch(int code) {
    eq_.pendant->setOverride(code);
}

int Simulation::overrideSwitch() const {
    return eq_.pendant->overrideCode();
}

bool Simulation::openDoor() {
    return eq_.door && eq_.door->open();
}

void Simulation::closeDoor() {
    if (eq_.door)
        eq_.door->close();
}

bool Simulation::changeWheel() {
    if (!eq_.grinding)
        return false;
    if (const Spindle* w = eq_.spindle("wheel"); w && std::fabs(w->rpm()) > 0)
        return false;
    eq_.grinding->changeWheel();
    const units::AxisScale sx = profile::axisScale(profile(), catalog::Axis::X);
    const auto disc =
        static_cast<std::int64_t>(std::llround(eq_.grinding->wheelDiameterMm() / sx.discreteMm()));
    ctl_->setR(engine::r::WheelCurrent, disc);
    // The dressing sum belongs to the old wheel: the new one starts the
    // bookkeeping again, so that machine X is again the edge's diameter.
    const double back = eq_.grinding->settings().referenceMm - eq_.grinding->wheelDiameterMm();
    ctl_->setR(engine::r::DressingSumX,
               static_cast<std::int64_t>(std::llround(back / sx.discreteMm())));
    return true;
}

// ---------------------------------------------------------------------------
// Faults

void Simulation::checkFault(const FaultSpec& f) const {
    const auto bad = [&](const std::string& why) {
        throw std::invalid_argument(describeFault(f) + ": " + why);
    };
    if (axisFault(f.kind) && !ax(f.axis).present)
        bad(std::string("the machine has no axis ") + axisLetter(f.axis));
    switch (f.kind) {
    case Fault::EncoderChannelBreak:
        if (f.detail != 1 && f.detail != 2)
            bad("the channel is 1 or 2");
        break;
    case Fault::LimitSwitch:
        if (f.detail != 1 && f.detail != -1)
            bad("the direction is +1 or -1");
        break;
    case Fault::PlcModuleFailure:
        if (f.detail < 0 || f.detail > 15)
            bad("module places are 0..15");
        break;
    case Fault::SpindleDrive:
    case Fault::SpindleOverheat:
        if (!const_cast<Equipment&>(eq_).spindle(f.equipment))
            bad("the machine has no spindle '" + f.equipment + "'");
        break;
    case Fault::PumpOverload:
        if (!const_cast<Equipment&>(eq_).pump(f.equipment))
            bad("the machine has no pump '" + f.equipment + "'");
        break;
    case Fault::ChuckPressure:
        if (!eq_.chuck)
            bad("the machine has no chuck");
        break;
    case Fault::TurretJam:
        if (!eq_.turret)
            bad("the machine has no turret");
        break;
    case Fault::GaugeFault:
        if (!eq_.grinding)
            bad("the machine has no gauge");
        break;
    case Fault::PositionerModule:
        if (f.detail < 1 || f.detail > kPositionerPartCount)
            bad("the positioner parts are 1..6");
        break;
    case Fault::K923:
        if (f.detail < 1 || f.detail > kK923PartCount)
            bad("the K923 parts are 1..4");
        break;
    default:
        break;
    }
}

void Simulation::applyFault(const FaultSpec& f, bool on) {
    switch (f.kind) {
    case Fault::EncoderChannelBreak:
        ax(f.axis).mech->setChannelBroken(f.detail, on);
        break;
    case Fault::DriveNotReady:
        ax(f.axis).driveFault = on;
        break;
    case Fault::LimitSwitch:
        ax(f.axis).stuckLimit = on ? f.detail : 0;
        break;
    case Fault::EmergencyStop:
        eq_.pendant->setEstopCircuitBroken(on);
        break;
    case Fault::DacLimit: {
        // A burst of counts large enough that the loop demands more than
        // ПРЕДЕЛ ЦАП in the tick it arrives (before the following error,
        // which the positioner checks after the DAC).
        const axis::Constants k = axis::Constants::fromC(ctl_->c(), f.axis);
        const double limit = static_cast<double>(std::max(k.dacLimit, k.dacMax));
        const double internal =
            2.0 * limit * 256.0 / static_cast<double>(std::max<std::int64_t>(k.ke, 1));
        const double counts = std::ceil(internal / std::max(k.internalPerCount(), 1e-9));
        ax(f.axis).glitchCounts = on ? static_cast<std::int64_t>(counts) : 0;
        break;
    }
    case Fault::PlcModuleFailure:
        plc_->setModuleFailed(f.detail, on);
        break;
    case Fault::LostLink:
        lostLink_ = on;
        plc_->setLinkOk(!on);
        break;
    case Fault::SpindleDrive:
        eq_.spindle(f.equipment)->setDriveFault(on);
        break;
    case Fault::SpindleOverheat:
        eq_.spindle(f.equipment)->setOverheat(on);
        break;
    case Fault::PumpOverload:
        eq_.pump(f.equipment)->setOverload(on);
        break;
    case Fault::ChuckPressure:
        eq_.chuck->setPressureLoss(on);
        break;
    case Fault::TurretJam:
        eq_.turret->setJammed(on);
        break;
    case Fault::GaugeFault:
        eq_.grinding->setGaugeFault(on);
        break;
    case Fault::PositionerModule: {
        const auto bit = static_cast<std::uint8_t>(1u << (f.detail - 1));
        brokenParts_ = static_cast<std::uint8_t>(on ? brokenParts_ | bit : brokenParts_ & ~bit);
        break;
    }
    case Fault::K923:
        break; // the panel's own state: k923Health()
    case Fault::PlcStopped:
        plc_->setStopped(on);
        break;
    }
    // The next tick looks at everything a fault can change: the sensors, the
    // axis switches and ready contacts, the positioner's inputs and wiring.
    signals_.markChanged();
    senseAll_ = true;
    ioStale_ = true;
}

void Simulation::inject(const FaultSpec& f) {
    checkFault(f);
    if (faultActive(f))
        return;
    faults_.push_back(f);
    applyFault(f, true);
}

void Simulation::clear(const FaultSpec& f) {
    const auto it = std::find(faults_.begin(), faults_.end(), f);
    if (it == faults_.end())
        return;
    faults_.erase(it);
    applyFault(f, false);
}

void Simulation::clearFaults() {
    while (!faults_.empty())
        clear(faults_.back());
}

bool Simulation::faultActive(const FaultSpec& f) const {
    return std::find(faults_.begin(), faults_.end(), f) != faults_.end();
}

std::vector<FaultSpec> Simulation::availableFaults() const {
    std::vector<FaultSpec> v;
    for (AxisId a : {AxisId::X, AxisId::Z}) {
        if (!ax(a).present)
            continue;
        v.push_back({Fault::EncoderChannelBreak, a, 1, {}});
        v.push_back({Fault::EncoderChannelBreak, a, 2, {}});
        v.push_back({Fault::DriveNotReady, a, 0, {}});
        v.push_back({Fault::LimitSwitch, a, 1, {}});
        v.push_back({Fault::LimitSwitch, a, -1, {}});
        v.push_back({Fault::DacLimit, a, 0, {}});
    }
    v.push_back({Fault::EmergencyStop, AxisId::X, 0, {}});
    for (const plc::ModuleDef& m : description().modules)
        v.push_back({Fault::PlcModuleFailure, AxisId::X, m.place, {}});
    v.push_back({Fault::LostLink, AxisId::X, 0, {}});
    for (const auto& s : eq_.spindles) {
        v.push_back({Fault::SpindleDrive, AxisId::X, 0, s->settings().name});
        v.push_back({Fault::SpindleOverheat, AxisId::X, 0, s->settings().name});
    }
    for (const auto& p : eq_.pumps)
        v.push_back({Fault::PumpOverload, AxisId::X, 0, p->settings().name});
    if (eq_.chuck)
        v.push_back({Fault::ChuckPressure, AxisId::X, 0, {}});
    if (eq_.turret)
        v.push_back({Fault::TurretJam, AxisId::X, 0, {}});
    if (eq_.grinding)
        v.push_back({Fault::GaugeFault, AxisId::X, 0, {}});
    for (int p = 1; p <= kPositionerPartCount; ++p)
        v.push_back({Fault::PositionerModule, AxisId::X, p, {}});
    for (int p = 1; p <= kK923PartCount; ++p)
        v.push_back({Fault::K923, AxisId::X, p, {}});
    v.push_back({Fault::PlcStopped, AxisId::X, 0, {}});
    return v;
}

panel::Health Simulation::k923Health() const {
    const auto broken = [&](K923Part p) {
        return faultActive({Fault::K923, AxisId::X, static_cast<int>(p), {}});
    };
    panel::Health h;
    h.plcLink = !broken(K923Part::PlcLink);
    h.positionerLink = !broken(K923Part::PositionerLink);
    h.ramOk = !broken(K923Part::Ram);
    h.residentOk = !broken(K923Part::Resident);
    h.plcStopped = plc_->stopped();
    return h;
}

// ---------------------------------------------------------------------------
// Views

double Simulation::slideMm(AxisId a) const {
    const AxisPlant& x = ax(a);
    return x.mech ? x.mech->slideMm() : 0.0;
}

double Simulation::machineMm(AxisId a) const {
    return slideMm(a) * ax(a).place.displayPerSlide;
}

const engine::AxisPlacement& Simulation::placement(AxisId a) const {
    return ax(a).place;
}

std::vector<int> Simulation::mCodes() const {
    std::vector<int> codes;
    for (const plc::MEvent& e : plc_->mLog())
        codes.push_back(e.code);
    return codes;
}

MachineView Simulation::view() const {
    MachineView v;
    const Pendant& p = *eq_.pendant;
    v.estopPressed = p.emergencyStop();
    v.estopCircuit = p.estopCircuitClosed();
    v.drivesPower = signals_.actuator(drivesPowerAct_);
    for (const std::string_view id : kLampIds) {
        const std::string sig = "lamp." + std::string(id);
        const auto a = signals_.findActuator(sig);
        const bool wired = a && std::any_of(outputs_.begin(), outputs_.end(),
                                            [&](const Wire& w) { return w.signal == *a; });
        if (wired)
            v.lamps.emplace_back(std::string(id), signals_.actuator(*a));
    }
    for (int i = 0; i < engine::kAxisCount; ++i) {
        const AxisPlant& x = axes_[static_cast<std::size_t>(i)];
        AxisPlantView& a = v.axes[static_cast<std::size_t>(i)];
        a.present = x.present;
        if (!x.present)
            continue;
        a.slideMm = x.mech->slideMm();
        a.machineMm = a.slideMm * x.place.displayPerSlide;
        a.cam = signals_.sensor(x.camSig);
        a.limitPlus = signals_.sensor(x.limPlusSig);
        a.limitMinus = signals_.sensor(x.limMinusSig);
        a.drivePower = v.drivesPower;
        a.driveReady = signals_.sensor(x.readySig);
    }
    for (const auto& s : eq_.spindles) {
        SpindleView sv;
        sv.name = s->settings().name;
        sv.rpm = s->rpm();
        sv.targetRpm = s->targetRpm();
        sv.nominalRpm = s->settings().rpm;
        sv.atSpeed =
            s->targetRpm() != 0 && std::fabs(s->rpm() - s->targetRpm()) <=
                                       s->settings().atSpeedPercent / 100.0 * s->settings().rpm;
        sv.driveReady = !s->driveFault();
        v.spindles.push_back(sv);
    }
    for (const auto& pu : eq_.pumps)
        v.pumps.push_back({pu->settings().name, pu->on(), pu->pressure(), pu->overload()});
    if (eq_.chuck) {
        v.hasChuck = true;
        v.chuckClamped = eq_.chuck->clamped() && !eq_.chuck->pressureLoss();
        v.chuckOpen = eq_.chuck->unclamped();
    }
    if (eq_.turret) {
        v.hasTurret = true;
        v.turretStation = eq_.turret->station();
        v.turretPositions = eq_.turret->positions();
        v.turretLocked = eq_.turret->locked();
    }
    if (eq_.door) {
        v.hasDoor = true;
        v.doorClosed = eq_.door->closed();
        v.doorLocked = eq_.door->locked();
    }
    if (const Grinding* g = eq_.grinding.get()) {
        v.hasGrinding = true;
        v.wheelMm = g->wheelDiameterMm();
        v.boreMm = g->boreMm();
        v.sizeMm = g->settings().sizeMm;
        v.dressedMm = g->dressedMm();
        v.ringPresent = g->ringPresent();
        v.gaugeIn = g->gaugeIn();
        v.touch = g->touch();
        v.rough = g->rough();
        v.finish = g->finish();
        v.size = g->size();
        v.ringsGround = g->ringsGround();
    }
    v.hasHandwheel = p.settings().handwheel;
    v.hasOverrideSwitch = p.settings().overrideSwitch;
    v.wheelAxis = p.wheelAxis();
    v.wheelStep = p.wheelMultiplier();
    v.overrideCode = p.overrideCode();
    return v;
}

} // namespace k528::machine
