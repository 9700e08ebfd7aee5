// The controller seam of the studio: one interface for what the workstation
// shows of a K528-05 and what it asks of it, whichever controller it is —
// the simulated one of this window (SimulatedController over the
// SimulationSession) or a real one on a line through a link plugin
// (LinkController, plugins/). The K923 dock, the Program tab, the messages
// and the axes views read a ControllerState and press keys through it; none
// of them reaches into the simulation.
//
// The state is core's own view types (engine/views.h, the interface words,
// the K923 display), so a view draws a real controller exactly as it draws
// the simulated one; what a controller cannot tell (the LCD over the link,
// the DAC) is flagged.
#pragma once

#include "engine/interface_words.h"
#include "engine/views.h"
#include "panel/display.h"
#include "panel/keys.h"
#include "profile/profile.h"
#include "program/model.h"

#include <QObject>
#include <QString>
#include <array>
#include <cstdint>
#include <vector>

namespace k528::studio {

struct ControllerState {
    bool connected = true;
    int mode = 0;          // 1..7 = F1..F7, 0 power-on
    bool pcReady = false;  // F7 «РАБОТА С ПЭВМ»: memory may be written
    engine::ProgramView program;
    std::array<engine::AxisView, 2> axes{};
    std::vector<engine::AlarmView> alarms;
    engine::PlcMessagesView plcMessages;
    engine::InterfaceWords words;
    panel::Display display;
    bool hasLcd = true;      // the link carries no LCD: the K923 shows the LEDs only
    bool hasServoData = true; // DAC, rest of path, feed (the link's map has none)
    std::vector<int> programNumbers; // programs present in the controller
};

class Controller : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    ~Controller() override = default;

    // "simulation" or the plugin's transport ("rs485"); a line for the status bar.
    virtual QString kind() const = 0;
    virtual QString description() const = 0;

    virtual const ControllerState& state() const = 0;
    // The programs the controller holds (the link: those read so far).
    virtual const program::ProgramStore& programs() const = 0;
    // Changes whenever programs() does.
    virtual std::uint64_t programsRevision() const = 0;
    // The machine's texts (PLC messages) and axis settings.
    virtual const profile::MachineProfile& profile() const = 0;

    // The operator's keys of the K923. A controller that cannot take them
    // (the link's map has the keys read-only) says so.
    virtual bool acceptsKeys() const = 0;
    virtual void pressKey(panel::KeyPress k) = 0;

signals:
    // The state moved on (the simulation advanced, a poll of the line came back).
    void updated();
};

// engine::AlarmView of positioner message `number` as the catalog words it
// (for a controller that only tells the numbers).
engine::AlarmView alarmOfNumber(int number);

} // namespace k528::studio
