#include "db/revisions.h"

#include "catalog/cparams.h"
#include "db/error.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>

namespace k528::db::revision {

namespace cat = k528::catalog;
using profile::Change;
using profile::DiffSection;
using profile::MachineProfile;

namespace {

std::string two(int k) {
    return (k < 10 ? "0" : "") + std::to_string(k);
}

std::optional<std::int64_t> toInt(const std::string& s) {
    if (s.empty())
        return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(s.c_str(), &end, 10);
    if (errno != 0 || end != s.c_str() + s.size())
        return std::nullopt;
    return v;
}

bool sameFinding(const profile::Finding& a, const profile::Finding& b) {
    return a.severity == b.severity && a.subject == b.subject && a.message == b.message;
}

// A finding about one item's own value (always rejected), as opposed to a
// cross-check between constants.
bool itemFinding(const profile::Finding& f, const MachineProfile& p) {
    if (f.cParams.empty())
        return f.severity == profile::Severity::Error;
    if (f.cParams.size() == 1) {
        const int n = f.cParams.front();
        return n >= 1 && n <= cat::kCParamCount && !profile::checkCValue(n, p.cValue(n)).empty();
    }
    return false;
}

} // namespace

std::string plcKey(cat::PlcGroup g, int k) {
    return std::string(1, cat::plcGroupLetter(g)) + two(k);
}

std::optional<cat::PlcGroup> plcGroupOf(char letter) {
    for (cat::PlcGroup g : cat::kPlcGroups)
        if (cat::plcGroupLetter(g) == letter)
            return g;
    return std::nullopt;
}

std::optional<DiffSection> sectionFromName(std::string_view s) {
    for (DiffSection d :
         {DiffSection::Machine, DiffSection::C, DiffSection::R, DiffSection::Program,
          DiffSection::Message, DiffSection::PlcMessage, DiffSection::Simulation})
        if (profile::diffSectionName(d) == s)
            return d;
    return std::nullopt;
}

std::optional<int> keyNumber(std::string_view key) {
    if (key.size() < 2)
        return std::nullopt;
    int n = 0;
    for (char ch : key.substr(1)) {
        if (ch < '0' || ch > '9' || n > 100000)
            return std::nullopt;
        n = n * 10 + (ch - '0');
    }
    return n;
}

std::string joinKeys(const profile::Settings& s, char sep) {
    std::string out;
    for (const auto& [k, v] : s.entries()) {
        if (!out.empty())
            out += sep;
        out += k;
    }
    return out;
}

std::vector<profile::Finding> checkWrite(const MachineProfile* old, const MachineProfile& neu,
                                         bool allowErrors) {
    std::vector<profile::Finding> found = profile::validate(neu);
    std::vector<profile::Finding> oldFound;
    if (old)
        oldFound = profile::validate(*old);
    std::vector<profile::Finding> rejected;
    for (const auto& f : found) {
        if (f.severity != profile::Severity::Error)
            continue;
        if (itemFinding(f, neu)) {
            rejected.push_back(f);
            continue;
        }
        const bool existed = std::any_of(oldFound.begin(), oldFound.end(),
                                         [&](const auto& o) { return sameFinding(o, f); });
        if (!existed && !allowErrors)
            rejected.push_back(f);
    }
    if (!rejected.empty())
        throw ValidationError(neu.name, std::move(rejected));
    return found;
}

std::vector<Change> computeChanges(const MachineProfile* old, const MachineProfile& neu) {
    if (!old) {
        std::vector<Change> out;
        out.push_back(Change{DiffSection::Machine, "name", "", std::nullopt, neu.name});
        out.push_back(Change{DiffSection::Machine, "title", "", std::nullopt, neu.title});
        for (const cat::CParamDef& d : cat::cParams())
            out.push_back(Change{DiffSection::C, d.key(), std::string(d.name), std::nullopt,
                                 std::to_string(neu.cValue(d.number))});
        MachineProfile base;
        base.name = neu.name;
        base.title = neu.title;
        base.c = neu.c;
        const auto rest = profile::diff(base, neu);
        out.insert(out.end(), rest.begin(), rest.end());
        return out;
    }
    std::vector<Change> out = profile::diff(*old, neu);
    // Keys of the simulation section that only moved: diff() does not report
    // them, the history records the new order.
    std::vector<std::string> expected;
    for (const auto& [k, v] : old->simulation.entries())
        if (neu.simulation.has(k))
            expected.push_back(k);
    for (const auto& [k, v] : neu.simulation.entries())
        if (!old->simulation.has(k))
            expected.push_back(k);
    std::vector<std::string> actual;
    for (const auto& [k, v] : neu.simulation.entries())
        actual.push_back(k);
    if (expected != actual)
        out.push_back(Change{DiffSection::Simulation, std::string(kOrderKey), "", joinKeys(old->simulation, ' '),
                             joinKeys(neu.simulation, ' ')});
    return out;
}

bool applyRecorded(MachineProfile& p, DiffSection section, const std::string& key,
                   const std::optional<std::string>& after) {
    const auto num = keyNumber(key);
    std::optional<std::int64_t> value;
    switch (section) {
    case DiffSection::Machine:
        if (!after)
            return false;
        if (key == "name")
            p.name = *after;
        else if (key == "title")
            p.title = *after;
        else
            return false;
        return true;
    case DiffSection::C:
        if (!num || *num < 1 || *num > cat::kCParamCount || !after || !(value = toInt(*after)))
            return false;
        p.setC(*num, *value);
        return true;
    case DiffSection::R:
        if (!num)
            return false;
        if (!after)
            p.r.erase(*num);
        else if ((value = toInt(*after)))
            p.r[*num] = *value;
        else
            return false;
        return true;
    case DiffSection::Message:
        if (!num)
            return false;
        if (after)
            p.messages[*num] = *after;
        else
            p.messages.erase(*num);
        return true;
    case DiffSection::PlcMessage: {
        const auto g = plcGroupOf(key.empty() ? '?' : key[0]);
        if (!g || !num)
            return false;
        if (after)
            p.plcTexts(*g)[*num] = *after;
        else
            p.plcTexts(*g).erase(*num);
        return true;
    }
    case DiffSection::Simulation:
        if (key == kOrderKey)
            return true;
        try {
            if (after)
                p.simulation.set(key, *after);
            else
                p.simulation.erase(key);
        } catch (const profile::SettingError&) {
            return false;
        }
        return true;
    case DiffSection::Program:
        return true; // the programs are their versions
    }
    return false;
}

std::pair<std::string, std::vector<std::string>> orderSettings(MachineProfile& p, const std::string& order) {
    profile::Settings sorted;
    std::size_t pos = 0;
    while (pos < order.size()) {
        auto end = order.find('\n', pos);
        if (end == std::string::npos)
            end = order.size();
        const std::string key = order.substr(pos, end - pos);
        const auto v = p.simulation.find(key);
        if (!v)
            return {"corrupt.settings-order-key", {key}};
        sorted.set(key, *v);
        pos = end + 1;
    }
    if (sorted.size() != p.simulation.size())
        return {"corrupt.settings-order-incomplete", {}};
    p.simulation = std::move(sorted);
    return {};
}

} // namespace k528::db::revision
