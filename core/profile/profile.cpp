#include "profile/profile.h"

#include <stdexcept>
#include <string>

namespace k528::profile {

namespace {

void checkNumber(int number) {
    if (number < 1 || number > catalog::kCParamCount)
        throw std::out_of_range("no C-parameter " + std::to_string(number) + " (1..152)");
}

} // namespace

std::int64_t MachineProfile::cValue(int number) const {
    checkNumber(number);
    return c[static_cast<std::size_t>(number)];
}

void MachineProfile::setC(int number, std::int64_t value) {
    checkNumber(number);
    c[static_cast<std::size_t>(number)] = value;
}

std::map<int, std::string>& MachineProfile::plcTexts(catalog::PlcGroup g) {
    switch (g) {
    case catalog::PlcGroup::Alarm:
        return plcAlarm;
    case catalog::PlcGroup::Work:
        return plcWork;
    case catalog::PlcGroup::System:
        return plcSystem;
    }
    return plcAlarm;
}

const std::map<int, std::string>& MachineProfile::plcTexts(catalog::PlcGroup g) const {
    return const_cast<MachineProfile*>(this)->plcTexts(g);
}

std::int64_t axisValue(const MachineProfile& p, catalog::Axis axis, int xNumber) {
    if (xNumber < 1 || xNumber > catalog::kAxisBlock || axis == catalog::Axis::Common)
        throw std::out_of_range("no axis parameter " + std::to_string(xNumber));
    return p.cValue(catalog::axisParam(xNumber, axis));
}

bool axisPresent(const MachineProfile& p, catalog::Axis axis) {
    return axisValue(p, axis, catalog::c::kAxisPresent) == 1;
}

units::AxisScale axisScale(const MachineProfile& p, catalog::Axis axis) {
    units::AxisScale s;
    if (axisValue(p, axis, catalog::c::kDiscrete0001) == 1)
        s.discrete = units::Discrete::Mm0_0001;
    else if (axisValue(p, axis, catalog::c::kDiscrete001) == 1)
        s.discrete = units::Discrete::Mm0_001;
    else if (axisValue(p, axis, catalog::c::kDiscrete01) == 1)
        s.discrete = units::Discrete::Mm0_01;
    else
        s.discrete = units::Discrete::Mm0_001;
    s.diameter = axisValue(p, axis, catalog::c::kDiameter) == 1;
    return s;
}

} // namespace k528::profile
