#include "controller/link_controller.h"

#include "link/monitor.h"
#include "link/register_map.h"
#include "program/parser.h"
#include "units/units.h"

#include <QElapsedTimer>
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

} // namespace

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
            post([error](LinkController* c) { emit c->opened(false, error); });
            return;
        }
        meter_ = std::make_unique<MeterTransport>(*t_, cancel_, closing_);
        link_ = std::make_unique<link::Link>(*meter_);
        link::LiveState live;
        std::vector<std::uint16_t> regs;
        const link::Block& cb = link_->map().block(link::BlockKind::C);
        link::LinkError e;
        try {
            e = link::identify(*link_, live);
            if (!e)
                e = link_->read(cb.first, cb.count(), regs);
        } catch (const Cancelled&) {
            e = {link::LinkError::Kind::NoAnswer, 0, "closed"};
        }
        if (e) {
            const QString why = fromStd(e.message);
            link_.reset();
            meter_.reset();
            t_.reset();
            post([why](LinkController* c) { emit c->opened(false, why); });
            return;
        }
        const std::vector<std::int64_t> cvals = link::unpackC(link_->map(), regs);
        post([cvals](LinkController* c) {
            for (std::size_t n = 1; n < cvals.size() && n < c->machine_.c.size(); ++n)
                c->machine_.c[n] = cvals[n];
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
            const QString why = fromStd(e.message);
            post([why](LinkController* c) { emit c->lost(why); });
            lostBefore_ = true;
            report();
            return;
        }
        if (changed.live || changed.words || std::exchange(lostBefore_, false))
            post([live, words, a, b](LinkController* c) { c->applyPoll(live, words, a, b); });
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

    void pull() {
        if (later([this] { pull(); }))
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
        report();
        if (cancelled || e) {
            const QString why = cancelled ? LinkController::tr("cancelled; nothing was kept") : fromStd(e.message);
            post([why](LinkController* c) {
                c->busy_ = false;
                emit c->pulled(false, why, {});
            });
            return;
        }
        profile::MachineProfile p = link::pulledProfile(r, "controller", "pulled");
        for (const auto& [n, text] : r.programs)
            fetched_.insert(n);
        post([p](LinkController* c) {
            c->busy_ = false;
            // The pulled memory on the machine's base (name, title, PLC texts, simulation settings).
            profile::MachineProfile m = c->machine_;
            m.c = p.c;
            m.r = p.r;
            m.programs = p.programs;
            m.messages = p.messages;
            for (const auto& [n, text] : p.programs)
                c->applyProgram(n, text);
            emit c->pulled(true, QString(), m);
        });
    }

    void push(const profile::MachineProfile& file) {
        if (later([this, file] { push(file); }))
            return;
        if (!link_)
            return;
        Busy busy(*this);
        cancel_->store(false);
        meter_->cancellable = true;
        link::PushReport rep;
        link::LinkError e;
        bool cancelled = false;
        try {
            e = link::push(*link_, file, rep, progressFn());
        } catch (const Cancelled&) {
            cancelled = true;
        }
        meter_->cancellable = false;
        if (cancelled)
            abortTransfer();
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
                                      : fromStd(e.message);
        post([ok, why, written](LinkController* c) {
            c->busy_ = false;
            c->programs_ = {};
            ++c->revision_;
            emit c->pushed(ok, why, written);
        });
    }

private:
    link::Progress progressFn() {
        return [this](const std::string& what, int done, int total) {
            const QString w = fromStd(what);
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
    return tr("%1, address %2, %3 bit/s").arg(line_.port).arg(line_.address).arg(line_.baud);
}

void LinkController::open() {
    QMetaObject::invokeMethod(worker_, [w = worker_] { w->open(); }, Qt::QueuedConnection);
}

void LinkController::pull() {
    if (!open_ || busy_)
        return;
    busy_ = true;
    QMetaObject::invokeMethod(worker_, [w = worker_] { w->pull(); }, Qt::QueuedConnection);
}

void LinkController::push(const profile::MachineProfile& file) {
    if (!open_ || busy_)
        return;
    busy_ = true;
    QMetaObject::invokeMethod(worker_, [w = worker_, file] { w->push(file); }, Qt::QueuedConnection);
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
}

} // namespace k528::studio
