// The electrical signals of the simulated machine, by name: sensors (switch
// contacts, relay contacts of drives, pressure switches — machine -> PLC
// inputs, or the positioner's fast inputs) and actuators (contactors,
// solenoid valves, lamps — PLC outputs -> machine). The machine description
// wires PLC inputs and outputs to these names (docs/machine-description.md
// lists them); the equipment of core/machine reads actuators and writes
// sensors. A sensor change marks the image changed, so that the PLC's inputs
// and the fast inputs are refreshed only when something happened; an
// actuator change wakes the equipment, which ticks only while it may change
// something (machine/equipment.h).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace k528::machine {

class Signals {
public:
    int addSensor(const std::string& name, std::string_view meaning);
    int addActuator(const std::string& name, std::string_view meaning);
    std::optional<int> findSensor(std::string_view name) const;
    std::optional<int> findActuator(std::string_view name) const;

    bool sensor(int s) const { return s >= 0 && sensors_[static_cast<std::size_t>(s)] != 0; }
    void setSensor(int s, bool v) {
        std::uint8_t& x = sensors_[static_cast<std::size_t>(s)];
        if (x != static_cast<std::uint8_t>(v)) {
            x = static_cast<std::uint8_t>(v);
            changed_ = true;
        }
    }
    bool actuator(int a) const { return a >= 0 && actuators_[static_cast<std::size_t>(a)] != 0; }
    void setActuator(int a, bool v) {
        std::uint8_t& x = actuators_[static_cast<std::size_t>(a)];
        if (x != static_cast<std::uint8_t>(v)) {
            x = static_cast<std::uint8_t>(v);
            equipmentAwake_ = true;
        }
    }

    // Whether a sensor changed since the last call.
    bool takeChanged() {
        const bool c = changed_;
        changed_ = false;
        return c;
    }
    void markChanged() { changed_ = true; }

    // The equipment (spindles, pumps, chuck, turret, door) needs a tick: an
    // actuator changed, a unit is in a transition (a ramp, a stroke, an
    // indexing), or an operator or a fault changed a unit (its mutators
    // call this). Otherwise each unit's tick would change nothing, and
    // Simulation skips them.
    void wakeEquipment() { equipmentAwake_ = true; }
    // Whether the equipment needs a tick; a unit still in a transition
    // wakes it again for the next one.
    bool takeEquipmentAwake() {
        const bool a = equipmentAwake_;
        equipmentAwake_ = false;
        return a;
    }

    struct Entry {
        std::string name;
        std::string meaning;
    };
    const std::vector<Entry>& sensorList() const { return sensorNames_; }
    const std::vector<Entry>& actuatorList() const { return actuatorNames_; }

private:
    std::vector<std::uint8_t> sensors_, actuators_;
    std::vector<Entry> sensorNames_, actuatorNames_;
    std::map<std::string, int, std::less<>> sensorIndex_, actuatorIndex_;
    bool changed_ = true;
    bool equipmentAwake_ = true;
};

} // namespace k528::machine
