// k528 link --port DEVICE [--address A] [--baud B] [--parity …] COMMAND (cli.md,
// docs/link.md): ping, status [--json], pull --out FILE, push FILE (a machine
// file or a program file), clear c|r, diag [--json] [--clear], watch [--json]
// [--seconds S], scan [--bauds …] [--addresses A-B] [--json]; `--frames FILE`
// saves the frame log; push and pull go on record in the shop's database
// (`--db LOCATION`, `--machine NAME`: link_record.h); `k528 link --list`
// lists the plugins and ports. The
// client procedures are core's (link/client.h) over the plugin's transport
// (core's RtuMaster over a QSerialPort).
#include "catalog/messages.h"
#include "cli.h"
#include "cli_texts.h"
#include "link/client.h"
#include "link_line.h"
#include "link_record.h"
#include "output_file.h"
#include "profile/text_format.h"
#include "util/json.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QElapsedTimer>
#include <QThread>
#include <cstdio>

namespace k528::cli {

namespace {

// The language of the command's messages (--lang, Russian unless en); the
// --json outputs are the same in both.
bool ru = true;
// A text of the command line's catalog in the command's language.
std::string say(std::string_view id, std::initializer_list<std::string> args = {}) { return cliText(id, args, ru); }
// A number with `digits` decimals, as the reports print seconds and milliseconds.
std::string fixed(double v, int digits) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", digits, v);
    return b;
}
std::string said(const link::Said& s) { return link::render(s, ru); }
// A plugin's error: a line failure of core's catalog, or the system's words.
std::string lineError(const QString& error) { return said(link::decodeSaid(error.toStdString())); }

// What a transfer moves now, as core's progress names it ("C-parameters",
// "R-parameters", "messages", "program 5").
std::string partText(const std::string& what) {
    if (what == "C-parameters")
        return said(link::say("link.part-c"));
    if (what == "R-parameters")
        return said(link::say("link.part-r"));
    if (what == "messages")
        return said(link::say("link.part-messages"));
    if (what.rfind("program ", 0) == 0)
        return said(link::say("link.part-program", {what.substr(8)}));
    return what;
}

int exitFor(const link::LinkError& e) {
    return e.kind == link::LinkError::Kind::NoAnswer ? ExitUsage : ExitInputErrors;
}

int fail(const link::LinkError& e) {
    std::fprintf(stderr, "k528 link: %s\n", e.text(ru).c_str());
    return exitFor(e);
}

// baud 0: a network line (Modbus TCP), no wire time.
void lineReport(const link::Link& l, const linkplugin::ClientTransport& t, int baud) {
    const linkplugin::WireCount w = t.wire();
    if (baud == 0) {
        std::fprintf(stderr, "%s\n",
                     say("link.report.line-tcp", {link::describe(l.stats(), ru), std::to_string(w.transactions),
                                                  std::to_string(w.bytes)})
                         .c_str());
        return;
    }
    std::fprintf(stderr, "%s\n",
                 say("link.report.line", {link::describe(l.stats(), ru), std::to_string(w.transactions),
                                          std::to_string(w.bytes), fixed(link::wireSeconds(w.bytes, w.frames, baud), 3),
                                          std::to_string(baud)})
                     .c_str());
}

std::string clockText(const QDateTime& t) { return t.toString(QStringLiteral("HH:mm:ss")).toStdString(); }
std::string isoText(const QDateTime& t) { return t.toString(Qt::ISODateWithMs).toStdString(); }

Json liveJson(const link::LiveState& s) {
    Json v;
    v["online"] = true;
    v["mode"] = s.mode;
    v["pc_ready"] = s.pcReady;
    v["running"] = s.running;
    v["alarm"] = s.alarm;
    Json homed;
    homed["X"] = s.homedX;
    homed["Z"] = s.homedZ;
    v["homed"] = std::move(homed);
    v["program"] = s.program;
    v["frame"] = s.frame;
    v["override"] = s.overridePercent;
    Json axes;
    for (const auto& [name, cur, mach, err] : {std::tuple{"X", s.xCurrent, s.xMachine, s.xError},
                                               std::tuple{"Z", s.zCurrent, s.zMachine, s.zError}}) {
        Json a;
        a["current"] = cur;
        a["machine"] = mach;
        a["following_error"] = err;
        axes[name] = std::move(a);
    }
    v["axes_disc"] = std::move(axes);
    Json alarms = Json::array();
    for (int n : s.alarms) {
        Json a;
        a["number"] = n;
        if (const catalog::PositionerMessage* m = catalog::findPositionerMessage(n)) {
            a["text_ru"] = std::string(m->textRu);
            a["text_en"] = std::string(m->textEn);
        }
        alarms.push_back(std::move(a));
    }
    v["alarms"] = std::move(alarms);
    v["message"] = s.message;
    Json progs = Json::array();
    for (int p : s.programs)
        progs.emplace_back(p);
    v["programs"] = std::move(progs);
    return v;
}

std::string liveText(const link::LiveState& s) {
    // The panel's own name of mode 7 «РАБОТА С ПЭВМ» is the same in both languages.
    std::string t = say("link.live.mode", {std::to_string(s.mode)}) + (s.pcReady ? " (РАБОТА С ПЭВМ)" : "") +
                    (s.running ? say("link.live.running") : "") +
                    say("link.live.program", {std::to_string(s.program), std::to_string(s.frame),
                                              std::to_string(s.overridePercent)}) +
                    say("link.live.axes", {std::to_string(s.xCurrent), std::to_string(s.zCurrent),
                                           std::to_string(s.xMachine), std::to_string(s.zMachine),
                                           std::to_string(s.xError), std::to_string(s.zError)});
    for (int n : s.alarms) {
        t += say("link.live.alarm", {std::to_string(n)});
        if (const catalog::PositionerMessage* m = catalog::findPositionerMessage(n))
            t += " «" + std::string(m->textRu) + "»";
    }
    return t;
}

// A machine file begins with a [section]; a program file with %L or %MESSAGES.
bool isMachineText(std::string_view text) {
    std::size_t pos = 0;
    while (pos < text.size()) {
        const std::size_t end = std::min(text.find('\n', pos), text.size());
        std::string_view line = text.substr(pos, end - pos);
        while (!line.empty() && (line.front() == ' ' || line.front() == '\t' || line.front() == '\r' ||
                                 line.front() == '\xEF' || line.front() == '\xBB' || line.front() == '\xBF'))
            line.remove_prefix(1); // blanks and a UTF-8 byte order mark
        if (!line.empty() && line.front() != ';')
            return line.front() == '[';
        pos = end + 1;
    }
    return false;
}

bool saveFrames(const std::optional<std::string>& path, const std::string& text) {
    if (!path)
        return true;
    std::string error;
    if (!writeOutputFile(*path, text, error)) {
        std::fprintf(stderr, "k528 link: %s\n", error.c_str());
        return false;
    }
    return true;
}

// "1-247", "7", "1-10,20" -> addresses.
std::optional<std::vector<int>> parseAddresses(const std::string& text) {
    std::vector<int> out;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t end = std::min(text.find(',', pos), text.size());
        const std::string part = text.substr(pos, end - pos);
        const std::size_t dash = part.find('-');
        const auto a = parseInt(part.substr(0, dash));
        const auto b = dash == std::string::npos ? a : parseInt(part.substr(dash + 1));
        if (!a || !b || *a < 1 || *b > 247 || *a > *b)
            return std::nullopt;
        for (long long n = *a; n <= *b; ++n)
            out.push_back(static_cast<int>(n));
        pos = end + 1;
    }
    return out;
}

std::optional<std::vector<int>> parseBauds(const std::string& text) {
    std::vector<int> out;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        const std::size_t end = std::min(text.find(',', pos), text.size());
        const auto v = parseInt(text.substr(pos, end - pos));
        if (!v || *v < 1200 || *v > 4000000)
            return std::nullopt;
        out.push_back(static_cast<int>(*v));
        pos = end + 1;
    }
    return out;
}

int runScan(const Args& args, linkplugin::LinkPlugin& plugin, linkplugin::LineSettings line,
            const std::optional<std::string>& framesPath) {
    std::vector<int> bauds = {line.baud};
    if (const auto b = args.value("--bauds")) {
        const auto v = parseBauds(*b);
        if (!v)
            return usageError(cliText("link.bauds"));
        bauds = *v;
    }
    std::vector<int> addresses;
    for (int a = 1; a <= 247; ++a)
        addresses.push_back(a);
    if (const auto a = args.value("--addresses")) {
        const auto v = parseAddresses(*a);
        if (!v)
            return usageError(cliText("link.addresses", {*a}));
        addresses = *v;
    }
    const bool asJson = args.has("--json");
    installStopSignals();
    std::string frames;
    int found = 0;
    for (int baud : bauds) {
        line.baud = baud;
        QString error;
        std::unique_ptr<linkplugin::ClientTransport> t = plugin.openClient(line, error);
        if (!t) {
            std::fprintf(stderr, "%s\n",
                         say("link.report.cannot-open-at", {line.port.toStdString(), std::to_string(baud),
                                                            lineError(error)})
                             .c_str());
            return ExitUsage;
        }
        std::fprintf(stderr, "%s\n",
                     say("link.report.scan", {std::to_string(baud), std::to_string(addresses.size()),
                                              std::to_string(line.timeoutMs)})
                         .c_str());
        link::Link l(*t, link::k528Map(), 1);
        for (int a : addresses) {
            if (stopRequested())
                break;
            const link::StationInfo s = link::probeStation(l, a);
            if (!s.answers && !s.garbled)
                continue;
            if (s.answers)
                ++found;
            if (asJson) {
                Json j;
                j["address"] = s.address;
                j["baud"] = baud;
                j["answers"] = s.answers;
                j["garbled"] = s.garbled;
                j["echo"] = s.echo;
                if (s.id) {
                    j["server_id"] = s.id->id;
                    j["running"] = s.id->running;
                    j["identity"] = s.id->data;
                }
                if (s.live)
                    j["live"] = liveJson(*s.live);
                j["round_trip_ms"] = s.roundTripMs;
                std::printf("%s\n", json::dump(j).c_str());
            } else {
                std::printf("%s\n", say("link.report.station", {std::to_string(baud), link::describe(s, ru)}).c_str());
            }
            if (standardOutputLost())
                return ExitUsage;
        }
        lineReport(l, *t, baud);
        frames += link::formatFrameLog(t->frameLog());
    }
    std::fprintf(stderr, "%s\n",
                 (found == 1 ? say("link.report.scan-found-one") : say("link.report.scan-found", {std::to_string(found)}))
                     .c_str());
    if (!saveFrames(framesPath, frames))
        return ExitUsage;
    return stopRequested() ? ExitUsage : ExitOk;
}

} // namespace

int runLinkQt(std::span<const std::string> argv) {
    std::vector<std::string_view> options = kLineOptions;
    options.insert(options.end(),
                   {"--out", "--seconds", "--timeout-ms", "--interval-ms", "--frames", "--bauds", "--addresses",
                    "--db", "--machine", "--lang"});
    const Args args(argv, {"--json", "--list", "--clear"}, options);
    if (!args.ok())
        return usageError(args.error());
    const auto lang = args.value("--lang");
    if (lang && *lang != "ru" && *lang != "en")
        return usageError(cliText("opt.lang", {*lang}));
    ru = lang.value_or("ru") == "ru";
    if (args.has("--list")) {
        for (const linkplugin::Found& f : linkplugin::discover()) {
            if (f.plugin)
                std::printf("plugin %s %s: %s (%s)\n", f.name.toUtf8().constData(), f.version.toUtf8().constData(),
                            f.transport.toUtf8().constData(), f.file.toUtf8().constData());
            else
                std::printf("refused %s: %s\n", f.file.toUtf8().constData(), f.refused.toUtf8().constData());
            if (f.plugin)
                for (const QString& p : f.plugin->ports())
                    std::printf("  port %s\n", p.toUtf8().constData());
        }
        std::printf("searched: %s\n", linkplugin::searchPath().join(", ").toUtf8().constData());
        return ExitOk;
    }
    if (args.positional().empty())
        return usageError(cliText("link.needs"));
    const std::string cmd = args.positional()[0];
    if (cmd != "ping" && cmd != "status" && cmd != "pull" && cmd != "push" && cmd != "watch" && cmd != "clear" &&
        cmd != "diag" && cmd != "scan")
        return usageError(cliText("link.unknown", {cmd}));
    // push --machine NAME without a file: the database machine as released.
    const bool pushReleased = cmd == "push" && args.positional().size() == 1 && args.value("--machine");
    if (cmd == "push" && args.positional().size() != 2 && !pushReleased)
        return usageError(cliText("link.push"));
    if ((args.value("--db") || args.value("--machine")) && cmd != "push" && cmd != "pull")
        return usageError(cliText("link.db"));
    if (cmd == "clear" && (args.positional().size() != 2 || (args.positional()[1] != "c" && args.positional()[1] != "r")))
        return usageError(cliText("link.clear"));
    if (cmd != "push" && cmd != "clear" && args.positional().size() != 1)
        return usageError(cliText("link.no-file", {cmd}));
    if (cmd == "pull" && !args.value("--out"))
        return usageError(cliText("link.pull"));
    if ((args.value("--bauds") || args.value("--addresses")) && cmd != "scan")
        return usageError(cliText("link.scan-only"));
    if (args.has("--clear") && cmd != "diag")
        return usageError(cliText("link.diag-only"));
    auto line = lineSettings(args);
    if (!line)
        return ExitUsage;
    if (const auto t = args.value("--timeout-ms")) {
        const auto v = parseInt(*t);
        if (!v || *v < 10 || *v > 60000)
            return usageError(cliText("opt.timeout"));
        line->timeoutMs = static_cast<int>(*v);
    }
    const std::optional<std::string> framesPath = args.value("--frames");

    // The file to push is read before the line is opened; a machine file is
    // also checked then (a program file is checked against the controller).
    std::string pushText;
    bool pushMachine = false;
    link::PushPlan plan;
    if (cmd == "push" && !pushReleased) {
        const std::string& path = args.positional()[1];
        std::string error;
        if (!readFile(path, pushText, error)) {
            std::fprintf(stderr, "k528 link: %s\n", error.c_str());
            return ExitUsage;
        }
        pushMachine = isMachineText(pushText);
        if (pushMachine) {
            try {
                const profile::MachineProfile file = profile::readMachineText(pushText, path);
                if (link::LinkError e = link::planMachineFile(link::k528Map(), file, plan))
                    return fail(e);
            } catch (const profile::FileError& e) {
                std::fprintf(stderr, "k528 link: %s\n", e.what());
                return ExitInputErrors;
            }
        }
    }
    // Push and pull go on record (docs/database.md, *Transfers on record*);
    // a log that must be kept and cannot be, or unreleased programs of a
    // database machine, send nothing.
    std::optional<TransferRecord> record;
    if (cmd == "push" || cmd == "pull") {
        // The line as a database machine's `line` names it (cli.md).
        const std::string lineText =
            transfer::lineText(line->port.toStdString(), line->baud, line->address, isTcpLine(args));
        if (!TransferRecord::open(args, lineText, ru, record))
            return ExitUsage;
        if (pushReleased && !(record && record->releasedPlan(plan)))
            return ExitUsage;
        if (pushMachine && record && !record->mayPush(plan))
            return ExitInputErrors;
    }
    QString error;
    linkplugin::LinkPlugin* plugin = linkplugin::find(linePlugin(args), error);
    if (!plugin) {
        std::fprintf(stderr, "k528 link: %s\n", error.toUtf8().constData());
        return ExitUsage;
    }
    if (cmd == "scan") {
        if (isTcpLine(args) && args.value("--bauds"))
            return usageError(cliText("link.tcp-bauds"));
        return runScan(args, *plugin, *line, framesPath);
    }
    std::unique_ptr<linkplugin::ClientTransport> t = plugin->openClient(*line, error);
    if (!t) {
        std::fprintf(stderr, "%s\n", say("link.report.cannot-open", {line->port.toStdString(), lineError(error)}).c_str());
        return ExitUsage;
    }
    link::Link l(*t);
    const bool asJson = args.has("--json");
    // Every way out saves the frame log when asked (a failure is when it helps most).
    auto done = [&](int code) -> int {
        if (!saveFrames(framesPath, link::formatFrameLog(t->frameLog())))
            return ExitUsage;
        return code;
    };

    if (cmd == "ping") {
        link::LiveState s;
        if (link::LinkError e = link::identify(l, s))
            return done(fail(e));
        link::ServerId id;
        const bool named = !l.serverId(id);
        const std::string name = named ? say("link.report.names-itself", {id.data}) : "";
        std::printf("%s\n", say("link.report.ping", {l.map().name, line->port.toStdString(),
                                                     std::to_string(line->address), liveText(s),
                                                     fixed(l.stats().roundTrip.median(), 1), name})
                                .c_str());
        return done(ExitOk);
    }
    if (cmd == "status") {
        link::LiveState s;
        if (link::LinkError e = link::readLive(l, s))
            return done(fail(e));
        std::printf("%s\n", asJson ? json::dump(liveJson(s)).c_str() : liveText(s).c_str());
        return done(ExitOk);
    }
    if (cmd == "diag") {
        link::BusCounters c;
        if (link::LinkError e = link::readBusCounters(l, c))
            return done(fail(e));
        if (asJson) {
            Json j;
            for (std::size_t i = 0; i < c.values.size(); ++i)
                j[link::modbus::counterName(link::modbus::kCounters[i])] = c.values[i];
            std::printf("%s\n", json::dump(j).c_str());
        } else {
            std::printf("%s\n", say("link.report.counters", {std::to_string(line->address)}).c_str());
            for (std::size_t i = 0; i < c.values.size(); ++i)
                std::printf("  %-26s %u\n", link::modbus::counterName(link::modbus::kCounters[i]),
                            static_cast<unsigned>(c.values[i]));
        }
        if (args.has("--clear")) {
            if (link::LinkError e = link::clearBusCounters(l))
                return done(fail(e));
            std::printf("%s\n", say("link.report.counters-cleared").c_str());
        }
        lineReport(l, *t, isTcpLine(args) ? 0 : line->baud);
        return done(ExitOk);
    }
    if (cmd == "clear") {
        const bool c = args.positional()[1] == "c";
        if (link::LinkError e = link::clearArea(l, c ? link::BlockKind::C : link::BlockKind::R))
            return done(fail(e));
        std::printf("%s\n", say("link.report.cleared", {c ? "C" : "R",
                                                        say(c ? "link.report.cleared-c" : "link.report.cleared-r")})
                                .c_str());
        lineReport(l, *t, isTcpLine(args) ? 0 : line->baud);
        return done(ExitOk);
    }
    if (cmd == "watch") {
        installStopSignals();
        double seconds = -1;
        if (const auto s = args.value("--seconds")) {
            const auto v = parseNumber(*s);
            if (!v || *v < 0)
                return usageError(cliText("opt.seconds"));
            seconds = *v;
        }
        int interval = 100;
        if (const auto s = args.value("--interval-ms")) {
            const auto v = parseInt(*s);
            if (!v || *v < 1 || *v > 60000)
                return usageError(cliText("link.interval"));
            interval = static_cast<int>(*v);
        }
        QElapsedTimer clock;
        clock.start();
        std::string last;
        std::optional<link::LiveState> lastState;
        std::optional<QDateTime> lostSince;
        while (!stopRequested() && (seconds < 0 || clock.elapsed() < seconds * 1000)) {
            const qint64 start = clock.elapsed();
            link::LiveState s;
            if (link::LinkError e = link::readLive(l, s)) {
                // The line is lost: say since when, keep the last values as
                // stale, and keep asking (the port is opened again by itself).
                const bool first = !lostSince;
                if (first)
                    lostSince = QDateTime::currentDateTime();
                if (asJson) {
                    Json j;
                    j["online"] = false;
                    j["lost_since"] = isoText(*lostSince);
                    j["why"] = e.text(false);
                    j["stale"] = lastState ? liveJson(*lastState) : Json();
                    std::printf("%s\n", json::dump(j).c_str());
                } else if (first) {
                    std::printf("%s\n", say("link.report.lost", {clockText(*lostSince), e.text(ru),
                                                                 lastState ? liveText(*lastState)
                                                                           : say("link.report.none-yet")})
                                            .c_str());
                }
                last.clear();
            } else {
                if (lostSince && !asJson)
                    std::printf(
                        "%s\n",
                        say("link.report.back",
                            {clockText(QDateTime::currentDateTime()),
                             fixed(static_cast<double>(lostSince->msecsTo(QDateTime::currentDateTime())) / 1000.0, 1)})
                            .c_str());
                lostSince.reset();
                lastState = s;
                const std::string text = asJson ? json::dump(liveJson(s)) : liveText(s);
                if (asJson || text != last)
                    std::printf("%s\n", text.c_str());
                last = text;
            }
            if (standardOutputLost())
                return done(ExitUsage);
            const qint64 spent = clock.elapsed() - start;
            if (spent < interval)
                QThread::msleep(static_cast<unsigned long>(interval - spent));
        }
        lineReport(l, *t, isTcpLine(args) ? 0 : line->baud);
        if (lostSince) {
            std::fprintf(stderr, "%s\n", say("link.report.silent", {clockText(*lostSince)}).c_str());
            return done(ExitUsage);
        }
        return done(ExitOk);
    }
    if (cmd == "pull") {
        link::PullResult r;
        const link::LinkError e = link::pull(l, r, [](const std::string& what, int, int) {
            std::fprintf(stderr, "%s\n", say("link.report.pulling", {partText(what)}).c_str());
        });
        if (record)
            record->recordPull(l, r, e);
        if (e)
            return done(fail(e));
        const profile::MachineProfile p =
            link::pulledProfile(r, "controller", "pulled from " + line->port.toStdString());
        std::string werror;
        if (!writeOutputFile(*args.value("--out"), profile::writeMachineText(p), werror)) {
            std::fprintf(stderr, "k528 link: %s\n", werror.c_str());
            return done(ExitUsage);
        }
        std::printf("%s\n", say("link.report.pulled", {std::to_string(p.programs.size()),
                                                       std::to_string(p.messages.size()), *args.value("--out")})
                                .c_str());
        lineReport(l, *t, isTcpLine(args) ? 0 : line->baud);
        return done(ExitOk);
    }
    // push: a program file is checked against the controller first.
    if (!pushMachine && !pushReleased) {
        if (link::LinkError e = link::planProgramFile(l, pushText, args.positional()[1], plan))
            return done(fail(e));
        if (record && !record->mayPush(plan))
            return done(ExitInputErrors);
    }
    link::PushReport rep;
    const link::LinkError e = link::push(l, plan, rep, [](const std::string& what, int, int) {
        std::fprintf(stderr, "%s\n", say("link.report.pushing", {partText(what)}).c_str());
    });
    if (record)
        record->recordPush(l, plan, rep, e);
    if (!e) {
        std::string names;
        for (const link::PushReport::Part& p : rep.parts)
            names += (names.empty() ? "" : ", ") + said(p.said);
        std::printf("%s\n",
                    say("link.report.pushed", {names.empty() ? say("link.report.pushed-nothing") : names}).c_str());
    } else if (rep.anyNew() || e.kind != link::LinkError::Kind::Input) {
        std::printf("%s\n", say("link.report.push-stopped", {said(rep.summary())}).c_str());
    }
    lineReport(l, *t, isTcpLine(args) ? 0 : line->baud);
    if (e)
        return done(fail(e));
    return done(ExitOk);
}

} // namespace k528::cli
