#include "controller/link_controller.h"

#include "window_language.h"
#include "controller/link_texts.h"

#include "link/monitor.h"
#include "session/shop_database.h"
#include "transfer/transfer.h"
#include "link/register_map.h"
#include "program/parser.h"
#include "units/units.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <algorithm>
#include <QTimer>
#include <deque>
#include <set>
#include <utility>

namespace k528::studio {

namespace {

struct Cancelled {};

// The plugin's transport, timed (round trip) and cancellable: once the flag
// is up the next exchange throws, the procedure unwinds like a broken line.
class MeterTransport final : public link::RegisterTransport {
public:
    MeterTransport(linkplugin::ClientTransport& t, std::shared_ptr<std::atomic<bool>> cancel,
                   std::shared_ptr<std::atomic<bool>> closing)
        : t_(t), cancel_(std::move(cancel)), closing_(std::move(closing)) {}
    link::Reply read(int first, int count, std::vector<std::uint16_t>& out) override {
        return timed([&] { return t_.read(first, count, out); });
    }
    link::Reply write(int first, std::span<const std::uint16_t> v) override {
        return timed([&] { return t_.write(first, v); });
    }
    link::Reply writeRead(int wf, std::span<const std::uint16_t> v, int rf, int rc,
                          std::vector<std::uint16_t>& out) override {
        return timed([&] { return t_.writeRead(wf, v, rf, rc, out); });
    }
    link::Reply echo(std::uint16_t value) override {
        return timed([&] { return t_.echo(value); });
    }
    bool cancellable = false;
    double lastMs = 0, sumMs = 0;
    std::int64_t answered = 0;

private:
    template <class F> link::Reply timed(F&& f) {
        if ((cancellable && cancel_->load()) || closing_->load())
            throw Cancelled{};
        QElapsedTimer clock;
        clock.start();
        link::Reply r = f();
        if (r.kind != link::Reply::Kind::NoAnswer) {
            lastMs = static_cast<double>(clock.nsecsElapsed()) / 1e6;
            sumMs += lastMs;
            ++answered;
        }
        return r;
    }
    linkplugin::ClientTransport& t_;
    std::shared_ptr<std::atomic<bool>> cancel_, closing_;
};

QString fromStd(const std::string& s) { return QString::fromUtf8(s.data(), static_cast<qsizetype>(s.size())); }

// Core's message (an id of core/link/link_texts.h) in the window's language.
QString said(const link::LinkError& e) { return linkErrorText(e); }

// What a transfer moves now, as core's progress names it ("C-parameters",
// "R-parameters", "messages", "program 5"), in the window's language.
QString partName(const std::string& what) {
    if (what == "C-parameters")
        return LinkController::tr("C-parameters");
    if (what == "R-parameters")
        return LinkController::tr("R-parameters");
    if (what == "messages")
        return LinkController::tr("messages");
    if (what.rfind("program ", 0) == 0)
        return LinkController::tr("program %1").arg(fromStd(what.substr(8)));
    return fromStd(what);
}

// A transfer stopped by the user, as the log words it.
link::LinkError cancelledError() { return {link::LinkError::Kind::Refused, 0, link::say("link.cancelled")}; }

// The controller's identity added to `where` after a transfer (one more
// exchange; none when the line is closing).
void identifyAfter(transfer::Context& where, link::Link& l, const link::LinkError& e) {
    try {
        transfer::identify(where, l, e);
    } catch (const Cancelled&) {
    }
}

// A request that pushes: the plan made on the line's thread, pushed, and its
// entry for the transfer log left in `entry` (also when cancelled). A plan
// the controller refuses sends nothing and is not on record.
using EntrySlot = std::shared_ptr<std::optional<db::TransferEntry>>;
std::function<link::LinkError(link::Link&)> pushOnRecord(
    std::function<link::LinkError(link::Link&, link::PushPlan&)> planner, std::string line, EntrySlot entry) {
    return [planner = std::move(planner), line = std::move(line), entry](link::Link& l) -> link::LinkError {
        link::PushPlan plan;
        if (link::LinkError e = planner(l, plan))
            return e;
        link::PushReport rep;
        link::LinkError e;
        transfer::Context where{{}, 0, line};
        try {
            e = link::push(l, plan, rep);
        } catch (const Cancelled&) {
            *entry = transfer::pushEntry(where, l.map(), plan, rep, cancelledError());
            throw;
        }
        identifyAfter(where, l, e);
        *entry = transfer::pushEntry(where, l.map(), plan, rep, e);
        if (e && rep.anyNew())
            e.append(rep.summary());
        return e;
    };
}

} // namespace

using MemoryDone = k528::studio::MemoryDone;

// Lives on the controller's thread; owns the plugin's transport there. The
// plugin waits for each answer in a local event loop, which also delivers
// this thread's timer and queued calls: one operation at a time (depth_),
// a call that comes in the middle of one runs after it.
class LinkWorker : public QObject {
public:
    LinkWorker(LinkController* owner, linkplugin::LinkPlugin& plugin, linkplugin::LineSettings line,
               std::shared_ptr<std::atomic<bool>> cancel, std::shared_ptr<std::atomic<bool>> closing)
        : owner_(owner), plugin_(plugin), line_(std::move(line)), cancel_(std::move(cancel)),
          closing_(std::move(closing)) {}

    struct Busy {
        LinkWorker& w;
        explicit Busy(LinkWorker& worker) : w(worker) { ++w.depth_; }
        ~Busy() {
            if (--w.depth_ == 0 && w.closeRequested_)
                w.close();
        }
    };
    template <class F> bool later(F&& f) {
        if (depth_ == 0)
            return false;
        QTimer::singleShot(5, this, std::forward<F>(f));
        return true;
    }

    void open() {
        if (later([this] { open(); }))
            return;
        Busy busy(*this);
        QString error;
        t_ = plugin_.openClient(line_, error);
        if (!t_) {
            const QString why = lineErrorText(error);
            post([why](LinkController* c) { emit c->opened(false, why); });
            return;
        }
        meter_ = std::make_unique<MeterTransport>(*t_, cancel_, closing_);
        link_ = std::make_unique<link::Link>(*meter_);
        link::LiveState live;
        std::vector<std::uint16_t> regs, rregs;
        const link::RegisterMap& map = link_->map();
        const link::Block& cb = map.block(link::BlockKind::C);
        link::LinkError e;
        try {
            // Who it is, then C and R: the views show the memory from the first moment.
            e = link::identify(*link_, live);
            if (!e)
                e = link_->read(cb.first, cb.count(), regs);
            if (!e)
                e = link_->read(map.rFirst, 2 * map.rCount, rregs);
        } catch (const Cancelled&) {
            e = {link::LinkError::Kind::NoAnswer, 0, link::say("link.closed")};
        }
        if (e) {
            const QString why = said(e);
            link_.reset();
            meter_.reset();
            t_.reset();
            post([why](LinkController* c) { emit c->opened(false, why); });
            return;
        }
        const std::vector<std::int64_t> cvals = link::unpackC(map, regs);
        std::array<std::int32_t, 300> rvals{};
        for (int i = 0; i < map.rCount && i < 300; ++i)
            rvals[static_cast<std::size_t>(i)] =
                link::joinSigned(rregs[static_cast<std::size_t>(2 * i)], rregs[static_cast<std::size_t>(2 * i + 1)]);
        post([cvals, rvals](LinkController* c) {
            c->applyMemory(cvals, &rvals);
            c->open_ = true;
            emit c->opened(true, QString());
        });
        clock_.start();
        timer_ = new QTimer(this);
        timer_->setInterval(100);
        connect(timer_, &QTimer::timeout, this, [this] { poll(); });
        timer_->start();
    }

    void close() {
        if (depth_ > 0) { // an exchange is under way: close when it unwinds
            closeRequested_ = true;
            return;
        }
        closeRequested_ = false;
        if (timer_)
            timer_->stop();
        link_.reset();
        meter_.reset();
        t_.reset();
    }

    void poll() {
        if (!link_ || depth_ > 0) // the next tick polls
            return;
        Busy busy(*this);
        try {
            pollOnce();
        } catch (const Cancelled&) {
        }
    }

    void pollOnce() {
        // Every view's data (link/monitor.h): the live block each tick, the
        // interface words in halves in turn, R and C in pieces.
        link::Monitor::Changes changed;
        link::LinkError e = monitor_.tick(*link_, changed);
        const link::LiveState live = monitor_.live();
        const engine::InterfaceWords words = monitor_.words();
        const bool a = true, b = true; // the monitor keeps both halves
        ++polls_;
        if (e) {
            const QString why = said(e);
            post([why](LinkController* c) {
                if (!c->lostSince_.isValid()) {
                    c->lostSince_ = QDateTime::currentDateTime();
                    c->state_.connected = false;
                }
                emit c->lost(why);
                emit c->updated(); // the views say since when
            });
            lostBefore_ = true;
            report();
            return;
        }
        if (changed.live || changed.words || std::exchange(lostBefore_, false))
            post([live, words, a, b](LinkController* c) { c->applyPoll(live, words, a, b); });
        else
            post([](LinkController* c) { emit c->sampled(); });
        if ((changed.c && monitor_.cRevision() != 0) || (changed.r && monitor_.rRevision() != 0)) {
            std::vector<std::int64_t> cv;
            if (monitor_.cRevision() != 0)
                cv = monitor_.c();
            const bool haveR = monitor_.rRevision() != 0;
            const std::array<std::int32_t, 300> rv = monitor_.r();
            post([cv, rv, haveR](LinkController* c) { c->applyMemory(cv, haveR ? &rv : nullptr); });
        }
        // The text of the running program, once (the Program tab shows it).
        if (live.program > 0 && !fetched_.count(live.program)) {
            fetched_.insert(live.program);
            std::string text;
            if (!link::readText(*link_, false, live.program, text)) {
                const int n = live.program;
                post([n, text](LinkController* c) { c->applyProgram(n, text); });
            }
        }
        report();
    }

    // `record`: the pull goes on record (the transfer log) — not the read
    // that shows what a push would change.
    void pull(MemoryDone done, bool record, std::string line) {
        if (later([this, done, record, line] { pull(done, record, line); }))
            return;
        if (!link_)
            return;
        Busy busy(*this);
        cancel_->store(false);
        meter_->cancellable = true;
        link::PullResult r;
        link::LinkError e;
        bool cancelled = false;
        try {
            e = link::pull(*link_, r, progressFn());
        } catch (const Cancelled&) {
            cancelled = true;
        }
        meter_->cancellable = false;
        if (cancelled)
            abortTransfer();
        std::optional<db::TransferEntry> entry;
        if (record) {
            transfer::Context where{{}, 0, line};
            const link::LinkError why = cancelled ? cancelledError() : e;
            identifyAfter(where, *link_, why);
            entry = transfer::pullEntry(where, link_->map(), r, why);
        }
        report();
        if (cancelled || e) {
            const QString why = cancelled ? LinkController::tr("cancelled; nothing was kept") : said(e);
            post([why, done, entry](LinkController* c) {
                c->busy_ = false;
                if (entry)
                    c->recordTransfer(*entry, {});
                if (done)
                    done(false, why, {});
                else
                    emit c->pulled(false, why, {});
                emit c->lineChanged();
            });
            return;
        }
        profile::MachineProfile p = link::pulledProfile(r, "controller", "pulled");
        for (const auto& [n, text] : r.programs)
            fetched_.insert(n);
        const std::array<std::int32_t, 300> rv = r.r;
        post([p, rv, done, entry](LinkController* c) {
            c->busy_ = false;
            if (entry)
                c->recordTransfer(*entry, {});
            // The pulled memory on the machine's base (name, title, PLC texts, simulation settings).
            profile::MachineProfile m = c->machine_;
            m.c = p.c;
            m.r = p.r;
            m.programs = p.programs;
            m.messages = p.messages;
            for (const auto& [n, text] : p.programs)
                c->applyProgram(n, text);
            c->applyMemory(std::vector<std::int64_t>(p.c.begin(), p.c.end()), &rv);
            if (done)
                done(true, QString(), m);
            else
                emit c->pulled(true, QString(), m);
            emit c->lineChanged();
        });
    }

    // A request of a view: one procedure, then the memory read again.
    void run(std::function<link::LinkError(link::Link&)> op, Done done, bool transfer) {
        if (later([this, op, done, transfer] { run(op, done, transfer); }))
            return;
        if (!link_) {
            post([done](LinkController*) { done(false, LinkController::tr("the controller is not connected")); });
            return;
        }
        Busy busy(*this);
        cancel_->store(false);
        meter_->cancellable = transfer;
        link::LinkError e;
        bool cancelled = false;
        try {
            e = op(*link_);
        } catch (const Cancelled&) {
            cancelled = true;
        }
        meter_->cancellable = false;
        if (cancelled)
            abortTransfer();
        monitor_.memoryChanged();
        if (transfer)
            fetched_.clear();
        report();
        const bool ok = !cancelled && !e;
        const QString why = cancelled ? LinkController::tr("cancelled; what was not committed is as it was")
                                      : said(e);
        post([ok, why, done, transfer](LinkController* c) {
            if (transfer) {
                c->busy_ = false;
                c->programs_ = {};
                ++c->revision_;
                emit c->lineChanged();
            }
            if (ok)
                emit c->memoryWritten();
            if (done)
                done(ok, why);
        });
    }

    void fetch(int number) {
        if (later([this, number] { fetch(number); }))
            return;
        if (!link_ || fetched_.count(number))
            return;
        Busy busy(*this);
        fetched_.insert(number);
        std::string text;
        try {
            if (!link::readText(*link_, false, number, text))
                post([number, text](LinkController* c) { c->applyProgram(number, text); });
        } catch (const Cancelled&) {
        }
    }

    QString frames() const {
        return t_ ? fromStd(link::formatFrameLog(t_->frameLog())) : QString();
    }

    void push(const profile::MachineProfile& file, std::string line, std::string machine) {
        if (later([this, file, line, machine] { push(file, line, machine); }))
            return;
        if (!link_)
            return;
        Busy busy(*this);
        cancel_->store(false);
        meter_->cancellable = true;
        link::PushReport rep;
        link::PushPlan plan;
        // A file the controller would refuse sends nothing and is not on
        // record (as `k528 link push`); what the push did is.
        link::LinkError e = link::planMachineFile(link_->map(), file, plan);
        const bool planned = !e;
        bool cancelled = false;
        try {
            if (planned)
                e = link::push(*link_, plan, rep, progressFn());
        } catch (const Cancelled&) {
            cancelled = true;
        }
        meter_->cancellable = false;
        if (cancelled)
            abortTransfer();
        std::optional<db::TransferEntry> entry;
        if (planned) {
            transfer::Context where{{}, 0, line};
            const link::LinkError why = cancelled ? cancelledError() : e;
            identifyAfter(where, *link_, why);
            entry = transfer::pushEntry(where, link_->map(), plan, rep, why);
        }
        fetched_.clear(); // the programs may have changed: read again when shown
        monitor_.memoryChanged(); // C and R read again at once
        report();
        QStringList written;
        if (rep.constants)
            written << LinkController::tr("C-parameters");
        if (rep.rParameters)
            written << LinkController::tr("R-parameters");
        if (rep.messages)
            written << LinkController::tr("messages");
        for (int n : rep.programs)
            written << QStringLiteral("L%1").arg(n);
        const bool ok = !cancelled && !e;
        const QString why = cancelled ? LinkController::tr("cancelled; the program being sent was not committed")
                                      : said(e);
        post([ok, why, written, entry, machine](LinkController* c) {
            c->busy_ = false;
            c->programs_ = {};
            ++c->revision_;
            if (entry)
                c->recordTransfer(*entry, machine);
            emit c->pushed(ok, why, written);
        });
    }

private:
    link::Progress progressFn() {
        return [this](const std::string& what, int done, int total) {
            const QString w = partName(what);
            post([w, done, total](LinkController* c) { emit c->progress(w, done, total); });
            report();
        };
    }
    void abortTransfer() {
        const std::uint16_t abort[] = {static_cast<std::uint16_t>(link::TransferCommand::Abort)};
        try {
            (void)link_->write(link_->map().transfer.command, abort);
        } catch (const Cancelled&) { // closing: the controller drops the text on its own next begin
        }
    }
    void report() {
        LineInfo info;
        info.stats = link_ ? link_->stats() : link::LineStats{};
        info.wire = t_ ? t_->wire() : linkplugin::WireCount{};
        if (meter_) {
            info.lastRoundTripMs = meter_->lastMs;
            info.meanRoundTripMs = meter_->answered ? meter_->sumMs / static_cast<double>(meter_->answered) : 0;
        }
        const qint64 now = clock_.elapsed();
        const double wire = link::wireSeconds(info.wire.bytes, info.wire.frames, line_.baud);
        samples_.push_back({now, wire});
        while (samples_.size() > 2 && now - samples_.front().first > 5000)
            samples_.pop_front();
        if (samples_.size() >= 2 && now > samples_.front().first)
            info.busyPercent = 100.0 * (wire - samples_.front().second) * 1000.0 /
                               static_cast<double>(now - samples_.front().first);
        post([info](LinkController* c) {
            c->info_ = info;
            emit c->lineChanged();
        });
    }
    template <class F> void post(F&& f) {
        LinkController* o = owner_;
        QMetaObject::invokeMethod(o, [o, f = std::forward<F>(f)] { f(o); }, Qt::QueuedConnection);
    }

    LinkController* owner_;
    linkplugin::LinkPlugin& plugin_;
    linkplugin::LineSettings line_;
    std::shared_ptr<std::atomic<bool>> cancel_, closing_;
    int depth_ = 0;
    bool closeRequested_ = false;
    std::unique_ptr<linkplugin::ClientTransport> t_;
    std::unique_ptr<MeterTransport> meter_;
    std::unique_ptr<link::Link> link_;
    QTimer* timer_ = nullptr;
    QElapsedTimer clock_;
    std::deque<std::pair<qint64, double>> samples_;
    std::int64_t polls_ = 0;
    link::Monitor monitor_;
    bool lostBefore_ = true; // the first answer is shown whatever it is
    std::set<int> fetched_;
};

LinkController::LinkController(linkplugin::LinkPlugin& plugin, const linkplugin::LineSettings& line,
                               const profile::MachineProfile& machine, QObject* parent)
    : Controller(parent), plugin_(plugin), line_(line), machine_(machine) {
    // The line as the transfer log names it: a Modbus TCP line is HOST:PORT
    // (a serial device is a path, or COMn).
    const bool tcp = line_.port.contains(QLatin1Char(':')) && !line_.port.startsWith(QLatin1Char('/'));
    lineText_ = transfer::lineText(line_.port.toStdString(), line_.baud, line_.address, tcp);
    state_.connected = false;
    state_.hasLcd = false;
    state_.hasServoData = false;
    worker_ = new LinkWorker(this, plugin_, line_, cancel_, closing_);
    worker_->moveToThread(&thread_);
    thread_.setObjectName("controller-link");
    thread_.start();
}

LinkController::~LinkController() {
    cancel_->store(true);
    closing_->store(true); // an operation under way unwinds at its next exchange
    QMetaObject::invokeMethod(worker_, [w = worker_] { w->close(); }, Qt::BlockingQueuedConnection);
    thread_.quit();
    thread_.wait();
    delete worker_;
}

QString LinkController::description() const {
    if (lineText_.rfind("tcp:", 0) == 0)
        return tr("%1, unit %2 (Modbus TCP)").arg(line_.port).arg(line_.address);
    return tr("%1, address %2, %3 bit/s").arg(line_.port).arg(line_.address).arg(line_.baud);
}

void LinkController::open() {
    QMetaObject::invokeMethod(worker_, [w = worker_] { w->open(); }, Qt::QueuedConnection);
}

void LinkController::pull(bool record) {
    if (!open_ || busy_)
        return;
    busy_ = true;
    QMetaObject::invokeMethod(worker_, [w = worker_, record, line = lineText_] { w->pull({}, record, line); },
                              Qt::QueuedConnection);
}

ReleasedPush releasedPush(const profile::MachineProfile& file, const QString& machine) {
    ReleasedPush out;
    out.file = file;
    if (machine.isEmpty())
        return out;
    const auto state = [](db::ProgramState s) {
        return s == db::ProgramState::Draft       ? QCoreApplication::translate("k528::studio::LinkController", "draft")
               : s == db::ProgramState::Withdrawn ? QCoreApplication::translate("k528::studio::LinkController", "withdrawn")
                                                  : QCoreApplication::translate("k528::studio::LinkController", "released");
    };
    const std::string name = machine.toStdString();
    try {
        ShopDatabase::at()->use([&](db::Database& d) {
            if (!d.hasMachine(name))
                return;
            link::PushPlan plan;
            plan.programs = file.programs;
            const transfer::ReleaseCheck check = transfer::checkReleased(d, name, plan);
            out.overridden = check.overridden;
            if (check.allowed)
                return;
            const link::PushPlan released = transfer::releasedPlan(d, name, link::k528Map());
            const std::vector<db::ProgramRelease> releases = d.programReleases(name);
            for (const int n : check.unreleased) {
                const db::ProgramRelease* r = nullptr;
                for (const db::ProgramRelease& p : releases)
                    if (p.number == n)
                        r = &p;
                const auto it = released.programs.find(n);
                if (it != released.programs.end() && r && r->releasedRevision) {
                    out.file.programs[n] = it->second;
                    out.leftOut << QCoreApplication::translate("k528::studio::LinkController",
                                                             "L%1: %2, not the released version: its released "
                                                             "version (revision %3) is sent")
                                       .arg(n)
                                       .arg(state(r->state))
                                       .arg(*r->releasedRevision);
                } else {
                    out.file.programs.erase(n);
                    out.leftOut << (r ? QCoreApplication::translate("k528::studio::LinkController", "L%1: %2, never released: not sent")
                                            .arg(n)
                                            .arg(state(r->state))
                                      : QCoreApplication::translate("k528::studio::LinkController", "L%1: not in the database: not sent").arg(n));
                }
            }
        });
    } catch (const std::exception& e) {
        out.error = databaseErrorText(e);
    }
    return out;
}

void LinkController::push(const profile::MachineProfile& file, const QString& databaseMachine) {
    if (!open_ || busy_)
        return;
    // A database machine's push sends what `k528 link push --machine` would:
    // released programs only, unless the machine's setting allows drafts.
    const ReleasedPush sent = releasedPush(file, databaseMachine);
    if (!sent.error.isEmpty()) {
        emit pushed(false, tr("The push did not start: %1; nothing was sent").arg(sent.error), {});
        return;
    }
    busy_ = true;
    QMetaObject::invokeMethod(
        worker_, [w = worker_, file = sent.file, line = lineText_, m = databaseMachine.toStdString()] { w->push(file, line, m); },
        Qt::QueuedConnection);
}

void LinkController::recordTransfer(db::TransferEntry entry, const std::string& databaseMachine) {
    // The database's machine: the one pushed, else this window's machine
    // when the database has it (as `k528 link --machine NAME`), else none.
    const std::string name = databaseMachine.empty() ? machine_.name : databaseMachine;
    try {
        const db::TransferEntry stored = ShopDatabase::at()->use([&](db::Database& d) {
            if (const auto m = d.machine(name)) {
                entry.machine = name;
                entry.revision = m->revision;
            }
            return d.recordTransfer(entry);
        });
        lastTransfer_ = stored;
        emit transferRecorded(true, tr("On record: transfer %1 in %2").arg(stored.id).arg(ShopDatabase::currentText()));
    } catch (const std::exception& e) {
        emit transferRecorded(false, tr("The transfer is not on record: %1").arg(databaseErrorText(e)));
    }
}

void LinkController::cancel() { cancel_->store(true); }

void LinkController::applyProgram(int number, const std::string& text) {
    program::ParseOptions po;
    po.programNumber = number;
    const program::ParseResult r = program::parse(text, po);
    for (const program::Program& p : r.store.programs())
        programs_.insert(p);
    ++revision_;
    applyPoll(live_, state_.words, false, false); // the frame index may be known now
}

void LinkController::applyPoll(const link::LiveState& live, const engine::InterfaceWords& words, bool wordsA,
                               bool wordsB) {
    live_ = live;
    lostSince_ = {};
    ControllerState& s = state_;
    s.connected = true;
    s.mode = live.mode;
    s.pcReady = live.pcReady;
    const auto copy = [&](int first, int count) {
        for (int i = first; i < first + count; ++i)
            s.words.setWord(i, words.word(i));
    };
    if (wordsA) {
        copy(1000, 14);
        copy(2000, 9);
    }
    if (wordsB) {
        copy(1300, 8);
        copy(1900, 8);
    }
    namespace z = engine::z;
    engine::ProgramView& p = s.program;
    p.mode = live.mode >= 1 && live.mode <= 7 ? static_cast<engine::Mode>(live.mode) : engine::Mode::Manual;
    using engine::ProgramState;
    p.state = s.words.bit(z::DwellRunning)         ? ProgramState::Dwell
              : s.words.bit(z::M0Stop)             ? ProgramState::M0
              : live.running                       ? ProgramState::Running
              : s.words.bit(z::ProgramInterrupted) ? ProgramState::Interrupted
              : live.alarm                         ? ProgramState::Alarm
                                                   : ProgramState::Idle;
    p.program = live.program;
    p.selectedProgram = live.program;
    p.mainProgram = live.program;
    p.frameNumber = live.frame;
    p.frameIndex = -1;
    if (const program::Program* prog = programs_.find(live.program))
        for (std::size_t i = 0; i < prog->frames.size(); ++i)
            if (live.frame > 0 && prog->frames[i].number() == live.frame) {
                p.frameIndex = static_cast<int>(i);
                break;
            }
    p.overridePercent = live.overridePercent;
    p.endOrReset = s.words.bit(z::EndOrReset);
    p.messageNumber = live.message;
    p.messageText.clear();
    if (live.message > 0) {
        if (const auto it = machine_.messages.find(live.message); it != machine_.messages.end())
            p.messageText = it->second;
    }
    const std::int32_t cur[2] = {live.xCurrent, live.zCurrent}, mach[2] = {live.xMachine, live.zMachine},
                       err[2] = {live.xError, live.zError};
    const bool homed[2] = {live.homedX, live.homedZ};
    for (int i = 0; i < 2; ++i) {
        engine::AxisView& a = s.axes[static_cast<std::size_t>(i)];
        const engine::AxisId id = engine::axisAt(i);
        a.axis = id;
        a.present = true;
        a.scale = profile::axisScale(machine_, i == 0 ? catalog::Axis::X : catalog::Axis::Z);
        a.currentDisc = cur[i];
        a.machineDisc = mach[i];
        a.errorInternal = static_cast<double>(err[i]) * static_cast<double>(a.scale.internalPerDisc());
        a.referenced = homed[i];
        a.loopClosed = s.words.bit(z::loopClosed(id));
        a.moving = s.words.bit(z::positionNotReached(id));
        a.inPosition = !a.moving;
    }
    s.alarms.clear();
    for (int n : live.alarms)
        s.alarms.push_back(alarmOfNumber(n));
    engine::PlcMessagesView& m = s.plcMessages;
    m.alarms = s.words.word(z::AlarmMessagesFirst) | (std::uint32_t{s.words.word(z::AlarmMessagesFirst + 1)} << 16);
    m.alarmsPresent = m.alarms; // the map tells the shown messages only
    m.work = s.words.word(z::WorkMessagesFirst) | (std::uint32_t{s.words.word(z::WorkMessagesFirst + 1)} << 16);
    m.system = s.words.word(z::SystemMessagesWord);
    m.systemPresent = m.system;
    // The K923's LEDs as the panel lights them (panel.cpp): K1..K12 from
    // Z1906/Z1907, L1..L4 the key whose code is the override in effect.
    panel::Leds l;
    const std::uint16_t green = s.words.word(z::GreenLedsWord), red = s.words.word(z::RedLedsWord);
    for (int k = 1; k <= 12; ++k) {
        const unsigned bit = z::keyBit(k);
        if ((green >> bit) & 1u)
            l.green = static_cast<std::uint16_t>(l.green | (1u << (k - 1)));
        if ((red >> bit) & 1u)
            l.red = static_cast<std::uint16_t>(l.red | (1u << (k - 1)));
    }
    const int code = units::overridePercentToCode(live.overridePercent);
    for (int n = 1; n <= 4; ++n)
        if (machine_.c[static_cast<std::size_t>(138 + n)] == code)
            l.override = static_cast<std::uint8_t>(l.override | (1u << (n - 1)));
    s.display.leds = l;
    s.display.lcd = {};
    for (std::string& line : s.display.lcd.lines)
        line = std::string(panel::kLcdColumns, ' ');
    s.programNumbers = live.programs;
    emit updated();
    emit sampled();
}

Capabilities LinkController::capabilities() const {
    Capabilities c;
    c.keys = false;
    c.lcd = false;
    c.servoData = false;
    c.training = false;
    c.liveRateHz = 1000.0 / link::Monitor::kTickMs;
    c.why = tr("the link's map carries no LCD text, no keys, no DAC or servo-tick data");
    return c;
}

void LinkController::fetchProgram(int number) {
    if (!open_ || number < 1 || programs_.contains(number) ||
        std::find(state_.programNumbers.begin(), state_.programNumbers.end(), number) == state_.programNumbers.end())
        return;
    QMetaObject::invokeMethod(worker_, [w = worker_, number] { w->fetch(number); }, Qt::QueuedConnection);
}

void LinkController::frameLog(std::function<void(const QString&)> done) {
    QMetaObject::invokeMethod(worker_, [this, w = worker_, done] {
        const QString text = w->frames();
        QMetaObject::invokeMethod(this, [done, text] { done(text); }, Qt::QueuedConnection);
    }, Qt::QueuedConnection);
}

void LinkController::applyMemory(const std::vector<std::int64_t>& c, const std::array<std::int32_t, 300>* r) {
    bool changed = false;
    if (c.size() == c_.size() && c != c_) {
        c_ = c;
        for (std::size_t n = 1; n < c.size() && n < machine_.c.size(); ++n)
            machine_.c[n] = c[n]; // the axis scales of the views follow the controller's constants
        changed = true;
    }
    if (r && *r != r_) {
        r_ = *r;
        changed = true;
    }
    if (changed || memoryRevision_ == 0) {
        ++memoryRevision_;
        emit updated();
    }
}

QString LinkController::whyNotWritable(MemoryArea area, int number) const {
    if (!open_)
        return tr("the controller is not connected");
    if (stale())
        return staleText(*this);
    if (busy_)
        return tr("a transfer is under way on the line");
    const link::RegisterMap& map = link::k528Map();
    if (area == MemoryArea::R && number >= 0 && !map.rWritable(number))
        return number == 158 || number == 222 || number == 223
                   ? tr("R%1 is the positioner's own: the PC does not write it (it writes %2)")
                         .arg(number)
                         .arg(QString::fromStdString(map.rWritableText()))
                   : tr("R%1 is read only over the link: the PC writes %2").arg(number).arg(QString::fromStdString(map.rWritableText()));
    if (area == MemoryArea::C && number > 0 &&
        std::none_of(map.c.begin(), map.c.end(), [&](const link::CPlacement& p) { return p.number == number; }))
        return tr("C%1 has no address in the positioner (table Е.1): it is not written").arg(number, 3, 10, QChar('0'));
    if (!state_.pcReady) {
        const QString mode = state_.mode >= 1 && state_.mode <= 7 ? QStringLiteral("F%1").arg(state_.mode) : tr("power-on");
        return state_.mode == 7
                   ? tr("the controller is in F7 УПРАВЛЕНИЕ ДАННЫМИ but not on «РАБОТА С ПЭВМ»: choose it in its menu on the K923")
                   : tr("the controller is not in F7 «РАБОТА С ПЭВМ» (mode %1 now): press F7 (УПРАВЛЕНИЕ ДАННЫМИ) on its K923 "
                        "and choose «РАБОТА С ПЭВМ»")
                         .arg(mode);
    }
    return {};
}

void LinkController::request(const QString& what, std::function<link::LinkError(link::Link&)> op, Done done) {
    if (!open_) {
        if (done)
            done(false, tr("%1: the controller is not connected").arg(what));
        return;
    }
    QMetaObject::invokeMethod(worker_, [w = worker_, op, done] { w->run(op, done, false); }, Qt::QueuedConnection);
}

void LinkController::setC(int number, std::int64_t value, Done done) {
    request(QStringLiteral("C%1").arg(number), [number, value](link::Link& l) { return link::setConstant(l, number, value); },
            [this, number, value, done](bool ok, const QString& why) {
                if (ok && static_cast<std::size_t>(number) < c_.size() && c_[static_cast<std::size_t>(number)] != value) {
                    std::vector<std::int64_t> c = c_;
                    c[static_cast<std::size_t>(number)] = value;
                    applyMemory(c, nullptr);
                }
                if (done)
                    done(ok, why);
            });
}

void LinkController::setAllC(std::vector<std::int64_t> c, Done done) {
    auto entry = std::make_shared<std::optional<db::TransferEntry>>();
    request(tr("C-parameters"),
            pushOnRecord(
                [c](link::Link&, link::PushPlan& plan) {
                    plan.hasC = true;
                    plan.c = c;
                    return link::LinkError{};
                },
                lineText_, entry),
            [this, c, done, entry](bool ok, const QString& why) {
                if (*entry)
                    recordTransfer(**entry, {});
                if (ok && c.size() == c_.size())
                    applyMemory(c, nullptr);
                if (done)
                    done(ok, why);
            });
}

void LinkController::setR(int number, std::int64_t value, Done done) {
    request(QStringLiteral("R%1").arg(number), [number, value](link::Link& l) { return link::setRParameter(l, number, value); },
            [this, number, value, done](bool ok, const QString& why) {
                if (ok && number >= 0 && number < 300 && r_[static_cast<std::size_t>(number)] != value) {
                    std::array<std::int32_t, 300> r = r_;
                    r[static_cast<std::size_t>(number)] = static_cast<std::int32_t>(value);
                    applyMemory(c_, &r);
                }
                if (done)
                    done(ok, why);
            });
}

void LinkController::clear(MemoryArea area, Done done) {
    request(area == MemoryArea::C ? tr("clear C") : tr("clear R"),
            [area](link::Link& l) { return link::clearArea(l, area == MemoryArea::C ? link::BlockKind::C : link::BlockKind::R); },
            [this, area, done](bool ok, const QString& why) {
                if (ok && area == MemoryArea::C)
                    applyMemory(std::vector<std::int64_t>(c_.size(), 0), nullptr);
                if (done)
                    done(ok, why);
            });
}

void LinkController::loadPrograms(const std::string& text, const QString& source, Done done) {
    if (!open_ || busy_) {
        if (done)
            done(false, busy_ ? tr("a transfer is under way on the line") : tr("the controller is not connected"));
        return;
    }
    busy_ = true;
    emit lineChanged();
    const std::string name = source.toStdString();
    auto entry = std::make_shared<std::optional<db::TransferEntry>>();
    auto op = pushOnRecord([text, name](link::Link& l, link::PushPlan& plan) {
        return link::planProgramFile(l, text, name, plan);
    }, lineText_, entry);
    Done recorded = [this, done, entry](bool ok, const QString& why) {
        if (*entry)
            recordTransfer(**entry, {});
        if (done)
            done(ok, why);
    };
    QMetaObject::invokeMethod(worker_, [w = worker_, op, recorded] { w->run(op, recorded, true); }, Qt::QueuedConnection);
}

void LinkController::readMemory(MemoryDone done) {
    if (!open_ || busy_) {
        done(false, busy_ ? tr("a transfer is under way on the line") : tr("the controller is not connected"), {});
        return;
    }
    busy_ = true;
    emit lineChanged();
    QMetaObject::invokeMethod(worker_, [w = worker_, done, line = lineText_] { w->pull(done, true, line); },
                              Qt::QueuedConnection);
}

} // namespace k528::studio
