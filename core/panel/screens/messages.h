// The service messages of the K923 (2.6, appendix М): the three lists of
// the HELP screens and the mark in column 20 of line 1.
//
//   list             what it shows                                       mark
//   1 СООБЩЕНИЯ      PLC work messages whose bit is set (Z1902/Z1903)     «*»
//   2 НЕИСПРАВНОСТИ  positioner faults and program errors, latched        «!»
//                    (AlarmCategory Fault and Program), then the latched
//                    machine alarms of the PLC (Z1900/Z1901)
//   3 СИСТЕМА        positioner system messages, latched (AlarmCategory    «?»
//                    System), then the latched PLC system messages (Z1307)
//
// The mark shows the most serious list that is not empty: «!» before «?»
// before «*». Positioner messages are listed in the order they came, PLC
// messages by bit; texts: «13.Ошибка …» for the positioner (appendix М), the
// profile's texts for the PLC (its address, «Z1900.3», when the profile has none).
#pragma once

#include "engine/positioner.h"

#include <string>
#include <string_view>
#include <vector>

namespace k528::panel {

enum class ServiceList { Messages = 1, Faults = 2, System = 3 };

// «СООБЩЕНИЯ», «НЕИСПРАВНОСТИ», «СИСТЕМА».
std::string_view serviceListTitle(ServiceList l);
// The entries of a list, as the panel shows them (one text per entry).
std::vector<std::string> serviceEntries(const engine::Positioner& c, ServiceList l);
// U'!', U'?', U'*' or 0.
char32_t serviceMark(const engine::Positioner& c);

} // namespace k528::panel
