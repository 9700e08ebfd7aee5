// A real K528-05 (or `k528 serve`) on a line, through a link plugin
// (plugins/link_plugin.h, found by app/cli/link_plugins): the Controller of
// the studio over core's client procedures (link/client.h).
//
// Everything that touches the line runs on a worker thread, so the window
// never waits for the line: the poll of the live state (every 100 ms, the
// live block and half of the interface words in turn — under 30 % of the
// line at 115 200 bit/s), the text of the running program (read once), and
// the memory transfers (pull, push) with progress and cancel. A cancelled or
// broken transfer leaves the controller as the link contract says: nothing
// half-committed (the transfer is aborted, the program stays as it was).
#pragma once

#include "controller/controller.h"
#include "link/client.h"
#include "../../plugins/link_plugin.h"

#include <QThread>
#include <atomic>
#include <memory>

namespace k528::studio {

class LinkWorker;

// The line as the dock shows it.
struct LineInfo {
    link::LineStats stats;
    linkplugin::WireCount wire;
    double lastRoundTripMs = 0, meanRoundTripMs = 0;
    double busyPercent = 0; // wire time over the time connected, last 5 s
};

class LinkController final : public Controller {
    Q_OBJECT
public:
    // `machine` gives the PLC texts, the names and the database revision base.
    LinkController(linkplugin::LinkPlugin& plugin, const linkplugin::LineSettings& line,
                   const profile::MachineProfile& machine, QObject* parent = nullptr);
    ~LinkController() override;

    QString kind() const override { return QStringLiteral("link"); }
    QString description() const override;
    const ControllerState& state() const override { return state_; }
    const program::ProgramStore& programs() const override { return programs_; }
    std::uint64_t programsRevision() const override { return revision_; }
    const profile::MachineProfile& profile() const override { return machine_; }
    bool acceptsKeys() const override { return false; } // Z1300 is read-only in the map
    void pressKey(panel::KeyPress) override {}

    const linkplugin::LineSettings& line() const { return line_; }
    bool isOpen() const { return open_; }
    bool busy() const { return busy_; }
    const LineInfo& lineInfo() const { return info_; }
    const link::LiveState& live() const { return live_; }

public slots:
    void open();                                      // opened() tells how it went
    void pull();                                      // pulled()
    void push(const profile::MachineProfile& file);   // pushed()
    void cancel();                                    // the transfer under way stops at its next exchange

signals:
    void opened(bool ok, const QString& error);
    void lineChanged();
    void lost(const QString& why); // the line stopped answering the poll
    void progress(const QString& what, int done, int total);
    // The memory read (C, R, programs, messages) as a profile on `machine`'s base.
    void pulled(bool ok, const QString& message, const k528::profile::MachineProfile& memory);
    void pushed(bool ok, const QString& message, const QStringList& written);

private:
    friend class LinkWorker;
    void applyPoll(const link::LiveState& live, const engine::InterfaceWords& words, bool wordsA, bool wordsB);
    void applyProgram(int number, const std::string& text);

    linkplugin::LinkPlugin& plugin_;
    linkplugin::LineSettings line_;
    profile::MachineProfile machine_;
    ControllerState state_;
    link::LiveState live_;
    program::ProgramStore programs_;
    std::uint64_t revision_ = 1;
    LineInfo info_;
    bool open_ = false;
    bool busy_ = false;
    QThread thread_;
    LinkWorker* worker_ = nullptr;
    std::shared_ptr<std::atomic<bool>> cancel_ = std::make_shared<std::atomic<bool>>(false);
    std::shared_ptr<std::atomic<bool>> closing_ = std::make_shared<std::atomic<bool>>(false);
};

} // namespace k528::studio
