#include "machine/equipment.h"

#include <algorithm>
#include <cmath>

namespace k528::machine {

namespace {

constexpr std::string_view kButtonSignals[kButtonCount] = {
    "pendant.drives_on",  "pendant.cycle_start", "pendant.cycle_stop", "pendant.reset",
    "pendant.jog_x_plus", "pendant.jog_x_minus", "pendant.jog_z_plus", "pendant.jog_z_minus",
    "pendant.rapid",      "pendant.chuck_pedal"};

constexpr std::string_view kButtonMeaning[kButtonCount] = {"push-button «drives on» pressed",
                                                           "push-button «cycle start» pressed",
                                                           "push-button «stop» pressed",
                                                           "push-button «reset» pressed",
                                                           "jog +X pressed",
                                                           "jog -X pressed",
                                                           "jog +Z pressed",
                                                           "jog -Z pressed",
                                                           "rapid pressed",
                                                           "chuck foot switch pressed"};

// The names an operator's script gives the buttons (`k528 panel --machine`,
// a training attempt's procedure).
constexpr std::string_view kButtonNames[kButtonCount] = {
    "DRIVES_ON", "START", "STOP", "RESET", "X+", "X-", "Z+", "Z-", "RAPID", "CHUCK"};

} // namespace

std::string_view buttonName(Button b) {
    return kButtonNames[static_cast<int>(b)];
}

std::optional<Button> buttonFromName(std::string_view name) {
    for (int i = 0; i < kButtonCount; ++i) {
        const std::string_view n = kButtonNames[i];
        if (n.size() == name.size() &&
            std::equal(n.begin(), n.end(), name.begin(), [](char a, char b) {
                return a == (b >= 'a' && b <= 'z' ? static_cast<char>(b - 'a' + 'A') : b);
            }))
            return static_cast<Button>(i);
    }
    return std::nullopt;
}

std::string_view buttonSignal(Button b) {
    return kButtonSignals[static_cast<int>(b)];
}

// ---------------------------------------------------------------------------
// Pendant

Pendant::Pendant(Signals& s, const Settings& settings) : s_(s), set_(settings) {
    for (int i = 0; i < kButtonCount; ++i)
        sig_[static_cast<std::size_t>(i)] =
            s_.addSensor(std::string(kButtonSignals[i]), kButtonMeaning[i]);
    estopSig_ = s_.addSensor("pendant.estop", "E-stop mushroom pressed (latched)");
    circuitSig_ = s_.addSensor("safety.estop_circuit",
                               "E-stop circuit closed (all mushrooms released, no break)");
    wheelX_ = s_.addSensor("pendant.wheel_x", "handwheel selector on X");
    wheelZ_ = s_.addSensor("pendant.wheel_z", "handwheel selector on Z");
    x10_ = s_.addSensor("pendant.wheel_x10", "handwheel multiplier on x10");
    x100_ = s_.addSensor("pendant.wheel_x100", "handwheel multiplier on x100");
    for (int b = 0; b < 4; ++b)
        ovBits_[static_cast<std::size_t>(b)] = s_.addSensor(
            "pendant.override_b" + std::to_string(b),
            "override selector code bit " + std::to_string(b) + " (code 15: position K923)");
    for (std::string_view id : kLampIds)
        lamps_.emplace_back(std::string(id),
                            s_.addActuator("lamp." + std::string(id), "pilot lamp on the pendant"));
    s_.setSensor(circuitSig_, true);
    setOverride(-1);
}

void Pendant::press(Button b, std::int64_t nowMs) {
    const auto i = static_cast<std::size_t>(b);
    if (want_[i])
        return;
    want_[i] = true;
    changedAt_[i] = nowMs;
    s_.setSensor(sig_[i], true);
    if (set_.bounceMs > 0)
        ++bouncing_;
}

void Pendant::release(Button b, std::int64_t nowMs) {
    const auto i = static_cast<std::size_t>(b);
    if (!want_[i])
        return;
    want_[i] = false;
    changedAt_[i] = nowMs;
    s_.setSensor(sig_[i], false);
    if (set_.bounceMs > 0)
        ++bouncing_;
}

// Contact bounce: for bounceMs after a change the contact alternates each
// millisecond, starting at the new level, then rests there.
void Pendant::tick(std::int64_t nowMs) {
    if (bouncing_ == 0)
        return;
    bouncing_ = 0;
    for (int i = 0; i < kButtonCount; ++i) {
        const auto k = static_cast<std::size_t>(i);
        const std::int64_t t = nowMs - changedAt_[k];
        if (t < 0 || t >= set_.bounceMs) {
            s_.setSensor(sig_[k], want_[k]);
            continue;
        }
        ++bouncing_;
        s_.setSensor(sig_[k], (t % 2 == 0) ? want_[k] : !want_[k]);
    }
}

void Pendant::setEmergencyStop(bool pressed) {
    estop_ = pressed;
    s_.setSensor(estopSig_, pressed);
    s_.setSensor(circuitSig_, estopCircuitClosed());
}

void Pendant::setEstopCircuitBroken(bool broken) {
    estopBroken_ = broken;
    s_.setSensor(circuitSig_, estopCircuitClosed());
}

void Pendant::selectWheelAxis(HandwheelAxis a) {
    wheelAxis_ = a;
    s_.setSensor(wheelX_, a == HandwheelAxis::X);
    s_.setSensor(wheelZ_, a == HandwheelAxis::Z);
}

void Pendant::selectWheelMultiplier(int step) {
    wheelStep_ = std::clamp(step, 0, 2);
    s_.setSensor(x10_, wheelStep_ == 1);
    s_.setSensor(x100_, wheelStep_ == 2);
}

void Pendant::turn(std::int64_t detents) {
    detents_ += detents;
    // The selector routes the generator to the handwheel channel of the axis.
    const int wheel = wheelAxis_ == HandwheelAxis::Z ? set_.wheelOfAxis[1] : set_.wheelOfAxis[0];
    if (wheel < 1 || wheel > 2)
        return;
    wheelCount_[static_cast<std::size_t>(wheel - 1)] +=
        detents * set_.pulsesPerDetent[static_cast<std::size_t>(wheelStep_)];
    wheelTurned_ = true;
}

void Pendant::setOverride(int code) {
    override_ = code < 0 ? -1 : std::min(code, 10);
    const int bits = override_ < 0 ? 15 : override_;
    for (int b = 0; b < 4; ++b)
        s_.setSensor(ovBits_[static_cast<std::size_t>(b)], (bits >> b) & 1);
}

bool Pendant::lampWired(std::string_view id) const {
    return std::any_of(lamps_.begin(), lamps_.end(), [&](const auto& l) { return l.first == id; });
}

bool Pendant::lamp(std::string_view id) const {
    for (const auto& [name, sig] : lamps_)
        if (name == id)
            return s_.actuator(sig);
    return false;
}

// ---------------------------------------------------------------------------
// Spindle

Spindle::Spindle(Signals& s, const Settings& settings) : s_(s), set_(settings) {
    const std::string& n = set_.name;
    fwd_ = s_.addActuator(n + ".fwd", "spindle drive: run forward (M3)");
    rev_ = s_.addActuator(n + ".rev", "spindle drive: run reverse (M4)");
    running_ = s_.addSensor(n + ".running", "spindle turns (above 2 % of its speed)");
    atSpeed_ = s_.addSensor(n + ".at_speed", "spindle drive relay «speed reached»");
    stopped_ = s_.addSensor(n + ".stopped", "spindle drive relay «zero speed»");
    ready_ = s_.addSensor(n + ".drive_ready", "spindle drive ready");
    overheat_ = s_.addSensor(n + ".overheat", "spindle motor thermal switch tripped");
    s_.setSensor(stopped_, true);
    s_.setSensor(ready_, true);
}

void Spindle::setDriveFault(bool f) {
    fault_ = f;
    s_.setSensor(ready_, !f);
    s_.wakeEquipment(); // the target speed changes
}

void Spindle::tick(double dtMs) {
    const bool fwd = s_.actuator(fwd_), rev = s_.actuator(rev_);
    target_ = fault_ || fwd == rev ? 0.0 : (fwd ? set_.rpm : -set_.rpm);
    if (n_ != target_) {
        // A drive that fails coasts down slower than it brakes.
        const double rate = set_.rpm / std::max(set_.rampMs, 1.0) * (fault_ ? 0.5 : 1.0);
        const double step = rate * dtMs;
        n_ = std::fabs(target_ - n_) <= step ? target_ : n_ + (target_ > n_ ? step : -step);
        s_.setSensor(running_, running());
        s_.setSensor(stopped_, std::fabs(n_) < 0.005 * set_.rpm);
        s_.setSensor(atSpeed_, target_ != 0 && std::fabs(n_ - target_) <=
                                                   set_.atSpeedPercent / 100.0 * set_.rpm);
    } else if (target_ != 0 && !s_.sensor(atSpeed_)) {
        s_.setSensor(atSpeed_, true);
    }
    // At its target with the relays as they stay, the next tick with the
    // same contactors changes nothing.
    if (n_ != target_ || (target_ != 0 && !s_.sensor(atSpeed_)))
        s_.wakeEquipment();
}

// ---------------------------------------------------------------------------
// Pump

Pump::Pump(Signals& s, const Settings& settings) : s_(s), set_(settings) {
    on_ = s_.addActuator(set_.name + ".on", "pump motor contactor");
    pressure_ = s_.addSensor(set_.name + ".pressure", "pressure switch: pressure present");
    overloadSig_ = s_.addSensor(set_.name + ".overload", "motor protection switch tripped");
}

void Pump::setOverload(bool f) {
    overload_ = f;
    s_.setSensor(overloadSig_, f);
    s_.wakeEquipment(); // on() changes
}

void Pump::tick(double dtMs) {
    const bool running = on();
    if (running && level_ < 1.0)
        level_ = std::min(1.0, level_ + dtMs / std::max(set_.riseMs, 1.0));
    else if (!running && level_ > 0.0)
        level_ = std::max(0.0, level_ - dtMs / std::max(set_.fallMs, 1.0));
    else
        return; // at full or no pressure
    // The switch closes at 80 % of the working pressure and opens at 50 %.
    if (!s_.sensor(pressure_) && level_ >= 0.8)
        s_.setSensor(pressure_, true);
    else if (s_.sensor(pressure_) && level_ < 0.5)
        s_.setSensor(pressure_, false);
    if (running ? level_ < 1.0 : level_ > 0.0)
        s_.wakeEquipment(); // still rising or falling
}

// ---------------------------------------------------------------------------
// Chuck

Chuck::Chuck(Signals& s, const Settings& settings)
    : s_(s), set_(settings), pos_(settings.clamped ? 1.0 : 0.0) {
    clamp_ = s_.addActuator("chuck.clamp", "chuck valve solenoid «clamp»");
    unclamp_ = s_.addActuator("chuck.unclamp", "chuck valve solenoid «unclamp»");
    clampedSig_ = s_.addSensor("chuck.clamped", "chuck pressure switch: clamped");
    unclampedSig_ = s_.addSensor("chuck.unclamped", "chuck limit switch: open");
    s_.setSensor(clampedSig_, clamped());
    s_.setSensor(unclampedSig_, unclamped());
}

void Chuck::setPressureLoss(bool f) {
    pressureLoss_ = f;
    s_.setSensor(clampedSig_, clamped() && !pressureLoss_);
}

void Chuck::tick(double dtMs) {
    const bool c = s_.actuator(clamp_), u = s_.actuator(unclamp_);
    if (c == u)
        return; // detented: stays
    const double step = dtMs / std::max(set_.strokeMs, 1.0);
    if (c && pos_ < 1.0)
        pos_ = std::min(1.0, pos_ + step);
    else if (u && pos_ > 0.0)
        pos_ = std::max(0.0, pos_ - step);
    else
        return; // at the end of the stroke
    s_.setSensor(clampedSig_, clamped() && !pressureLoss_);
    s_.setSensor(unclampedSig_, unclamped());
    if (c ? pos_ < 1.0 : pos_ > 0.0)
        s_.wakeEquipment(); // still moving
}

// ---------------------------------------------------------------------------
// Turret

Turret::Turret(Signals& s, const Settings& settings) : s_(s), set_(settings) {
    cw_ = s_.addActuator("turret.cw", "turret motor forward (unlock and index)");
    ccw_ = s_.addActuator("turret.ccw", "turret motor reverse (lock)");
    lockedSig_ = s_.addSensor("turret.locked", "turret locked at a station");
    inPosSig_ = s_.addSensor("turret.in_position", "turret at a station");
    for (int b = 0; b < 3; ++b)
        code_[static_cast<std::size_t>(b)] = s_.addSensor(
            "turret.pos_b" + std::to_string(b), "turret station code bit " + std::to_string(b));
    angle_ = std::clamp(set_.position, 1, set_.positions) - 1.0;
    publish();
}

int Turret::station() const {
    const double r = std::round(angle_);
    if (std::fabs(angle_ - r) > 0.05)
        return 0;
    return static_cast<int>(r) % set_.positions + 1;
}

void Turret::publish() {
    const int st = station();
    s_.setSensor(inPosSig_, st != 0);
    s_.setSensor(lockedSig_, locked_);
    for (int b = 0; b < 3; ++b)
        s_.setSensor(code_[static_cast<std::size_t>(b)], (st >> b) & 1);
}

void Turret::tick(double dtMs) {
    const bool cw = s_.actuator(cw_), ccw = s_.actuator(ccw_);
    if (cw && !ccw) {
        locked_ = false;
        lockProgress_ = 0;
        if (!jammed_) {
            angle_ += dtMs / std::max(set_.indexMs, 1.0);
            if (angle_ >= set_.positions)
                angle_ -= set_.positions;
        }
        publish();
        s_.wakeEquipment(); // indexes while the motor runs forward
    } else if (ccw && !cw && !locked_) {
        // Turning back against the pawl: the head settles on the station and clamps.
        const double r = std::round(angle_);
        if (std::fabs(angle_ - r) < 0.25) {
            angle_ = r >= set_.positions ? 0.0 : r;
            lockProgress_ += dtMs;
            if (lockProgress_ >= set_.lockMs)
                locked_ = true;
        }
        publish();
        if (!locked_)
            s_.wakeEquipment(); // still settling onto the station
    }
}

// ---------------------------------------------------------------------------
// Door

Door::Door(Signals& s, const Settings& settings) : s_(s), closed_(settings.closed) {
    lock_ = s_.addActuator("door.lock", "door lock solenoid");
    closedSig_ = s_.addSensor("door.closed", "door switch: closed");
    lockedSig_ = s_.addSensor("door.locked", "door lock engaged");
    tick();
}

bool Door::open() {
    if (locked())
        return false;
    closed_ = false;
    tick();
    return true;
}

void Door::close() {
    closed_ = true;
    tick();
}

void Door::tick() {
    s_.setSensor(closedSig_, closed_);
    s_.setSensor(lockedSig_, locked());
}

// ---------------------------------------------------------------------------
// Grinding

Grinding::Grinding(Signals& s, const Settings& settings, const Spindle* wheel, const Spindle* work,
                   const Chuck* chuck)
    : s_(s), set_(settings), wheel_(wheel), work_(work), chuck_(chuck), wheelMm_(settings.wheelMm),
      boreMm_(settings.blankBoreMm) {
    advance_ =
        s_.addActuator("gauge.advance", "in-process gauge (ПАК): measuring head into the bore");
    inPos_ = s_.addSensor("gauge.in_position", "gauge head in the bore");
    ok_ = s_.addSensor("gauge.ok", "gauge ready (no fault)");
    touchSig_ = s_.addSensor("gauge.touch", "touch relay: the wheel touches the ring");
    rough_ = s_.addSensor("gauge.rough", "ПАК: rough allowance removed");
    finish_ = s_.addSensor("gauge.finish", "ПАК: finish allowance removed");
    size_ = s_.addSensor("gauge.size", "ПАК: size reached");
    present_ = s_.addSensor("ring.present", "a ring is in the chuck");
    s_.setSensor(ok_, true);
    s_.setSensor(present_, true);
    wasClamped_ = chuck_ ? chuck_->clamped() : true;
}

void Grinding::setGaugeFault(bool f) {
    gaugeFault_ = f;
    s_.setSensor(ok_, !f);
}

void Grinding::tick(double dtMs, double xMachineMm, double zMachineMm) {
    // The operator changes the ring while the chuck is open.
    if (chuck_) {
        const bool clamped = chuck_->clamped();
        if (!clamped && chuck_->unclamped() && ringPresent_ && ground_) {
            ringPresent_ = false; // the ground ring is taken out
            s_.setSensor(present_, false);
        }
        if (clamped && !wasClamped_ && !ringPresent_) {
            ringPresent_ = true; // a new blank is clamped
            ground_ = false;
            boreMm_ = set_.blankBoreMm;
            s_.setSensor(present_, true);
        }
        wasClamped_ = clamped;
    }

    const bool wheelTurns = wheel_ && wheel_->running();
    const double edge = edgeMm(xMachineMm);
    // Dressing: the diamond trims the wheel to its X as it passes.
    if (wheelTurns && zMachineMm >= set_.dresserZMinMm && zMachineMm <= set_.dresserZMaxMm &&
        edge > set_.dresserXMm) {
        const double cut = edge - set_.dresserXMm;
        wheelMm_ -= cut;
        dressedMm_ += cut;
    }
    // Grinding the bore.
    const bool inRing =
        ringPresent_ && zMachineMm >= set_.ringZMinMm && zMachineMm <= set_.ringZMaxMm;
    const bool contact = inRing && edge >= boreMm_;
    touch_ = contact && wheelTurns;
    if (touch_ && work_ && work_->running() && edge > boreMm_) {
        const double k = 1.0 - std::exp(-dtMs / std::max(set_.removalMs, 1.0));
        const double removed = (edge - boreMm_) * k;
        boreMm_ += removed;
        wheelMm_ -= removed * set_.wearRatio;
        if (!ground_) {
            ground_ = true;
            ++rings_;
        }
    }
    s_.setSensor(touchSig_, touch_);

    // The gauge head.
    const bool adv = s_.actuator(advance_);
    if (adv && gaugePos_ < 1.0)
        gaugePos_ = std::min(1.0, gaugePos_ + dtMs / std::max(set_.gaugeAdvanceMs, 1.0));
    else if (!adv && gaugePos_ > 0.0)
        gaugePos_ = std::max(0.0, gaugePos_ - dtMs / std::max(set_.gaugeAdvanceMs, 1.0));
    s_.setSensor(inPos_, gaugeIn());
    const bool measuring = gaugeIn() && ringPresent_ && !gaugeFault_;
    s_.setSensor(rough_, measuring && boreMm_ >= set_.sizeMm - set_.roughBeforeSizeMm);
    s_.setSensor(finish_, measuring && boreMm_ >= set_.sizeMm - set_.finishBeforeSizeMm);
    s_.setSensor(size_, measuring && boreMm_ >= set_.sizeMm);
}

// ---------------------------------------------------------------------------

Spindle* Equipment::spindle(std::string_view name) {
    for (auto& s : spindles)
        if (s->settings().name == name)
            return s.get();
    return nullptr;
}

Pump* Equipment::pump(std::string_view name) {
    for (auto& p : pumps)
        if (p->settings().name == name)
            return p.get();
    return nullptr;
}

Equipment buildEquipment(const plc::JsonNode& eq, Signals& s) {
    Equipment e;
    eq.expectObject({"pendant", "drives", "spindles", "pumps", "chuck", "turret", "door",
                     "grinding", "fast_inputs"});
    {
        Pendant::Settings ps;
        if (eq.has("pendant")) {
            const plc::JsonNode p = eq.child("pendant");
            p.expectObject({"bounce_ms", "handwheel", "override_switch"});
            ps.bounceMs = static_cast<int>(p.integer("bounce_ms", 0, 20, 3));
            ps.overrideSwitch = p.boolean("override_switch", false);
            if (p.has("handwheel")) {
                const plc::JsonNode h = p.child("handwheel");
                h.expectObject({"x", "z", "pulses_per_detent"});
                ps.wheelOfAxis[0] = static_cast<int>(h.integer("x", 1, 2, 1));
                ps.wheelOfAxis[1] = static_cast<int>(h.integer("z", 1, 2, 2));
                if (h.has("pulses_per_detent")) {
                    const auto steps = h.child("pulses_per_detent").elements();
                    if (steps.size() != 3)
                        h.failAt("pulses_per_detent", profile::problem("equipment.detents"));
                    for (std::size_t i = 0; i < 3; ++i)
                        ps.pulsesPerDetent[i] = static_cast<int>(steps[i].asInteger(1, 1000));
                }
            } else {
                ps.handwheel = false;
            }
        }
        e.pendant = std::make_unique<Pendant>(s, ps);
    }
    if (eq.has("drives")) {
        const plc::JsonNode d = eq.child("drives");
        d.expectObject({"ready_delay_ms"});
        e.drivesReadyDelayMs = d.number("ready_delay_ms", 0, 60000, 300);
    }
    for (const plc::JsonNode& n : eq.optionalArray("spindles")) {
        n.expectObject({"name", "rpm", "ramp_ms", "at_speed_percent"});
        Spindle::Settings st;
        st.name = n.string("name");
        if (st.name != "spindle" && st.name != "wheel" && st.name != "work")
            n.failAt("name", profile::problem("equipment.spindle-name", {st.name}));
        if (e.spindle(st.name))
            n.failAt("name", profile::problem("equipment.spindle-twice", {st.name}));
        st.rpm = n.number("rpm", 1, 200000);
        st.rampMs = n.number("ramp_ms", 0, 600000, 1500);
        st.atSpeedPercent = n.number("at_speed_percent", 0.1, 50, 5);
        e.spindles.push_back(std::make_unique<Spindle>(s, st));
    }
    for (const plc::JsonNode& n : eq.optionalArray("pumps")) {
        n.expectObject({"name", "rise_ms", "fall_ms"});
        Pump::Settings pt;
        pt.name = n.string("name");
        if (pt.name != "coolant" && pt.name != "lube" && pt.name != "hydraulics" &&
            pt.name != "air")
            n.failAt("name", profile::problem("equipment.pump-name", {pt.name}));
        if (e.pump(pt.name))
            n.failAt("name", profile::problem("equipment.pump-twice", {pt.name}));
        pt.riseMs = n.number("rise_ms", 0, 600000, 400);
        pt.fallMs = n.number("fall_ms", 0, 600000, 200);
        e.pumps.push_back(std::make_unique<Pump>(s, pt));
    }
    if (eq.has("chuck")) {
        const plc::JsonNode n = eq.child("chuck");
        n.expectObject({"stroke_ms", "clamped"});
        Chuck::Settings cs;
        cs.strokeMs = n.number("stroke_ms", 1, 60000, 400);
        cs.clamped = n.boolean("clamped", true);
        e.chuck = std::make_unique<Chuck>(s, cs);
    }
    if (eq.has("turret")) {
        const plc::JsonNode n = eq.child("turret");
        n.expectObject({"positions", "index_ms", "lock_ms", "position"});
        Turret::Settings ts;
        ts.positions = static_cast<int>(n.integer("positions", 2, 7, 4));
        ts.indexMs = n.number("index_ms", 1, 60000, 600);
        ts.lockMs = n.number("lock_ms", 1, 60000, 300);
        ts.position = static_cast<int>(n.integer("position", 1, ts.positions, 1));
        e.turret = std::make_unique<Turret>(s, ts);
    }
    if (eq.has("door")) {
        const plc::JsonNode n = eq.child("door");
        n.expectObject({"closed"});
        e.door = std::make_unique<Door>(s, Door::Settings{n.boolean("closed", true)});
    }
    if (eq.has("grinding")) {
        const plc::JsonNode g = eq.child("grinding");
        g.expectObject({"wheel", "ring", "gauge", "dresser"});
        Grinding::Settings gs;
        const plc::JsonNode w = g.child("wheel");
        w.expectObject({"new_diameter_mm", "wear_ratio"});
        gs.newWheelMm = w.number("new_diameter_mm", 1, 1000);
        gs.wheelMm = gs.referenceMm = gs.newWheelMm;
        gs.wearRatio = w.number("wear_ratio", 0, 10, 0.02);
        const plc::JsonNode r = g.child("ring");
        r.expectObject({"blank_bore_mm", "size_mm", "z_min_mm", "z_max_mm", "removal_ms"});
        gs.blankBoreMm = r.number("blank_bore_mm", 0.1, 10000);
        gs.sizeMm = r.number("size_mm", 0.1, 10000);
        if (gs.sizeMm <= gs.blankBoreMm)
            r.failAt("size_mm", profile::problem("equipment.ring-size"));
        gs.ringZMinMm = r.number("z_min_mm", -100000, 100000);
        gs.ringZMaxMm = r.number("z_max_mm", gs.ringZMinMm, 100000);
        gs.removalMs = r.number("removal_ms", 1, 60000, 300);
        const plc::JsonNode ga = g.child("gauge");
        ga.expectObject({"advance_ms", "rough_before_size_mm", "finish_before_size_mm"});
        gs.gaugeAdvanceMs = ga.number("advance_ms", 1, 60000, 400);
        gs.roughBeforeSizeMm = ga.number("rough_before_size_mm", 0, 10, 0.010);
        gs.finishBeforeSizeMm = ga.number("finish_before_size_mm", 0, gs.roughBeforeSizeMm, 0.002);
        const plc::JsonNode d = g.child("dresser");
        d.expectObject({"x_mm", "z_min_mm", "z_max_mm"});
        gs.dresserXMm = d.number("x_mm", -100000, 100000);
        gs.dresserZMinMm = d.number("z_min_mm", -100000, 100000);
        gs.dresserZMaxMm = d.number("z_max_mm", gs.dresserZMinMm, 100000);
        const Spindle* wheel = e.spindle("wheel");
        const Spindle* work = e.spindle("work");
        if (!wheel || !work)
            g.fail(profile::problem("equipment.grinding-spindles"));
        if (!e.chuck)
            g.fail(profile::problem("equipment.grinding-chuck"));
        e.grinding = std::make_unique<Grinding>(s, gs, wheel, work, e.chuck.get());
    }
    if (eq.has("fast_inputs")) {
        const plc::JsonNode f = eq.child("fast_inputs");
        f.expectObject({"x", "z", "reset"});
        for (int a = 0; a < 2; ++a) {
            const char* key = a == 0 ? "x" : "z";
            if (!f.has(key))
                continue;
            const plc::JsonNode ax = f.child(key);
            ax.expectObject({"erase1", "erase2", "erase3", "erase4"});
            for (int n = 0; n < 4; ++n) {
                const std::string k = "erase" + std::to_string(n + 1);
                if (!ax.has(k))
                    continue;
                const std::string name = ax.string(k);
                const auto src = s.findSensor(name);
                if (!src)
                    ax.failAt(k, profile::problem("equipment.unknown-signal", {name}));
                e.eraseSource[static_cast<std::size_t>(a)][static_cast<std::size_t>(n)] = *src;
            }
        }
        if (f.has("reset")) {
            const std::string name = f.string("reset");
            const auto src = s.findSensor(name);
            if (!src)
                f.failAt("reset", profile::problem("equipment.unknown-signal", {name}));
            e.resetSource = *src;
        }
    }
    return e;
}

} // namespace k528::machine
