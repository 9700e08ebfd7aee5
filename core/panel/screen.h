// The small framework the K923 screens are built on (docs/panel.md):
//
//   - a Screen draws itself on a Canvas from the engine's views each time the
//     panel is displayed (no copy of engine state), and handles the keys the
//     panel gives it;
//   - one Screen object per mode (screens/*.h) holds the pages of its mode
//     and what the panel remembers of it (the preset group last chosen, the
//     C-parameter last edited, the program last opened, …);
//   - the Panel (panel.h) owns them, switches modes with the F keys through
//     the engine, asks the password, overlays the HELP service screens,
//     handles K, L, SHIFT, ESC and MODE, and puts the service mark «*», «!»,
//     «?» in column 20 of line 1.
#pragma once

#include "engine/positioner.h"
#include "panel/keys.h"
#include "panel/text.h"

#include <string>

namespace k528::panel {

// What the password opened for the mode shown (2.6: «В случае неверного
// ввода пароля доступ в режим «РЕДАКТИРОВАНИЕ С-ПАРАМЕТРОВ» открывается
// только для просмотра»).
enum class Access { Full, ViewOnly };

// What a screen may ask of the panel, and the engine it works on.
class Context {
public:
    explicit Context(engine::Positioner& e) : engine_(e) {}

    engine::Positioner& engine() { return engine_; }
    const engine::Positioner& engine() const { return engine_; }

    // «ОШИБКА ВВОДА» (appendix М): shown on line 2 until the next key.
    void inputError();
    // A line of our own (the manual has none for the case) on line 2 until the next key.
    void note(std::string text) { message_ = std::move(text); }
    const std::string& message() const { return message_; }
    void clearMessage() { message_.clear(); }

    Access access() const { return access_; }
    void setAccess(Access a) { access_ = a; }

    // УПРАВЛЕНИЕ ДАННЫМИ «РАБОТА С ПЭВМ»: the panel is ready for the PC link.
    bool pcLinkReady() const { return pcLinkReady_; }
    void setPcLinkReady(bool on) { pcLinkReady_ = on; }

private:
    engine::Positioner& engine_;
    std::string message_;
    Access access_ = Access::Full;
    bool pcLinkReady_ = false;
};

class Screen {
public:
    virtual ~Screen() = default;

    // The mode is entered: show its main screen (what the panel remembers
    // of the mode stays).
    virtual void enter(Context&) {}
    // The mode is left (another mode, or the PLC changed it).
    virtual void leave(Context&) {}
    // Draws the screen on a blank canvas.
    virtual void render(Canvas& c, const Context& ctx) const = 0;
    // A key the panel did not take (not F, K, L, HELP, SHIFT, ESC or MODE).
    virtual void key(KeyPress k, Context& ctx) = 0;
    // A value is being typed: ESC restores the field (and does nothing else).
    virtual bool editing() const { return false; }
    virtual void cancelEdit() {}
    // ESC when nothing is typed (after the engine's ESC, C123..C125).
    virtual void escape(Context&) {}
    // MODE: the next screen of the mode, or back to the mode's menu.
    virtual void mode(Context&) {}
    // Line 1 is a title line: the service mark goes in column 20.
    virtual bool titleLine() const { return true; }
};

// The status line of АВТ, РУЧ and ПБТ screens: the mode tag in columns 1–3,
// the override right-aligned in columns 16–19 («100%»).
void renderOverride(Canvas& c, const Context& ctx);

// Moves a marker over `count` items by `step` (clamped to the list).
int moveMarker(int marker, int step, int count);
// The first visible item of a window of `rows` rows that shows `marker`,
// keeping `top` where it can.
int windowTop(int top, int marker, int rows, int count);

} // namespace k528::panel
