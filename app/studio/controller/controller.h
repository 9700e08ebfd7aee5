// The controller seam of the studio: the one door through which a view
// reaches a K528-05, whichever it is — the simulated one of this window
// (SimulatedController over the SimulationSession) or a real one on a line
// through a link plugin (LinkController, plugins/). A view reads the
// ControllerState, the programs, C and R with their revision, and asks
// through it: keys, a C or R value, clearing C or R, programs from a text,
// the whole memory (for the database). Each request answers once through
// its Done (at once for the simulation; when the line has answered for a
// real controller), with the controller's own rules: the panel's for the
// simulation, F7 «РАБОТА С ПЭВМ» for the link. What a controller cannot give
// (the link: no LCD, no DAC, no keys, no faults or servo trace) is told by
// capabilities(), so a view says it plainly instead of showing nothing.
//
// The training-only parts of the simulated machine (its ticks: the
// servo-tick trace, the history and the live path sampled every tick; its
// pendant, faults and debugger) are behind SimulatedMachine
// (controller/simulated_machine.h), which only the simulated controller
// gives (simulated()). Only simulation-only views include the session
// itself (the architecture test architecture.views_use_the_seam keeps
// simulation_session.h out of the rest).
//
// The state is core's own view types (engine/views.h, the interface words,
// the K923 display), so a view draws a real controller exactly as it draws
// the simulated one.
#pragma once

#include "engine/interface_words.h"
#include "engine/views.h"
#include "panel/display.h"
#include "panel/keys.h"
#include "profile/profile.h"
#include "program/model.h"

#include <QDateTime>
#include <QObject>
#include <QSet>
#include <QString>
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
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

enum class MemoryArea { C, R };

class SimulatedMachine;

// What a controller can give the views.
struct Capabilities {
    bool keys = true;       // takes the K923's keys (and ESC from the history)
    bool lcd = true;        // the K923's LCD lines
    bool servoData = true;  // DAC, rest of path, feed, every servo tick
    bool training = true;   // the simulated machine: pendant, faults, servo-tick trace
    double liveRateHz = 30; // how often the state moves on (the link: its poll)
    QString why;            // why the rest is missing ("" for the simulation)
};

// The answer to a request: done, or why not.
using Done = std::function<void(bool ok, const QString& message)>;
using MemoryDone = std::function<void(bool ok, const QString& message, const profile::MachineProfile& memory)>;

class Controller : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    ~Controller() override = default;

    // "simulation" or the plugin's transport ("rs485"); a line for the status bar.
    virtual QString kind() const = 0;
    virtual QString description() const = 0;
    // Where a real controller is, untranslated ("/dev/ttyUSB0#1"); "" for the simulation.
    virtual QString where() const { return {}; }

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

    virtual Capabilities capabilities() const = 0;
    // The simulated machine behind this controller (its ticks, faults,
    // pendant), or nullptr for a real one.
    virtual SimulatedMachine* simulated() { return nullptr; }
    // A program the views want whose text the controller has not given yet
    // (the link reads it; programsRevision() moves when it came).
    virtual void fetchProgram(int /*number*/) {}
    // A request is under way (the link: a transfer); another waits for it.
    virtual bool busy() const { return false; }

    // The memory: C (index = number, 153 values) and R0..R299 as the
    // controller holds them, and a revision that moves when a value does (0:
    // not read yet — a linked controller reads them in the first seconds).
    virtual std::span<const std::int64_t> cValues() const = 0;
    virtual std::span<const std::int32_t> rValues() const = 0;
    virtual std::uint64_t memoryRevision() const = 0;

    // "" when C or R (`number`, or the area with -1) may be written now, else why not.
    virtual QString whyNotWritable(MemoryArea area, int number = -1) const = 0;
    virtual void setC(int number, std::int64_t value, Done done) = 0;
    virtual void setAllC(std::vector<std::int64_t> c, Done done) = 0; // all 152 at once
    virtual void setR(int number, std::int64_t value, Done done) = 0;
    virtual void clear(MemoryArea area, Done done) = 0;
    // Programs (and %MESSAGES) from the text of a program file, checked with
    // the controller's rules first; `source` names it in messages.
    virtual void loadPrograms(const std::string& text, const QString& source, Done done) = 0;
    // The whole memory (C, R, programs, messages) on this window's machine.
    virtual void readMemory(MemoryDone done) = 0;

    // The line stopped answering at this time (invalid: it answers). The
    // views keep their last values and say they are stale.
    virtual QDateTime lostSince() const { return {}; }
    bool stale() const { return lostSince().isValid(); }

signals:
    // The state moved on (the simulation advanced, a poll of the line came back).
    void updated();
    // The memory (C, R, programs) changed by a write of this window.
    void memoryWritten();
    // A real controller's poll came back, changed or not (its live rate:
    // the oscilloscope samples on it). The simulation's ticks are its own.
    void sampled();
};

// Which controller the views show: the simulated one of the window, or a
// real one on the link (the Controller dock switches). Every dock follows it.
class ViewedController : public QObject {
    Q_OBJECT
public:
    explicit ViewedController(Controller& simulated, QObject* parent = nullptr)
        : QObject(parent), simulated_(simulated), current_(&simulated) {}
    Controller& current() const { return *current_; }
    Controller& simulatedController() const { return simulated_; }
    bool isSimulated() const { return current_ == &simulated_; }
    // nullptr: the simulated one. A controller destroyed while viewed gives
    // way to the simulated one.
    void set(Controller* c);

signals:
    // current() is another controller now (`before` is still alive).
    void changed(k528::studio::Controller* before);

private:
    Controller& simulated_;
    Controller* current_;
    QSet<Controller*> watched_;
};

// "stale since 10:15:02" for a view's caption, or "".
QString staleText(const Controller& c);

// engine::AlarmView of positioner message `number` as the catalog words it
// (for a controller that only tells the numbers).
engine::AlarmView alarmOfNumber(int number);

} // namespace k528::studio
