// The simulated machine with its K528-05: the positioner (engine::Positioner),
// the PLC (plc::Plc running the machine description) and the plant — two
// feed axes (axis::Mechanics with switches placed along the slides, encoder
// zero marks once per motor revolution), the drives, and the equipment of
// the description (pendant, spindles, pumps, chuck, turret, door, grinding
// with the gauge ПАК). One tick, in a fixed order:
//
//   1. sensors: contact bounce of the pendant, axis switches (cams, limits),
//      drive ready;
//   2. the positioner's own inputs: encoder channels, handwheels, fast inputs;
//   3. the PLC: inputs -> scan -> outputs; the interface words exchanged
//      (unless the link is lost);
//   4. the positioner: Positioner::tick();
//   5. the plant: DAC and regulator enable -> drives and slides; PLC outputs
//      -> spindles, pumps, chuck, turret, door, gauge; time advances.
//
// Work only where something can change (the result is the same as doing
// it all every tick, bit for bit; test machine.trace_golden): the axis
// switches are looked at when a slide leaves the stretch between two switch
// points, the drives' power changes, the ready delay runs or a fault
// changes an axis; the positioner's inputs are copied when their source
// changed (an encoder that moved, the handwheel turned, a fault); the
// equipment ticks while it is awake (machine/equipment.h). Every mutator
// (operator, fault) marks what it changes, so it acts in the next tick.
//
// Deterministic: no clock, the caller ticks. docs/simulated-machines.md
// describes both shipped machines, the operator API and the faults.
#pragma once

#include "engine/positioner.h"
#include "engine/ideal_machine.h"
#include "machine/equipment.h"
#include "machine/fault_catalog.h"
#include "machine/signals.h"
#include "panel/health.h"
#include "plc/plc.h"
#include "profile/profile.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include <utility>

namespace k528::machine {

using engine::AxisId;

// ---------------------------------------------------------------------------
// Faults for training: one enum, inject / clear.
enum class Fault : std::uint8_t {
    EncoderChannelBreak, // axis, channel 1 or 2: messages 4/5 (X), 20/21 (Z)
    DriveNotReady,       // axis: the feed drive drops «ready»: 16 / 32
    LimitSwitch,         // axis, direction +1/-1: the switch is hit: 11/10 (X), 27/26 (Z)
    EmergencyStop,       // the E-stop circuit opens: 9
    DacLimit,            // axis: interference adds counts on the encoder lines: 6 / 22
    PlcModuleFailure,    // module place 0..15: 55, and the PLC's system message S(place+1)
    LostLink,            // the PLC <-> positioner exchange: 19
    SpindleDrive,        // a spindle drive (equipment name) is not ready
    SpindleOverheat,     // a spindle motor's thermal switch
    PumpOverload,        // a pump motor's protection (equipment name)
    ChuckPressure,       // the chuck loses its clamping pressure
    TurretJam,           // the turret does not index
    GaugeFault,          // the in-process gauge reports a fault
    PositionerModule,    // a part of the positioner itself (PositionerPart): 2, 18, 3, 14, 25, 30
    K923,                // the operator panel (K923Part): its messages of table М.1
    PlcStopped,          // the PLC in «ОТЛАДКА СТОП»: «Режим ПЛК СТОП !», outputs off, 9
};
inline constexpr int kFaultCount = 16;

// The parts of the K923 a K923 fault breaks (its detail), appendix М table М.1.
enum class K923Part : int {
    PlcLink = 1,        // «НЕТ СВЯЗИ С ПЛК»: K keys lost, K LEDs dark
    PositionerLink = 2, // «НЕТ СВЯЗИ С БП»: no screens
    Ram = 3,            // «НЕИСПРАВНО ОЗУ»
    Resident = 4,       // «НАРУШЕН РЕЗИДЕНТ»
};
inline constexpr int kK923PartCount = 4;

// The parts of the positioner a PositionerModule fault breaks (its detail)
// and the message each gives (appendix М, the power-on test and the
// system checks of every tick).
enum class PositionerPart : int {
    PulseModule1 = 1, // CP34.23 at place 0 (axis X encoder, handwheel 1): 2; its counters stop
    PulseModule2 = 2, // CP34.23 at place 1 (axis Z encoder, handwheel 2): 18; its counters stop
    DacModule = 3,    // CM32.03: 3; the drives get 0 V
    CommModule = 4,   // CP52.05: 14
    PanelLink = 5,    // positioner <-> K923 exchange unstable: 25
    Memory = 6,       // the RAM/ROM test fails: 30
};
inline constexpr int kPositionerPartCount = 6;
std::string_view faultName(Fault f); // "encoder_channel_break", ...

struct FaultSpec {
    FaultSpec() = default;
    FaultSpec(Fault k, AxisId a = AxisId::X, int d = 0, std::string e = {})
        : kind(k), axis(a), detail(d), equipment(std::move(e)) {}
    Fault kind = Fault::EmergencyStop;
    AxisId axis = AxisId::X;
    int detail = 0;        // channel (1, 2), direction (+1, -1), module place
    std::string equipment; // spindle or pump name
    bool operator==(const FaultSpec&) const = default;
};
// A fault as displays name it (machine/fault_catalog.h: the id, its arguments
// and core's catalog of them; the desktop's app/studio/machine/fault_texts.cpp).
FaultText faultText(const FaultSpec& f);
// In a language from core's catalog, e.g. "Encoder X: channel 1 broken": the
// text of faultText for the CLI and logs.
std::string describeFault(const FaultSpec& f, bool russian = false);

// ---------------------------------------------------------------------------
// Views for displays.
struct AxisPlantView {
    bool present = false;
    double slideMm = 0, machineMm = 0; // machine system as displayed (× 2 on a diameter axis)
    bool cam = false, limitPlus = false, limitMinus = false;
    bool drivePower = false, driveReady = false;
};
struct SpindleView {
    std::string name;
    double rpm = 0, targetRpm = 0, nominalRpm = 0;
    bool atSpeed = false, driveReady = true;
};
struct PumpView {
    std::string name;
    bool on = false, pressure = false, overload = false;
};
struct MachineView {
    bool estopPressed = false, estopCircuit = true, drivesPower = false;
    std::vector<std::pair<std::string, bool>> lamps; // the lamps the description wires
    std::array<AxisPlantView, 2> axes{};
    std::vector<SpindleView> spindles;
    std::vector<PumpView> pumps;
    bool hasChuck = false, chuckClamped = false, chuckOpen = false;
    bool hasTurret = false, turretLocked = false;
    int turretStation = 0, turretPositions = 0;
    bool hasDoor = false, doorClosed = true, doorLocked = false;
    bool hasGrinding = false;
    double wheelMm = 0, boreMm = 0, sizeMm = 0, dressedMm = 0;
    bool ringPresent = false, gaugeIn = false, touch = false, rough = false, finish = false,
         size = false;
    int ringsGround = 0;
    bool hasHandwheel = false, hasOverrideSwitch = false;
    HandwheelAxis wheelAxis = HandwheelAxis::Off;
    int wheelStep = 0;
    int overrideCode = -1; // -1: the K923 L keys decide
};

class Simulation {
public:
    // The machine of `profile`: its description is found by the simulation
    // key `machine`, else by the profile's name (resources/machines/<name>.json),
    // else the generic machine. Throws plc::DescriptionError for a bad
    // description or wiring.
    explicit Simulation(const profile::MachineProfile& profile);
    Simulation(const profile::MachineProfile& profile, const plc::MachineDescription& description);
    // A built-in profile by name, or a machine file (profile::load).
    explicit Simulation(std::string_view profileNameOrPath);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    static plc::MachineDescription descriptionFor(const profile::MachineProfile& profile);

    engine::Positioner& controller() { return *ctl_; }
    const engine::Positioner& controller() const { return *ctl_; }
    plc::Plc& plc() { return *plc_; }
    const plc::Plc& plc() const { return *plc_; }
    const profile::MachineProfile& profile() const { return ctl_->profile(); }
    const plc::MachineDescription& description() const { return plc_->description(); }
    // Things that work but look wrong (a PLC message without a text ...).
    const std::vector<std::string>& warnings() const { return warnings_; }

    // --- time -----------------------------------------------------------------
    // The controller's power-on (self-test); tick() does it when needed.
    void powerOn();
    void tick();
    void advance(std::int64_t ms); // whole ticks
    bool runUntil(const std::function<bool()>& done, std::int64_t maxMs);
    // Called at the end of every tick (a trace recorder: machine/trace.h).
    void setAfterTick(std::function<void()> f) { afterTick_ = std::move(f); }
    // More observers of every tick, beside that hook (the backplot's live
    // path, the message recorder core/msglog): called after it, in the order
    // added. The id removes it.
    int addTickObserver(std::function<void()> f);
    void removeTickObserver(int id);
    std::int64_t timeMs() const { return ctl_->timeMs(); }
    std::int64_t tickMs() const { return ctl_->tickMs(); }

    // --- the operator at the machine ------------------------------------------
    void press(Button b);
    void release(Button b);
    // Pressed now, released `ms` later (a push of the hand).
    void pressFor(Button b, std::int64_t ms = 100);
    bool buttonDown(Button b) const;
    void pressEmergencyStop();   // latches
    void releaseEmergencyStop(); // pull out the mushroom
    bool emergencyStopPressed() const;
    bool hasHandwheel() const;
    void selectHandwheel(HandwheelAxis a);
    void selectHandwheelMultiplier(int step); // 0, 1, 2
    void turnHandwheel(std::int64_t detents);
    // Display discretes of the selected axis per detent at multiplier step
    // 0..2 (what the multiplier positions really give on this machine).
    std::int64_t handwheelDiscretesPerDetent(int step) const;
    bool hasOverrideSwitch() const;
    void setOverrideSwitch(int code); // 0..10, -1 = «K923» (the panel's L keys)
    int overrideSwitch() const;
    bool openDoor(); // false while the door is locked or absent
    void closeDoor();
    bool hasDoor() const { return eq_.door != nullptr; }
    // Grinder: a new wheel is mounted and the setter enters its diameter
    // R207 = R204 (ПРЕДУСТАНОВКИ); false if the machine has no wheel or the
    // wheel turns.
    bool changeWheel();

    // --- faults for training ----------------------------------------------------
    // Throws std::invalid_argument when the fault does not fit the machine
    // (an absent axis or equipment, a module place outside 0..15).
    void inject(const FaultSpec& f);
    void clear(const FaultSpec& f);
    void clearFaults();
    bool faultActive(const FaultSpec& f) const;
    const std::vector<FaultSpec>& faults() const { return faults_; }
    // The faults this machine can show (for a trainer's menu).
    std::vector<FaultSpec> availableFaults() const;
    // The K923's state for its panel model (K923 and PlcStopped faults).
    panel::Health k923Health() const;

    // --- views -----------------------------------------------------------------
    MachineView view() const;
    const Signals& machineSignals() const { return signals_; }
    Equipment& equipment() { return eq_; }
    const Equipment& equipment() const { return eq_; }
    double slideMm(AxisId a) const;
    double machineMm(AxisId a) const; // × 2 on a diameter axis
    const engine::AxisPlacement& placement(AxisId a) const;
    // M codes the positioner handed to the PLC, in order.
    std::vector<int> mCodes() const;

private:
    struct AxisPlant {
        bool present = false;
        std::optional<axis::Mechanics> mech;
        engine::AxisPlacement place;
        int encoderChannel = -1, dacChannel = -1;
        int camSig = -1, limPlusSig = -1, limMinusSig = -1, readySig = -1;
        std::array<engine::FastFunction, 8> inputFn{};
        std::array<bool, 8> inputLevel{};
        bool driveFault = false;
        int stuckLimit = 0; // +1 / -1: a limit switch reads as hit
        std::int64_t glitchCounts = 0;
        // Slide positions (mm) between the switch points around the last
        // position looked at, an open interval: inside it the cam and the
        // limit switches read as they do (senseSwitches).
        double switchLoMm = 0, switchHiMm = 0;
        bool ready = false; // the ready contact as last sensed
        // Channels the plant writes (refreshIoWiring): the encoder's pulse
        // channel unless absent, unwired or its CP34.23 failed; the DAC
        // channel unless unwired or the CM32.03 failed (then 0 V). -1: none.
        int encoderOut = -1, dacIn = -1;
    };
    struct Wire {
        int plcIndex;
        int signal;
        bool inverted;
    };
    struct TimedRelease {
        Button button;
        std::int64_t atMs;
    };

    void build(const profile::MachineProfile& profile, const plc::MachineDescription& d);
    AxisPlant& ax(AxisId a) { return axes_[static_cast<std::size_t>(engine::axisIndex(a))]; }
    const AxisPlant& ax(AxisId a) const {
        return axes_[static_cast<std::size_t>(engine::axisIndex(a))];
    }
    void readPlant(std::int64_t nowMs);
    void senseDrives(std::int64_t nowMs);
    void senseSwitches(AxisPlant& x);
    void refreshIoWiring();
    void writeAllInputs();
    void writeHandwheels(engine::MachineIo& io) const;
    void writeSensorInputs();
    void actuate(double dtMs);
    void checkFault(const FaultSpec& f) const;
    void applyFault(const FaultSpec& f, bool on);

    std::unique_ptr<engine::Positioner> ctl_;
    Signals signals_;
    Equipment eq_;
    std::unique_ptr<plc::Plc> plc_;
    std::array<AxisPlant, 2> axes_{};
    std::vector<Wire> inputs_, outputs_;
    std::array<int, 2> wheelChannel_{-1, -1};
    int drivesPowerAct_ = -1, drivesOnSig_ = -1;
    std::int64_t drivesPowerSinceMs_ = -1;
    // senseDrives: the drives' power and ready delay (ms) it last saw, and
    // whether it must look at everything (a fault changed an axis, the
    // ready delay runs, the PLC switched the drives' contactor).
    bool sensedPower_ = false;
    double sensedDelayMs_ = -1;
    bool senseAll_ = true;
    // readPlant: a fault changed the positioner's inputs or
    // their wiring (module health, the link, counts added): write them all.
    bool ioStale_ = true;
    std::array<int, 2> wheelOut_{-1, -1}; // the handwheels' live channels
    bool wheelOverEncoder_ = false;       // a handwheel shares an encoder's channel
    bool lostLink_ = false;
    std::uint8_t brokenParts_ = 0; // bit PositionerPart-1
    std::vector<TimedRelease> releases_;
    std::vector<FaultSpec> faults_;
    std::vector<std::string> warnings_;
    std::function<void()> afterTick_;
    std::vector<std::pair<int, std::function<void()>>> tickObservers_;
    int nextObserver_ = 1;
};

} // namespace k528::machine
