// k528 link --port DEVICE [--address A] [--baud B] [--parity …] COMMAND (cli.md):
// ping, status [--json], pull --out FILE, push FILE, watch [--json] [--seconds S];
// `k528 link --list` lists the plugins and ports. The client procedures are
// core's (link/client.h) over the plugin's transport (QModbusRtuSerialClient).
#include "catalog/messages.h"
#include "cli.h"
#include "link/client.h"
#include "link_line.h"
#include "profile/text_format.h"
#include "util/json.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QThread>
#include <cstdio>

namespace k528::cli {

namespace {

int exitFor(const link::LinkError& e) {
    return e.kind == link::LinkError::Kind::NoAnswer ? ExitUsage : ExitInputErrors;
}

int fail(const link::LinkError& e) {
    std::fprintf(stderr, "k528 link: %s\n", e.message.c_str());
    return exitFor(e);
}

void lineReport(const link::Link& l, const linkplugin::ClientTransport& t) {
    const link::LineStats& s = l.stats();
    const linkplugin::WireCount w = t.wire();
    std::fprintf(stderr,
                 "line: %lld answers, %lld without answer, %lld bad replies, %lld exceptions, %lld retries; "
                 "%lld transactions, %lld bytes, wire time %.3f s at 115200\n",
                 static_cast<long long>(s.exchanges), static_cast<long long>(s.noAnswer),
                 static_cast<long long>(s.badReplies), static_cast<long long>(s.exceptions),
                 static_cast<long long>(s.retries), static_cast<long long>(w.transactions),
                 static_cast<long long>(w.bytes), link::wireSeconds(w.bytes, w.frames));
}


Json liveJson(const link::LiveState& s) {
    Json v;
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
    std::string t = "mode F" + std::to_string(s.mode) + (s.pcReady ? " (РАБОТА С ПЭВМ)" : "") +
                    (s.running ? ", running" : "") + ", program " + std::to_string(s.program) + " N" +
                    std::to_string(s.frame) + ", override " + std::to_string(s.overridePercent) + "%";
    char buf[160];
    std::snprintf(buf, sizeof buf, ", X %d Z %d (machine X %d Z %d, error X %d Z %d disc)", s.xCurrent,
                  s.zCurrent, s.xMachine, s.zMachine, s.xError, s.zError);
    t += buf;
    for (int n : s.alarms) {
        t += "; alarm " + std::to_string(n);
        if (const catalog::PositionerMessage* m = catalog::findPositionerMessage(n))
            t += " «" + std::string(m->textRu) + "»";
    }
    return t;
}

} // namespace

int runLinkQt(std::span<const std::string> argv) {
    std::vector<std::string_view> options = kLineOptions;
    options.insert(options.end(), {"--out", "--seconds", "--timeout-ms", "--interval-ms"});
    const Args args(argv, {"--json", "--list"}, options);
    if (!args.ok())
        return usageError(args.error());
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
        return usageError("link needs a command: ping, status, pull, push or watch");
    const std::string cmd = args.positional()[0];
    if (cmd != "ping" && cmd != "status" && cmd != "pull" && cmd != "push" && cmd != "watch")
        return usageError("unknown link command '" + cmd + "' (ping, status, pull, push, watch)");
    if (cmd == "push" && args.positional().size() != 2)
        return usageError("push takes one machine file: k528 link --port DEVICE push FILE");
    if (cmd != "push" && args.positional().size() != 1)
        return usageError("link " + cmd + " takes no file");
    if (cmd == "pull" && !args.value("--out"))
        return usageError("pull needs --out FILE");
    auto line = lineSettings(args);
    if (!line)
        return ExitUsage;
    if (const auto t = args.value("--timeout-ms")) {
        const auto v = parseInt(*t);
        if (!v || *v < 10 || *v > 60000)
            return usageError("--timeout-ms takes 10..60000");
        line->timeoutMs = static_cast<int>(*v);
    }
    // The file to push is read and checked before the line is opened.
    profile::MachineProfile file;
    if (cmd == "push") {
        try {
            file = profile::readMachineFile(args.positional()[1]);
        } catch (const profile::FileError& e) {
            std::fprintf(stderr, "k528 link: %s\n", e.what());
            return ExitInputErrors;
        }
    }
    QString error;
    linkplugin::LinkPlugin* plugin = linkplugin::find(QStringLiteral("modbus-rtu"), error);
    if (!plugin) {
        std::fprintf(stderr, "k528 link: %s\n", error.toUtf8().constData());
        return ExitUsage;
    }
    std::unique_ptr<linkplugin::ClientTransport> t = plugin->openClient(*line, error);
    if (!t) {
        std::fprintf(stderr, "k528 link: cannot open %s: %s\n", line->port.toUtf8().constData(),
                     error.toUtf8().constData());
        return ExitUsage;
    }
    link::Link l(*t);
    const bool asJson = args.has("--json");

    if (cmd == "ping") {
        QElapsedTimer rt;
        rt.start();
        link::LiveState s;
        if (link::LinkError e = link::identify(l, s))
            return fail(e);
        std::printf("K528-05 (map %s) answers on %s at address %d: %s; round trip %.1f ms\n",
                    l.map().name.c_str(), line->port.toUtf8().constData(), line->address, liveText(s).c_str(),
                    static_cast<double>(rt.nsecsElapsed()) / 2e6);
        return ExitOk;
    }
    if (cmd == "status") {
        link::LiveState s;
        if (link::LinkError e = link::readLive(l, s))
            return fail(e);
        std::printf("%s\n", asJson ? json::dump(liveJson(s)).c_str() : liveText(s).c_str());
        return ExitOk;
    }
    if (cmd == "watch") {
        installStopSignals();
        double seconds = -1;
        if (const auto s = args.value("--seconds")) {
            const auto v = parseNumber(*s);
            if (!v || *v < 0)
                return usageError("--seconds takes a duration in seconds");
            seconds = *v;
        }
        int interval = 100;
        if (const auto s = args.value("--interval-ms")) {
            const auto v = parseInt(*s);
            if (!v || *v < 1 || *v > 60000)
                return usageError("--interval-ms takes 1..60000");
            interval = static_cast<int>(*v);
        }
        QElapsedTimer clock;
        clock.start();
        std::string last;
        while (!stopRequested() && (seconds < 0 || clock.elapsed() < seconds * 1000)) {
            const qint64 start = clock.elapsed();
            link::LiveState s;
            if (link::LinkError e = link::readLive(l, s))
                return fail(e);
            const std::string text = asJson ? json::dump(liveJson(s)) : liveText(s);
            if (asJson || text != last)
                std::printf("%s\n", text.c_str());
            std::fflush(stdout);
            last = text;
            const qint64 spent = clock.elapsed() - start;
            if (spent < interval)
                QThread::msleep(static_cast<unsigned long>(interval - spent));
        }
        lineReport(l, *t);
        return ExitOk;
    }
    if (cmd == "pull") {
        link::PullResult r;
        if (link::LinkError e = link::pull(l, r, [](const std::string& what, int, int) {
                std::fprintf(stderr, "pull: %s\n", what.c_str());
            }))
            return fail(e);
        const profile::MachineProfile p =
            link::pulledProfile(r, "controller", "pulled from " + line->port.toStdString());
        try {
            profile::writeMachineFile(*args.value("--out"), p);
        } catch (const profile::FileError& e) {
            std::fprintf(stderr, "k528 link: %s\n", e.what());
            return ExitUsage;
        }
        std::printf("pulled 152 C-parameters, 300 R-parameters, %zu programs, %zu messages into %s\n",
                    p.programs.size(), p.messages.size(), args.value("--out")->c_str());
        lineReport(l, *t);
        return ExitOk;
    }
    // push
    link::PushReport rep;
    const link::LinkError e = link::push(l, file, rep, [](const std::string& what, int, int) {
        std::fprintf(stderr, "push: %s\n", what.c_str());
    });
    std::string done = std::string(rep.constants ? "C-parameters" : "") + (rep.rParameters ? ", R0..R149" : "") +
                       (rep.messages ? ", messages" : "");
    for (int p : rep.programs)
        done += ", program " + std::to_string(p);
    if (!done.empty())
        std::printf("written and verified: %s\n", done.c_str());
    lineReport(l, *t);
    if (e)
        return fail(e);
    return ExitOk;
}

} // namespace k528::cli
