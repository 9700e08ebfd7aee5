// A real K528-05 (or `k528 serve`) on a line, through a link plugin
// (plugins/link_plugin.h, found by app/cli/link_plugins): the Controller of
// the studio over core's client procedures (link/client.h).
//
// Everything that touches the line runs on a worker thread, so the window
// never waits for the line: the poll of the live state (every 100 ms, the
// live block and half of the interface words in turn — under 30 % of the
// line at 115 200 bit/s), the text of the running program (read once), and
// the memory transfers (pull, push) with progress and cancel, and the
// requests of the views (a constant, an R-parameter, a clear, programs from
// a text, the whole memory), one at a time in order. A cancelled or
// broken transfer leaves the controller as the link contract says: nothing
// half-committed (the transfer is aborted, the program stays as it was).
// Each push and pull goes on record in the window's database as `k528 link
// push/pull` does (core/transfer: the same entry, the line's name and the
// controller's identity), a failed or cancelled one with its failure.
#pragma once

#include "controller/controller.h"
#include "db/database.h"
#include "link/client.h"
#include "link_plugin.h"

#include <QThread>
#include <array>
#include <atomic>
#include <functional>
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
    QString where() const override { return QStringLiteral("%1#%2").arg(line_.port).arg(line_.address); }
    const ControllerState& state() const override { return state_; }
    const program::ProgramStore& programs() const override { return programs_; }
    std::uint64_t programsRevision() const override { return revision_; }
    const profile::MachineProfile& profile() const override { return machine_; }
    bool acceptsKeys() const override { return false; } // Z1300 is read-only in the map
    void pressKey(panel::KeyPress) override {}
    Capabilities capabilities() const override;
    void fetchProgram(int number) override;

    std::span<const std::int64_t> cValues() const override { return c_; }
    std::span<const std::int32_t> rValues() const override { return r_; }
    std::uint64_t memoryRevision() const override { return memoryRevision_; }
    QString whyNotWritable(MemoryArea area, int number = -1) const override;
    void setC(int number, std::int64_t value, Done done) override;
    void setAllC(std::vector<std::int64_t> c, Done done) override;
    void setR(int number, std::int64_t value, Done done) override;
    void clear(MemoryArea area, Done done) override;
    void loadPrograms(const std::string& text, const QString& source, Done done) override;
    void readMemory(MemoryDone done) override;
    QDateTime lostSince() const override { return lostSince_; }

    const linkplugin::LineSettings& line() const { return line_; }
    bool isOpen() const { return open_; }
    bool busy() const override { return busy_; }
    // The frame log of the line (the newest 20 000 frames) as text, read on
    // the line's thread; `done` gets it on this one.
    void frameLog(std::function<void(const QString& text)> done);
    const LineInfo& lineInfo() const { return info_; }
    const link::LiveState& live() const { return live_; }
    // The line as the transfer log names it ("serial:/dev/ttyUSB0?baud=…&address=1").
    const std::string& lineText() const { return lineText_; }
    // The last transfer put on record by this controller (id 0: none yet).
    const db::TransferEntry& lastTransfer() const { return lastTransfer_; }

public slots:
    void open();                                      // opened() tells how it went
    // pulled(); `record`: on record in the transfer log (not the read that
    // shows what a push would change).
    void pull(bool record = true);
    // pushed(); `databaseMachine`: the database's machine pushed ("": this
    // window's machine) for the transfer log.
    void push(const profile::MachineProfile& file, const QString& databaseMachine = {});
    void cancel();                                    // the transfer under way stops at its next exchange

signals:
    void opened(bool ok, const QString& error);
    void lineChanged();
    void lost(const QString& why); // the line stopped answering the poll
    void progress(const QString& what, int done, int total);
    // The memory read (C, R, programs, messages) as a profile on `machine`'s base.
    void pulled(bool ok, const QString& message, const k528::profile::MachineProfile& memory);
    void pushed(bool ok, const QString& message, const QStringList& written);
    // Each push and pull (the dock's, the editor's programs, the constants'
    // C block, the memory kept in the database) goes on record in the
    // window's database as `k528 link push/pull` does (core/transfer):
    // said before pulled()/pushed()/the request's answer.
    void transferRecorded(bool ok, const QString& message);

private:
    friend class LinkWorker;
    void applyPoll(const link::LiveState& live, const engine::InterfaceWords& words, bool wordsA, bool wordsB);
    void applyProgram(int number, const std::string& text);
    void applyMemory(const std::vector<std::int64_t>& c, const std::array<std::int32_t, 300>* r);
    // Runs `op` on the line's thread after what is under way; `done` on this one.
    void request(const QString& what, std::function<link::LinkError(link::Link&)> op, Done done);
    void recordTransfer(db::TransferEntry entry, const std::string& databaseMachine);

    linkplugin::LinkPlugin& plugin_;
    linkplugin::LineSettings line_;
    std::string lineText_;
    db::TransferEntry lastTransfer_;
    profile::MachineProfile machine_;
    ControllerState state_;
    link::LiveState live_;
    program::ProgramStore programs_;
    std::uint64_t revision_ = 1;
    std::vector<std::int64_t> c_ = std::vector<std::int64_t>(153, 0);
    std::array<std::int32_t, 300> r_{};
    std::uint64_t memoryRevision_ = 0;
    QDateTime lostSince_;
    LineInfo info_;
    bool open_ = false;
    bool busy_ = false;
    QThread thread_;
    LinkWorker* worker_ = nullptr;
    std::shared_ptr<std::atomic<bool>> cancel_ = std::make_shared<std::atomic<bool>>(false);
    std::shared_ptr<std::atomic<bool>> closing_ = std::make_shared<std::atomic<bool>>(false);
};

} // namespace k528::studio
