// k528 serve --port DEVICE|--tcp HOST:PORT [--profile …] [--address A] [--baud B] [--parity …] [--keys "…"]
// [--lang ru|en] (its own messages on stderr; docs/cli-decisions.md)
// (cli.md): the simulated K528-05 — the machine of `k528 run`, its PLC and
// K923 — as a Modbus RTU server (--keys: the K923's keys, WAIT:S, and the
// pendant's buttons PUSH:NAME, HOLD:NAME:S, PULL:ESTOP as `k528 panel
// --machine` takes them, so a served controller can run a program) (the plugin's QModbusRtuSerialServer) over
// core's ControllerImage, in real time until SIGINT/SIGTERM. It answers the
// bus counters of function 08 and names itself to function 17.
#include "cli.h"
#include "cli_texts.h"
#include "link/image.h"
#include "link/link_texts.h"
#include "link/transport.h"
#include "link_line.h"
#include "machine/simulation.h"
#include "machine_buttons.h"
#include "machine_profile.h"
#include "panel/keys.h"
#include "panel/panel.h"
#include "plc/description.h"
#include "plc/json_reader.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QSocketNotifier>
#include <QTimer>
#include <cmath>
#include <cstdio>
#include <memory>
#include <unistd.h>
#include <variant>

namespace k528::cli {


int runServeQt(std::span<const std::string> argv) {
    std::vector<std::string_view> options = kLineOptions;
    options.insert(options.end(), {"--profile", "--db", "--keys", "--lang"});
    const Args args(argv, {"--stdin-keys"}, options);
    if (!args.ok())
        return usageError(args.error());
    if (!args.positional().empty())
        return usageError(cliText("serve.no-file"));
    // (k528-link holds no cmd_check.cpp: its parseLang and printDescriptionError are said here.)
    const auto lang = args.value("--lang");
    if (lang && *lang != "ru" && *lang != "en")
        return usageError(cliText("opt.lang", {*lang}));
    const bool ru = lang.value_or("ru") == "ru";
    const auto line = lineSettings(args);
    if (!line)
        return ExitUsage;
    using Step = std::variant<panel::KeyPress, std::int64_t, ButtonStep>;
    std::vector<Step> steps;
    for (const std::string& token : panel::splitKeys(args.value("--keys").value_or(""))) {
        if (token.size() > 5 && (token.rfind("WAIT:", 0) == 0 || token.rfind("wait:", 0) == 0)) {
            const auto s = parseNumber(std::string_view(token).substr(5));
            if (!s || *s < 0 || *s > 1e6)
                return usageError(cliText("serve.wait", {token}));
            steps.emplace_back(static_cast<std::int64_t>(std::llround(*s * 1000.0)));
        } else if (const std::string t = upperToken(token.substr(0, 5));
                   t == "PUSH:" || t == "HOLD:" || t == "PULL:") {
            std::string error;
            const auto b = parseButton(token, error);
            if (!b)
                return usageError(error);
            steps.emplace_back(*b);
        } else if (const auto k = panel::parseKey(token)) {
            steps.emplace_back(*k);
        } else {
            return usageError(cliText("serve.key", {token}));
        }
    }
    const auto prof = machineProfile(args);
    if (!prof)
        return ExitUsage;
    std::unique_ptr<machine::Simulation> sim;
    try {
        sim = std::make_unique<machine::Simulation>(*prof);
    } catch (const plc::DescriptionError& e) {
        std::fprintf(stderr, "%s\n", cliText("machine.description", {e.text(ru)}, ru).c_str());
        return ExitUsage;
    }
    sim->powerOn();
    sim->advance(10);
    panel::Panel k923(sim->controller());
    for (const Step& s : steps) {
        if (const auto* k = std::get_if<panel::KeyPress>(&s))
            k923.press(*k);
        else if (const auto* b = std::get_if<ButtonStep>(&s))
            pressButton(*sim, *b);
        else
            sim->advance(std::get<std::int64_t>(s));
    }
    link::ControllerImage image(sim->controller());
    image.setPcReady([&] { return k923.pcLinkReady(); });
    link::ImageHandler handler(image);

    QString error;
    linkplugin::LinkPlugin* plugin = linkplugin::find(linePlugin(args), error);
    if (!plugin) {
        std::fprintf(stderr, "k528: %s\n", error.toUtf8().constData());
        return ExitUsage;
    }
    // FC 17 names the station, for a bus scan to tell who answers.
    const QString identity = QStringLiteral("K528-05 simulated by k528 serve: %1").arg(QString::fromStdString(prof->name));
    std::unique_ptr<linkplugin::Server> server = plugin->openServer(*line, handler, identity, error);
    if (!server) {
        std::fprintf(stderr, "%s\n",
                     cliText("serve.cannot",
                             {line->port.toStdString(), link::render(link::decodeSaid(error.toStdString()), ru)}, ru)
                         .c_str());
        return ExitUsage;
    }
    if (isTcpLine(args))
        std::fprintf(stderr, "%s\n",
                     cliText("serve.tcp", {prof->name, line->port.toStdString(), std::to_string(line->address)}, ru)
                         .c_str());
    else
        std::fprintf(stderr, "%s\n",
                     cliText("serve.serial",
                             {prof->name, line->port.toStdString(), std::to_string(line->address),
                              std::to_string(line->baud), std::string(1, line->parity), std::to_string(line->stopBits)},
                             ru)
                         .c_str());
    std::fflush(stderr);

    // --stdin-keys: K923 keys read from standard input while serving, a line
    // at a time (an instructor's script; a test or a benchmark that changes
    // the controller's state at a moment it knows).
    std::unique_ptr<QSocketNotifier> stdinKeys;
    std::string typed;
    if (args.has("--stdin-keys")) {
        stdinKeys = std::make_unique<QSocketNotifier>(0, QSocketNotifier::Read);
        QObject::connect(stdinKeys.get(), &QSocketNotifier::activated, [&] {
            char buf[512];
            const ssize_t n = ::read(0, buf, sizeof buf);
            if (n <= 0) {
                stdinKeys->setEnabled(false); // the end of the input: serving goes on
                return;
            }
            typed.append(buf, static_cast<std::size_t>(n));
            for (std::size_t eol; (eol = typed.find('\n')) != std::string::npos;) {
                const std::string line = typed.substr(0, eol);
                typed.erase(0, eol + 1);
                for (const std::string& token : panel::splitKeys(line)) {
                    if (const auto k = panel::parseKey(token))
                        k923.press(*k);
                    else
                        std::fprintf(stderr, "%s\n", cliText("serve.stdin-key", {token}, ru).c_str());
                }
            }
        });
    }
    installStopSignals();
    QElapsedTimer clock;
    clock.start();
    std::int64_t simulatedMs = 0;
    QTimer tick;
    QObject::connect(&tick, &QTimer::timeout, [&] {
        if (stopRequested()) {
            QCoreApplication::quit();
            return;
        }
        const std::int64_t now = clock.elapsed();
        if (now > simulatedMs) {
            sim->advance(now - simulatedMs); // real time: the machine catches up with the clock
            simulatedMs = now;
        }
    });
    tick.start(5);
    QCoreApplication::exec();
    std::fprintf(stderr, "%s\n",
                 cliText("serve.stopped", {std::to_string(server->requests()), std::to_string(image.commits())}, ru)
                     .c_str());
    return ExitOk;
}

} // namespace k528::cli
