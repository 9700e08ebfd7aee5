// k528 db log [MACHINE] [--since TIME] [--limit N] [--json] (docs/database.md).
#include "args.h"
#include "cli.h"
#include "cli_texts.h"
#include "db/database.h"
#include "db_cli_util.h"
#include "util/json.h"
#include "util/utf8.h"

#include <algorithm>

namespace k528::cli::dbcli {

namespace {

// "2024-05-17", "2024-05-17T08:30", "2024-05-17T08:30:00Z": a prefix of a timestamp.
bool validSince(const std::string& s) {
    static const std::string kShape = "0000-00-00T00:00:00Z";
    if (s.size() < 10 || s.size() > kShape.size())
        return false;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (kShape[i] == '0' ? !(s[i] >= '0' && s[i] <= '9') : s[i] != kShape[i])
            return false;
    return true;
}

std::string itemText(const db::TransferItem& i) {
    const std::string what = i.kind == "program" ? "L" + std::to_string(i.number)
                             : i.kind == "c"     ? std::string("C")
                             : i.kind == "r"     ? std::string("R")
                                                 : cliText("db.log.messages");
    return what + " " + i.crc32 + " " + i.state;
}

// A transfer's direction and result as stored (push, pull; ok, partial,
// failed), said in the command's language; what the catalog lacks as stored.
std::string storedWord(const std::string& w) {
    if (w == "push")
        return cliText("db.log.push");
    if (w == "pull")
        return cliText("db.log.pull");
    if (w == "ok")
        return cliText("db.log.ok");
    if (w == "partial")
        return cliText("db.log.partial");
    if (w == "failed")
        return cliText("db.log.failed");
    return w;
}

std::size_t storedWidth(std::initializer_list<const char*> words) {
    std::size_t w = 0;
    for (const char* word : words)
        w = std::max(w, utf8::length(storedWord(word)));
    return w;
}

} // namespace

int cmdLog(std::span<const std::string> argv) {
    const Args a(argv, {"--json"}, {"--db", "--lang", "--since", "--limit"});
    if (!a.ok())
        return usageError(a.error());
    if (a.positional().size() > 1)
        return usageError(cliText("db.usage.log"));
    db::TransferFilter f;
    if (!a.positional().empty())
        f.machine = a.positional()[0];
    if (const auto since = a.value("--since")) {
        if (!validSince(*since))
            return usageError(cliText("db.usage.since", {*since}));
        f.since = *since;
    }
    if (const auto v = a.value("--limit")) {
        const auto n = parseInt(*v);
        if (!n || *n < 0)
            return usageError(cliText("db.usage.limit"));
        f.limit = static_cast<int>(*n);
    }
    DbTarget t;
    auto d = openDbOf(a, t, false);
    if (!d)
        return ExitUsage;
    try {
        const auto entries = d->transfers(f);
        if (a.has("--json")) {
            Json arr = Json::array();
            for (const auto& e : entries) {
                Json j;
                j["id"] = e.id;
                j["at"] = e.at;
                j["user"] = e.user;
                j["host"] = e.host;
                j["machine"] = e.machine;
                j["revision"] = e.revision;
                j["controller"] = e.controller;
                j["direction"] = e.direction;
                j["result"] = e.result;
                j["detail"] = e.detail;
                Json items = Json::array();
                for (const auto& i : e.items) {
                    Json ij;
                    ij["kind"] = i.kind;
                    ij["number"] = i.number;
                    ij["crc32"] = i.crc32;
                    ij["sha256"] = optJson(i.sha256);
                    ij["state"] = i.state;
                    items.push_back(std::move(ij));
                }
                j["items"] = std::move(items);
                arr.push_back(std::move(j));
            }
            Json root;
            root["database"] = t.path.string();
            root["transfers"] = std::move(arr);
            out(json::dump(root) + "\n");
            return ExitOk;
        }
        std::string s;
        const std::size_t directionWidth = storedWidth({"push", "pull"});
        const std::size_t resultWidth = storedWidth({"ok", "partial", "failed"});
        for (const auto& e : entries) {
            s += e.at + "  " + pad(storedWord(e.direction), directionWidth) + "  " +
                 pad(storedWord(e.result), resultWidth) + "  " +
                 pad(e.machine.empty() ? "-" : e.machine +
                                                   (e.revision ? "@" + std::to_string(e.revision) : ""),
                     16) +
                 "  " + e.user + "@" + e.host + "  " + e.controller + "\n";
            std::string items;
            for (const auto& i : e.items)
                items += (items.empty() ? "" : ", ") + itemText(i);
            if (!items.empty())
                s += "    " + items + "\n";
            if (!e.detail.empty())
                s += "    " + e.detail + "\n";
        }
        if (entries.empty())
            s = (f.machine.empty() ? cliText("db.log.none") : cliText("db.log.none-for", {f.machine})) + "\n";
        out(s);
        return ExitOk;
    } catch (const db::Error& e) {
        return dbFail(e, langOf(a));
    }
}

} // namespace k528::cli::dbcli
