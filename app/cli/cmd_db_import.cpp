// k528 db import (docs/database.md); helpers in db_cli_util.h.
#include "profile/error_text.h"
#include "db_cli_util.h"
#include "db/notes.h"
#include "args.h"
#include "catalog/cparams.h"
#include "cli.h"
#include "cli_texts.h"
#include "db/database.h"
#include "db/explain.h"
#include "db_cli.h"
#include "profile/csv.h"
#include "profile/diff.h"
#include "profile/text_format.h"
#include "profile/validate.h"
#include "util/json.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace k528::cli::dbcli {

namespace {

// The line of `key` ("C017") in the [c] section of a machine file, 0 if none.
int lineOfC(const std::string& text, int number) {
    std::istringstream in(text);
    std::string line;
    int n = 0;
    bool inC = false;
    while (std::getline(in, line)) {
        ++n;
        std::string s = line;
        while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t'))
            s.pop_back();
        const auto b = s.find_first_not_of(" \t");
        if (b == std::string::npos)
            continue;
        s = s.substr(b);
        if (s[0] == '[') {
            inC = s == "[c]";
            continue;
        }
        if (!inC || (s[0] != 'C' && s[0] != 'c'))
            continue;
        const auto eq = s.find('=');
        if (eq == std::string::npos)
            continue;
        std::string k = s.substr(1, eq - 1);
        while (!k.empty() && (k.back() == ' ' || k.back() == '\t'))
            k.pop_back();
        if (const auto v = parseInt(k); v && *v == number)
            return n;
    }
    return 0;
}

bool looksLikeCsv(const std::string& path, const std::string& text) {
    if (path.size() > 4 && path.substr(path.size() - 4) == ".csv")
        return true;
    std::string t = text.substr(0, 64);
    if (t.rfind("\xEF\xBB\xBF", 0) == 0)
        t = t.substr(3);
    return t.rfind("number;", 0) == 0;
}

} // namespace

int cmdImport(std::span<const std::string> argv) {
    const Args a(argv, {"--replace", "--allow-errors"},
                 {"--db", "--as", "--author", "--format", "--lang"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().size() != 1)
        return usageError(cliText("db.usage.import"));
    Lang lang;
    if (!parseLangOption(a, lang))
        return ExitUsage;
    const std::string file = a.positional()[0];
    std::string text, err;
    if (file == "-") {
        if (!readStandardInput(text, err))
            return fail(err);
    } else if (!readFile(file, text, err)) {
        return fail(err);
    }
    const std::string source = file == "-" ? "<stdin>" : file;
    std::string format = a.value("--format").value_or("");
    if (!format.empty() && format != "k528m" && format != "csv")
        return usageError(cliText("db.usage.format", {format}));
    if (format.empty())
        format = looksLikeCsv(file, text) ? "csv" : "k528m";
    const auto asName = a.value("--as");
    if (asName) {
        if (const profile::Problem e = profile::nameProblem(*asName); !e.empty())
            return usageError("--as " + *asName + ": " + profile::problemText(e, russianCommandLine()));
    }
    db::WriteOptions o;
    o.author = a.value("--author").value_or("");
    o.allowErrors = a.has("--allow-errors");
    o.action = "import";
    o.summary = db::noteText({"import", {fs::path(source).filename().string()}});

    // Read and check the whole file before the database is touched.
    MachineProfile p;
    profile::CValues csv{};
    try {
        if (format == "csv") {
            if (!asName)
                return usageError(cliText("db.usage.import-csv"));
            csv = profile::readCParamsCsv(text, source);
        } else {
            p = profile::readMachineText(text, source);
            if (asName)
                p.name = *asName;
        }
    } catch (const profile::FileError& e) {
        return fail(cliText("db.import.nothing", {profile::fileErrorText(e, lang == Lang::Ru)}, lang == Lang::Ru),
                    ExitInputErrors);
    }
    DbTarget t;
    auto d = openDbOf(a, t, true, o.author, lang);
    if (!d)
        return ExitUsage;
    const std::string machine = format == "csv" ? *asName : p.name;
    try {
        db::SaveResult r;
        if (format == "csv") {
            db::Edit e;
            for (int n = 1; n <= cat::kCParamCount; ++n)
                e.c[n] = csv[static_cast<std::size_t>(n)];
            r = d->applyEdit(machine, e, o);
        } else if (d->hasMachine(machine)) {
            if (!a.has("--replace")) {
                const auto info = *d->machine(machine);
                return fail(cliText("db.import.exists", {machine, t.path.string(), std::to_string(info.revision)}));
            }
            r = d->saveMachine(machine, p, o);
        } else {
            r = d->createMachine(p, o);
        }
        out(savedText(machine, r, lang));
        return ExitOk;
    } catch (const db::ValidationError& e) {
        std::fprintf(stderr, "k528: %s\n", e.head(lang).c_str());
        for (const auto& f : e.findings()) {
            int line = 0;
            if (format == "k528m")
                for (int n : f.cParams)
                    if (const int l = lineOfC(text, n); l && (!line || l < line))
                        line = l;
            std::fprintf(stderr, "%s:%s %s\n", source.c_str(),
                         line ? (std::to_string(line) + ":").c_str() : "",
                         findingText(f, lang).c_str());
        }
        return ExitInputErrors;
    } catch (const db::Error& e) {
        return dbFail(e, lang);
    }
}

} // namespace k528::cli::dbcli
