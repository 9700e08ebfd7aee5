// An ideal machine and a minimal PLC around a Positioner: the test double of
// the engine and the machine `k528 run` drives (the full simulated PLC and
// machine are core/plc and core/machine).
//
// Machine side: one axis::Mechanics per present axis, built from the
// profile's simulation keys (screw lead and gear ratio -> slide travel per
// motor revolution, encoder lines, drive volts/speed, time constant) and
// wired as the constants expect (ЗНАК ДОС, ЗНАК ЦАП, N ДОС, N ЦАП, N М1/М2).
// Switches are placed physically along the slide, derived from the
// constants so that the reference-point cycle ends with the machine system
// equal to the slide position (× 2 on a diameter axis): the deceleration cam
// before the reference point, the encoder's zero mark where the cycle finds
// it, limit switches 2 mm of slide beyond the soft limits (or where the
// simulation keys put them). Their signals reach the positioner through a
// fast input when C107..C122 give one that function, else through the PLC
// bit of appendix И (Z1005.3/.5/.6, Z1006.12..15).
//
// PLC side (writes only its own bits; tests may set the others): emergency
// stop released, general and axis feed enable, start enable, regulator
// enable of present axes, «ДОС включен»; «Пуск», «Стоп», «Сброс» and
// acknowledgement as pulses; the mode code; the override code; jog and
// handwheel bits on request; M functions acknowledged on Z1000.11 a settable
// delay after the strobe (plc.m_ack_delay_ms, 40 ms = GOST T3).
// Details and defaults: docs/plc-interface.md.
#pragma once

#include "axis/mechanics.h"
#include "engine/positioner.h"
#include "engine/fast_inputs.h"

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace k528::engine {

// Where the switches and marks of one axis are, in mm of slide travel.
struct AxisPlacement {
    double displayPerSlide = 1; // 2 on a diameter axis
    double camLoMm = 0, camHiMm = 0;
    double zeroMarkMm = 0;
    double limitMinusMm = -1e9, limitPlusMm = 1e9;
    double startMm = 0;
};

// The placement the machine derives from a profile (exposed for tests and docs).
AxisPlacement placeAxis(const profile::MachineProfile& p, AxisId axis);
// The mechanics of an axis from the profile's simulation keys.
axis::MechanicsSettings mechanicsOf(const profile::MachineProfile& p, AxisId axis);

class IdealMachine {
public:
    explicit IdealMachine(Positioner& controller);

    Positioner& controller() { return c_; }

    // --- time -----------------------------------------------------------
    // One tick: the PLC scan and the switches, the positioner, the drives.
    void tick();
    void advance(std::int64_t ms);
    // Ticks until `done()` or `maxMs` passed; true if done.
    bool runUntil(const std::function<bool()>& done, std::int64_t maxMs);

    // --- the machine's operator panel (through the PLC) --------------------
    void pressStart() { startPulse_ = pulseTicks_; }
    void pressStop() { stopPulse_ = pulseTicks_; }
    void pressReset() { resetPulse_ = pulseTicks_; }
    void pressAcknowledge() { ackPulse_ = pulseTicks_; }
    void setEmergencyStop(bool pressed) { estop_ = pressed; }
    void setFeedEnable(bool on) { feedEnable_ = on; }
    void setStartEnable(bool on) { startEnable_ = on; }
    void setDataHold(bool on) { dataHold_ = on; }
    void setModeCode(int code) { modeCode_ = code; }
    void setOverrideCode(std::optional<int> code) { overrideCode_ = code; }
    void startCycle(int n) { cyclePulse_[static_cast<std::size_t>(n - 1)] = pulseTicks_; }
    void setR150Bit(bool on) { r150_ = on; }
    // Jog: dir +1/-1, 0 releases.
    void setJog(AxisId a, int dir, bool rapid = false);
    void setRegulatorEnable(AxisId a, bool on) { ax(a).regulator = on; }
    void setAxisFeedEnable(AxisId a, bool on) { ax(a).feed = on; }
    void setLoopOff(AxisId a, bool on) { ax(a).loopOff = on; }
    void setAccel2(AxisId a, bool on) { ax(a).accel2 = on; }
    // Handwheel `wheel` (1, 2) on axis a, with multiplier and DRF.
    void setHandwheel(AxisId a, int wheel, bool on, bool multiplier = false, bool drf = false);
    void turnHandwheel(int wheel, std::int64_t pulses) {
        wheelCount_[static_cast<std::size_t>(wheel - 1)] += pulses;
    }
    // Gauge / touch signal n (1..4) of axis a (Gx36..Gx39).
    void setSignal(AxisId a, int n, bool on) { ax(a).signal[static_cast<std::size_t>(n - 1)] = on; }
    // PLC messages: alarm k (1..32), work k (1..32), system k (1..16).
    void setPlcAlarm(int k, bool on);
    void setPlcWork(int k, bool on);
    void setPlcSystem(int k, bool on);

    // --- M functions ------------------------------------------------------
    void setMAckDelayMs(std::int64_t ms) { mAckDelayMs_ = ms; }
    void setAutoAcknowledgeM(bool on) { autoAckM_ = on; }
    // Acknowledges the M on the strobe now (when automatic acknowledgement is off).
    void acknowledgeM() { manualAck_ = true; }
    // M codes acknowledged so far, in order.
    const std::vector<int>& mLog() const { return mLog_; }

    // --- machine faults (training) -----------------------------------------
    void setDriveReady(AxisId a, bool ready) { ax(a).driveReady = ready; }
    axis::Mechanics* mechanics(AxisId a) { return ax(a).mech ? &*ax(a).mech : nullptr; }

    // --- state -------------------------------------------------------------
    const AxisPlacement& placement(AxisId a) const {
        return axes_[static_cast<std::size_t>(axisIndex(a))].place;
    }
    double slideMm(AxisId a) const;
    // The slide position as the machine system shows it (× 2 on a diameter axis).
    double machineMm(AxisId a) const { return slideMm(a) * placement(a).displayPerSlide; }
    bool camPressed(AxisId a) const;
    bool limitPlusPressed(AxisId a) const;
    bool limitMinusPressed(AxisId a) const;

private:
    struct Axis {
        bool present = false;
        std::optional<axis::Mechanics> mech;
        AxisPlacement place;
        int encoderChannel = -1, dacChannel = -1;
        bool regulator = true, feed = true, loopOff = false, accel2 = false, driveReady = true;
        int jogDir = 0;
        bool jogRapid = false;
        std::array<bool, 2> wheelOn{}, wheelMult{}, wheelDrf{};
        std::array<bool, 4> signal{};
        // Fast inputs of the axis' CP34.23: function of each input, its
        // active level, and which functions are wired (bit f).
        std::array<FastFunction, 8> inputFn{};
        std::array<bool, 8> inputLevel{};
        unsigned wiredFunctions = 0;
    };
    Axis& ax(AxisId a) { return axes_[static_cast<std::size_t>(axisIndex(a))]; }
    void plcScan();
    void sensors();
    static void countDown(int& pulse) {
        if (pulse > 0)
            --pulse;
    }

    Positioner& c_;
    std::array<Axis, kAxisCount> axes_{};
    std::array<std::int64_t, 2> wheelCount_{};
    std::array<int, 2> wheelChannel_{-1, -1};
    int pulseTicks_ = 20;
    int startPulse_ = 0, stopPulse_ = 0, resetPulse_ = 0, ackPulse_ = 0;
    std::array<int, 8> cyclePulse_{};
    bool estop_ = false, feedEnable_ = true, startEnable_ = true, dataHold_ = false, r150_ = false;
    int modeCode_ = 0;
    std::optional<int> overrideCode_;
    std::int64_t mAckDelayMs_ = 40;
    bool autoAckM_ = true, manualAck_ = false;
    std::int64_t strobeSince_ = -1;
    std::vector<int> mLog_;
};

} // namespace k528::engine
