// Appendix Л (table Л.1) and the preset screens УСТ 1..9 of section 2.6.5.
//
// Appendix Л gives only «(резерв)» for groups 7, 8, 9 and prints no meaning
// for R200..R203, R214..R217 and R220/R221; their meanings come from the
// explanatory lines of the preset screens (noted per parameter). Units of the
// screen-only parameters are our reading of the screens (coordinates in
// discretes of the axis named by the text, speeds in discretes per minute,
// times in ms shown as seconds): see docs/machine-constants.md.
// OCR: the heading «УСТАНОВОЧНЫЕ ДАННЫЕ 3» is printed below R218/R219 (after a
// page break); screen 3 (ПОДНАЛАДКА) shows R218/R219, so they are group 3.
#include "catalog/rparams.h"

#include <array>
#include <stdexcept>
#include <string>

namespace k528::catalog {

namespace {

using A = RAccess;
using U = RUnit;

// clang-format off
const RParamDef kAssigned[] = {
    {150, A::System, U::Flag, 0, "Бит, передаваемый в параметр R150 в БП: 0: R150=0 1: R150=1",
        "Bit passed from the PLC (Z1001.8): 0 – R150=0, 1 – R150=1", "", ""},
    {151, A::System, U::DiscX, 0, "Координата \"X-\" зоны безопасности (без учета коррекций), дискр X",
        "Coordinate \"X-\" of the safety zone (without corrections), discretes of X", "", ""},
    {152, A::System, U::DiscX, 0, "Координата \"X+\" зоны безопасности (без учета коррекций), дискр X",
        "Coordinate \"X+\" of the safety zone (without corrections), discretes of X", "", ""},
    {153, A::System, U::DiscZ, 0, "Координата \"Z-\" зоны безопасности (без учета коррекций), дискр Z",
        "Coordinate \"Z-\" of the safety zone (without corrections), discretes of Z", "", ""},
    {154, A::System, U::DiscZ, 0, "Координата \"Z+\" зоны безопасности (без учета коррекций), дискр Z",
        "Coordinate \"Z+\" of the safety zone (without corrections), discretes of Z", "", ""},
    {158, A::System, U::Number, 0, "Указатель текущего уровня вложения программ",
        "Current subprogram nesting level", "", ""},
    // Group 9: ОСЕВАЯ ОРИЕНТАЦИЯ (screen 9; appendix Л: «УСТАНОВОЧНЫЕ ДАННЫЕ 9 (резерв)»).
    {164, A::System, U::DiscZ, 9, "Расстояние круг-щуп", "Wheel-to-probe distance", "РАССТОЯНИЕ КРУГ-ЩУП", "Screen 9."},
    {165, A::System, U::Number, 9, "Направление ориентации", "Orientation direction (+1/-1)", "НАПРАВЛЕНИЕ ОРИЕНТ.", "Screen 9."},
    {166, A::System, U::DiscZ, 9, "Смещение позиции начала", "Start position offset", "СМЕЩЕНИЕ ПОЗ.НАЧАЛА", "Screen 9."},
    {167, A::System, U::DiscZ, 9, "Допуск", "Tolerance", "ДОПУСК", "Screen 9."},
    {168, A::System, U::DiscZPerMin, 9, "Скорость начала", "Start speed", "СКОРОСТЬ НАЧАЛА", "Screen 9."},
    {169, A::System, U::DiscZPerMin, 9, "Скорость окончания", "End speed", "СКОРОСТЬ ОКОНЧАНИЯ", "Screen 9."},
    {170, A::System, U::DiscX, 9, "X-позиция", "X position", "X-ПОЗИЦИЯ", "Screen 9."},
    {171, A::System, U::DiscZ, 9, "Z-позиция", "Z position", "Z-ПОЗИЦИЯ", "Screen 9."},
    // Group 8: ДОП.СКОРОСТИ (screen 8).
    {174, A::System, U::DiscXPerMin, 8, "Дополнительная скорость 1 по X", "Additional speed 1 of X", "ДОП.СКОРОСТЬ 1", "Screen 8."},
    {175, A::System, U::DiscXPerMin, 8, "Дополнительная скорость 2 по X", "Additional speed 2 of X", "ДОП.СКОРОСТЬ 2", "Screen 8."},
    {176, A::System, U::DiscXPerMin, 8, "Дополнительная скорость 3 по X", "Additional speed 3 of X", "ДОП.СКОРОСТЬ 3", "Screen 8."},
    {177, A::System, U::DiscXPerMin, 8, "Дополнительная скорость 4 по X", "Additional speed 4 of X", "ДОП.СКОРОСТЬ 4", "Screen 8."},
    {178, A::System, U::Number, 8, "УСТАНОВОЧНЫЕ ДАННЫЕ 8 (резерв)", "Preset data 8 (reserve)", "", "Not on screen 8."},
    {179, A::System, U::DiscZPerMin, 8, "Дополнительная скорость 1 по Z", "Additional speed 1 of Z", "ДОП.СКОРОСТЬ 1", "Screen 8."},
    {180, A::System, U::DiscZPerMin, 8, "Дополнительная скорость 2 по Z", "Additional speed 2 of Z", "ДОП.СКОРОСТЬ 2", "Screen 8."},
    {181, A::System, U::DiscZPerMin, 8, "Дополнительная скорость 3 по Z", "Additional speed 3 of Z", "ДОП.СКОРОСТЬ 3", "Screen 8."},
    {182, A::System, U::DiscZPerMin, 8, "Дополнительная скорость 4 по Z", "Additional speed 4 of Z", "ДОП.СКОРОСТЬ 4", "Screen 8."},
    {183, A::System, U::Number, 8, "УСТАНОВОЧНЫЕ ДАННЫЕ 8 (резерв)", "Preset data 8 (reserve)", "", "Not on screen 8."},
    // Group 7: ОСЦИЛЛЯЦИЯ X (R184..R191) and Z (R192..R199), screen 7.
    {184, A::System, U::DiscX, 7, "Координата -MX осцилляции по X", "Oscillation X: reversal point -MX", "-MX: координата X", "Screen 7."},
    {185, A::System, U::DiscX, 7, "Координата +MX осцилляции по X", "Oscillation X: reversal point +MX", "+MX: координата X", "Screen 7."},
    {186, A::System, U::DiscXPerMin, 7, "Скорость осцилляции по X", "Oscillation speed of X", "СКОРОСТЬ ОСЦИЛЛЯЦИИ", "Screen 7."},
    {187, A::System, U::Ms, 7, "Задержка реверса осцилляции по X, с", "Oscillation X: dwell at reversal", "ЗАДЕРЖКА РЕВЕРСА, СЕК", "Screen 7; ms, shown in seconds."},
    {188, A::System, U::Flag, 7, "Реверс точно в точке -MX", "Oscillation X: exact reversal at -MX", "-РЕВЕРС ТОЧНО", "Screen 7."},
    {189, A::System, U::Flag, 7, "Реверс точно в точке +MX", "Oscillation X: exact reversal at +MX", "+РЕВЕРС ТОЧНО", "Screen 7."},
    {190, A::System, U::Number, 7, "Точка завершения осцилляции по X", "Oscillation X: end point", "ТОЧКА ЗАВЕРШЕНИЯ", "Screen 7."},
    {191, A::System, U::Number, 7, "Ходы выхаживания по X", "Oscillation X: spark-out strokes", "ХОДЫ ВЫХАЖИВАНИЯ", "Screen 7."},
    {192, A::System, U::DiscZ, 7, "Координата -MZ осцилляции по Z", "Oscillation Z: reversal point -MZ", "-MZ: координата Z", "Screen 7."},
    {193, A::System, U::DiscZ, 7, "Координата +MZ осцилляции по Z", "Oscillation Z: reversal point +MZ", "+MZ: координата Z", "Screen 7."},
    {194, A::System, U::DiscZPerMin, 7, "Скорость осцилляции по Z", "Oscillation speed of Z", "СКОРОСТЬ ОСЦИЛЛЯЦИИ", "Screen 7."},
    {195, A::System, U::Ms, 7, "Задержка реверса осцилляции по Z, с", "Oscillation Z: dwell at reversal", "ЗАДЕРЖКА РЕВЕРСА, СЕК", "Screen 7; ms, shown in seconds."},
    {196, A::System, U::Flag, 7, "Реверс точно в точке -MZ", "Oscillation Z: exact reversal at -MZ", "-РЕВЕРС ТОЧНО", "Screen 7."},
    {197, A::System, U::Flag, 7, "Реверс точно в точке +MZ", "Oscillation Z: exact reversal at +MZ", "+РЕВЕРС ТОЧНО", "Screen 7."},
    {198, A::System, U::Number, 7, "Точка завершения осцилляции по Z", "Oscillation Z: end point", "ТОЧКА ЗАВЕРШЕНИЯ", "Screen 7."},
    {199, A::System, U::Number, 7, "Ходы выхаживания по Z", "Oscillation Z: spark-out strokes", "ХОДЫ ВЫХАЖИВАНИЯ", "Screen 7."},
    // Group 6: АЛМАЗ (screen 6; appendix Л: «УСТАНОВОЧНЫЕ ДАННЫЕ 6 (резерв)»).
    {200, A::System, U::DiscX, 6, "Координата X алмаза", "Diamond position X", "MX: координата X", "Screen 6."},
    {201, A::System, U::DiscZ, 6, "Координата Z алмаза", "Diamond position Z", "MZ: координата Z", "Screen 6."},
    {202, A::System, U::Number, 6, "NZ алмаза", "Diamond NZ", "NZ АЛМАЗА", "Screen 6; meaning not explained by the manual."},
    {203, A::System, U::Number, 6, "УСТАНОВОЧНЫЕ ДАННЫЕ 6 (резерв)", "Preset data 6 (reserve)", "", "Not on screen 6."},
    // Group 5: ДАННЫЕ ШЛИФОВАЛЬНОГО КРУГА (discretes of X, not on the diameter).
    {204, A::System, U::DiscX, 5, "Диаметр нового круга в дискр X", "New wheel diameter, discretes of X", "ДИАМЕТР НОВ.КРУГА", ""},
    {205, A::System, U::DiscX, 5, "Минимальный диаметр круга в дискр X", "Smallest wheel diameter, discretes of X", "MIN ДИАМЕТР КРУГА", ""},
    {206, A::System, U::DiscX, 5, "Максимальный диаметр круга в дискр X", "Largest wheel diameter, discretes of X", "MAX ДИАМЕТР КРУГА", ""},
    {207, A::System, U::DiscX, 5, "Текущий диаметр круга в дискр X", "Current wheel diameter, discretes of X", "ТЕК.ДИАМЕТР КРУГА", ""},
    // Group 4: ДАННЫЕ ПРАВКИ ПЕРИФЕРИИ (R210..R213) и ТОРЦА (R214..R217) КРУГА.
    {210, A::System, U::DiscX, 4, "Черновая правка периферии на ход правки в дискр X",
        "Rough dressing of the periphery per dressing stroke, discretes of X", "DX ЧЕРН.ПРАВКИ", ""},
    {211, A::System, U::DiscX, 4, "Чистовая правка периферии на ход правки в дискр X",
        "Finish dressing of the periphery per dressing stroke, discretes of X", "DX ЧИСТ.ПРАВКИ", ""},
    {212, A::System, U::DiscZPerMin, 4, "Скорость черновой правки периферии круга в дискр FZ/мин",
        "Rough periphery dressing speed, discretes of Z per minute", "FZ ЧЕРН.ПРАВКИ", ""},
    {213, A::System, U::DiscZPerMin, 4, "Скорость чистовой правки периферии круга в дискр FZ/мин",
        "Finish periphery dressing speed, discretes of Z per minute", "FZ ЧИСТ.ПРАВКИ", ""},
    {214, A::System, U::DiscZ, 4, "Черновая правка торца на ход правки в дискр Z",
        "Rough dressing of the face per dressing stroke, discretes of Z", "DZ ЧЕРН.ПРАВКИ", "Appendix Л: «данные правки торца круга (резерв)»; screen 4."},
    {215, A::System, U::DiscZ, 4, "Чистовая правка торца на ход правки в дискр Z",
        "Finish dressing of the face per dressing stroke, discretes of Z", "DZ ЧИСТ.ПРАВКИ", "Screen 4."},
    {216, A::System, U::DiscXPerMin, 4, "Скорость черновой правки торца круга в дискр FX/мин",
        "Rough face dressing speed, discretes of X per minute", "FX ЧЕРН.ПРАВКИ", "Screen 4."},
    {217, A::System, U::DiscXPerMin, 4, "Скорость чистовой правки торца круга в дискр FX/мин",
        "Finish face dressing speed, discretes of X per minute", "FX ЧИСТ.ПРАВКИ", "Screen 4 (printed «FXЧИСТ.ПРАВКИ»)."},
    // Group 3: ПОДНАЛАДКА.
    {218, A::System, U::DiscX, 3, "Величина подналадки по коорд. \"X\" в дискр X", "Adjustment step of X, discretes of X", "", ""},
    {219, A::System, U::DiscZ, 3, "Величина подналадки по коорд. \"Z\" в дискр Z", "Adjustment step of Z, discretes of Z", "", ""},
    // Group 2: ИСХОДНОЕ (screen 2; not in appendix Л).
    {220, A::System, U::DiscX, 2, "Исходное положение MX: координата X в системе станка с учетом радиуса/диаметра",
        "Initial position MX: X in machine coordinates, radius/diameter as programmed", "MX: координата X", "Screen 2."},
    {221, A::System, U::DiscZ, 2, "Исходное положение MZ: координата Z в системе станка",
        "Initial position MZ: Z in machine coordinates", "MZ: координата Z", "Screen 2."},
    {222, A::System, U::DiscX, 3, "Значение координаты \"X\" в системе станка с учетом радиуса/диаметра",
        "X in machine coordinates, radius/diameter as programmed", "", "Appendix Л places it under «УСТАНОВОЧНЫЕ ДАННЫЕ 3»."},
    {223, A::System, U::DiscZ, 3, "Значение координаты \"Z\" в системе станка с учетом радиуса/диаметра",
        "Z in machine coordinates", "", "Appendix Л places it under «УСТАНОВОЧНЫЕ ДАННЫЕ 3»."},
    // Group 1: ДАННЫЕ СМЕЩЕНИЯ СИСТЕМЫ ДЕТАЛИ.
    {224, A::System, U::DiscX, 1, "Сумма правок по координате \"X\" в дискр X", "Dressing sum of X, discretes of X", "СУММА ПРАВОК", ""},
    {225, A::System, U::DiscZ, 1, "Сумма правок по координате \"Z\" в дискр Z", "Dressing sum of Z, discretes of Z", "СУММА ПРАВОК", ""},
    {226, A::System, U::DiscX, 1, "Коррекция координаты \"X\" в дискр X", "Correction of X, discretes of X", "КОРРЕКЦИЯ", ""},
    {227, A::System, U::DiscZ, 1, "Коррекция координаты \"Z\" в дискр Z", "Correction of Z, discretes of Z", "КОРРЕКЦИЯ", ""},
    {228, A::System, U::DiscX, 1, "Смещение нуля координаты \"X\" в дискр X", "Zero offset of X, discretes of X", "СМЕЩЕНИЕ НУЛЯ", ""},
    {229, A::System, U::DiscZ, 1, "Смещение нуля координаты \"Z\" в дискр Z", "Zero offset of Z, discretes of Z", "СМЕЩЕНИЕ НУЛЯ", ""},
    {230, A::System, U::DiscX, 1, "Смещение маховиком (DRF) координаты \"X\"", "Handwheel offset (DRF) of X", "СМЕЩЕНИЕ МАХОВИКОМ", ""},
    {231, A::System, U::DiscZ, 1, "Смещение маховиком (DRF) координаты \"Z\"", "Handwheel offset (DRF) of Z", "СМЕЩЕНИЕ МАХОВИКОМ", ""},
    // Read only.
    {232, A::ReadOnly, U::DiscX, 0, "Значение координаты \"X\" в системе станка", "X in machine coordinates", "", ""},
    {233, A::ReadOnly, U::DiscZ, 0, "Значение координаты \"Z\" в системе станка", "Z in machine coordinates", "", ""},
    {234, A::ReadOnly, U::DiscX, 0, "Значение координаты \"X\" в текущей системе", "X in the current coordinate system", "", ""},
    {235, A::ReadOnly, U::DiscZ, 0, "Значение координаты \"Z\" в текущей системе", "Z in the current coordinate system", "", ""},
    {236, A::ReadOnly, U::DiscXPerMin, 0, "Текущая скорость по \"X\"", "Current speed of X", "", ""},
    {237, A::ReadOnly, U::DiscZPerMin, 0, "Текущая скорость по \"Z\"", "Current speed of Z", "", ""},
    {238, A::ReadOnly, U::DiscX, 0, "Текущее рассогласование по \"X\"", "Current following error of X", "", ""},
    {239, A::ReadOnly, U::DiscZ, 0, "Текущее рассогласование по \"Z\"", "Current following error of Z", "", ""},
    {240, A::ReadOnly, U::DacUnits, 0, "Код ЦАП оси X", "DAC code of axis X", "", ""},
    {241, A::ReadOnly, U::DacUnits, 0, "Код ЦАП оси Z", "DAC code of axis Z", "", ""},
    {242, A::ReadOnly, U::DiscX, 0, "Рассогласование по \"X\" при стирании остатка пути",
        "Following error of X when the rest of the path was erased", "", ""},
    {243, A::ReadOnly, U::DiscZ, 0, "Рассогласование по \"Z\" при стирании остатка пути",
        "Following error of Z when the rest of the path was erased", "", ""},
    {244, A::ReadOnly, U::DiscX, 0, "Остаток пути по \"X\"", "Remaining path of X", "", ""},
    {245, A::ReadOnly, U::DiscZ, 0, "Остаток пути по \"Z\"", "Remaining path of Z", "", ""},
    {246, A::ReadOnly, U::DiscX, 0, "Расстояние по \"X\" от коорд.съезда с конечника торможения до 0-метки датчика",
        "Distance of X from leaving the deceleration switch to the encoder zero mark", "", ""},
    {247, A::ReadOnly, U::DiscZ, 0, "Расстояние по \"Z\" от коорд.съезда с конечника торможения до 0-метки датчика",
        "Distance of Z from leaving the deceleration switch to the encoder zero mark", "", ""},
    {249, A::ReadOnly, U::Number, 0, "Значение корректора скорости", "Feed override value, %", "", ""},
    {250, A::ReadOnly, U::ProgramNumber, 0, "Номер текущей программы обработки в автоматическом или ручном режиме",
        "Number of the current program in automatic or manual mode", "", ""},
    {252, A::ReadOnly, U::ProgramNumber, 0, "Номер программы обработки от K923 для автоматического режима",
        "Program number chosen on the K923 for automatic mode", "", ""},
    {253, A::ReadOnly, U::ProgramNumber, 0, "Номер текущей выполняемой программы/подпрограммы",
        "Number of the program/subprogram running", "", ""},
    {254, A::ReadOnly, U::FrameNumber, 0, "Номер кадра выполняемой программы/подпрограммы",
        "Frame number of the program/subprogram running", "", ""},
    {256, A::ReadOnly, U::Number, 0, "Значение для записи R-параметра от K923", "Value of an R-parameter written from the K923", "", ""},
    {257, A::ReadOnly, U::Number, 0, "Мл.слово=адрес R-параметра для записи Ст.слово=признак записи R-параметра (D0)",
        "Low word: number of the R-parameter to write; high word: write flag (D0)", "", ""},
    {261, A::ReadOnly, U::Pulses, 0, "Число импульсов ДОС по X за 1 таймерный интервал", "Encoder pulses of X per timer interval", "", ""},
    {262, A::ReadOnly, U::Pulses, 0, "Число импульсов ДОС по Z за 1 таймерный интервал", "Encoder pulses of Z per timer interval", "", ""},
};
// clang-format on

int groupOfUnassigned(int n) {
    if (n >= 164 && n <= 171)
        return 9;
    if (n >= 174 && n <= 183)
        return 8;
    if (n >= 184 && n <= 199)
        return 7;
    if (n >= 200 && n <= 203)
        return 6;
    return 0;
}

const std::array<RParamDef, kRParamCount>& table() {
    static const std::array<RParamDef, kRParamCount> t = [] {
        std::array<RParamDef, kRParamCount> a{};
        for (int n = 0; n < kRParamCount; ++n) {
            const auto i = static_cast<std::size_t>(n);
            if (n <= kRUserLast)
                a[i] = {n,  A::User, U::Number, 0, "Параметр пользователя", "User parameter",
                        "", ""};
            else if (n >= kRReadOnlyFirst && n <= kRReadOnlyLast)
                a[i] = {n,  A::ReadOnly, U::Number, 0,
                        "", "",          "",        "Read-only area, no meaning printed."};
            else
                a[i] = {n,         A::Unassigned,
                        U::Number, groupOfUnassigned(n),
                        "",        "",
                        "",        "Reserved by the system, no meaning printed."};
        }
        for (const RParamDef& d : kAssigned)
            a[static_cast<std::size_t>(d.number)] = d;
        return a;
    }();
    return t;
}

} // namespace

std::string_view rUnitRu(RUnit u) {
    switch (u) {
    case U::Number:
        return "число";
    case U::Flag:
        return "флаг 0/1";
    case U::DiscX:
        return "дискр X";
    case U::DiscZ:
        return "дискр Z";
    case U::DiscXPerMin:
        return "дискр X/мин";
    case U::DiscZPerMin:
        return "дискр Z/мин";
    case U::Ms:
        return "мс";
    case U::DacUnits:
        return "единицы ЦАП";
    case U::Pulses:
        return "импульсы ДОС";
    case U::ProgramNumber:
        return "номер УП";
    case U::FrameNumber:
        return "номер кадра";
    }
    return "";
}

std::string_view rUnitEn(RUnit u) {
    switch (u) {
    case U::Number:
        return "number";
    case U::Flag:
        return "flag 0/1";
    case U::DiscX:
        return "discretes of X";
    case U::DiscZ:
        return "discretes of Z";
    case U::DiscXPerMin:
        return "discretes of X/min";
    case U::DiscZPerMin:
        return "discretes of Z/min";
    case U::Ms:
        return "ms";
    case U::DacUnits:
        return "DAC units";
    case U::Pulses:
        return "encoder pulses";
    case U::ProgramNumber:
        return "program number";
    case U::FrameNumber:
        return "frame number";
    }
    return "";
}

Axis rUnitAxis(RUnit u) {
    switch (u) {
    case U::DiscX:
    case U::DiscXPerMin:
        return Axis::X;
    case U::DiscZ:
    case U::DiscZPerMin:
        return Axis::Z;
    default:
        return Axis::Common;
    }
}

const RParamDef* findRParam(int number) noexcept {
    if (number < 0 || number >= kRParamCount)
        return nullptr;
    return &table()[static_cast<std::size_t>(number)];
}

const RParamDef& rParam(int number) {
    const RParamDef* d = findRParam(number);
    if (!d)
        throw std::out_of_range("no R-parameter " + std::to_string(number) + " (0..299)");
    return *d;
}

std::string_view rGroupNameRu(int group) {
    static constexpr std::string_view names[] = {
        "",      "КООРД.И СМЕЩЕНИЯ", "ИСХОДНОЕ", "ПОДНАЛАДКА", "ПРАВКА", "ШЛИФ.КРУГ",
        "АЛМАЗ", "ОСЦИЛЛЯЦИЯ",       "СКОРОСТИ", "ОСЕВАЯ"};
    return group >= 1 && group <= 9 ? names[group] : "";
}

std::string_view rGroupNameEn(int group) {
    static constexpr std::string_view names[] = {
        "",         "coordinates and offsets", "initial position", "adjustment",
        "dressing", "grinding wheel",          "diamond",          "oscillation",
        "speeds",   "axial orientation"};
    return group >= 1 && group <= 9 ? names[group] : "";
}

} // namespace k528::catalog
