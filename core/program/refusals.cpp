#include "program/refusals.h"

#include "program/gfunctions.h"

namespace k528::program {

namespace {

using namespace refusal;

// The interpreter raises the first match, so the dwell's refusals come
// before the others a dwell frame can match, and the refusals of a call
// before those of an end.
constexpr Refusal kRefusals[] = {
    {63, Rule::DwellWithZ, Dwell | Z, 0, RefusalSpot::Z, "refusal.dwell-with-z"},
    {64, Rule::DwellWithCall, Dwell | Call, 0, RefusalSpot::Call, "refusal.dwell-with-call"},
    {34, Rule::AxisWithCall, CoordinateX | Call, 0, RefusalSpot::X, "refusal.x-with-call"},
    {50, Rule::AxisWithCall, Z | Call, 0, RefusalSpot::Z, "refusal.z-with-call"},
    {35, Rule::AxisWithM17, CoordinateX | SubprogramEnd, 0, RefusalSpot::X, "refusal.x-with-m17"},
    {51, Rule::AxisWithM17, Z | SubprogramEnd, 0, RefusalSpot::Z, "refusal.z-with-m17"},
    {58, Rule::EndCombination, EndRewind | Call, 0, RefusalSpot::M30, "refusal.m30-call"},
    {59, Rule::EndCombination, End | Call, 0, RefusalSpot::M2, "refusal.m2-call"},
    {60, Rule::EndCombination, SubprogramEnd | Call, 0, RefusalSpot::M17, "refusal.m17-call"},
    {61, Rule::EndCombination, EndRewind | SubprogramEnd, 0, RefusalSpot::M30, "refusal.m30-m17"},
    {62, Rule::EndCombination, End | SubprogramEnd, 0, RefusalSpot::M2, "refusal.m2-m17"},
    {36, Rule::AxisAtSubprogramEnd, CoordinateX | LastOfSubprogram, SubprogramEnd, RefusalSpot::X, "refusal.x-at-end"},
    {52, Rule::AxisAtSubprogramEnd, Z | LastOfSubprogram, SubprogramEnd, RefusalSpot::Z, "refusal.z-at-end"},
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
