// k528 db show (docs/database.md); helpers in db_cli_util.h.
#include "db_cli_util.h"
#include "args.h"
#include "catalog/cparams.h"
#include "catalog/messages.h"
#include "catalog/rparams.h"
#include "cli.h"
#include "cli_texts.h"
#include "db/database.h"
#include "db/explain.h"
#include "db/sha256.h"
#include "db_cli.h"
#include "profile/diff.h"
#include "profile/validate.h"
#include "util/json.h"

#include <algorithm>
#include <map>
#include <cstdio>
#include <filesystem>

namespace k528::cli::dbcli {

namespace {

// "--history" may be followed by a number: "--history 5" -> "--history=5",
// "--history" alone -> "--history=0" (all).
std::vector<std::string> normalizeHistory(std::span<const std::string> argv) {
    std::vector<std::string> v;
    for (std::size_t i = 0; i < argv.size(); ++i) {
        if (argv[i] == "--history") {
            if (i + 1 < argv.size() && parseInt(argv[i + 1])) {
                v.push_back("--history=" + argv[i + 1]);
                ++i;
            } else {
                v.push_back("--history=0");
            }
            continue;
        }
        v.push_back(argv[i]);
    }
    return v;
}

std::optional<int> parseCNumber(const std::string& s) {
    std::string t = s;
    if (!t.empty() && (t[0] == 'C' || t[0] == 'c'))
        t = t.substr(1);
    const auto n = parseInt(t);
    if (!n || *n < 1 || *n > cat::kCParamCount)
        return std::nullopt;
    return static_cast<int>(*n);
}

std::optional<int> parseRNumber(const std::string& s) {
    std::string t = s;
    if (!t.empty() && (t[0] == 'R' || t[0] == 'r'))
        t = t.substr(1);
    const auto n = parseInt(t);
    if (!n || *n < 0 || *n >= cat::kRParamCount)
        return std::nullopt;
    return static_cast<int>(*n);
}

// A program's state ("draft", "released", "withdrawn") in the command's language.
std::string stateWord(db::ProgramState state) {
    switch (state) {
    case db::ProgramState::Draft: return cliText("db.state.draft");
    case db::ProgramState::Released: return cliText("db.state.released");
    case db::ProgramState::Withdrawn: return cliText("db.state.withdrawn");
    }
    return std::string(db::programStateName(state));
}

std::string historyText(const db::Database& d, const std::string& machine,
                        const std::optional<std::string>& key, int limit) {
    std::string s;
    if (key) {
        const auto h = d.history(machine, key, limit);
        s += (h.empty() ? cliText("db.history.of-none", {*key}) : cliText("db.history.of", {*key})) + "\n";
        for (const auto& e : h) {
            s += cliText("db.history.entry", {std::to_string(e.revision), e.at, e.author});
            if (e.change.section == profile::DiffSection::Program)
                s += changeWord(e.change.before.has_value(), e.change.after.has_value()) + "\n";
            else
                s += e.change.before.value_or(cliText("db.change.none")) + " -> " +
                     e.change.after.value_or(cliText("db.change.none")) + "\n";
        }
        return s;
    }
    const auto revs = d.revisions(machine);
    const auto all = d.history(machine, std::nullopt, limit);
    int shown = 0;
    for (const auto& r : revs) {
        if (limit > 0 && shown >= limit)
            break;
        ++shown;
        s += cliText("db.history.revision", {std::to_string(r.revision), r.at, r.author, r.summary,
                                              changeCount(static_cast<std::size_t>(r.changeCount))}) +
             "\n";
        if (r.revision == 1 && r.changeCount > 20) {
            s += cliText("db.history.first", {machine}) + "\n";
            continue;
        }
        std::vector<profile::Change> cs;
        for (const auto& e : all)
            if (e.revision == r.revision)
                cs.push_back(e.change);
        s += changeLines(cs, &d, machine, r.revision);
    }
    return s;
}

Json historyJson(const db::Database& d, const std::string& machine,
                 const std::optional<std::string>& key, int limit) {
    Json arr = Json::array();
    const auto all = d.history(machine, key, limit);
    int shown = 0;
    for (const auto& r : d.revisions(machine)) {
        if (limit > 0 && shown >= limit)
            break;
        ++shown;
        Json cs = Json::array();
        for (const auto& e : all)
            if (e.revision == r.revision)
                cs.push_back(changeJson(e.change));
        if (key && cs.empty())
            continue;
        Json j;
        j["revision"] = r.revision;
        j["author"] = r.author;
        j["at"] = r.at;
        j["summary"] = r.summary;
        j["changes"] = std::move(cs);
        arr.push_back(std::move(j));
    }
    return arr;
}

Json cJson(const MachineProfile& p, const cat::CParamDef& d, bool full) {
    Json j;
    j["number"] = d.number;
    j["key"] = d.key();
    j["axis"] = cat::axisName(d.axis);
    j["name"] = d.name;
    j["name_en"] = d.nameEn;
    j["value"] = p.cValue(d.number);
    j["unit"] = cat::unitSymbol(d.unit);
    j["explanation_ru"] = db::explainCValue(p, d.number, Lang::Ru);
    j["explanation_en"] = db::explainCValue(p, d.number, Lang::En);
    if (full) {
        j["kind"] = cat::kindName(d.kind);
        j["min"] = d.min;
        j["max"] = d.max;
        j["address"] = d.address.text();
        j["description_ru"] = d.descriptionRu;
        j["description_en"] = d.descriptionEn;
        j["hint_ru"] = d.hintRu;
        j["hint_en"] = d.hintEn;
        j["note"] = d.note;
    }
    return j;
}

} // namespace

int cmdShow(std::span<const std::string> argvIn) {
    const auto argv = normalizeHistory(argvIn);
    const Args a(argv, {"--programs", "--messages", "--json"},
                 {"--db", "--c", "--r", "--program", "--history", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().size() != 1)
        return usageError(cliText("db.usage.one-machine", {"show"}));
    Lang lang;
    if (!parseLangOption(a, lang))
        return ExitUsage;
    const auto ref = parseRef(a.positional()[0]);
    if (!ref)
        return ExitUsage;
    int views = 0;
    for (const char* o : {"--c", "--r", "--program"})
        views += a.value(o) ? 1 : 0;
    views += a.has("--programs") + a.has("--messages");
    if (views > 1)
        return usageError(cliText("db.usage.show-one"));
    std::optional<int> cNumber, rNumber, programNumber;
    if (const auto v = a.value("--c"); v && !(cNumber = parseCNumber(*v)))
        return usageError(cliText("db.usage.show-c", {*v}));
    if (const auto v = a.value("--r"); v && !(rNumber = parseRNumber(*v)))
        return usageError(cliText("db.usage.show-r", {*v}));
    if (const auto v = a.value("--program")) {
        const auto n = parseInt(*v);
        if (!n || *n < 1 || *n > 99)
            return usageError(cliText("db.usage.show-program", {*v}));
        programNumber = static_cast<int>(*n);
    }
    std::optional<int> historyLimit;
    if (const auto v = a.value("--history")) {
        const auto n = parseInt(*v);
        if (!n || *n < 0)
            return usageError(cliText("db.usage.history"));
        historyLimit = static_cast<int>(*n);
    }
    DbTarget t;
    auto d = openDbOf(a, t, false, {}, lang);
    if (!d)
        return ExitUsage;
    try {
        const MachineProfile p = loadRef(*d, *ref);
        const db::MachineInfo info = *d->machine(ref->name);
        const bool ru = lang == Lang::Ru;
        std::optional<std::string> historyKey;
        if (cNumber)
            historyKey = cat::cParam(*cNumber).key();
        else if (rNumber)
            historyKey = "R" + std::to_string(*rNumber);
        else if (programNumber)
            historyKey = "L" + std::to_string(*programNumber);

        if (a.has("--json")) {
            Json root;
            root["name"] = p.name;
            root["title"] = p.title;
            root["revision"] = ref->revision ? *ref->revision : info.revision;
            root["current_revision"] = info.revision;
            root["changed_at"] = info.changedAt;
            root["changed_by"] = info.changedBy;
            root["created_at"] = info.createdAt;
            Json cs = Json::array();
            for (const auto& def : cat::cParams())
                if (!cNumber || *cNumber == def.number)
                    cs.push_back(cJson(p, def, cNumber.has_value()));
            root["c"] = std::move(cs);
            Json rs = Json::array();
            for (const auto& [n, v] : p.r)
                if (!rNumber || *rNumber == n) {
                    Json j;
                    j["number"] = n;
                    j["value"] = v;
                    j["meaning_ru"] = rMeaning(n, Lang::Ru);
                    j["meaning_en"] = rMeaning(n, Lang::En);
                    rs.push_back(std::move(j));
                }
            root["r"] = std::move(rs);
            Json ps = Json::array();
            std::map<int, db::ProgramRelease> states;
            if (!ref->revision)
                for (db::ProgramRelease& r : d->programReleases(info.name))
                    states.emplace(r.number, std::move(r));
            for (const auto& [n, text] : p.programs)
                if (!programNumber || *programNumber == n) {
                    Json j;
                    j["number"] = n;
                    if (const auto it = states.find(n); it != states.end()) {
                        j["state"] = db::programStateName(it->second.state);
                        j["released_revision"] =
                            it->second.releasedRevision ? Json(*it->second.releasedRevision) : Json();
                    }
                    j["title"] = db::programTitle(text);
                    j["lines"] = static_cast<long long>(std::count(text.begin(), text.end(), '\n'));
                    j["sha256"] = db::sha256Hex(text);
                    if (programNumber)
                        j["text"] = text;
                    ps.push_back(std::move(j));
                }
            root["programs"] = std::move(ps);
            Json ms = Json::object();
            for (const auto& [n, text] : p.messages)
                ms["#" + std::to_string(n)] = text;
            root["messages"] = std::move(ms);
            Json plc = Json::object();
            for (cat::PlcGroup g : cat::kPlcGroups)
                for (const auto& [k, text] : p.plcTexts(g))
                    plc[std::string(1, cat::plcGroupLetter(g)) + (k < 10 ? "0" : "") +
                        std::to_string(k)] = text;
            root["plc_messages"] = std::move(plc);
            Json fs = Json::array();
            for (const auto& f : profile::validate(p))
                fs.push_back(findingJson(f));
            root["findings"] = std::move(fs);
            if (historyLimit)
                root["history"] = historyJson(*d, info.name, historyKey, *historyLimit);
            out(json::dump(root) + "\n");
            return ExitOk;
        }

        std::string s = machineHeader(info, ref->revision);
        if (cNumber) {
            const auto& def = cat::cParam(*cNumber);
            s += "\n" + def.key() + " " + std::string(ru ? def.name : def.nameEn);
            if (def.axis != cat::Axis::Common)
                s += cliText("db.show.c.axis", {std::string(cat::axisName(def.axis))}, ru);
            s += " = " + std::to_string(p.cValue(*cNumber)) + "\n";
            const std::string ex = db::explainCValue(p, *cNumber, lang);
            if (!ex.empty())
                s += cliText("db.show.c.meaning", {ex}, ru) + "\n";
            s += cliText("db.show.c.unit", {unitText(def.unit, lang)}, ru) + "\n";
            s += cliText("db.show.c.range", {std::to_string(def.min), std::to_string(def.max)}, ru) + "\n";
            s += cliText("db.show.c.kind", {std::string(cat::kindName(def.kind))}, ru) + "\n";
            if (!def.address.text().empty())
                s += cliText("db.show.c.address", {ru ? def.address.text() : def.address.textEn()}, ru) + "\n";
            const std::string hint(ru ? def.hintRu : def.hintEn);
            if (!hint.empty())
                s += cliText("db.show.c.hint", {hint}, ru) + "\n";
            s += "  " + std::string(ru ? def.descriptionRu : def.descriptionEn) + "\n";
            if (!def.note.empty())
                s += cliText("db.show.note", {std::string(def.note)}) + "\n";
            for (const auto& f : profile::validate(p))
                if (std::find(f.cParams.begin(), f.cParams.end(), *cNumber) != f.cParams.end())
                    s += "  " + findingText(f, lang) + "\n";
            s += historyText(*d, info.name, historyKey, historyLimit.value_or(0));
        } else if (rNumber) {
            const cat::RParamDef& def = cat::rParam(*rNumber);
            const auto it = p.r.find(*rNumber);
            s += "\nR" + std::to_string(*rNumber) + " = " +
                 (it == p.r.end() ? cliText("db.show.r.not-preset", {}, ru)
                                  : std::to_string(it->second) + " " +
                                        rValueText(p, *rNumber, it->second, lang)) +
                 "\n";
            const std::string meaning = rMeaning(*rNumber, lang);
            if (!meaning.empty())
                s += "  " + meaning + "\n";
            s += "  " +
                 cliText(def.readOnly() ? "db.show.r.read-only" : def.user() ? "db.show.r.user" : "db.show.r.system",
                         {}, ru) +
                 ", " + std::string(ru ? cat::rUnitRu(def.unit) : cat::rUnitEn(def.unit)) + "\n";
            if (def.group > 0)
                s += cliText("db.show.r.screen",
                             {std::to_string(def.group),
                              std::string(ru ? cat::rGroupNameRu(def.group) : cat::rGroupNameEn(def.group))},
                             ru) +
                     "\n";
            s += historyText(*d, info.name, historyKey, historyLimit.value_or(0));
        } else if (programNumber) {
            const auto it = p.programs.find(*programNumber);
            if (it == p.programs.end())
                return fail(cliText("db.show.no-program", {p.name, std::to_string(*programNumber)}));
            if (historyLimit) {
                out(s + historyText(*d, info.name, historyKey, *historyLimit));
                return ExitOk;
            }
            out(it->second);
            return ExitOk;
        } else if (historyLimit) {
            s += "\n" + historyText(*d, info.name, std::nullopt, *historyLimit);
            out(s);
            return ExitOk;
        } else if (a.has("--programs")) {
            s += "\n";
            // The state of each program now (draft, released, withdrawn), with
            // the released version when a newer draft exists.
            std::map<int, db::ProgramRelease> states;
            if (!ref->revision)
                for (db::ProgramRelease& r : d->programReleases(info.name))
                    states.emplace(r.number, std::move(r));
            for (const auto& [n, text] : p.programs) {
                std::string line = programSummary(n, text);
                if (const auto it = states.find(n); it != states.end()) {
                    line.pop_back();
                    line += "  " + stateWord(it->second.state);
                    if (it->second.state == db::ProgramState::Draft && it->second.releasedRevision)
                        line += cliText("db.state.released-revision", {std::to_string(*it->second.releasedRevision)});
                    else if (it->second.state == db::ProgramState::Released && it->second.last)
                        line += cliText("db.state.released-by", {it->second.last->author, it->second.last->at});
                    line += "\n";
                }
                s += line;
            }
            if (p.programs.empty())
                s += cliText("db.show.no-programs", {}, ru) + "\n";
        } else if (a.has("--messages")) {
            s += "\n" + cliText("db.show.messages", {}, ru) + "\n";
            for (const auto& [n, text] : p.messages)
                s += "  #" + pad(std::to_string(n), 3) + text + "\n";
            for (cat::PlcGroup g : cat::kPlcGroups) {
                s += "\n" + std::string(ru ? cat::plcGroupNameRu(g) : cat::plcGroupNameEn(g)) +
                     ":\n";
                for (const auto& [k, text] : p.plcTexts(g))
                    s += "  " + std::string(1, cat::plcGroupLetter(g)) + (k < 10 ? "0" : "") +
                         std::to_string(k) + "  " + pad(cat::plcMessageAddress(g, k), 8) + "  " +
                         text + "\n";
            }
        } else {
            s += "\n";
            for (const auto& def : cat::cParams()) {
                if (def.number == 1)
                    s += cliText("db.show.axis", {"X"}, ru) + "\n";
                else if (def.number == 53)
                    s += cliText("db.show.axis", {"Z"}, ru) + "\n";
                else if (def.number == 105)
                    s += cliText("db.show.common", {}, ru) + "\n";
                s += cLine(p, def, lang);
            }
            s += "\n" + cliText("db.show.r-presets", {}, ru) + "\n";
            for (const auto& [n, v] : p.r) {
                const std::string vt = rValueText(p, n, v, lang);
                s += "R" + pad(std::to_string(n), 4) + " " + padLeft(std::to_string(v), 11) + "  " +
                     pad(vt, 18) + " " + rMeaning(n, lang) + "\n";
            }
            if (p.r.empty())
                s += cliText("db.change.none", {}, ru) + "\n";
            s += "\n" + cliText("db.show.programs", {std::to_string(p.programs.size())}, ru);
            if (!p.programs.empty()) {
                s += " (";
                bool first = true;
                for (const auto& [n, text] : p.programs) {
                    s += (first ? "L" : ", L") + std::to_string(n);
                    first = false;
                }
                s += ")";
            }
            s += cliText("db.show.messages-count",
                         {std::to_string(p.messages.size()),
                          std::to_string(p.plcAlarm.size() + p.plcWork.size() + p.plcSystem.size())},
                         ru) +
                 "\n";
        }
        if (!cNumber) {
            const auto findings = profile::validate(p);
            if (!findings.empty()) {
                s += "\n" + cliText("db.show.checks", {}, ru) + "\n";
                for (const auto& f : findings)
                    s += "  " + findingText(f, lang) + "\n";
            }
        }
        if (historyLimit && (a.has("--programs") || a.has("--messages")))
            s += "\n" + historyText(*d, info.name, std::nullopt, *historyLimit);
        out(s);
        return ExitOk;
    } catch (const db::Error& e) {
        return dbFail(e, lang);
    }
}

} // namespace k528::cli::dbcli
