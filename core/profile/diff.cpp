#include "profile/diff.h"

#include "catalog/rparams.h"

#include <algorithm>
#include <set>
#include <sstream>

namespace k528::profile {

namespace cat = k528::catalog;

std::string_view diffSectionName(DiffSection s) {
    switch (s) {
    case DiffSection::Machine:
        return "machine";
    case DiffSection::C:
        return "c";
    case DiffSection::R:
        return "r";
    case DiffSection::Program:
        return "program";
    case DiffSection::Message:
        return "message";
    case DiffSection::PlcMessage:
        return "plc-message";
    case DiffSection::Simulation:
        return "simulation";
    }
    return "";
}

namespace {

template <typename V, typename KeyFn, typename LabelFn, typename ValueFn>
void diffMaps(std::vector<Change>& out, DiffSection section, const std::map<int, V>& a,
              const std::map<int, V>& b, KeyFn key, LabelFn label, ValueFn value) {
    std::set<int> keys;
    for (const auto& e : a)
        keys.insert(e.first);
    for (const auto& e : b)
        keys.insert(e.first);
    for (int k : keys) {
        const auto ia = a.find(k);
        const auto ib = b.find(k);
        std::optional<std::string> before, after;
        if (ia != a.end())
            before = value(ia->second);
        if (ib != b.end())
            after = value(ib->second);
        if (before != after)
            out.push_back(Change{section, key(k), label(k), before, after});
    }
}

std::vector<std::string> splitLines(const std::string& s) {
    std::vector<std::string> lines;
    std::size_t pos = 0;
    while (pos < s.size()) {
        auto end = s.find('\n', pos);
        if (end == std::string::npos)
            end = s.size();
        lines.push_back(s.substr(pos, end - pos));
        pos = end + 1;
    }
    return lines;
}

std::string two(int k) {
    return (k < 10 ? "0" : "") + std::to_string(k);
}

} // namespace

std::vector<Change> diff(const MachineProfile& a, const MachineProfile& b) {
    std::vector<Change> out;
    if (a.name != b.name)
        out.push_back(Change{DiffSection::Machine, "name", "", a.name, b.name});
    if (a.title != b.title)
        out.push_back(Change{DiffSection::Machine, "title", "", a.title, b.title});
    for (const cat::CParamDef& d : cat::cParams()) {
        const auto va = a.cValue(d.number), vb = b.cValue(d.number);
        if (va != vb)
            out.push_back(Change{DiffSection::C, d.key(), std::string(d.name), std::to_string(va),
                                 std::to_string(vb)});
    }
    diffMaps(
        out, DiffSection::R, a.r, b.r, [](int n) { return "R" + std::to_string(n); },
        [](int n) {
            const cat::RParamDef& d = cat::rParam(n);
            return std::string(d.panelHint.empty() ? d.meaningRu : d.panelHint);
        },
        [](std::int64_t v) { return std::to_string(v); });
    diffMaps(
        out, DiffSection::Program, a.programs, b.programs,
        [](int n) { return "L" + std::to_string(n); }, [](int) { return std::string(); },
        [](const std::string& t) { return t; });
    diffMaps(
        out, DiffSection::Message, a.messages, b.messages,
        [](int n) { return "#" + std::to_string(n); }, [](int) { return std::string(); },
        [](const std::string& t) { return t; });
    for (cat::PlcGroup g : cat::kPlcGroups)
        diffMaps(
            out, DiffSection::PlcMessage, a.plcTexts(g), b.plcTexts(g),
            [g](int k) { return std::string(1, cat::plcGroupLetter(g)) + two(k); },
            [g](int k) { return cat::plcMessageAddress(g, k); },
            [](const std::string& t) { return t; });
    // Settings: a's order, then b's new keys.
    for (const auto& [key, va] : a.simulation.entries()) {
        const auto vb = b.simulation.find(key);
        if (vb != va)
            out.push_back(Change{DiffSection::Simulation, key, "", va, vb});
    }
    for (const auto& [key, vb] : b.simulation.entries())
        if (!a.simulation.has(key))
            out.push_back(Change{DiffSection::Simulation, key, "", std::nullopt, vb});
    return out;
}

std::string lineDiff(const std::string& before, const std::string& after) {
    if (before == after)
        return {};
    const auto x = splitLines(before), y = splitLines(after);
    const std::size_t n = x.size(), m = y.size();
    // lcs[i][j]: length of the LCS of x[i..] and y[j..].
    std::vector<std::vector<int>> lcs(n + 1, std::vector<int>(m + 1, 0));
    for (std::size_t i = n; i-- > 0;)
        for (std::size_t j = m; j-- > 0;)
            lcs[i][j] =
                x[i] == y[j] ? lcs[i + 1][j + 1] + 1 : std::max(lcs[i + 1][j], lcs[i][j + 1]);
    std::string out;
    std::size_t i = 0, j = 0;
    while (i < n || j < m) {
        if (i < n && j < m && x[i] == y[j]) {
            out += "  " + x[i++] + "\n";
            ++j;
        } else if (i < n && (j == m || lcs[i + 1][j] >= lcs[i][j + 1])) {
            out += "- " + x[i++] + "\n";
        } else {
            out += "+ " + y[j++] + "\n";
        }
    }
    return out;
}

std::string formatDiff(const std::vector<Change>& changes) {
    std::ostringstream o;
    for (const Change& c : changes) {
        o << c.key;
        if (!c.label.empty())
            o << " " << c.label;
        if (c.section == DiffSection::Program) {
            if (!c.before)
                o << ": added\n";
            else if (!c.after)
                o << ": removed\n";
            else
                o << ": changed\n";
            std::string d = lineDiff(c.before.value_or(""), c.after.value_or(""));
            std::istringstream lines(d);
            for (std::string line; std::getline(lines, line);)
                if (line.rfind("  ", 0) != 0 || !c.before || !c.after)
                    o << "    " << line << "\n";
            continue;
        }
        o << ": " << c.before.value_or("(none)") << " -> " << c.after.value_or("(none)") << "\n";
    }
    return o.str();
}

} // namespace k528::profile
