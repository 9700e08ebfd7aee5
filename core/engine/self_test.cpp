#include "engine/self_test.h"

#include "engine/rparams.h"
#include "program/formatter.h"

#include "profile/english.h"
#include "profile/validate.h"
#include "program/parser.h"

namespace k528::engine {

std::array<bool, 65> configurationMessages(std::span<const std::int64_t> c) {
    std::array<bool, 65> m{};
    for (const profile::Finding& f : profile::checkCParams(c)) {
        if (f.severity != profile::Severity::Error)
            continue;
        const int n = f.message.value_or(0);
        switch (n) {
        case 13:
        case 29:
        case 37:
        case 38:
        case 39:
        case 15:
            m[static_cast<std::size_t>(n)] = true;
            break;
        case 6:
        case 22:
            // ПРЕДЕЛ ЦАП below МАКС.ЦАП: a prediction, the servo raises 6/22
            // when the DAC really exceeds it.
            break;
        default:
            m[15] = true;
            break;
        }
    }
    return m;
}

program::ProgramStore loadStore(const profile::MachineProfile& p, bool& intact) {
    program::ProgramStore store;
    intact = true;
    for (const auto& [number, text] : p.programs) {
        program::ParseOptions o;
        o.programNumber = number;
        program::ParseResult pr = program::parse(text, o);
        if (pr.hasErrors())
            intact = false;
        for (program::Program& prog : pr.store.programs())
            store.insert(std::move(prog));
    }
    for (const auto& [k, text] : p.messages)
        store.messages.setMachineFile(k, text);
    return store;
}

profile::MachineProfile memoryProfile(const profile::MachineProfile& base,
                                      std::span<const std::int64_t> c,
                                      std::span<const std::int32_t> r,
                                      const program::ProgramStore& store) {
    profile::MachineProfile p = base;
    for (std::size_t n = 1; n < p.c.size() && n < c.size(); ++n)
        p.c[n] = c[n];
    p.r.clear();
    for (std::size_t n = 0; n < r.size() && rValid(static_cast<int>(n)); ++n)
        if (r[n] != 0 && !rReadOnly(static_cast<int>(n)))
            p.r[static_cast<int>(n)] = r[n];
    p.programs.clear();
    for (const program::Program& prog : store.programs()) {
        program::ProgramStore one;
        one.insert(prog);
        p.programs[prog.number] = program::format(one);
    }
    p.messages.clear();
    for (const program::Message& m : store.messages.entries)
        p.messages[m.number] = m.text;
    // The machine file's English of a message is of its Russian: it goes
    // with a message the memory holds no more or holds another text in (a
    // program's), else a window in English would show it for that text.
    for (const auto& [k, text] : base.messages)
        if (const auto it = p.messages.find(k); it == p.messages.end() || it->second != text) {
            std::string item = "#";
            item += std::to_string(k);
            p.simulation.erase(profile::englishKey(item));
        }
    return p;
}

bool storeIntact(const program::ProgramStore& store) {
    for (const program::Program& p : store.programs())
        for (const program::Frame& f : p.frames)
            if (f.malformed)
                return false;
    return true;
}

} // namespace k528::engine
