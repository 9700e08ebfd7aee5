// Rendering the texts of a grade from core's catalog (catalog/training_texts.h).
#include "training/texts.h"

#include "catalog/training_texts.h"

#include <cmath>
#include <cstdio>

namespace k528::training {

std::string fillTemplate(std::string_view tpl, std::span<const TextArg> args, Language l) {
    std::string out;
    out.reserve(tpl.size() + 32);
    for (std::size_t i = 0; i < tpl.size(); ++i) {
        const char c = tpl[i];
        if (c == '%' && i + 1 < tpl.size() && tpl[i + 1] >= '1' && tpl[i + 1] <= '9') {
            const auto n = static_cast<std::size_t>(tpl[i + 1] - '1');
            if (n < args.size())
                out += args[n].in(l);
            ++i;
        } else if (c == '%' && i + 1 < tpl.size() && tpl[i + 1] == '%') {
            out += '%';
            ++i;
        } else {
            out += c;
        }
    }
    return out;
}

std::string render(const Text& t, Language l) {
    if (const catalog::TrainingText* tpl = catalog::findTrainingText(t.id))
        return fillTemplate(l == Language::Ru ? tpl->ru : tpl->en, t.args, l);
    std::string out = t.id;
    for (const TextArg& a : t.args)
        out += " " + a.in(l);
    return out;
}

std::string mmArg(double mm) {
    if (std::fabs(mm) < 0.0005)
        mm = 0;
    char b[40];
    std::snprintf(b, sizeof b, "%.3f", mm);
    std::string s(b);
    while (!s.empty() && s.back() == '0')
        s.pop_back();
    if (!s.empty() && s.back() == '.')
        s.pop_back();
    return s;
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
