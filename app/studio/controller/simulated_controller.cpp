#include "controller/simulated_controller.h"

#include "catalog/messages.h"
#include "engine/alarms.h"
#include "engine/controller.h"
#include "session/simulation_session.h"

#include <cstdio>

namespace k528::studio {

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
    const engine::Controller& c = session_.controller();
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

} // namespace k528::studio
