// Rendering the texts of a grade from core's catalog (catalog/training_texts.h).
#include "training/texts.h"

#include "catalog/training_texts.h"
#include "units/units.h"

#include <cmath>
#include <cstdio>

namespace k528::training {

std::vector<std::string> argsIn(std::span<const TextArg> args, Language l) {
    std::vector<std::string> out;
    out.reserve(args.size());
    for (const TextArg& a : args)
        out.push_back(a.in(l));
    return out;
}

std::string render(const Text& t, Language l) {
    return catalog::trainingTexts().render(t.id, argsIn(t.args, l), l == Language::Ru);
}

std::string mmArg(double mm) {
    return units::formatTrimmed(std::fabs(mm) < 0.0005 ? 0.0 : mm, 3);
}

std::string areaArg(double mm2) {
    char b[40];
    std::snprintf(b, sizeof b, mm2 < 0.01 ? "%.4f" : "%.3f", mm2 < 0.00005 ? 0.0 : mm2);
    return b;
}

std::string intArg(long long v) {
    return std::to_string(v);
}

std::string frameArg(int program, int n) {
    std::string s = "L" + std::to_string(program);
    if (n > 0)
        s += " N" + std::to_string(n);
    return s;
}

} // namespace k528::training
