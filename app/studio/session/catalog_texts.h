// Names and messages of core's catalogs in the window's language: each is
// marked for the translators with core's English and translated into
// core's Russian letter by letter (studio.ui_language compares them). The
// positioner's messages of table М.1, the controller's modes, the preset
// groups of the R-parameters, the kinds of tool.
#pragma once

#include <QString>

#include <cstdint>

namespace k528::engine {
enum class Mode : std::uint8_t;
struct AlarmView;
} // namespace k528::engine
namespace k528::profile {
enum class ToolKind;
} // namespace k528::profile

namespace k528::studio {

// The positioner's message 1..64 without its number, e.g. «Конечник оси X
// в «-»» / "Limit switch X \"-\""; "" outside 1..64.
QString positionerMessageText(int number);
// An alarm's message without its number: the catalog's in the window's
// language, else what the alarm carries (a number outside the catalog: «#70»).
QString alarmMessage(const engine::AlarmView& a);
// An alarm as one line with its number, e.g. «10. Конечник оси X в «-»».
QString alarmLine(const engine::AlarmView& a);
// Message `number` of table М.1 as one line with its number in the window's
// language (in Russian the panel's text, «15.Разрушены С-параметры»).
QString positionerMessageLine(int number);
// «АВТОМАТ» / "automatic", «РУЧНОЙ» / "manual", …
QString modeName(engine::Mode m);
// The name of the R-parameters' preset group 1..9, «КООРД.И СМЕЩЕНИЯ» /
// "coordinates and offsets"; "" outside 1..9.
QString rGroupName(int group);
// «проходной» / "turning", «расточной» / "boring", …
QString toolKindText(profile::ToolKind k);

} // namespace k528::studio
