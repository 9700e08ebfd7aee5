// The names of the simulated machine's faults: a fault as displays name it
// (a stable id and its arguments, machine::faultText) and core's catalog of
// those ids in Russian and English. The command line says them from here
// (describeFault), the desktop the same ids through its translators
// (app/studio/machine/fault_texts.cpp; studio.ui_language fails on an id it
// lacks or says differently).
#pragma once

#include "util/text_catalog.h"

#include <string>
#include <vector>

namespace k528::machine {

// A fault as displays name it: a stable id and its arguments.
//   encoder_channel_break {axis, channel}   drive_not_ready {axis}
//   limit_switch {axis, "+"|"-"}            emergency_stop {}
//   dac_limit {axis}                        plc_module_failure {place}
//   lost_link {}                            spindle_drive {equipment}
//   spindle_overheat {equipment}            pump_overload {equipment}
//   chuck_pressure {}  turret_jam {}  gauge_fault {}  plc_stopped {}
//   positioner_module.pulse_module_1 / .pulse_module_2 / .dac_module /
//     .comm_module / .panel_link / .memory {}
//   k923.plc_link / .positioner_link / .ram / .resident {}
// (axis "X"/"Z", numbers in decimal, equipment by its description name).
struct FaultText {
    std::string id;
    std::vector<std::string> args;
    // args[0] is a piece of equipment by its description's name: said as
    // the catalog's "equipment.<name>" when it has one (the shipped
    // machines' spindles and pumps), else as the name.
    bool namesEquipment = false;
};

// The catalog: each id with its Russian and English (%1..%9 the arguments),
// and the shipped machines' equipment ("equipment.coolant": «насос СОЖ»).
util::TextCatalog faultTexts();

// The id of a piece of equipment's name in faultTexts().
std::string equipmentTextId(const std::string& name);

// The fault in a language, e.g. «ДОС X: обрыв канала 1» / "Encoder X:
// channel 1 broken"; an id the catalog lacks says the id and its arguments.
std::string faultTextIn(const FaultText& t, bool russian);

} // namespace k528::machine
