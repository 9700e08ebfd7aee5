// Messages of the K528-05 shown on the K923 panel (appendix М, section 2.3):
//   - the positioner's messages 1..64 («Сообщения от БП», table М.1);
//   - the K923's own messages at the top of table М.1 (no number);
//   - the three groups of PLC messages the machine builder writes (32 alarm
//     messages Z1900/Z1901, 32 work messages Z1902/Z1903, 16 system messages
//     Z1307) and the technological messages #1..99 of programs.
#pragma once

#include "catalog/cparams.h"

#include <span>
#include <string>
#include <string_view>

namespace k528::catalog {

inline constexpr int kPositionerMessageCount = 64;

enum class MessageGroup {
    Servo,         // drive, position loop, limit switches of an axis
    Encoder,       // encoder channels and checks
    Configuration, // machine constants (13, 15, 29, 37..39)
    Homing,        // reference-point cycle (40..42)
    Wheel,         // grinding wheel diameter (43, 44)
    Program,       // errors in a control program («Ошибка в УП», 31, 45)
    Hardware,      // modules, memory, emergency stop
    Communication, // links between positioner, PLC and panel
};

std::string_view messageGroupName(MessageGroup g); // "servo", "encoder", ...

struct PositionerMessage {
    int number;                 // 1..64
    std::string_view textRu;    // the panel text without its number
    std::string_view commentRu; // column «Комментарий»
    std::string_view textEn;
    std::string_view commentEn;
    Axis axis;       // X, Z, or Common when not about one axis
    int counterpart; // the same message of the other axis (7 <-> 23), 0 if none
    MessageGroup group;
    std::string_view note; // OCR fixes (English) or ""

    // "13.Ошибка коэфф.преобразования ДОС (X)", "37. Ошибка N ДОС": the
    // number, a dot (and the blank table М.1 prints after some), the text,
    // as the panel shows it.
    std::string panelText() const;
};

// A message's line with its number, for every place that shows one: Russian
// as the panel and table М.1 print it — a dot, and the blank after it where
// the manual has one («37. Ошибка N ДОС», «39.Ошибка N маховика»); English
// always with the blank («39. Handwheel N error»).
std::string numberedMessage(int number, std::string_view text, bool russian);

// All 64 in number order: positionerMessages()[i].number == i + 1.
std::span<const PositionerMessage> positionerMessages();
// Throws std::out_of_range outside 1..64.
const PositionerMessage& positionerMessage(int number);
const PositionerMessage* findPositionerMessage(int number) noexcept;
// The same message for the other axis (7 -> 23, 23 -> 7), 0 if it has none.
int messageCounterpart(int number);
// The message `xNumber` means for `axis` (e.g. 13 for X is 29 for Z). Returns
// `xNumber` for messages that are not per axis.
int messageForAxis(int xNumber, Axis axis);

// The K923's own messages (top of table М.1).
enum class PanelMessageId {
    PlcStop,         // Режим ПЛК СТОП !
    ResidentCorrupt, // НАРУШЕН РЕЗИДЕНТ
    RamFault,        // НЕИСПРАВНО ОЗУ
    InputError,      // ОШИБКА ВВОДА
    PlcLinkError,    // ОШИБКА СВЯЗИ С ПЛК
    NoPlcLink,       // НЕТ СВЯЗИ С ПЛК
    NoPositionerLink // НЕТ СВЯЗИ С БП
};

struct PanelMessage {
    PanelMessageId id;
    std::string_view textRu;
    std::string_view commentRu;
    std::string_view textEn;
    std::string_view commentEn;
};

std::span<const PanelMessage> panelMessages();
const PanelMessage& panelMessage(PanelMessageId id);

// PLC messages (section 2.3, appendix И): written by the machine builder,
// shown while / after the bit of the group's word is set.
enum class PlcGroup {
    Alarm, // «аварийные сообщения» (machine faults), Z1900.0..Z1901.15, kept until acknowledged
    Work, // «рабочие сообщения» (operator information), Z1902.0..Z1903.15, shown while set
    System, // «системные сообщения» (module failures), Z1307.0..Z1307.15, kept until acknowledged
};

inline constexpr PlcGroup kPlcGroups[] = {PlcGroup::Alarm, PlcGroup::Work, PlcGroup::System};

// 32, 32, 16.
int plcMessageCount(PlcGroup g);
// The PLC bit of message k (1-based): Alarm 1 -> "Z1900.0", Alarm 17 -> "Z1901.0",
// Work 1 -> "Z1902.0", System 16 -> "Z1307.15". Throws std::out_of_range.
std::string plcMessageAddress(PlcGroup g, int k);
std::string_view plcGroupNameRu(PlcGroup g);
std::string_view plcGroupNameEn(PlcGroup g);
// Key letter in machine files: 'A', 'W', 'S'.
char plcGroupLetter(PlcGroup g);

// Text limits, in characters (code points) of the 20-column LCD.
// A technological message is shown on one LCD line (program-language.md).
inline constexpr int kTechMessageCount = 99;
inline constexpr int kTechMessageMaxChars = 20;
// PLC messages take two LCD lines of the service screens, as the positioner's
// own messages do (table М.1 prints them broken after 20 characters, e.g.
// «8.Контроль полож/за-|жима оси X»): at most 40 characters. See
// docs/machine-constants.md.
inline constexpr int kPlcMessageMaxChars = 40;

} // namespace k528::catalog
