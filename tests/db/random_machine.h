// A full, valid, randomized machine for database tests and benchmarks: all 152
// constants, every writable R-parameter (R0..R299 without the read-only
// R232..R262: 269 presets), 99 programs of realistic size, 99 technological
// messages, all 80 PLC texts and the simulation settings. Deterministic for a
// seed. Constants that take part in error-level cross-checks keep the values
// of appendix Ж; the others are random within their ranges, so
// profile::validate() reports no errors.
#pragma once

#include "catalog/cparams.h"
#include "catalog/messages.h"
#include "catalog/rparams.h"
#include "profile/builtin.h"
#include "profile/profile.h"

#include <cstdint>
#include <random>
#include <set>
#include <string>

namespace k528::testing {

inline std::string randomWord(std::mt19937& rng, std::size_t maxChars) {
    static const char* const kLetters[] = {"А", "Б", "В", "Г", "Д", "Е", "Ж", "З", "И", "К", "Л",
                                           "М", "Н", "О", "П", "Р", "С", "Т", "У", "Ф", "Х", "Ц",
                                           "Ч", "Ш", "Ы", "Э", "Ю", "Я", "0", "1", "2", "5", "A",
                                           "Z", "X", ".", "-", "«", "»", ";", "="};
    std::uniform_int_distribution<std::size_t> len(1, maxChars);
    std::uniform_int_distribution<std::size_t> pick(0, std::size(kLetters) - 1);
    const std::size_t n = len(rng);
    std::string s;
    for (std::size_t i = 0; i < n; ++i) {
        // Blanks inside, never at the end.
        if (i > 0 && i + 1 < n && rng() % 6 == 0)
            s += ' ';
        else
            s += kLetters[pick(rng)];
    }
    return s;
}

// A program of `frames` frames with a header, comments and a few R lines.
inline std::string randomProgram(std::mt19937& rng, int number, int frames) {
    std::uniform_int_distribution<int> coord(-99999, 99999);
    std::string t = "%L" + std::to_string(number) + " (" + randomWord(rng, 16) + ")\n";
    t += "; " + randomWord(rng, 40) + "\n";
    for (int i = 1; i <= frames; ++i) {
        const auto mm = [&] {
            const int v = coord(rng);
            std::string s = std::to_string(std::abs(v) / 1000) + "." +
                            std::to_string(std::abs(v) % 1000 + 1000).substr(1);
            return (v < 0 ? "-" : "") + s;
        };
        switch (rng() % 5) {
        case 0:
            t += "N" + std::to_string(i) + " G0 X" + mm() + " Z" + mm() + "\n";
            break;
        case 1:
            t += "N" + std::to_string(i) + " G1 X" + mm() + " FX" +
                 std::to_string(rng() % 500 + 1) + "\n";
            break;
        case 2:
            t += "N" + std::to_string(i) + " R" + std::to_string(rng() % 150) + "=R" +
                 std::to_string(rng() % 150) + "+" + std::to_string(rng() % 1000) + "\n";
            break;
        case 3:
            t += "N" + std::to_string(i) + " G04 X" + std::to_string(rng() % 9 + 1) + " #" +
                 std::to_string(rng() % 99 + 1) + "\n";
            break;
        default:
            t += "N" + std::to_string(i) + " G1 Z" + mm() + " FZ" +
                 std::to_string(rng() % 900 + 1) + " ; " + randomWord(rng, 12) + "\n";
            break;
        }
    }
    t += "N" + std::to_string(frames + 1) + " M30\n";
    return t;
}

inline profile::MachineProfile randomMachine(std::uint32_t seed, std::string name = "random") {
    std::mt19937 rng(seed);
    profile::MachineProfile p = profile::builtin("grinder-205");
    p.name = std::move(name);
    p.title = "Случайный станок " + std::to_string(seed) + " " + randomWord(rng, 30);
    // Constants free of error-level cross-checks (per axis, X numbers).
    static const std::set<int> kFreeAxis = {2,  3,  8,  9,  11, 12, 13, 14, 21, 22, 23,
                                            24, 25, 26, 27, 30, 31, 32, 33, 34, 35, 36,
                                            37, 38, 39, 40, 41, 42, 43, 44, 45, 48};
    for (const catalog::CParamDef& d : catalog::cParams()) {
        const int x = d.number > catalog::kAxisBlock && d.number <= 2 * catalog::kAxisBlock
                          ? d.number - catalog::kAxisBlock
                          : d.number;
        const bool free = (d.number <= 2 * catalog::kAxisBlock && kFreeAxis.count(x)) ||
                          (d.number >= 107 && d.number <= 125) ||
                          (d.number >= 139 && d.number <= 150);
        if (!free || d.reserved())
            continue;
        std::uniform_int_distribution<std::int64_t> v(d.min, d.max);
        p.setC(d.number, v(rng));
    }
    // Manual cycles name programs 1..99 (all exist) or 0.
    p.r.clear();
    std::uniform_int_distribution<std::int64_t> rv(catalog::kRMin, catalog::kRMax);
    for (int n = 0; n < catalog::kRParamCount; ++n)
        if (!catalog::rParam(n).readOnly())
            p.r[n] = rv(rng);
    p.programs.clear();
    for (int n = 1; n <= 99; ++n)
        p.programs[n] = randomProgram(rng, n, 25 + static_cast<int>(rng() % 50));
    p.messages.clear();
    for (int n = 1; n <= catalog::kTechMessageCount; ++n)
        p.messages[n] = randomWord(rng, catalog::kTechMessageMaxChars);
    for (catalog::PlcGroup g : catalog::kPlcGroups) {
        p.plcTexts(g).clear();
        for (int k = 1; k <= catalog::plcMessageCount(g); ++k)
            p.plcTexts(g)[k] = randomWord(rng, catalog::kPlcMessageMaxChars);
    }
    p.simulation.set("x.drive_time_constant_ms", std::to_string(rng() % 100));
    p.simulation.set("handwheel1.lines", std::to_string(rng() % 1000 + 1));
    return p;
}

} // namespace k528::testing
