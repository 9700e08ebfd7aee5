// The controller link's wire time. A pty has no baud rate, so the
// time is computed from the RTU bytes of every exchange actually made (bytes
// × 10 bits at 115,200 + 1.75 ms per frame): pulling a full controller
// (152 C, 300 R, 99 programs × 999 frames, the messages) against the
// minimum for the same payload read 125 registers at a time; and the share
// of the line a live monitor polling every 100 ms takes, alone and with
// everything every view of the studio reads (link/monitor.h). The exchanges are
// those of core's client procedures over the in-process transport, which
// counts the same frame sizes as the RS485 plugin.
#include "report.h"

#include "engine/positioner.h"
#include "link/client.h"
#include "link/image.h"
#include "link/monitor.h"
#include "profile/builtin.h"
#include "program/diagnostic_texts.h"
#include "program/parser.h"

#include <cstdio>

using namespace k528;

namespace {

double readCost(int registers) {
    return link::wireSeconds(link::readFrameBytes(registers).request + link::readFrameBytes(registers).reply, 2);
}

double minimumFor(std::int64_t registers) {
    double t = 0;
    for (; registers >= 125; registers -= 125)
        t += readCost(125);
    if (registers > 0)
        t += readCost(static_cast<int>(registers));
    return t;
}

} // namespace

int main() {
    bench::Report report;
    profile::MachineProfile prof = profile::builtin("training-lathe");
    engine::Positioner ctl(prof);
    ctl.powerOn();
    {
        std::string text;
        for (int p = 1; p <= 99; ++p) {
            text += "%L" + std::to_string(p) + " (full)\n";
            for (int n = 1; n <= 999; ++n)
                text += "N" + std::to_string(n) + " G1 X" + std::to_string(n % 97) + ".125 FX" +
                        std::to_string(100 + n % 50) + " Z-" + std::to_string(n % 13) + ".5\n";
        }
        text += "%MESSAGES\n";
        for (int k = 1; k <= 99; ++k)
            text += "#" + std::to_string(k) + "=СООБЩЕНИЕ " + std::to_string(k) + "\n";
        program::ParseResult parsed = program::parse(text);
        if (parsed.hasErrors()) {
            std::fprintf(stderr, "bench program does not parse: %s\n", k528::program::diagnosticText(parsed.diagnostics[0], false).c_str());
            return 2;
        }
        program::ProgramStore* store = ctl.editablePrograms();
        for (const program::Program& p : parsed.store.programs())
            store->insert(p);
        store->messages = parsed.store.messages;
        ctl.programsEdited();
    }
    link::ControllerImage image(ctl);
    link::ImageTransport t(image);
    link::Link l(t);
    link::PullResult r;
    const double t0 = bench::nowSeconds();
    if (link::LinkError e = link::pull(l, r)) {
        std::fprintf(stderr, "pull failed: %s\n", e.text(false).c_str());
        return 2;
    }
    const double cpu = bench::nowSeconds() - t0;
    std::int64_t payload = 117 + 600 + 32; // C block, R block, live state
    std::int64_t textBytes = static_cast<std::int64_t>(r.messagesText.size());
    for (const auto& [n, text] : r.programs)
        textBytes += static_cast<std::int64_t>(text.size());
    payload += (textBytes + 1) / 2;
    const double wire = link::wireSeconds(t.bytes(), t.frames());
    const double minimum = minimumFor(payload);
    std::printf("pull: %zu programs, %lld text bytes, %lld payload registers, %lld transactions, %lld bytes; "
                "wire %.2f s, minimum %.2f s (%.0f registers/s), host %.2f s\n",
                r.programs.size(), static_cast<long long>(textBytes), static_cast<long long>(payload),
                static_cast<long long>(t.transactions()), static_cast<long long>(t.bytes()), wire, minimum,
                static_cast<double>(payload) / wire, cpu);
    report.figure("link pull full controller / minimum", wire / minimum, "x", 1.15, bench::Better::Lower);

    // The live monitor: one status poll (registers 6000..6031) every 100 ms.
    link::ImageTransport m(image);
    link::Link lm(m);
    const int polls = 100;
    for (int i = 0; i < polls; ++i) {
        link::LiveState s;
        if (link::LinkError e = link::readLive(lm, s)) {
            std::fprintf(stderr, "poll failed: %s\n", e.text(false).c_str());
            return 2;
        }
    }
    const double perPoll = link::wireSeconds(m.bytes(), m.frames()) / polls;
    report.figure("link monitor poll every 100 ms: line share", perPoll / 0.100 * 100.0, "%", 30,
                  bench::Better::Lower);

    // Every view of the studio together (link/monitor.h, the plan of the
    // studio's LinkController): the live block every tick, the interface
    // words in halves in turn, a piece of the R block every 5th tick, the C
    // block every 10 s — measured over 1000 ticks (100 s), after the first
    // read of the whole memory.
    link::ImageTransport d(image);
    link::Link ld(d);
    link::Monitor monitor;
    link::Monitor::Changes changes;
    for (int i = 0; i < 10; ++i) // the first reads of R and C
        if (link::LinkError e = monitor.tick(ld, changes)) {
            std::fprintf(stderr, "monitor failed: %s\n", e.text(false).c_str());
            return 2;
        }
    const std::int64_t bytes0 = d.bytes(), frames0 = d.frames();
    const int ticks = 1000;
    for (int i = 0; i < ticks; ++i)
        if (link::LinkError e = monitor.tick(ld, changes)) {
            std::fprintf(stderr, "monitor failed: %s\n", e.text(false).c_str());
            return 2;
        }
    const double perTick = link::wireSeconds(d.bytes() - bytes0, d.frames() - frames0) / ticks;
    std::printf("monitor: %.1f bytes and %.2f frames a tick of %d ms; R whole every %.1f s, C every %.0f s\n",
                static_cast<double>(d.bytes() - bytes0) / ticks, static_cast<double>(d.frames() - frames0) / ticks,
                link::Monitor::kTickMs, 5.0 * link::Monitor::kRPieceEvery * link::Monitor::kTickMs / 1000.0,
                link::Monitor::kCEvery * link::Monitor::kTickMs / 1000.0);
    report.figure("link monitor of every view, 100 ms ticks: line share at 115200", perTick / 0.100 * 100.0, "%", 30,
                  bench::Better::Lower);
    return report.exitCode();
}
