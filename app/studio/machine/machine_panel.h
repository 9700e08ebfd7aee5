// The machine's own control panel (dock "dock.machine"), beside the K923:
// the E-stop, «drives on», cycle start / stop / reset, jog ±X ±Z with rapid,
// the handwheel with its axis selector and multiplier, the feed override
// selector (when the machine has one), the door, the chuck foot switch, the
// pilot lamps the machine description wires, and read-outs of the spindles,
// the turret and (grinder) the in-process gauge. It drives the simulated
// machine of a SimulationSession through machine::Simulation's operator API
// and redraws on SimulationSession::advanced(). It scales (setScale; the main
// window fits it to its dock, workspace/panel_scaler.h). A click shorter than
// a hand's push still reaches the machine: the button stays down for
// kShortestPushMs of machine time.
#pragma once

#include "machine/pendant_controls.h"
#include "machine/simulation.h"

#include <QWidget>
#include <map>

class QLabel;
class QGridLayout;
class QBoxLayout;
class QVBoxLayout;

namespace k528::studio {

class SimulationSession;
class MushroomButton;
class PilotLamp;
class HandwheelDial;
class SelectorSwitch;

class MachinePanelWidget : public QWidget {
    Q_OBJECT
public:
    explicit MachinePanelWidget(SimulationSession& session, QWidget* parent = nullptr);

    // Controls by role (object names "machine.<role>", tests use them).
    PendantButton* button(machine::Button b) const { return buttons_.at(b); }
    MushroomButton* emergencyStop() const { return estop_; }
    HandwheelDial* handwheel() const { return dial_; }
    SelectorSwitch* handwheelAxis() const { return wheelAxis_; }
    SelectorSwitch* handwheelMultiplier() const { return wheelMult_; }
    SelectorSwitch* overrideSelector() const { return override_; } // nullptr without one
    PendantButton* doorButton() const { return door_; }            // nullptr without a door
    PilotLamp* lamp(const QString& id) const;                      // nullptr if not wired

    // The override selector's positions: «K923» then the codes 0..10.
    static int overrideCodeOfPosition(int position) { return position - 1; }

    // A push shorter than this (machine time) is held down until it lasted
    // so long: the PLC debounces its inputs (8 ms) and scans them once a
    // tick, and a mouse click can come and go between two frames.
    static constexpr std::int64_t kShortestPushMs = 100;

    // The panel's scale: 1 = its natural size; the controls, letters,
    // margins and gaps follow (clamped to 0.5..3).
    void setScale(double scale);
    double scale() const { return scale_; }
    // Its two columns side by side (false) or one above the other (true,
    // for a tall narrow dock).
    void setStacked(bool stacked);
    bool stacked() const;
    // The arrangement and the largest scale (in 5 % steps, 0.6..2.5) at
    // which the panel fits `room`.
    void fitTo(QSize room);

public slots:
    void refresh(); // from the simulation's state

protected:
    void paintEvent(QPaintEvent*) override;
    void changeEvent(QEvent*) override;

private:
    // The panel, section by section (the columns left_ and right_).
    void build();
    void buildCycleControls();
    void buildJog();
    void buildLamps(const machine::MachineView& v);
    void buildHandwheel();
    void buildOverrideDoorChuck(const machine::MachineView& v);
    void buildReadouts(const machine::MachineView& v);
    // A push-button of the machine's panel wired to the simulation: pressed,
    // released, a short click held for a push.
    PendantButton* makeButton(machine::Button b, PendantButton::Cap cap, const char* name, bool illuminated);
    void retranslate();
    QString lampLegend(const std::string& id) const;
    void updateMultiplierLegends();
    void applyScale();

    SimulationSession& session_;
    std::map<machine::Button, PendantButton*> buttons_;
    MushroomButton* estop_ = nullptr;
    HandwheelDial* dial_ = nullptr;
    SelectorSwitch* wheelAxis_ = nullptr;
    SelectorSwitch* wheelMult_ = nullptr;
    SelectorSwitch* override_ = nullptr;
    PendantButton* door_ = nullptr;
    PendantButton* changeWheel_ = nullptr;
    std::map<std::string, PilotLamp*> lamps_;
    QLabel* title_ = nullptr;
    QLabel* readout_ = nullptr;
    QLabel* gauge_ = nullptr;
    QLabel* handwheelLabel_ = nullptr;
    QLabel* overrideLabel_ = nullptr;
    QLabel* jogLabel_ = nullptr;
    QString lastReadout_, lastGauge_;
    double scale_ = 1;
    QVBoxLayout* outer_ = nullptr;
    QBoxLayout* columns_ = nullptr;
    QVBoxLayout* left_ = nullptr;
    QVBoxLayout* right_ = nullptr;
    std::map<machine::Button, std::int64_t> pressedAtMs_;
};

} // namespace k528::studio
