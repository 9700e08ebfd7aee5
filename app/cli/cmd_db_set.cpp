// k528 db set (docs/database.md); helpers in db_cli_util.h.
#include "db_cli_util.h"
#include "args.h"
#include "cli_texts.h"
#include "catalog/cparams.h"
#include "catalog/messages.h"
#include "catalog/rparams.h"
#include "cli.h"
#include "db/database.h"
#include "db/db_texts.h"
#include "db/explain.h"
#include "db_cli.h"
#include "profile/diff.h"
#include "profile/settings.h"
#include "profile/validate.h"
#include "util/json.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string_view>
#include <vector>

namespace k528::cli::dbcli {

namespace {

// The item an ITEM=VALUE names, the same for C22, c022 and C022.
std::string itemKey(const std::string& item) {
    std::string key = item.substr(0, item.find('='));
    if (key.size() < 2 || std::string_view("CcRr#AWS").find(key[0]) == std::string_view::npos)
        return key;
    const std::size_t nz = key.find_first_not_of('0', 1);
    const std::string digits = nz == std::string::npos ? "0" : key.substr(nz);
    return std::string(1, static_cast<char>(std::toupper(static_cast<unsigned char>(key[0])))) + digits;
}

// One ITEM=VALUE of `set` into the edit; what is wrong (the database
// catalog's id and arguments), an empty id when nothing is.
db::ErrorText parseItem(const std::string& item, db::Edit& e) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
        return {"item.syntax", {item}};
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    const auto digits = [](const std::string& s) {
        return !s.empty() &&
               std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    const std::string rest = key.substr(1);
    if ((key[0] == 'C' || key[0] == 'c') && digits(rest)) {
        const auto n = parseInt(rest);
        if (!n || *n < 1 || *n > cat::kCParamCount)
            return {"item.c-none", {key}};
        const auto v = parseInt(value);
        if (!v)
            return {"item.not-whole", {key, value}};
        e.c[static_cast<int>(*n)] = *v;
        return {};
    }
    if ((key[0] == 'R' || key[0] == 'r') && digits(rest)) {
        const auto n = parseInt(rest);
        if (!n || *n < 0 || *n >= cat::kRParamCount)
            return {"item.r-none", {key}};
        if (value.empty()) {
            e.r[static_cast<int>(*n)] = std::nullopt;
            return {};
        }
        const auto v = parseInt(value);
        if (!v)
            return {"item.not-whole", {key, value}};
        e.r[static_cast<int>(*n)] = *v;
        return {};
    }
    if (key[0] == '#' && digits(rest)) {
        const auto n = parseInt(rest);
        if (!n || *n < 1 || *n > cat::kTechMessageCount)
            return {"item.message-none", {key}};
        e.messages[static_cast<int>(*n)] =
            value.empty() ? std::nullopt : std::optional<std::string>(value);
        return {};
    }
    if ((key[0] == 'A' || key[0] == 'W' || key[0] == 'S') && digits(rest)) {
        const cat::PlcGroup g = key[0] == 'A'   ? cat::PlcGroup::Alarm
                                : key[0] == 'W' ? cat::PlcGroup::Work
                                                : cat::PlcGroup::System;
        const auto n = parseInt(rest);
        if (!n || *n < 1 || *n > cat::plcMessageCount(g))
            return {"item.plc-none",
                    {key, std::string(1, key[0]) + "01", std::string(1, key[0]) + std::to_string(cat::plcMessageCount(g))}};
        e.plc[{g, static_cast<int>(*n)}] =
            value.empty() ? std::nullopt : std::optional<std::string>(value);
        return {};
    }
    if (key == "title") {
        e.title = value;
        return {};
    }
    if (profile::Settings::keyError(key).empty()) {
        e.simulation[key] = value.empty() ? std::nullopt : std::optional<std::string>(value);
        return {};
    }
    return {"item.unknown", {key}};
}

// Edit distance with a swap of two neighbours as one step ("tilte" is one step
// from "title"): how far a typed key is from a known one.
std::size_t typoDistance(std::string_view a, std::string_view b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i)
        d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j)
        d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

// The known items a mistyped key is close to: the registry's simulation keys
// and `title` (the one named item that looks like a key).
std::vector<std::string> closeKeys(std::string_view key) {
    std::vector<std::pair<std::size_t, std::string>> found;
    const std::size_t limit = std::max<std::size_t>(2, key.size() / 3);
    const auto consider = [&](std::string_view known) {
        if (const std::size_t dist = typoDistance(key, known); dist <= limit)
            found.emplace_back(dist, std::string(known));
    };
    consider("title");
    for (const auto& k : profile::simulationKeys())
        consider(k.key);
    std::stable_sort(found.begin(), found.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::string> out;
    for (std::size_t i = 0; i < found.size() && i < 5; ++i)
        out.push_back(found[i].second);
    return out;
}

// A simulation key the registry does not know is refused before anything is
// written: a typo saved as a revision stays in the history and warns on every
// later change. "" when every key set is known (removing one is always allowed:
// that is how a stored typo goes away).
std::string unknownKeyError(const db::Edit& e, Lang lang) {
    const bool ru = lang == Lang::Ru;
    for (const auto& [key, value] : e.simulation) {
        if (!value || profile::findSimulationKey(key))
            continue;
        const auto close = closeKeys(key);
        if (close.empty())
            return db::dbText("item.unknown-key", std::vector<std::string>{key}, ru);
        std::string list = close.front(); // "a, b or c"
        for (std::size_t i = 1; i + 1 < close.size(); ++i)
            list += ", " + close[i];
        if (close.size() > 1)
            list = db::dbText("list.or", std::vector<std::string>{list, close.back()}, ru);
        return db::dbText("item.unknown-key.close", std::vector<std::string>{key, list}, ru);
    }
    return {};
}

// A wrong ITEM=VALUE: said in the command's language, with the hint where the help is.
int itemError(const std::string& text, Lang lang) {
    return usageError(text, lang == Lang::Ru);
}

void printRejection(const db::ValidationError& e, Lang lang, const std::string& where) {
    std::fprintf(stderr, "k528: %s\n", e.head(lang).c_str());
    for (const auto& f : e.findings())
        std::fprintf(stderr, "%s%s\n", where.c_str(), findingText(f, lang).c_str());
}

} // namespace

int cmdSet(std::span<const std::string> argv) {
    const Args a(argv, {"--allow-errors", "--allow-unknown"}, {"--db", "--author", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().size() < 2)
        return usageError(cliText("db.usage.set"));
    Lang lang;
    if (!parseLangOption(a, lang))
        return ExitUsage;
    db::Edit edit;
    std::map<std::string, std::string> given; // item key -> the ITEM=VALUE that set it
    for (std::size_t i = 1; i < a.positional().size(); ++i) {
        const std::string& item = a.positional()[i];
        if (const db::ErrorText err = parseItem(item, edit); !err.id.empty())
            return itemError(db::renderText(err, lang == Lang::Ru), lang);
        const auto [it, fresh] = given.emplace(itemKey(item), item);
        if (!fresh)
            return itemError(db::dbText("item.twice",
                                        std::vector<std::string>{item.substr(0, item.find('=')), it->second, item},
                                        lang == Lang::Ru),
                             lang);
    }
    if (!a.has("--allow-unknown"))
        if (const std::string err = unknownKeyError(edit, lang); !err.empty())
            return itemError(err, lang);
    DbTarget t;
    auto d = openDbOf(a, t, false, a.value("--author").value_or(""), lang);
    if (!d)
        return ExitUsage;
    const std::string machine = a.positional()[0];
    try {
        db::WriteOptions o;
        o.author = a.value("--author").value_or("");
        o.allowErrors = a.has("--allow-errors");
        const auto r = d->applyEdit(machine, edit, o);
        out(savedText(machine, r, lang));
        return ExitOk;
    } catch (const db::ValidationError& e) {
        printRejection(e, lang, "  ");
        return ExitInputErrors;
    } catch (const db::Error& e) {
        return dbFail(e, lang);
    }
}

} // namespace k528::cli::dbcli
