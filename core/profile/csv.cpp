#include "profile/csv.h"

#include "profile/text_format.h"
#include "profile/validate.h"
#include "util/utf8.h"

#include <set>
#include <vector>

namespace k528::profile {

namespace cat = k528::catalog;

namespace {

constexpr std::string_view kHeader = "number;axis;name;value;unit";

std::string field(std::string_view s) {
    const bool quote = s.find_first_of(";\"") != std::string_view::npos ||
                       (!s.empty() && (s.front() == ' ' || s.back() == ' '));
    if (!quote)
        return std::string(s);
    std::string out = "\"";
    for (char ch : s) {
        if (ch == '"')
            out += '"';
        out += ch;
    }
    return out + "\"";
}

// Splits one CSV line; false (and `error`, a problem id) on a malformed quote.
bool splitLine(std::string_view line, std::vector<std::string>& out, std::string& error) {
    out.clear();
    std::string cur;
    std::size_t i = 0;
    bool fieldStart = true;
    while (true) {
        if (fieldStart && i < line.size() && line[i] == '"') {
            ++i;
            while (true) {
                if (i >= line.size()) {
                    error = "csv.quote-open";
                    return false;
                }
                if (line[i] == '"') {
                    if (i + 1 < line.size() && line[i + 1] == '"') {
                        cur += '"';
                        i += 2;
                        continue;
                    }
                    ++i;
                    break;
                }
                cur += line[i++];
            }
            if (i < line.size() && line[i] != ';') {
                error = "csv.quote-text";
                return false;
            }
        }
        if (i >= line.size()) {
            out.push_back(std::move(cur));
            return true;
        }
        if (line[i] == ';') {
            out.push_back(std::move(cur));
            cur.clear();
            fieldStart = true;
            ++i;
            continue;
        }
        if (line[i] == '"') {
            error = "a quote inside an unquoted field";
            return false;
        }
        cur += line[i++];
        fieldStart = false;
    }
}

} // namespace

std::string writeCParamsCsv(std::span<const std::int64_t> c) {
    std::string out(kHeader);
    out += '\n';
    for (const cat::CParamDef& d : cat::cParams()) {
        out += std::to_string(d.number) + ";" + std::string(cat::axisName(d.axis)) + ";" +
               field(d.name) + ";" + std::to_string(c[static_cast<std::size_t>(d.number)]) + ";" +
               field(cat::unitSymbol(d.unit)) + "\n";
    }
    return out;
}

CValues readCParamsCsv(std::string_view text, std::string_view source) {
    const std::string src(source);
    if (text.substr(0, 3) == "\xEF\xBB\xBF")
        text.remove_prefix(3);
    CValues c{};
    std::set<int> seen;
    std::vector<std::string> f;
    std::string error;
    int lineNo = 0;
    bool header = false;
    std::size_t pos = 0;
    while (pos < text.size()) {
        auto end = text.find('\n', pos);
        if (end == std::string_view::npos)
            end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        if (!utf8::isValid(line))
            throw FileError(src, lineNo, problem("file.utf8"));
        if (line.find_first_not_of(" \t") == std::string_view::npos)
            continue;
        if (!header) {
            if (line != kHeader)
                throw FileError(src, lineNo, problem("csv.header", {std::string(kHeader)}));
            header = true;
            continue;
        }
        if (!splitLine(line, f, error))
            throw FileError(src, lineNo, problem(error));
        if (f.size() != 5)
            throw FileError(src, lineNo, problem("csv.fields", {std::to_string(f.size())}));
        const auto n = parseInt(f[0]);
        if (!n || *n < 1 || *n > cat::kCParamCount)
            throw FileError(src, lineNo, problem("csv.number", {f[0]}));
        const cat::CParamDef& d = cat::cParam(static_cast<int>(*n));
        if (f[1] != cat::axisName(d.axis))
            throw FileError(src, lineNo,
                            problem("csv.axis", {d.key(), std::string(cat::axisName(d.axis)), f[1]}));
        if (!seen.insert(d.number).second)
            throw FileError(src, lineNo, problem("csv.twice", {d.key()}));
        const auto v = parseInt(f[3]);
        if (!v)
            throw FileError(src, lineNo, problem("csv.value", {d.key(), f[3]}));
        if (Problem p = cValueProblem(d.number, *v); !p.empty())
            throw FileError(src, lineNo, std::move(p));
        c[static_cast<std::size_t>(d.number)] = *v;
    }
    if (!header)
        throw FileError(src, 0, problem("csv.empty"));
    if (seen.size() != static_cast<std::size_t>(cat::kCParamCount)) {
        for (int n = 1; n <= cat::kCParamCount; ++n)
            if (!seen.contains(n))
                throw FileError(src, 0, problem("csv.missing", {cat::cParam(n).key()}));
    }
    return c;
}

} // namespace k528::profile
