#include "args.h"
#include "cli.h"
#include "cli_texts.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace k528::cli {

namespace {

bool russianLine = true;

} // namespace

bool asksForEnglish(std::span<const std::string> args) {
    for (std::size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "--")
            break;
        if (args[i] == "--lang=en" || (args[i] == "--lang" && i + 1 < args.size() && args[i + 1] == "en"))
            return true;
    }
    return false;
}

void readCommandLineLanguage(std::span<const std::string> args) {
    russianLine = !asksForEnglish(args);
}

bool russianCommandLine() {
    return russianLine;
}

std::string cliText(std::string_view id, std::initializer_list<std::string> args) {
    return cliText(id, args, russianLine);
}

Args::Args(std::span<const std::string> args, std::vector<std::string_view> flags,
           std::vector<std::string_view> options) {
    const bool ru = !asksForEnglish(args);
    bool onlyPositional = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (onlyPositional || a.size() < 2 || a.compare(0, 2, "--") != 0) {
            positional_.push_back(a);
            continue;
        }
        if (a == "--") {
            onlyPositional = true;
            continue;
        }
        std::string name = a;
        std::optional<std::string> inlineValue;
        if (const auto eq = a.find('='); eq != std::string::npos) {
            name = a.substr(0, eq);
            inlineValue = a.substr(eq + 1);
        }
        if (std::find(flags.begin(), flags.end(), name) != flags.end()) {
            if (inlineValue) {
                error_ = cliText("opt.no-value", {name}, ru);
                return;
            }
            given_.emplace_back(name, "");
        } else if (std::find(options.begin(), options.end(), name) != options.end()) {
            if (inlineValue) {
                given_.emplace_back(name, *inlineValue);
            } else if (i + 1 < args.size()) {
                given_.emplace_back(name, args[++i]);
            } else {
                error_ = cliText("opt.needs-value", {name}, ru);
                return;
            }
        } else {
            error_ = cliText("opt.unknown", {name}, ru);
            return;
        }
    }
}

bool Args::has(std::string_view flag) const {
    return std::any_of(given_.begin(), given_.end(), [&](const auto& g) { return g.first == flag; });
}

std::optional<std::string> Args::value(std::string_view option) const {
    std::optional<std::string> v;
    for (const auto& g : given_)
        if (g.first == option)
            v = g.second;
    return v;
}

std::vector<std::string> Args::values(std::string_view option) const {
    std::vector<std::string> v;
    for (const auto& g : given_)
        if (g.first == option)
            v.push_back(g.second);
    return v;
}

std::optional<long long> parseInt(std::string_view s) {
    long long v = 0;
    const char* b = s.data();
    const char* e = s.data() + s.size();
    if (b != e && *b == '+')
        ++b;
    auto [ptr, ec] = std::from_chars(b, e, v);
    if (b == e || ec != std::errc() || ptr != e)
        return std::nullopt;
    return v;
}

std::optional<double> parseNumber(std::string_view s) {
    double v = 0;
    const char* b = s.data();
    const char* e = s.data() + s.size();
    if (b != e && *b == '+')
        ++b;
    auto [ptr, ec] = std::from_chars(b, e, v, std::chars_format::fixed);
    // "nan", "inf" and numbers out of range are not numbers of seconds, percent…
    if (b == e || ec != std::errc() || ptr != e || !std::isfinite(v))
        return std::nullopt;
    return v;
}

bool parseAssignment(const std::string& text, long long& n, long long& v) {
    const auto eq = text.find('=');
    if (eq == std::string::npos)
        return false;
    const auto a = parseInt(text.substr(0, eq));
    const auto b = parseInt(text.substr(eq + 1));
    if (!a || !b)
        return false;
    n = *a;
    v = *b;
    return true;
}

} // namespace k528::cli
