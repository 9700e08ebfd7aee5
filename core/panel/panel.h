// The K923 operator panel (manual 2.3, 2.6, table 3, appendix М) over one
// positioner: key presses in; the 4×20 LCD with its blinking field and the
// 17 LEDs out. It talks to the engine only through engine::Positioner's
// public functions and views, and keeps no copy of the engine's state: the
// screens are drawn from the engine's views whenever display() is called.
// What it keeps is what a K923 keeps: the screen shown, markers, the text
// being typed, the password given for the mode shown.
//
//   Panel panel(controller);
//   panel.press({Key::F2});
//   panel.press({Key::Mode});
//   const Display d = panel.display();
//
// Keys the panel takes on every screen:
//   F1..F7   the mode through engine.selectMode (F5, F6, F7 after the
//            password «1111» + ENTER); refused while the PLC imposes the mode
//            (line 2 says «РЕЖИМ ЗАДАН ПЛК»). F8 has no mode.
//   K1..K12  set their bit of Z1300 (the PLC clears it).
//   L1..L4   engine.pressOverrideKey.
//   HELP     the service screens, and back.
//   SHIFT    the next key is the shifted one (SHIFT LED); SHIFT again cancels.
//   ESC      while a value is typed: the field gets its value back, nothing
//            else. Otherwise engine.escape() (C123..C125: reset, acknowledge
//            machine faults, system messages), then the screen's own ESC
//            (back from a sub-screen).
//   MODE     the next screen of the mode.
// Decisions and every layout: docs/panel.md.
#pragma once

#include "engine/positioner.h"
#include "panel/display.h"
#include "panel/health.h"
#include "panel/keys.h"
#include "panel/screen.h"

#include <array>
#include <memory>
#include <string_view>

namespace k528::panel {

class AutoManualScreens;
class ReferenceScreen;
class PresetScreens;
class CParamScreen;
class ProgramEditScreens;
class DataControlScreens;
class ServiceScreens;
class PasswordScreen;

class Panel {
public:
    // The password of the modes F5, F6, F7 (2.6).
    static constexpr std::string_view kPassword = "1111";

    explicit Panel(engine::Positioner& controller);
    ~Panel();
    Panel(const Panel&) = delete;
    Panel& operator=(const Panel&) = delete;

    void press(KeyPress k);
    void press(Key k) { press(KeyPress{k}); }
    // Follows the engine: a mode set by the PLC shows its main screen (or
    // asks the password). press() and display() call it.
    void refresh();
    // The LCD and the LEDs now.
    Display display();

    // The K923's links and self-test (panel/health.h): what table М.1
    // reports. The owner sets it whenever it may have changed.
    void setHealth(const Health& h) { health_ = h; }
    const Health& health() const { return health_; }

    // --- what the panel shows (tests, the desktop, the PC link plugin) -------
    engine::Mode shownMode() const { return shown_; }
    bool helpShown() const { return help_; }
    bool passwordShown() const { return passwordActive_; }
    bool shiftLatched() const { return shift_; }
    Access access() const { return ctx_.access(); }
    // УПРАВЛЕНИЕ ДАННЫМИ «РАБОТА С ПЭВМ» is on the LCD.
    bool pcLinkReady() const;

    const AutoManualScreens& autoScreens() const { return *auto_; }
    const AutoManualScreens& manualScreens() const { return *manual_; }
    const PresetScreens& presetScreens() const { return *presets_; }
    const CParamScreen& cparamScreen() const { return *cparams_; }
    const ProgramEditScreens& programScreens() const { return *programs_; }
    const DataControlScreens& dataScreens() const { return *data_; }
    const ServiceScreens& serviceScreens() const { return *service_; }
    const PasswordScreen& passwordScreen() const { return *password_; }

private:
    Screen& modeScreen(engine::Mode m);
    Screen& current();
    void functionKey(int n);
    void switchTo(engine::Mode m, Access access);
    void askPassword(engine::Mode m, bool imposed);
    void passwordEntered();
    Leds leds() const;

    engine::Positioner& engine_;
    Context ctx_;
    Health health_;
    std::unique_ptr<AutoManualScreens> auto_, manual_;
    std::unique_ptr<ReferenceScreen> reference_;
    std::unique_ptr<PresetScreens> presets_;
    std::unique_ptr<CParamScreen> cparams_;
    std::unique_ptr<ProgramEditScreens> programs_;
    std::unique_ptr<DataControlScreens> data_;
    std::unique_ptr<ServiceScreens> service_;
    std::unique_ptr<PasswordScreen> password_;

    engine::Mode shown_ = engine::Mode::Manual;
    bool help_ = false;
    bool passwordActive_ = false;
    bool shift_ = false;
};

// True for F5, F6, F7: the modes behind the password.
constexpr bool passwordProtected(engine::Mode m) {
    return m == engine::Mode::MachineData || m == engine::Mode::ProgramEdit ||
           m == engine::Mode::DataControl;
}

} // namespace k528::panel
