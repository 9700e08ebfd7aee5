// The machine's equipment beside the feed axes, as the machine description's
// "equipment" section declares it (docs/machine-description.md): the
// machine's control panel (pendant), spindles, pumps, the chuck, the tool
// turret, the guard door, and the grinding process of grinder-205 (wheel,
// dresser, ring, in-process gauge ПАК). Each piece reads its actuators and
// writes its sensors in Signals; tick(dt) advances it. Times in ms, lengths
// in mm, speeds in rpm. Everything is deterministic.
//
// A unit at rest (a spindle at its speed or standing, a pump at full or no
// pressure, the chuck at the end of its stroke, the turret locked or idle,
// the door) changes nothing in a tick while its actuators stay as they are,
// so Simulation ticks spindles, pumps, chuck, turret and door only while
// Signals says the equipment is awake (Signals::wakeEquipment): an actuator
// changed, a unit's tick ended in a transition, or a mutator changed what a
// tick computes (a drive fault, a pump's overload). Mutators that only set a
// contact the tick does not read (overheat, chuck pressure, the turret's jam,
// which only acts while it indexes) need no wake-up. The grinding process
// ticks always: it follows the slides.
#pragma once

#include "machine/signals.h"
#include "plc/json_reader.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace k528::machine {

// ---------------------------------------------------------------------------
// The machine's control panel: push-buttons, E-stop, selectors, lamps.

enum class Button : std::uint8_t {
    DrivesOn,   // «Включение приводов» (control on)
    CycleStart, // «Пуск»
    CycleStop,  // «Стоп»
    Reset,      // «Сброс»
    JogXPlus,
    JogXMinus,
    JogZPlus,
    JogZMinus,
    Rapid,
    ChuckPedal, // foot switch: clamp / unclamp
};
inline constexpr int kButtonCount = 10;
std::string_view buttonSignal(Button b); // "pendant.cycle_start" ...
// The button's name in an operator's script: "DRIVES_ON", "START", "STOP",
// "RESET", "X+", "X-", "Z+", "Z-", "RAPID", "CHUCK"; back (case-insensitive).
std::string_view buttonName(Button b);
std::optional<Button> buttonFromName(std::string_view name);

enum class HandwheelAxis : std::uint8_t { Off, X, Z };

// Pilot lamps a pendant may have (actuators "lamp.<id>").
inline constexpr std::string_view kLampIds[] = {
    "drives", "cycle_start", "cycle_stop", "reset", "spindle", "coolant", "limit",  "reference",
    "door",   "chuck",       "alarm",      "lube",  "wheel",   "gauge",   "turret", "hydraulics"};

class Pendant {
public:
    struct Settings {
        int bounceMs = 3;                     // contact bounce after a change (0 = none)
        std::array<int, 2> wheelOfAxis{1, 2}; // handwheel channel (1 = C105, 2 = C106) of X, Z
        std::array<int, 3> pulsesPerDetent{1, 1, 10}; // of the multiplier positions x1, x10, x100
        bool overrideSwitch = false;
        bool handwheel = true;
    };
    Pendant(Signals& s, const Settings& settings);
    const Settings& settings() const { return set_; }

    void press(Button b, std::int64_t nowMs);
    void release(Button b, std::int64_t nowMs);
    bool down(Button b) const { return want_[static_cast<std::size_t>(b)]; }

    void setEmergencyStop(bool pressed);
    bool emergencyStop() const { return estop_; }
    void setEstopCircuitBroken(bool broken); // a fault: the circuit opens elsewhere
    bool estopCircuitClosed() const { return !estop_ && !estopBroken_; }

    void selectWheelAxis(HandwheelAxis a);
    HandwheelAxis wheelAxis() const { return wheelAxis_; }
    void selectWheelMultiplier(int step); // 0: x1, 1: x10, 2: x100
    int wheelMultiplier() const { return wheelStep_; }
    void turn(std::int64_t detents); // + clockwise
    std::int64_t wheelCount(int wheel) const {
        return wheelCount_[static_cast<std::size_t>(wheel - 1)];
    }
    std::int64_t detents() const { return detents_; }
    // Whether the handwheel turned since the last call (its counts are the
    // positioner's inputs: Simulation copies them only then).
    bool takeWheelTurned() {
        const bool t = wheelTurned_;
        wheelTurned_ = false;
        return t;
    }

    // The override selector: code 0..10, or -1 for the position «K923» (the
    // panel's L keys decide).
    void setOverride(int code);
    int overrideCode() const { return override_; }

    bool lampWired(std::string_view id) const;
    bool lamp(std::string_view id) const;

    void tick(std::int64_t nowMs); // contact bounce

private:
    Signals& s_;
    Settings set_;
    std::array<int, kButtonCount> sig_{};
    std::array<bool, kButtonCount> want_{};
    std::array<std::int64_t, kButtonCount> changedAt_{};
    int bouncing_ = 0;
    bool estop_ = false, estopBroken_ = false;
    int estopSig_ = -1, circuitSig_ = -1;
    HandwheelAxis wheelAxis_ = HandwheelAxis::Off;
    int wheelStep_ = 0;
    std::array<std::int64_t, 2> wheelCount_{};
    std::int64_t detents_ = 0;
    bool wheelTurned_ = false;
    int wheelX_ = -1, wheelZ_ = -1, x10_ = -1, x100_ = -1;
    std::array<int, 4> ovBits_{-1, -1, -1, -1};
    int override_ = -1;
    std::vector<std::pair<std::string, int>> lamps_;
};

// ---------------------------------------------------------------------------
// A spindle drive with its contactor: forward / reverse, a speed ramp, the
// drive's relay contacts (running, at speed, stopped, ready).

class Spindle {
public:
    struct Settings {
        std::string name = "spindle";
        double rpm = 1000;         // speed the drive runs at (set on the drive)
        double rampMs = 1500;      // 0 -> rpm
        double atSpeedPercent = 5; // «скорость достигнута» band
    };
    Spindle(Signals& s, const Settings& settings);
    const Settings& settings() const { return set_; }
    void tick(double dtMs);
    double rpm() const { return n_; } // signed, + forward
    double targetRpm() const { return target_; }
    bool running() const { return std::abs(n_) > 0.02 * set_.rpm; }
    void setDriveFault(bool f); // wakes the equipment: the drive coasts down
    bool driveFault() const { return fault_; }
    void setOverheat(bool f) { s_.setSensor(overheat_, f); } // a contact only

private:
    Signals& s_;
    Settings set_;
    int fwd_, rev_, running_, atSpeed_, stopped_, ready_, overheat_;
    double n_ = 0, target_ = 0;
    bool fault_ = false;
};

// A pump with a pressure switch (coolant, lubrication, hydraulics).
class Pump {
public:
    struct Settings {
        std::string name;
        double riseMs = 400, fallMs = 200;
    };
    Pump(Signals& s, const Settings& settings);
    const Settings& settings() const { return set_; }
    void tick(double dtMs);
    bool on() const { return s_.actuator(on_) && !overload_; }
    bool pressure() const { return s_.sensor(pressure_); }
    void setOverload(bool f); // wakes the equipment: the motor stops
    bool overload() const { return overload_; }

private:
    Signals& s_;
    Settings set_;
    int on_, pressure_, overloadSig_;
    double level_ = 0; // 0..1
    bool overload_ = false;
};

// A power chuck with a detented valve (clamp / unclamp solenoids): it keeps
// its state without power.
class Chuck {
public:
    struct Settings {
        double strokeMs = 400;
        bool clamped = true; // at start
    };
    Chuck(Signals& s, const Settings& settings);
    const Settings& settings() const { return set_; }
    void tick(double dtMs);
    bool clamped() const { return pos_ >= 1.0; }
    bool unclamped() const { return pos_ <= 0.0; }
    double position() const { return pos_; }
    void setPressureLoss(bool f); // the pressure switch only
    bool pressureLoss() const { return pressureLoss_; }

private:
    Signals& s_;
    Settings set_;
    int clamp_, unclamp_, clampedSig_, unclampedSig_;
    double pos_;
    bool pressureLoss_ = false;
};

// A 2..8-position tool turret (резцовая головка): turning forward unlocks
// and indexes, turning back at a station locks it. Position code 1..N on
// three bits while at a station.
class Turret {
public:
    struct Settings {
        int positions = 4;
        double indexMs = 600; // one station
        double lockMs = 300;
        int position = 1;
    };
    Turret(Signals& s, const Settings& settings);
    const Settings& settings() const { return set_; }
    void tick(double dtMs);
    int positions() const { return set_.positions; }
    int station() const;                    // 1..N at a station, 0 between
    double angle() const { return angle_; } // in stations, 0 = station 1
    bool locked() const { return locked_; }
    // Acts while it indexes (then the turret ticks anyway): no wake-up.
    void setJammed(bool j) { jammed_ = j; }
    bool jammed() const { return jammed_; }

private:
    void publish();
    Signals& s_;
    Settings set_;
    int cw_, ccw_, lockedSig_, inPosSig_;
    std::array<int, 3> code_{};
    double angle_ = 0, lockProgress_ = 0;
    bool locked_ = true, jammed_ = false;
};

// The guard door with its switch and lock solenoid.
class Door {
public:
    struct Settings {
        bool closed = true;
    };
    Door(Signals& s, const Settings& settings);
    // The operator opens / closes it; opening is refused while it is locked.
    bool open();
    void close();
    bool closed() const { return closed_; }
    bool locked() const { return closed_ && s_.actuator(lock_); }
    void tick();

private:
    Signals& s_;
    int lock_, closedSig_, lockedSig_;
    bool closed_;
};

// ---------------------------------------------------------------------------
// Internal grinding of the ring bore (grinder-205): the wheel, the diamond,
// the ring and the in-process gauge ПАК (appendix Ж: touch relay, rough and
// finish allowance removed, size, on fast inputs X5..X8).
//
// X is the diameter of the wheel's working edge as the machine system shows
// it (machine X + wheel diameter − the reference diameter): the bore the
// wheel would grind. The ring's bore grows towards the edge with the
// system's elastic lag (removalMs) while the wheel touches it, both
// spindles turn and Z lies within the ring; the wheel wears by wearRatio of
// the diameter removed. The diamond cuts the wheel down to its X when the
// wheel passes it along Z.

class Grinding {
public:
    struct Settings {
        double newWheelMm = 20, wheelMm = 20; // new and current wheel diameter
        double referenceMm = 20; // wheel diameter at which machine X = edge (set by Simulation)
        double wearRatio = 0.02;
        double blankBoreMm = 24.7, sizeMm = 25.0;
        double ringZMinMm = 100, ringZMaxMm = 135; // machine Z where the wheel is in the bore
        double removalMs = 300;
        double gaugeAdvanceMs = 400;
        double roughBeforeSizeMm = 0.010, finishBeforeSizeMm = 0.002;
        double dresserXMm = 21.5, dresserZMinMm = 150, dresserZMaxMm = 156;
    };
    Grinding(Signals& s, const Settings& settings, const Spindle* wheel, const Spindle* work,
             const Chuck* chuck);
    const Settings& settings() const { return set_; }
    // Machine coordinates (as displayed: X on the diameter).
    void tick(double dtMs, double xMachineMm, double zMachineMm);

    double wheelDiameterMm() const { return wheelMm_; }
    double edgeMm(double xMachineMm) const { return xMachineMm + wheelMm_ - set_.referenceMm; }
    bool ringPresent() const { return ringPresent_; }
    double boreMm() const { return boreMm_; }
    bool gaugeIn() const { return gaugePos_ >= 1.0; }
    double dressedMm() const { return dressedMm_; }
    int ringsGround() const { return rings_; }
    bool touch() const { return touch_; }
    bool rough() const { return s_.sensor(rough_); }
    bool finish() const { return s_.sensor(finish_); }
    bool size() const { return s_.sensor(size_); }
    void setGaugeFault(bool f);
    bool gaugeFault() const { return gaugeFault_; }
    // A new wheel is mounted.
    void changeWheel() { wheelMm_ = set_.newWheelMm; }
    // The wheel as the setter left it, and the diameter at which machine X
    // is the edge's diameter.
    void setWheel(double wheelMm, double referenceMm) {
        wheelMm_ = set_.wheelMm = wheelMm;
        set_.referenceMm = referenceMm;
    }

private:
    Signals& s_;
    Settings set_;
    const Spindle* wheel_;
    const Spindle* work_;
    const Chuck* chuck_;
    int advance_, inPos_, ok_, touchSig_, rough_, finish_, size_, present_;
    double wheelMm_, boreMm_, gaugePos_ = 0, dressedMm_ = 0;
    bool ringPresent_ = true, touch_ = false, gaugeFault_ = false, wasClamped_ = true;
    int rings_ = 0;
    bool ground_ = false; // the present ring has been ground
};

// ---------------------------------------------------------------------------
// All equipment of one machine, built from the description.
struct Equipment {
    std::unique_ptr<Pendant> pendant;
    std::vector<std::unique_ptr<Spindle>> spindles;
    std::vector<std::unique_ptr<Pump>> pumps;
    std::unique_ptr<Chuck> chuck;
    std::unique_ptr<Turret> turret;
    std::unique_ptr<Door> door;
    std::unique_ptr<Grinding> grinding;
    double drivesReadyDelayMs = 300;
    // Sources of the fast-input functions 7..10 («стирание остатка пути»,
    // signal 1..4) per axis: sensor indices, -1 none.
    std::array<std::array<int, 4>, 2> eraseSource{{{-1, -1, -1, -1}, {-1, -1, -1, -1}}};
    int resetSource = -1; // fast-input function 1

    Spindle* spindle(std::string_view name);
    Pump* pump(std::string_view name);
};

// Reads the "equipment" section (plc::DescriptionError on a bad value) and
// registers the signals. Spindles and pumps by name; grinding needs the
// spindles "wheel" and "work" and the chuck.
Equipment buildEquipment(const plc::JsonNode& equipment, Signals& s);

} // namespace k528::machine
