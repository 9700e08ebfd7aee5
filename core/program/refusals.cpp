#include "program/refusals.h"

#include "program/gfunctions.h"

namespace k528::program {

namespace {

using namespace refusal;

// The interpreter raises the first match, so the dwell's refusals come
// before the others a dwell frame can match, and the refusals of a call
// before those of an end.
constexpr Refusal kRefusals[] = {
    {63, Rule::DwellWithZ, Dwell | Z, 0, RefusalSpot::Z,
     "G04/X/Z: %1 с выдержкой времени G04 задан Z; время задаётся только в X",
     "G04/X/Z: Z is given %1 with the dwell G04; the time goes in X only"},
    {64, Rule::DwellWithCall, Dwell | Call, 0, RefusalSpot::Call,
     "G04/L: %1 с выдержкой времени G04 вызывается подпрограмма %2",
     "G04/L: subprogram %2 is called %1 with the dwell G04"},
    {34, Rule::AxisWithCall, CoordinateX | Call, 0, RefusalSpot::X,
     "X/L: %1 с вызовом подпрограммы %2 задана координата X",
     "X/L: X is given %1 that calls subprogram %2"},
    {50, Rule::AxisWithCall, Z | Call, 0, RefusalSpot::Z,
     "Z/L: %1 с вызовом подпрограммы %2 задана координата Z",
     "Z/L: Z is given %1 that calls subprogram %2"},
    {35, Rule::AxisWithM17, CoordinateX | SubprogramEnd, 0, RefusalSpot::X,
     "X/M17: %1 с концом подпрограммы M17 задана координата X",
     "X/M17: X is given %1 that ends the subprogram with M17"},
    {51, Rule::AxisWithM17, Z | SubprogramEnd, 0, RefusalSpot::Z,
     "Z/M17: %1 с концом подпрограммы M17 задана координата Z",
     "Z/M17: Z is given %1 that ends the subprogram with M17"},
    {58, Rule::EndCombination, EndRewind | Call, 0, RefusalSpot::M30,
     "M30/L: конец программы M30 и вызов %2 %1", "M30/L: end of program M30 and a call of %2 %1"},
    {59, Rule::EndCombination, End | Call, 0, RefusalSpot::M2,
     "M2/L: конец программы M02 и вызов %2 %1", "M2/L: end of program M02 and a call of %2 %1"},
    {60, Rule::EndCombination, SubprogramEnd | Call, 0, RefusalSpot::M17,
     "M17/L: конец подпрограммы M17 и вызов %2 %1",
     "M17/L: end of subprogram M17 and a call of %2 %1"},
    {61, Rule::EndCombination, EndRewind | SubprogramEnd, 0, RefusalSpot::M30,
     "M30/M17: конец программы M30 и конец подпрограммы M17 %1",
     "M30/M17: end of program M30 and end of subprogram M17 %1"},
    {62, Rule::EndCombination, End | SubprogramEnd, 0, RefusalSpot::M2,
     "M2/M17: конец программы M02 и конец подпрограммы M17 %1",
     "M2/M17: end of program M02 and end of subprogram M17 %1"},
    {36, Rule::AxisAtSubprogramEnd, CoordinateX | LastOfSubprogram, SubprogramEnd, RefusalSpot::X,
     "X/конец L: последний кадр подпрограммы %2 без M17 задаёт координату X",
     "X/end of L: the last frame of subprogram %2 has no M17 and gives X"},
    {52, Rule::AxisAtSubprogramEnd, Z | LastOfSubprogram, SubprogramEnd, RefusalSpot::Z,
     "Z/конец L: последний кадр подпрограммы %2 без M17 задаёт координату Z",
     "Z/end of L: the last frame of subprogram %2 has no M17 and gives Z"},
};

} // namespace

std::span<const Refusal> refusals() { return kRefusals; }

refusal::Words refusalWords(const IsoFrame& iso) {
    Words w = 0;
    bool dwell = false;
    for (const program::Word& g : iso.g)
        dwell |= classifyG(g.number).function == GFunction::Dwell;
    if (dwell)
        w |= Dwell;
    if (iso.x && !dwell)
        w |= CoordinateX;
    if (iso.z)
        w |= Z;
    if (iso.call)
        w |= Call;
    for (const program::Word& m : iso.m) {
        if (m.number == mfunc::kEnd)
            w |= End;
        else if (m.number == mfunc::kSubprogramEnd)
            w |= SubprogramEnd;
        else if (m.number == mfunc::kEndRewind)
            w |= EndRewind;
    }
    return w;
}

} // namespace k528::program
