// Table М.1 of the manual (appendix М) and the PLC message groups of section 2.3.
//
// Panel texts are as printed, with the number kept apart. OCR slips fixed:
//   - line-break hyphens of the two-line panel texts removed
//     (8 «Контроль полож/за- жима», 12 «ко- нечный», 13 «пре- образования»);
//   - the number kept apart: «14. Отказ» -> number 14, «Отказ»; the blank
//     after the dot of the messages printed with one (14, 34..38, 47, 50..53,
//     55..64) is given back by panelText();
//   - module names in Latin letters (CP52.05, CP34.23) written in Cyrillic;
//   - quotes as printed: 9, 10, 11 typographic «» (10's broken «-« closed as
//     «-»), 26, 27, 40, 41 straight ("-").
//   - comments of 26/27 print «←»/«→» for «-»/«+» (as in 10/11).
#include "catalog/messages.h"

#include <stdexcept>
#include <string>

namespace k528::catalog {

namespace {

using G = MessageGroup;
constexpr Axis X = Axis::X;
constexpr Axis Z = Axis::Z;
constexpr Axis N = Axis::Common;

// clang-format off
const PositionerMessage kMessages[kPositionerMessageCount] = {
    {1, "Нет деблокировки регулятора X", "Нет деблокировки регулятора оси X",
        "No regulator enable X", "The drive regulator of axis X is not enabled", X, 17, G::Servo, ""},
    {2, "Нет ответа от ДОС 0-место", "Нет ответа от модуля СР34.23 на 0 месте в каркасе БП",
        "No answer from encoder slot 0", "No answer from the CP34.23 module in slot 0 of the positioner rack", N, 0, G::Hardware,
        "Comment prints the module as Latin «CP34.23»."},
    {3, "Нет ответа от ЦАП", "Нет ответа от модуля ЦАП в БП",
        "No answer from DAC", "No answer from the DAC module of the positioner", N, 0, G::Hardware, ""},
    {4, "Обрыв канала 1 ДОС (ось X)", "Обрыв первого канала датчика обратной связи оси X",
        "Encoder channel 1 broken (X)", "The first channel of the axis X encoder is broken", X, 20, G::Encoder, ""},
    {5, "Обрыв канала 2 ДОС (ось X)", "Обрыв второго канала датчика обратной связи оси X",
        "Encoder channel 2 broken (X)", "The second channel of the axis X encoder is broken", X, 21, G::Encoder, ""},
    {6, "Превышен предел ЦАП (ось X)", "Превышение предела ЦАП оси X",
        "DAC limit exceeded (X)", "The DAC code of axis X exceeded ПРЕДЕЛ ЦАП", X, 22, G::Servo, ""},
    {7, "Макс.рассогл.по X при движении", "Максимальное рассогласование по оси X при движении",
        "Max. following error X in motion", "The following error of axis X exceeded МАКС.ОШИБКА during motion", X, 23, G::Servo, ""},
    {8, "Контроль полож/зажима оси X", "Контроль положения оси X в остановленном состоянии по оси",
        "Position/clamp check X", "Position check of the stopped axis X (ДОПУСК КП exceeded)", X, 24, G::Servo,
        "Printed «Контроль полож/за- жима оси X» (line break)."},
    {9, "Аварийный «СТОП» от ПЛК", "Есть сигнал аварийного отключения от ПЛК",
        "Emergency \"STOP\" from PLC", "The PLC signals an emergency stop", N, 0, G::Hardware,
        ""},
    {10, "Конечник оси X в «-»", "Конечный выключатель по оси X в «-»",
        "Limit switch X \"-\"", "Limit switch of axis X in «-»", X, 26, G::Servo,
        "Printed «Конечник оси X в «-«» (broken quote)."},
    {11, "Конечник оси X в «+»", "Конечный выключатель по оси X в «+»",
        "Limit switch X \"+\"", "Limit switch of axis X in «+»", X, 27, G::Servo,
        ""},
    {12, "Программный конечный выключ.(X)", "Программный конечный выключатель по оси X",
        "Software limit switch (X)", "Software limit switch of axis X", X, 28, G::Servo,
        "Printed «Программный ко- нечный выключ.(X)» (line break)."},
    {13, "Ошибка коэфф.преобразования ДОС (X)",
        "Ошибка коэффициента преобразования импульсов датчика обратной связи оси X в параметрах станка",
        "Encoder ratio error (X)", "The encoder pulse ratio L/N of axis X in the machine constants is wrong", X, 29,
        G::Configuration, "Printed «Ошибка коэфф.пре- образования ДОС (X)» (line break)."},
    {14, "Отказ СР52.05 в БП", "Отказ связного модуля СР52.05 в БП",
        "CP52.05 failure in positioner", "The CP52.05 communication module of the positioner failed", N, 0, G::Hardware,
        "Printed «14. Отказ CP52.05 в БП» with a Latin «CP»."},
    {15, "Разрушены С-параметры", "Содержимое станочных параметров некорректно",
        "C-parameters destroyed", "The contents of the machine constants are not valid", N, 0, G::Configuration, ""},
    {16, "Нет готовности привода оси X", "Нет готовности привода оси X",
        "Drive X not ready", "The drive of axis X is not ready", X, 32, G::Servo, ""},
    {17, "Нет деблокировки регулятора Z", "Нет деблокировки регулятора оси Z",
        "No regulator enable Z", "The drive regulator of axis Z is not enabled", Z, 1, G::Servo, ""},
    {18, "Нет ответа от ДОС 1-место", "Нет ответа от модуля СР34.23 на 1 месте в каркасе БП",
        "No answer from encoder slot 1", "No answer from the CP34.23 module in slot 1 of the positioner rack", N, 0, G::Hardware,
        "Comment prints the module as Latin «CP34.23»."},
    {19, "Нет связи с ПЛК", "Нет связи БП с ПЛК",
        "No link with PLC", "The positioner has no link with the PLC", N, 0, G::Communication, ""},
    {20, "Обрыв канала 1 ДОС (ось Z)", "Обрыв первого канала датчика обратной связи оси Z",
        "Encoder channel 1 broken (Z)", "The first channel of the axis Z encoder is broken", Z, 4, G::Encoder, ""},
    {21, "Обрыв канала 2 ДОС (ось Z)", "Обрыв второго канала датчика обратной связи оси Z",
        "Encoder channel 2 broken (Z)", "The second channel of the axis Z encoder is broken", Z, 5, G::Encoder, ""},
    {22, "Превышен предел ЦАП (ось Z)", "Превышение предела ЦАП оси Z",
        "DAC limit exceeded (Z)", "The DAC code of axis Z exceeded ПРЕДЕЛ ЦАП", Z, 6, G::Servo, ""},
    {23, "Макс.рассогл.по Z при движении", "Максимальное рассогласование по оси Z при движении",
        "Max. following error Z in motion", "The following error of axis Z exceeded МАКС.ОШИБКА during motion", Z, 7, G::Servo, ""},
    {24, "Контроль полож/зажима оси Z", "Контроль положения оси Z в остановленном состоянии по оси",
        "Position/clamp check Z", "Position check of the stopped axis Z (ДОПУСК КП exceeded)", Z, 8, G::Servo, ""},
    {25, "Нет связи с панелью", "Связь БП и K923 неустойчива",
        "No link with panel", "The link between the positioner and the K923 is unstable", N, 0, G::Communication, ""},
    {26, "Конечник оси Z в \"-\"", "Конечный выключатель по оси Z в «-»",
        "Limit switch Z \"-\"", "Limit switch of axis Z in «-»", Z, 10, G::Servo,
        "Comment printed «←» for «-» (as in message 10)."},
    {27, "Конечник оси Z в \"+\"", "Конечный выключатель по оси Z в «+»",
        "Limit switch Z \"+\"", "Limit switch of axis Z in «+»", Z, 11, G::Servo,
        "Comment printed «→» for «+» (as in message 11)."},
    {28, "Программный конечный выключ.(Z)", "Программный конечный выключатель по оси Z",
        "Software limit switch (Z)", "Software limit switch of axis Z", Z, 12, G::Servo, ""},
    {29, "Ошибка коэфф.преобразования ДОС (Z)",
        "Ошибка коэффициента преобразования импульсов датчика обратной связи оси Z в параметрах станка",
        "Encoder ratio error (Z)", "The encoder pulse ratio L/N of axis Z in the machine constants is wrong", Z, 13,
        G::Configuration, ""},
    {30, "Отказ ОЗУ/ПЗУ позиционера", "Тестированием выявлена ошибка ОЗУ/ПЗУ",
        "Positioner RAM/ROM failure", "The self-test found a RAM/ROM error", N, 0, G::Hardware, ""},
    {31, "Разрушена управляющая программа", "Содержание области УП некорректно",
        "Control program destroyed", "The contents of the program area are not valid", N, 0, G::Program, ""},
    {32, "Нет готовности привода оси Z", "Нет готовности привода оси Z",
        "Drive Z not ready", "The drive of axis Z is not ready", Z, 16, G::Servo, ""},
    {33, "Задание координаты X", "Ошибка в УП",
        "X coordinate setting", "Error in the program", X, 49, G::Program, ""},
    {34, "X/L", "Ошибка в УП", "X/L", "Error in the program: X together with L", X, 50, G::Program, ""},
    {35, "X/M17", "Ошибка в УП", "X/M17", "Error in the program: X together with M17", X, 51, G::Program, ""},
    {36, "X/конец L", "Ошибка в УП", "X/end of L",
        "Error in the program: X in the last frame of a subprogram without M17", X, 52, G::Program, ""},
    {37, "Ошибка N ДОС", "Неверно задан номер ДОС в параметрах станка",
        "N encoder error", "Wrong encoder number in the machine constants", N, 0, G::Configuration, ""},
    {38, "Ошибка N ЦАП", "Неверно задан номер ЦАП в параметрах станка",
        "N DAC error", "Wrong DAC number in the machine constants", N, 0, G::Configuration, ""},
    {39, "Ошибка N маховика", "Неверно задан номер маховика в параметрах станка",
        "N handwheel error", "Wrong handwheel number in the machine constants", N, 0, G::Configuration, ""},
    {40, "Нет съезда с конечника \"0\"", "Ошибка при выполнении привязки к базовой точке",
        "Home switch not left", "Error in the reference-point cycle: the deceleration switch was not left", N, 0, G::Homing, ""},
    {41, "Нет \"0\"-метки", "Ошибка при выполнении привязки к базовой точке",
        "No \"0\" mark", "Error in the reference-point cycle: no encoder zero mark", N, 0, G::Homing, ""},
    {42, "Нет привязки к базовой точке", "Попытка запустить УП без привязки к базовой точке",
        "Not homed", "A program was started before homing", N, 0, G::Homing, ""},
    {43, "D круга > Dmax",
        "Диаметр шлифовального круга больше максимально допустимого. Выполнение УП блокируется. Циклы ручного режима разрешены",
        "Wheel D > Dmax",
        "The grinding wheel diameter is larger than the largest allowed. Programs are blocked; manual cycles are allowed",
        N, 0, G::Wheel, ""},
    {44, "D круга < Dmin",
        "Диаметр шлифовального круга меньше минимально допустимого. Выполнение УП блокируется. Циклы ручного режима разрешены",
        "Wheel D < Dmin",
        "The grinding wheel diameter is smaller than the smallest allowed. Programs are blocked; manual cycles are allowed",
        N, 0, G::Wheel, ""},
    {45, "L отсутствует", "Попытка запустить отсутствующую УП",
        "L missing", "A program that does not exist was started or called", N, 0, G::Program, ""},
    {46, "Переполнение", "Ошибка в УП", "Overflow", "Error in the program: arithmetic overflow", N, 0, G::Program, ""},
    {47, "G?", "Ошибка в УП", "G?", "Error in the program: unknown G-function", N, 0, G::Program, ""},
    {48, "Глубина вложения L", "Ошибка в УП", "Nesting depth L",
        "Error in the program: subprograms nested too deep", N, 0, G::Program, ""},
    {49, "Задание координаты Z", "Ошибка в УП", "Z coordinate setting", "Error in the program", Z, 33, G::Program, ""},
    {50, "Z/L", "Ошибка в УП", "Z/L", "Error in the program: Z together with L", Z, 34, G::Program, ""},
    {51, "Z/M17", "Ошибка в УП", "Z/M17", "Error in the program: Z together with M17", Z, 35, G::Program, ""},
    {52, "Z/конец L", "Ошибка в УП", "Z/end of L",
        "Error in the program: Z in the last frame of a subprogram without M17", Z, 36, G::Program, ""},
    {53, "Ошибка перехода", "Ошибка в УП", "Jump error",
        "Error in the program: jump to a frame that does not exist", N, 0, G::Program, ""},
    {54, "Дублирование номеров кадров", "Ошибка в УП", "Duplicate frame numbers",
        "Error in the program: two frames with one number", N, 0, G::Program, ""},
    {55, "Отказ модулей ввода/вывода в ПЛК", "Отказ модулей ввода/вывода в ПЛК",
        "PLC I/O module failure", "An input/output module of the PLC failed", N, 0, G::Hardware, ""},
    {56, "Контроль ДОС оси X",
        "В течение заданного в станочных параметрах времени контроля ДОС оси X выдавал неизменное значение положения при включенном приводе",
        "Encoder check X",
        "For the check time set in the machine constants the axis X encoder reported an unchanged position with the drive enabled",
        X, 57, G::Encoder, ""},
    {57, "Контроль ДОС оси Z",
        "В течение заданного в станочных параметрах времени контроля ДОС оси Z выдавал неизменное значение положения при включенном приводе",
        "Encoder check Z",
        "For the check time set in the machine constants the axis Z encoder reported an unchanged position with the drive enabled",
        Z, 56, G::Encoder, ""},
    {58, "M30/L", "Ошибка в УП", "M30/L", "Error in the program: M30 together with L", N, 0, G::Program, ""},
    {59, "M2/L", "Ошибка в УП", "M2/L", "Error in the program: M2 together with L", N, 0, G::Program, ""},
    {60, "M17/L", "Ошибка в УП", "M17/L", "Error in the program: M17 together with L", N, 0, G::Program, ""},
    {61, "M30/M17", "Ошибка в УП", "M30/M17", "Error in the program: M30 together with M17", N, 0, G::Program, ""},
    {62, "M2/M17", "Ошибка в УП", "M2/M17", "Error in the program: M2 together with M17", N, 0, G::Program, ""},
    {63, "G04/X/Z", "Ошибка в УП", "G04/X/Z", "Error in the program: G04 with Z", N, 0, G::Program, ""},
    {64, "G04/L", "Ошибка в УП", "G04/L", "Error in the program: G04 with L", N, 0, G::Program, ""},
};

const PanelMessage kPanelMessages[] = {
    {PanelMessageId::PlcStop, "Режим ПЛК СТОП !", "ПЛК в состоянии «ОТЛАДКА СТОП»",
        "PLC STOP mode !", "The PLC is in the «DEBUG STOP» state"},
    {PanelMessageId::ResidentCorrupt, "НАРУШЕН РЕЗИДЕНТ",
        "Разрушено резидентное программное обеспечение K923. Отказы системы",
        "RESIDENT CORRUPTED", "The resident software of the K923 is destroyed. System failure"},
    {PanelMessageId::RamFault, "НЕИСПРАВНО ОЗУ", "ОЗУ K923 неисправно. Отказы системы",
        "RAM FAULT", "The K923 RAM is faulty. System failure"},
    {PanelMessageId::InputError, "ОШИБКА ВВОДА", "Попытка ввести параметр недопустимого формата",
        "INPUT ERROR", "A value of an invalid format was entered"},
    {PanelMessageId::PlcLinkError, "ОШИБКА СВЯЗИ С ПЛК", "Сбой при обмене информацией с ПЛК",
        "PLC LINK ERROR", "An exchange with the PLC failed"},
    {PanelMessageId::NoPlcLink, "НЕТ СВЯЗИ С ПЛК",
        "Связь K923 с ПЛК не установлена. Постоянный вывод сообщения означает отказ системы",
        "NO LINK WITH PLC", "The K923 has no link with the PLC. A permanent message means a system failure"},
    {PanelMessageId::NoPositionerLink, "НЕТ СВЯЗИ С БП",
        "Связь K923 с БП не установлена. Постоянный вывод сообщения означает отказ системы",
        "NO LINK WITH POSITIONER", "The K923 has no link with the positioner. A permanent message means a system failure"},
};
// clang-format on

} // namespace

std::string_view messageGroupName(MessageGroup g) {
    switch (g) {
    case MessageGroup::Servo:
        return "servo";
    case MessageGroup::Encoder:
        return "encoder";
    case MessageGroup::Configuration:
        return "configuration";
    case MessageGroup::Homing:
        return "homing";
    case MessageGroup::Wheel:
        return "wheel";
    case MessageGroup::Program:
        return "program";
    case MessageGroup::Hardware:
        return "hardware";
    case MessageGroup::Communication:
        return "communication";
    }
    return "";
}

// Table М.1 prints these with a blank after the number's dot («37. Ошибка N ДОС»).
static bool printedWithBlank(int number) {
    return number == 14 || (number >= 34 && number <= 38) || number == 47 ||
           (number >= 50 && number <= 53) || number >= 55;
}

std::string numberedMessage(int number, std::string_view text, bool russian) {
    return std::to_string(number) + (!russian || printedWithBlank(number) ? ". " : ".") + std::string(text);
}

std::string PositionerMessage::panelText() const { return numberedMessage(number, textRu, true); }

std::span<const PositionerMessage> positionerMessages() {
    return kMessages;
}

const PositionerMessage* findPositionerMessage(int number) noexcept {
    if (number < 1 || number > kPositionerMessageCount)
        return nullptr;
    return &kMessages[number - 1];
}

const PositionerMessage& positionerMessage(int number) {
    const PositionerMessage* m = findPositionerMessage(number);
    if (!m)
        throw std::out_of_range("no positioner message " + std::to_string(number) + " (1..64)");
    return *m;
}

int messageCounterpart(int number) {
    const PositionerMessage* m = findPositionerMessage(number);
    return m ? m->counterpart : 0;
}

int messageForAxis(int xNumber, Axis axis) {
    const PositionerMessage& m = positionerMessage(xNumber);
    if (m.axis == Axis::Common || m.axis == axis || axis == Axis::Common)
        return xNumber;
    return m.counterpart;
}

std::span<const PanelMessage> panelMessages() {
    return kPanelMessages;
}

const PanelMessage& panelMessage(PanelMessageId id) {
    for (const PanelMessage& m : kPanelMessages)
        if (m.id == id)
            return m;
    throw std::out_of_range("no panel message");
}

int plcMessageCount(PlcGroup g) {
    return g == PlcGroup::System ? 16 : 32;
}

std::string plcMessageAddress(PlcGroup g, int k) {
    if (k < 1 || k > plcMessageCount(g))
        throw std::out_of_range("no PLC message " + std::to_string(k) + " in this group");
    const int bit = (k - 1) % 16;
    int word = 0;
    switch (g) {
    case PlcGroup::Alarm:
        word = 1900 + (k - 1) / 16;
        break;
    case PlcGroup::Work:
        word = 1902 + (k - 1) / 16;
        break;
    case PlcGroup::System:
        word = 1307;
        break;
    }
    return "Z" + std::to_string(word) + "." + std::to_string(bit);
}

std::string_view plcGroupNameRu(PlcGroup g) {
    switch (g) {
    case PlcGroup::Alarm:
        return "аварийные сообщения (неисправности станка)";
    case PlcGroup::Work:
        return "рабочие сообщения";
    case PlcGroup::System:
        return "системные сообщения (отказы модулей)";
    }
    return "";
}

std::string_view plcGroupNameEn(PlcGroup g) {
    switch (g) {
    case PlcGroup::Alarm:
        return "alarm messages (machine faults)";
    case PlcGroup::Work:
        return "work messages";
    case PlcGroup::System:
        return "system messages (module failures)";
    }
    return "";
}

char plcGroupLetter(PlcGroup g) {
    switch (g) {
    case PlcGroup::Alarm:
        return 'A';
    case PlcGroup::Work:
        return 'W';
    case PlcGroup::System:
        return 'S';
    }
    return '?';
}

} // namespace k528::catalog
