// k528-link: the Qt half of `k528 serve` and `k528 link` (docs/link.md). The
// k528 command line is plain C++ and starts without Qt; these two commands
// need Qt's event loop and the plugin loader, so k528 runs this program
// (next to it in the build tree, in /usr/lib/k528studio when installed:
// helper_path.h) with the same arguments.
#include "cli.h"
#include "cli_texts.h"
#include "link_line.h"
#include "output_file.h"

#include <QCoreApplication>
#include <atomic>
#include <csignal>
#include <cstdio>

namespace k528::cli {

int runServeQt(std::span<const std::string> args); // cmd_serve.cpp
int runLinkQt(std::span<const std::string> args);  // cmd_link.cpp
int runShopQt(std::span<const std::string> args);  // cmd_shop_qt.cpp

namespace {
std::atomic<bool> g_stop{false};
extern "C" void onStop(int) { g_stop = true; }
} // namespace

void installStopSignals() {
    std::signal(SIGINT, onStop);
    std::signal(SIGTERM, onStop);
}
bool stopRequested() { return g_stop; }

bool isTcpLine(const Args& args) { return args.value("--tcp").has_value(); }

std::optional<linkplugin::LineSettings> lineSettings(const Args& args) {
    linkplugin::LineSettings s;
    const bool ru = russianCommandLine();
    const auto port = args.value("--port");
    const auto tcp = args.value("--tcp");
    if (port && tcp) {
        usageError(cliText("link.two-lines", {}, ru));
        return std::nullopt;
    }
    if (tcp) {
        const std::size_t colon = tcp->rfind(':');
        const auto p = colon == std::string::npos ? std::nullopt : parseInt(tcp->substr(colon + 1));
        if (colon == 0 || !p || *p < 1 || *p > 65535) {
            usageError(cliText("link.tcp", {*tcp}, ru));
            return std::nullopt;
        }
        for (const char* serial : {"--baud", "--parity", "--stop-bits"})
            if (args.value(serial)) {
                usageError(cliText("link.serial-setting", {serial}, ru));
                return std::nullopt;
            }
        s.port = QString::fromStdString(*tcp);
    } else if (!port || port->empty()) {
        usageError(cliText("link.no-line", {}, ru));
        return std::nullopt;
    } else {
        s.port = QString::fromStdString(*port);
    }
    if (const auto a = args.value("--address")) {
        const auto v = parseInt(*a);
        if (!v || *v < 1 || *v > 247) {
            usageError(cliText("link.address", {*a}, ru));
            return std::nullopt;
        }
        s.address = static_cast<int>(*v);
    }
    if (const auto b = args.value("--baud")) {
        const auto v = parseInt(*b);
        if (!v || *v < 1200 || *v > 4000000) {
            usageError(cliText("link.baud", {*b}, ru));
            return std::nullopt;
        }
        s.baud = static_cast<int>(*v);
    }
    if (const auto p = args.value("--parity")) {
        if (*p == "none")
            s.parity = 'N';
        else if (*p == "even")
            s.parity = 'E';
        else if (*p == "odd")
            s.parity = 'O';
        else {
            usageError(cliText("link.parity", {*p}, ru));
            return std::nullopt;
        }
    }
    if (const auto st = args.value("--stop-bits")) {
        if (*st != "1" && *st != "2") {
            usageError(cliText("link.stop-bits", {}, ru));
            return std::nullopt;
        }
        s.stopBits = *st == "2" ? 2 : 1;
    }
    return s;
}

} // namespace k528::cli

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    if (argc < 2) {
        std::fprintf(stderr, "k528-link: run as `k528 serve ...`, `k528 link ...` or `k528 shop ...`\n");
        return k528::cli::ExitUsage;
    }
    const std::string cmd = argv[1];
    std::vector<std::string> args(argv + 2, argv + argc);
    k528::cli::readCommandLineLanguage(args);
    try {
        // As k528's main: a lost write of standard output fails the command.
        if (cmd == "serve")
            return k528::cli::finishStandardOutput(k528::cli::runServeQt(args));
        if (cmd == "link")
            return k528::cli::finishStandardOutput(k528::cli::runLinkQt(args));
        if (cmd == "shop")
            return k528::cli::finishStandardOutput(k528::cli::runShopQt(args));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "k528 %s: %s\n", cmd.c_str(), e.what());
        return k528::cli::ExitUsage;
    }
    std::fprintf(stderr, "k528-link: unknown command '%s' (serve, link, shop)\n", cmd.c_str());
    return k528::cli::ExitUsage;
}
