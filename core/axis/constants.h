// The machine constants of one axis (appendix Е), as the servo uses them.
//
// C-parameters 1..52 describe X, 53..104 describe Z with the same layout
// (C(53 + k) is the Z counterpart of C(1 + k)). Values keep the manual's
// units; the accessors below convert them through core/units.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "units/units.h"

namespace k528::axis {

enum class AxisId { X = 0, Z = 1 };

constexpr const char* axisName(AxisId a) { return a == AxisId::X ? "X" : "Z"; }
// First C-parameter number of an axis' block: 1 for X, 53 for Z.
constexpr int cBase(AxisId a) { return a == AxisId::X ? 1 : 53; }

struct Constants {
    bool present = true;                 // C1   НАЛИЧ.ОСИ
    bool encoderInvert = false;          // C2   ЗНАК ДОС
    bool dacInvert = false;              // C3   ЗНАК ЦАП
    units::AxisScale scale;              // C4..6 discrete, C7 ИНД.ДИАМЕТР
    bool autoWithoutHoming = false;      // C8   АВТ.БЕЗ ПБТ
    bool homeNegative = false;           // C9   ПБТ В "-"
    bool softLimitsOn = false;           // C10  ВКЛ.ПРГ.КОН
    bool handwheel1Invert = false;       // C11  ЗНАК М1
    bool handwheel2Invert = false;       // C12  ЗНАК М2
    bool adjustEnabled = false;          // C13  ВКЛ.ПОДНАЛ.
    bool encoderCheckAtRest = false;     // C14  Контр.ДОС в останове
    int encoderChannel = 1;              // C17  N ДОС (1..4)
    int dacChannel = 1;                  // C18  N ЦАП (1..4)
    std::int64_t encoderL = 1;           // C19  L ИМП.ДОС
    std::int64_t encoderN = 2;           // C20  N ИМП.ДОС
    std::int64_t encoderCheckMs = 0;     // C21  T контроля ДОС, ms (0: off)
    std::int64_t accel1 = 0;             // C22  УСКОРЕНИЕ 1 (25600·A/Kd)
    std::int64_t accel2 = 0;             // C23  УСКОРЕНИЕ 2 (0: use УСКОРЕНИЕ 1)
    std::int64_t handwheel1Mult = 1;     // C24  МНОЖИТ.М1, discretes per pulse
    std::int64_t handwheel2Mult = 1;     // C25  МНОЖИТ.М2
    std::int64_t ks = 0;                 // C26  K(СКОР)
    std::int64_t ke = 0;                 // C27  K(ОШИБ)
    std::int64_t dacLimit = 0;           // C28  ПРЕДЕЛ ЦАП
    std::int64_t dacMax = 2047;          // C29  МАКС.ЦАП
    std::int64_t maxErrorInternal = 0;   // C30  МАКС.ОШИБКА (0: off)
    std::int64_t posToleranceInternal = 1; // C31 ДОПУСК ПОЗ.
    std::int64_t clampCheckDelayMs = 0;  // C32  ЗАДЕРЖКА КП (0: = ЗАДЕРЖКА БР)
    std::int64_t clampToleranceInternal = 1; // C33 ДОПУСК КП
    std::int64_t driftCompDac = 0;       // C34  КОМП.ДРЕЙФА, DAC units
    std::int64_t backlashDisc = 0;       // C35  КОМП.ЛЮФТА, discretes
    std::int64_t regulatorOffDelayMs = 0; // C36 ЗАДЕРЖКА БР
    std::int64_t beforeZeroSearchDisc = 0; // C37 S до поиска 0-метки (signed)
    std::int64_t zeroSearchDisc = 0;     // C38  S поиска 0-метки (signed, 0: unlimited)
    std::int64_t homeOffsetDisc = 0;     // C39  СМЕЩЕНИЕ БТ
    std::int64_t feedNormal = 0;         // C40  F ОБЫЧНАЯ, 10·disc/min
    std::int64_t feedRapid = 0;          // C41  F УСКОРЕН.
    std::int64_t feedAutoMax = 0;        // C42  F УСК.АВТ.
    std::int64_t feedHomeStart = 0;      // C43  F СТАРТ БТ
    std::int64_t feedHomeSlow = 0;       // C44  F ОТКЛ.БТ
    std::int64_t homeValueDisc = 0;      // C45  ЗНАЧЕНИЕ БТ
    std::int64_t softMinusDisc = 0;      // C46  -ОГРАНИЧЕН
    std::int64_t softPlusDisc = 0;       // C47  +ОГРАНИЧЕН
    std::int64_t decelCamDisc = 0;       // C48  S конечника БТ (signed, 0: unchecked)

    // Reads an axis block from C-parameter values indexed by number
    // (`c[n]` is C-parameter n; c.size() must be at least 105).
    static Constants fromC(std::span<const std::int64_t> c, AxisId axis);

    // Conversions to the servo's working units: internal units and ms.
    double speedParamToInternalPerMs(std::int64_t param10DiscPerMin) const;
    double mmPerMinToInternalPerMs(double mmPerMin) const;
    double internalPerMsToMmPerMin(double v) const;
    double accelToInternalPerMs2(std::int64_t accelParam) const;
    double discToInternal(double disc) const { return disc * static_cast<double>(scale.internalPerDisc()); }
    double internalToDisc(double internal) const { return units::internalToDisc(internal, scale); }
    // Internal units per encoder count (2·L/N).
    double internalPerCount() const { return 2.0 * static_cast<double>(encoderL) / static_cast<double>(encoderN); }
    // The effective stand-still check delay (ЗАДЕРЖКА КП, or ЗАДЕРЖКА БР when 0).
    std::int64_t effectiveClampDelayMs() const { return clampCheckDelayMs > 0 ? clampCheckDelayMs : regulatorOffDelayMs; }
    // The braking acceleration on limit switches (УСКОРЕНИЕ 2, or 1 when 0).
    std::int64_t emergencyAccel() const { return accel2 > 0 ? accel2 : accel1; }
    bool ratioValid() const { return encoderL >= 1 && encoderL <= 32767 && encoderN >= 1 && encoderN <= 32767; }
};

} // namespace k528::axis
