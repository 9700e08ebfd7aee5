#include "proveout_cli.h"

#include "cli.h"
#include "cli_texts.h"
#include "plc/description.h"
#include "profile/tools.h"
#include "util/json.h"
#include "util/utf8.h"

namespace k528::cli {

namespace {
// Code points of line `line` (1-based) of `text`.
int lineLength(std::string_view text, int line) {
    std::size_t start = 0;
    for (int l = 1; l < line; ++l) {
        const std::size_t nl = text.find('\n', start);
        if (nl == std::string_view::npos)
            return 0;
        start = nl + 1;
    }
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos)
        end = text.size();
    std::string_view s = text.substr(start, end - start);
    if (!s.empty() && s.back() == '\r')
        s.remove_suffix(1);
    int n = 0;
    for (const char c : s)
        if ((static_cast<unsigned char>(c) & 0xC0) != 0x80)
            ++n;
    return n;
}
} // namespace

bool blankFor(const Args& args, std::string_view fileText, std::optional<stock::Blank>& blank) {
    std::string id;
    if (const auto b = args.value(kBlankOption)) {
        blank = stock::parseUcg(*b, nullptr, &id);
        if (!blank) {
            usageError("--blank " + *b + ": " + stock::ucgErrorText(id, {}, russianCommandLine()));
            return false;
        }
        return true;
    }
    if (fileText.find("UCG") == std::string_view::npos)
        return true;
    blank = stock::findUcg(fileText, nullptr, &id);
    if (!blank && id != stock::kNoUcg) {
        std::fprintf(stderr, "k528: %s\n",
                     cliText("opt.file-blank", {stock::ucgErrorText(id, {}, russianCommandLine())}).c_str());
        return false;
    }
    return true;
}

Json findingJson(const proveout::Finding& f, std::string_view fileText, bool inFile) {
    Json j;
    j["line"] = inFile ? f.line : 0;
    j["column"] = inFile ? 1 : 0;
    j["end_column"] = inFile ? lineLength(fileText, f.line) + 1 : 0;
    j["severity"] = f.isError() ? "error" : "warning";
    j["manual_number"] = Json();
    j["message_ru"] = f.message(true);
    j["message_en"] = f.message(false);
    j["rule"] = std::string(proveout::ruleId(f.rule));
    j["program"] = f.program;
    j["n"] = f.n;
    Json at = Json::array();
    at.push_back(f.at.x);
    at.push_back(f.at.z);
    j["at"] = std::move(at);
    j["occurrences"] = f.occurrences;
    return j;
}

void printFinding(std::FILE* out, const std::string& file, const proveout::Finding& f,
                  bool inFile, Lang lang) {
    std::string where = inFile ? std::to_string(f.line) + ":1" : "0:0";
    std::string extra;
    if (!inFile)
        extra = " (L" + std::to_string(f.program) + " N" + std::to_string(f.n) + ")";
    if (f.occurrences > 1)
        extra += " (×" + std::to_string(f.occurrences) + ")";
    std::fprintf(out, "%s:%s: %s: [%s] %s%s\n", file.c_str(), where.c_str(),
                 f.isError() ? "error" : "warning", std::string(proveout::ruleId(f.rule)).c_str(),
                 f.message(lang == Lang::Ru).c_str(), extra.c_str());
}

bool withMachineData(Lang lang, const std::function<void()>& prove) {
    try {
        prove();
        return true;
    } catch (const plc::DescriptionError& e) {
        printDescriptionError(e, lang);
    } catch (const profile::ToolError& e) {
        printToolError(e, lang);
    }
    return false;
}

} // namespace k528::cli
