#include "profile/text_format.h"
#include "profile/english.h"
#include "util/input_file.h"

#include "catalog/rparams.h"
#include "profile/validate.h"
#include "util/utf8.h"

#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace k528::profile {

namespace cat = k528::catalog;

FileError::FileError(std::string source, int line, Problem problem)
    : std::runtime_error(source + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " +
                         problem.text()),
      source_(std::move(source)), line_(line), message_(problem.text()), problem_(std::move(problem)) {}

namespace {

constexpr std::string_view kEndProgram = "[end program]";

std::string_view trim(std::string_view s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string_view::npos)
        return {};
    const auto e = s.find_last_not_of(" \t");
    return s.substr(b, e - b + 1);
}

std::string two(int k) {
    return (k < 10 ? "0" : "") + std::to_string(k);
}

// Splits "key=value" (the '=' is required). Returns false without '='.
bool splitKeyValue(std::string_view line, std::string_view& key, std::string_view& value) {
    const auto eq = line.find('=');
    if (eq == std::string_view::npos)
        return false;
    key = trim(line.substr(0, eq));
    value = line.substr(eq + 1);
    return true;
}

// Drops a trailing "; comment" and blanks.
std::string_view stripComment(std::string_view v) {
    const auto sc = v.find(';');
    return trim(sc == std::string_view::npos ? v : v.substr(0, sc));
}

// "C022" / "c22" / "R204": the number after the letter, or -1.
int keyNumber(std::string_view key, char letter) {
    if (key.size() < 2 || key.size() > 4 || (key[0] != letter && key[0] != letter + ('a' - 'A')))
        return -1;
    int n = 0;
    for (std::size_t i = 1; i < key.size(); ++i) {
        if (key[i] < '0' || key[i] > '9')
            return -1;
        n = n * 10 + (key[i] - '0');
    }
    return n;
}

enum class Section { None, Machine, C, R, Messages, Plc, Simulation };

class Reader {
public:
    Reader(std::string_view text, std::string_view source) : source_(source) {
        if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF")
            text.remove_prefix(3); // UTF-8 byte-order mark
        std::size_t pos = 0;
        while (pos < text.size()) {
            auto end = text.find('\n', pos);
            if (end == std::string_view::npos)
                end = text.size();
            std::string_view line = text.substr(pos, end - pos);
            if (!line.empty() && line.back() == '\r')
                line.remove_suffix(1);
            lines_.push_back(line);
            pos = end + 1;
        }
    }

    MachineProfile read() {
        for (std::size_t i = 0; i < lines_.size(); ++i) {
            lineNo_ = static_cast<int>(i) + 1;
            const std::string_view raw = lines_[i];
            if (!utf8::isValid(raw))
                fail("file.utf8");
            // An invisible character would make the error below unreadable:
            // name it. (One at the very start of the file is skipped above.)
            if (const auto bom = raw.find("\xEF\xBB\xBF"); bom != std::string_view::npos)
                fail("file.bom", {std::to_string(utf8::length(raw.substr(0, bom)) + 1)});
            const std::string_view line = trim(raw);
            if (line.empty() || line[0] == ';')
                continue;
            if (line[0] == '[') {
                i = header(stripComment(line), i); // "[c] ; comment" is fine
                continue;
            }
            entry(raw, line);
        }
        finish();
        return std::move(p_);
    }

private:
    [[noreturn]] void fail(Problem p, int line = -1) const {
        throw FileError(std::string(source_), line < 0 ? lineNo_ : line, std::move(p));
    }
    [[noreturn]] void fail(std::string id, std::vector<std::string> args = {}, int line = -1) const {
        fail(problem(std::move(id), std::move(args)), line);
    }
    void check(Problem p) const {
        if (!p.empty())
            fail(std::move(p));
    }
    // Records `key` (unique within `scope`); fails if seen before.
    void once(const std::string& key, std::string_view scope = "") {
        const auto [it, inserted] = seen_.emplace(std::string(scope) + "\n" + key, lineNo_);
        if (!inserted)
            fail("file.twice", {key, std::to_string(it->second)});
    }

    // A section header; returns the index of the last line consumed.
    std::size_t header(std::string_view line, std::size_t i) {
        if (line.back() != ']')
            fail("file.header-bracket", {std::string(line)});
        const std::string name(trim(line.substr(1, line.size() - 2)));
        if (name.rfind("program", 0) == 0 && name.size() > 7 && (name[7] == ' ' || name[7] == '\t'))
            return program(name, i);
        if (name == "end program")
            fail("file.end-without-program");
        static const std::map<std::string, Section> sections = {
            {"machine", Section::Machine},
            {"c", Section::C},
            {"r", Section::R},
            {"messages", Section::Messages},
            {"plc-messages", Section::Plc},
            {"simulation", Section::Simulation},
        };
        const auto it = sections.find(name);
        if (it == sections.end())
            fail("file.unknown-section", {name});
        once("[" + name + "]");
        section_ = it->second;
        sectionLine_[section_] = lineNo_;
        return i;
    }

    std::size_t program(const std::string& name, std::size_t i) {
        const std::string_view numText = trim(std::string_view(name).substr(7));
        const auto n = parseInt(numText);
        if (!n || *n < 1 || *n > 99)
            fail("file.program-number", {std::string(numText)});
        const int number = static_cast<int>(*n);
        once("[program " + std::to_string(number) + "]");
        const int headerLine = lineNo_;
        std::string text;
        for (std::size_t j = i + 1; j < lines_.size(); ++j) {
            lineNo_ = static_cast<int>(j) + 1;
            const std::string_view l = lines_[j];
            if (!utf8::isValid(l))
                fail("file.utf8");
            if (trim(l) == kEndProgram) {
                if (text.empty())
                    fail("file.program-empty", {std::to_string(number)}, headerLine);
                if (Problem p = programProblem(number, text); !p.empty())
                    fail(std::move(p), headerLine);
                p_.programs[number] = std::move(text);
                section_ = Section::None; // entries after [end program] need a section
                return j;
            }
            if (trim(l).starts_with('['))
                fail("file.program-bracket", {std::to_string(number), std::to_string(headerLine)});
            text.append(l);
            text.push_back('\n');
        }
        fail("file.program-unended", {std::to_string(number)}, headerLine);
    }

    void entry(std::string_view raw, std::string_view line) {
        std::string_view key, value;
        if (section_ == Section::None)
            fail("file.outside-section", {std::string(line)});
        if (!splitKeyValue(raw, key, value))
            fail("file.no-equals", {std::string(line)});
        switch (section_) {
        case Section::Machine:
            machine(key, trim(value));
            break;
        case Section::C:
            cParam(key, stripComment(value));
            break;
        case Section::R:
            rParam(key, stripComment(value));
            break;
        case Section::Messages:
            message(key, value);
            break;
        case Section::Plc:
            plc(key, value);
            break;
        case Section::Simulation:
            setting(key, stripComment(value));
            break;
        case Section::None:
            break;
        }
    }

    // `item.en=` beside a text for people: its English, kept as a setting
    // (profile.h, englishKey); the Russian must be given too (finish()).
    bool english(std::string_view key, std::string_view value) {
        if (!key.ends_with(".en"))
            return false;
        const std::string item(key.substr(0, key.size() - 3));
        const std::string setting = englishKey(item);
        if (setting.empty())
            return false;
        once(englishItem(setting) + ".en");
        check(englishTextProblem(item, value));
        check(settingProblem(setting, value));
        if (!value.empty()) {
            p_.simulation.set(setting, value);
            englishLine_[englishItem(setting)] = lineNo_;
        }
        return true;
    }

    void machine(std::string_view key, std::string_view value) {
        if (key == "title.en" && english(key, value))
            return;
        if (key != "format" && key != "name" && key != "title")
            fail("file.machine-key", {std::string(key)});
        once(std::string(key), "machine");
        if (key == "format") {
            const auto v = parseInt(value);
            if (!v)
                fail("file.format-nan", {std::string(value)});
            if (*v != kMachineFileFormat)
                fail("file.format-unknown", {std::string(value), std::to_string(kMachineFileFormat)});
            sawFormat_ = true;
        } else if (key == "name") {
            check(nameProblem(value));
            p_.name = std::string(value);
        } else {
            check(titleProblem(value));
            p_.title = std::string(value);
        }
    }

    void cParam(std::string_view key, std::string_view value) {
        const int n = keyNumber(key, 'C');
        if (n < 1 || n > cat::kCParamCount)
            fail("file.c-key", {std::string(key)});
        once(cat::cParam(n).key());
        const auto v = parseInt(value);
        if (!v)
            fail("file.not-integer", {cat::cParam(n).key(), std::string(value)});
        check(cValueProblem(n, *v));
        p_.setC(n, *v);
        cSeen_.insert(n);
    }

    void rParam(std::string_view key, std::string_view value) {
        const int n = keyNumber(key, 'R');
        if (n < 0 || n >= cat::kRParamCount)
            fail("file.r-key", {std::string(key)});
        once("R" + std::to_string(n));
        const auto v = parseInt(value);
        if (!v)
            fail("file.not-integer", {"R" + std::to_string(n), std::string(value)});
        check(rPresetProblem(n, *v));
        p_.r[n] = *v;
    }

    void message(std::string_view key, std::string_view text) {
        if (english(key, text))
            return;
        const auto n = key.size() >= 2 && key[0] == '#' ? parseInt(key.substr(1)) : std::nullopt;
        if (!n || key[1] == '+' || key[1] == '-')
            fail("file.message-key", {std::string(key)});
        if (*n < 1 || *n > cat::kTechMessageCount)
            fail("file.message-number", {std::string(key)});
        once("#" + std::to_string(*n));
        check(messageProblem(static_cast<int>(*n), text));
        p_.messages[static_cast<int>(*n)] = std::string(text);
    }

    void plc(std::string_view key, std::string_view text) {
        if (english(key, text))
            return;
        const char letter = key.empty() ? '?' : static_cast<char>(key[0] & ~0x20);
        cat::PlcGroup g{};
        if (letter == 'A')
            g = cat::PlcGroup::Alarm;
        else if (letter == 'W')
            g = cat::PlcGroup::Work;
        else if (letter == 'S')
            g = cat::PlcGroup::System;
        else
            fail("file.plc-key", {std::string(key)});
        const auto k = parseInt(key.substr(1));
        if (!k || key[1] == '+' || key[1] == '-' || *k < 1 || *k > cat::plcMessageCount(g))
            fail("file.plc-number", {std::string(key), std::to_string(cat::plcMessageCount(g))});
        once(std::string(1, letter) + two(static_cast<int>(*k)));
        check(plcTextProblem(g, static_cast<int>(*k), text));
        p_.plcTexts(g)[static_cast<int>(*k)] = std::string(text);
    }

    void setting(std::string_view key, std::string_view value) {
        if (!englishItem(key).empty()) // beside its Russian, not here
            fail("file.english-place", {std::string(key), englishItem(key) + ".en"});
        check(settingProblem(key, value));
        once(std::string(key), "simulation");
        p_.simulation.set(key, value);
    }

    void finish() {
        lineNo_ = static_cast<int>(lines_.size());
        if (!sectionLine_.contains(Section::Machine))
            fail("file.no-machine", {}, 0);
        const int machineLine = sectionLine_[Section::Machine];
        if (!sawFormat_)
            fail("file.no-format", {std::to_string(kMachineFileFormat)}, machineLine);
        if (p_.name.empty())
            fail("file.no-name", {}, machineLine);
        // An English without its Russian: a typo in the number, or the Russian lost.
        for (const auto& [item, line] : englishLine_) {
            const bool russian = item == "title" ? !p_.title.empty()
                                 : item[0] == '#' ? p_.messages.contains(std::stoi(item.substr(1)))
                                                  : !plcRussian(item).empty();
            if (!russian)
                fail("file.english-alone", {item + ".en", item}, line);
        }
        if (!sectionLine_.contains(Section::C))
            fail("file.no-c", {}, 0);
        if (cSeen_.size() != static_cast<std::size_t>(cat::kCParamCount)) {
            std::string missing;
            int count = 0;
            for (int n = 1; n <= cat::kCParamCount; ++n) {
                if (cSeen_.contains(n))
                    continue;
                if (++count <= 8)
                    missing += (missing.empty() ? "" : ", ") + cat::cParam(n).key();
            }
            if (count > 8)
                fail("file.c-lacks-more", {missing, std::to_string(count - 8)}, sectionLine_[Section::C]);
            fail("file.c-lacks", {missing}, sectionLine_[Section::C]);
        }
    }

    std::string plcRussian(const std::string& item) const {
        for (cat::PlcGroup g : cat::kPlcGroups)
            if (cat::plcGroupLetter(g) == item[0])
                return plcText(p_, g, std::stoi(item.substr(1)), false);
        return {};
    }

    std::string_view source_;
    std::map<std::string, int> englishLine_; // item -> the line of its English
    std::vector<std::string_view> lines_;
    int lineNo_ = 0;
    Section section_ = Section::None;
    std::map<Section, int> sectionLine_;
    std::map<std::string, int> seen_;
    std::set<int> cSeen_;
    bool sawFormat_ = false;
    MachineProfile p_;
};

// The comment written after an R preset: the preset screen's line or the
// meaning, and the value in mm for coordinates.
std::string rComment(const MachineProfile& p, int n, std::int64_t v) {
    const cat::RParamDef& d = cat::rParam(n);
    if (d.user())
        return {};
    std::string s(d.panelHint.empty() ? d.meaningRu : d.panelHint);
    const cat::Axis axis = cat::rUnitAxis(d.unit);
    if (d.unit == cat::RUnit::DiscX || d.unit == cat::RUnit::DiscZ)
        s += " = " + units::formatDisc(v, axisScale(p, axis)) + " мм";
    else if (d.unit == cat::RUnit::DiscXPerMin || d.unit == cat::RUnit::DiscZPerMin)
        s += " = " + units::formatDisc(v, axisScale(p, axis)) + " мм/мин";
    else if (d.unit == cat::RUnit::Ms)
        s += " = " + units::formatDisc(v, units::AxisScale{units::Discrete::Mm0_001, false}) + " с";
    return s;
}

} // namespace

MachineProfile readMachineText(std::string_view text, std::string_view source) {
    return Reader(text, source).read();
}

std::string writeMachineText(const MachineProfile& p) {
    std::ostringstream o;
    o << "; K528 Studio machine file (.k528m): docs/profile-format.md\n";
    o << "[machine]\n";
    o << "format=" << kMachineFileFormat << "\n";
    o << "name=" << p.name << "\n";
    o << "title=" << p.title << "\n";
    // An English beside its Russian (kept as a setting: profile.h, englishKey).
    const auto english = [&](const std::string& item, const std::string& key) {
        if (const auto en = p.simulation.find(englishKey(item)))
            o << key << ".en=" << *en << "\n";
    };
    english("title", "title");
    o << "\n[c]\n";
    for (const cat::CParamDef& d : cat::cParams()) {
        if (d.number == 1)
            o << "; X\n";
        else if (d.number == 53)
            o << "; Z\n";
        else if (d.number == 105)
            o << "; common\n";
        o << d.key() << "=" << p.cValue(d.number) << " ; " << d.name << "\n";
    }
    o << "\n[r]\n";
    for (const auto& [n, v] : p.r) {
        o << "R" << n << "=" << v;
        const std::string comment = rComment(p, n, v);
        if (!comment.empty())
            o << " ; " << comment;
        o << "\n";
    }
    for (const auto& [n, text] : p.programs)
        o << "\n[program " << n << "]\n" << text << kEndProgram << "\n";
    o << "\n[messages]\n";
    for (const auto& [n, text] : p.messages) {
        o << "#" << n << "=" << text << "\n";
        english("#" + std::to_string(n), "#" + std::to_string(n));
    }
    o << "\n[plc-messages]\n";
    for (cat::PlcGroup g : cat::kPlcGroups) {
        const auto& texts = p.plcTexts(g);
        if (texts.empty())
            continue;
        o << "; " << cat::plcGroupLetter(g) << ": " << cat::plcGroupNameRu(g) << ", "
          << cat::plcMessageAddress(g, 1) << "...\n";
        for (const auto& [k, text] : texts) {
            const std::string item = cat::plcGroupLetter(g) + two(k);
            o << item << "=" << text << "\n";
            english(item, item);
        }
    }
    o << "\n[simulation]\n";
    for (const auto& [key, value] : p.simulation.entries())
        if (englishItem(key).empty()) // the English of a text is written beside it
            o << key << "=" << value << "\n";
    return o.str();
}

namespace {

Problem systemProblem(const util::Message& m) {
    Problem p = problem(m.id, m.args);
    for (const util::Message& w : m.within)
        p.within.push_back(systemProblem(w));
    return p;
}

} // namespace

MachineProfile readMachineFile(const std::filesystem::path& path) {
    std::string text;
    util::Message error;
    if (!util::readInputFile(path.string(), text, error)) {
        // Why (util/system_texts.h: problemText says it from that catalog);
        // the path is the FileError's.
        Problem p = problem("file.cannot-read");
        p.within.push_back(systemProblem(error.within.front()));
        throw FileError(path.string(), 0, std::move(p));
    }
    return readMachineText(text, path.string());
}

void writeMachineFile(const std::filesystem::path& path, const MachineProfile& p) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out)
        throw FileError(path.string(), 0, problem("file.cannot-create"));
    out << writeMachineText(p);
    out.flush();
    if (!out)
        throw FileError(path.string(), 0, problem("file.cannot-write"));
}

std::string programsFileText(const MachineProfile& p) {
    std::string out;
    for (const auto& [n, text] : p.programs) {
        bool hasHeader = false;
        std::size_t pos = 0;
        while (pos < text.size() && !hasHeader) {
            const auto end = text.find('\n', pos);
            hasHeader =
                programHeaderNumber(std::string_view(text).substr(pos, end - pos)).has_value();
            pos = end == std::string::npos ? text.size() : end + 1;
        }
        if (!hasHeader)
            out += "%L" + std::to_string(n) + "\n";
        out += text;
        if (!out.empty() && out.back() != '\n')
            out += '\n';
    }
    if (!p.messages.empty()) {
        out += "%MESSAGES\n";
        for (const auto& [n, text] : p.messages)
            out += "#" + std::to_string(n) + "=" + text + "\n";
    }
    return out;
}

} // namespace k528::profile
