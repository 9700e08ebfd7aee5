#include "controller/simulated_controller.h"

#include "catalog/messages.h"
#include "engine/alarms.h"
#include "engine/positioner.h"
#include "engine/self_test.h"
#include "session/core_texts.h"
#include "session/program_loader.h"
#include "machine/simulation.h"
#include "session/simulation_session.h"

#include <QCoreApplication>
#include <algorithm>
#include <cstdio>

namespace k528::studio {

namespace {

QString trc(const char* text) { return QCoreApplication::translate("k528::studio::ConstantsEditor", text); }

// Why the constants cannot change now ("" when they can).
QString whyNotConstants(const engine::Positioner& c) {
    if (engine::programActive(c.state()))
        return trc("a program is under way: the constants are changed when it has ended");
    for (engine::AxisId a : {engine::AxisId::X, engine::AxisId::Z})
        if (c.axisView(a).moving)
            return trc("an axis is moving: the constants are changed at standstill");
    return {};
}

// The mode of the moment of a change: F5 (one value) or F7 (all, a clear).
template <class F>
QString inMode(engine::Positioner& c, engine::Mode mode, F&& change) {
    if (const QString why = whyNotConstants(c); !why.isEmpty())
        return why;
    const engine::Mode was = c.mode();
    if (was != mode) {
        const engine::OpResult r = c.selectMode(mode);
        if (!r.ok())
            return refusalText(r);
    }
    const engine::OpResult r = change();
    if (was != mode)
        c.selectMode(was);
    return r.ok() ? QString() : refusalText(r);
}

} // namespace

QString applyCToController(engine::Positioner& controller, int number, std::int64_t value) {
    return inMode(controller, engine::Mode::MachineData, [&] { return controller.setC(number, value); });
}

QString staleText(const Controller& c) {
    const QDateTime since = c.lostSince();
    if (!since.isValid())
        return {};
    return QCoreApplication::translate("k528::studio::Controller",
                                       "The controller has not answered since %1: the values shown are its last, stale; "
                                       "the line is tried again by itself")
        .arg(since.toString(QStringLiteral("HH:mm:ss")));
}

void ViewedController::set(Controller* c) {
    Controller* next = c ? c : &simulated_;
    if (next == current_)
        return;
    Controller* before = current_;
    current_ = next;
    if (c && c != &simulated_ && !watched_.contains(c)) {
        watched_.insert(c);
        connect(c, &QObject::destroyed, this, [this, c] {
            watched_.remove(c);
            if (current_ == c) {
                current_ = &simulated_;
                emit changed(nullptr);
            }
        });
    }
    emit changed(before);
}

engine::AlarmView alarmOfNumber(int number) {
    engine::AlarmView a;
    a.number = number;
    a.active = true;
    a.category = engine::alarmCategory(number);
    if (const catalog::PositionerMessage* m = catalog::findPositionerMessage(number)) {
        a.textRu = std::string(m->textRu);
        a.textEn = std::string(m->textEn);
    } else {
        char buf[16];
        std::snprintf(buf, sizeof buf, "#%d", number); // (GCC 12's false -Wrestrict on string +)
        a.textRu = a.textEn = buf;
    }
    return a;
}

SimulatedController::SimulatedController(SimulationSession& session, QObject* parent)
    : Controller(parent), session_(session) {
    connect(&session_, &SimulationSession::advanced, this, [this] {
        dirty_ = true;
        emit updated();
    });
}

QString SimulatedController::description() const {
    return tr("simulated %1").arg(QString::fromStdString(session_.simulation().profile().name));
}

const ControllerState& SimulatedController::state() const {
    if (!dirty_)
        return state_;
    dirty_ = false;
    const engine::Positioner& c = session_.controller();
    ControllerState& s = state_;
    s.connected = true;
    s.program = c.programView();
    s.mode = static_cast<int>(s.program.mode);
    s.pcReady = session_.panel().pcLinkReady();
    for (int i = 0; i < 2; ++i)
        s.axes[static_cast<std::size_t>(i)] = c.axisView(engine::axisAt(i));
    s.alarms = c.alarms();
    s.plcMessages = c.plcMessages();
    s.words = c.words();
    s.display = session_.panel().display();
    s.hasLcd = true;
    s.hasServoData = true;
    s.programNumbers.clear();
    for (const program::Program& p : c.programs().programs())
        s.programNumbers.push_back(p.number);
    return s;
}

const program::ProgramStore& SimulatedController::programs() const { return session_.controller().programs(); }

std::uint64_t SimulatedController::programsRevision() const { return session_.controller().programsRevision(); }

const profile::MachineProfile& SimulatedController::profile() const { return session_.controller().profile(); }

void SimulatedController::pressKey(panel::KeyPress k) {
    session_.panel().press(k);
    dirty_ = true;
    emit updated();
}

Capabilities SimulatedController::capabilities() const {
    Capabilities c;
    c.liveRateHz = 1000.0 / SimulationSession::kFrameIntervalMs;
    return c;
}

std::span<const std::int64_t> SimulatedController::cValues() const { return session_.controller().c(); }

std::span<const std::int32_t> SimulatedController::rValues() const { return session_.controller().rValues(); }

std::uint64_t SimulatedController::memoryRevision() const {
    const auto c = cValues();
    const auto r = rValues();
    if (memoryRevision_ == 0 || !std::equal(c.begin(), c.end(), seenC_.begin(), seenC_.end()) ||
        !std::equal(r.begin(), r.end(), seenR_.begin(), seenR_.end())) {
        seenC_.assign(c.begin(), c.end());
        seenR_.assign(r.begin(), r.end());
        ++memoryRevision_;
    }
    return memoryRevision_;
}

QString SimulatedController::whyNotWritable(MemoryArea area, int number) const {
    const engine::Positioner& c = session_.controller();
    if (area == MemoryArea::C)
        return whyNotConstants(c);
    if (number >= 0 && engine::rReadOnly(number))
        return QCoreApplication::translate("k528::studio::RParamsModel", "R%1 is read only: the controller writes R232..R262")
            .arg(number);
    if (engine::executing(c.state()))
        return QCoreApplication::translate("k528::studio::RParamsModel",
                                           "A program is executing: R-parameters are changed when it stops, as on the K923");
    return {};
}

void SimulatedController::written(const QString& why, const Done& done) {
    if (why.isEmpty()) {
        session_.advance(0); // the views show it at once
        emit memoryWritten();
    }
    if (done)
        done(why.isEmpty(), why);
}

void SimulatedController::setC(int number, std::int64_t value, Done done) {
    written(applyCToController(session_.controller(), number, value), done);
}

void SimulatedController::setAllC(std::vector<std::int64_t> c, Done done) {
    engine::Positioner& ctl = session_.controller();
    written(inMode(ctl, engine::Mode::DataControl, [&] { return ctl.loadCParameters(c); }), done);
}

void SimulatedController::setR(int number, std::int64_t value, Done done) {
    QString why = whyNotWritable(MemoryArea::R, number);
    if (why.isEmpty()) {
        const engine::OpResult r = session_.controller().setR(number, value);
        if (!r.ok())
            why = refusalText(r);
    }
    written(why, done);
}

void SimulatedController::clear(MemoryArea area, Done done) {
    engine::Positioner& ctl = session_.controller();
    written(inMode(ctl, engine::Mode::DataControl,
                   [&] { return area == MemoryArea::C ? ctl.clearCParameters() : ctl.clearRParameters(); }),
            done);
}

void SimulatedController::loadPrograms(const std::string& text, const QString& source, Done done) {
    const ProgramLoad r = loadProgramText(session_, text, source);
    if (r.loaded)
        emit memoryWritten();
    if (done)
        done(r.loaded, r.loaded ? r.findings.join('\n') : r.problem + (r.findings.isEmpty() ? QString() : '\n' + r.findings.join('\n')));
}

void SimulatedController::readMemory(MemoryDone done) {
    const engine::Positioner& c = session_.controller();
    done(true, {}, engine::memoryProfile(session_.simulation().profile(), c.c(), c.rValues(), c.programs()));
}

machine::Simulation& SimulatedController::simulation() { return session_.simulation(); }

double SimulatedController::speed() const { return session_.speed(); }

void SimulatedController::showNow() { session_.advance(0); }

QObject* SimulatedController::lifetime() { return &session_; }

} // namespace k528::studio
