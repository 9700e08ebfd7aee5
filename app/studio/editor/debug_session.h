// The editor's debugger on the simulated machine: runs a program
// of the file as the operator would — drives on at the machine's panel,
// the reference-point cycle of every axis that needs it (skipped where
// АВТ.БЕЗ ПБТ allows, C8/C60), АВТОМАТ, the program, «Пуск» — then holds,
// continues («Пуск»), stops («Стоп»/«Сброс») and resets, through the
// machine's own push-buttons. Breakpoints, single frame and run to cursor
// are the engine's DebugGate (engine/debug_gate.h): the program stops
// *before* the frame, with the controller's frame pointer on it.
//
// On every step of the session it marks the executing frame in the target
// editor (also inside subprograms of the file) and says what changed.
#pragma once

#include "engine/debug_gate.h"
#include "machine/equipment.h"

#include <QObject>
#include <QPointer>
#include <QString>

namespace k528::studio {

class ProgramEditor;
class SimulationSession;

class DebugSession : public QObject {
    Q_OBJECT
public:
    // What the debugger itself is doing before the program runs.
    enum class Phase { Idle, SwitchingOn, Homing, Starting, Active };

    explicit DebugSession(SimulationSession* session, QObject* parent = nullptr);
    ~DebugSession() override;

    engine::DebugGate& gate() { return gate_; }
    SimulationSession* session() const { return session_; }
    Phase phase() const { return phase_; }
    // The editor whose file was sent: breakpoints from its margin, the marker in it.
    void setTarget(ProgramEditor* editor);
    ProgramEditor* target() const { return target_; }
    // A program is under way (executing or held).
    bool programActive() const;
    // The program is held and «Пуск» continues it (the gate, M00, «Стоп»).
    bool held() const;
    // The gate holds the program before a frame.
    bool heldByGate() const;
    // One line for the status of the debugger, in the UI language.
    QString statusText() const;
    // The first frame of `program` in the target's file at or after the
    // 1-based `line` (a breakpoint on a comment stops at the next frame);
    // 0 if none.
    int frameLineAtOrAfter(int program, int line) const;

public slots:
    // Starts program `number` (already in the controller) from the top:
    // drives, homing, АВТОМАТ, «Пуск». False (with message()) if it cannot.
    bool start(int number);
    // «Пуск»: continues a held program.
    void resume();
    // «Стоп»: holds the program (feed hold, then data hold).
    void hold();
    // «Сброс»: the program ends without continuation.
    void stop();
    // «Сброс» and ESC (acknowledge the messages); the markers go.
    void reset();
    void setSingleFrame(bool on);
    // Run to the frame at or after the target's 0-based `line` (a one-shot
    // stop of the gate); continues a held program, else the caller starts
    // one. False (with message()) when no frame follows the line.
    bool setRunTo(int line);
    // The breakpoints of the target's margin into the gate.
    void syncBreakpoints();

signals:
    void changed();                     // phase, state or frame changed
    void message(const QString& text);  // something to tell the user

private:
    void advanced();
    void fail(const QString& why);
    void press(machine::Button b);
    void nextHoming();
    void pressStartNow();
    bool startFree() const;
    // Why the positioner does not take «Пуск» now, in the UI language.
    QString whyNoStart() const;
    void updateMarker();

    QPointer<SimulationSession> session_;
    QPointer<ProgramEditor> target_;
    engine::DebugGate gate_;
    Phase phase_ = Phase::Idle;
    int program_ = 0;
    int homingAxis_ = -1;
    bool homingSeen_ = false;
    bool startPending_ = false; // «Пуск» waits for the button to be up again
    std::int64_t phaseSinceMs_ = 0;
    std::int64_t pressedAtMs_ = -1;
    std::int64_t lastStartPressMs_ = -1;
    // A «Пуск» that continues a held program: when it was pressed, and the
    // gate's stops and the frame then (it was taken when either moved).
    std::int64_t resumeAtMs_ = -1;
    std::int64_t resumeStops_ = 0;
    int resumeFrame_ = -1;
    std::int64_t pendingSinceMs_ = -1; // «Пуск» waiting for the button to be up
    int lastState_ = -1;
    Phase lastPhase_ = Phase::Idle;
    int lastLine_ = -1, lastProgram_ = -1;
    std::int64_t lastStops_ = 0;
};

} // namespace k528::studio
