#include "machine/signals.h"

#include <stdexcept>

namespace k528::machine {

int Signals::addSensor(const std::string& name, std::string_view meaning) {
    if (sensorIndex_.count(name))
        throw std::logic_error("machine signal added twice: " + name);
    const int i = static_cast<int>(sensors_.size());
    sensors_.push_back(0);
    sensorNames_.push_back({name, std::string(meaning)});
    sensorIndex_.emplace(name, i);
    changed_ = true;
    return i;
}

int Signals::addActuator(const std::string& name, std::string_view meaning) {
    if (actuatorIndex_.count(name))
        throw std::logic_error("machine signal added twice: " + name);
    const int i = static_cast<int>(actuators_.size());
    actuators_.push_back(0);
    actuatorNames_.push_back({name, std::string(meaning)});
    actuatorIndex_.emplace(name, i);
    return i;
}

std::optional<int> Signals::findSensor(std::string_view name) const {
    const auto it = sensorIndex_.find(name);
    if (it == sensorIndex_.end())
        return std::nullopt;
    return it->second;
}

std::optional<int> Signals::findActuator(std::string_view name) const {
    const auto it = actuatorIndex_.find(name);
    if (it == actuatorIndex_.end())
        return std::nullopt;
    return it->second;
}

} // namespace k528::machine
