#include "panel/panel.h"

#include "engine/interface_words.h"
#include "panel/screens/auto_manual.h"
#include "panel/screens/cparams.h"
#include "panel/screens/data_control.h"
#include "panel/screens/messages.h"
#include "panel/screens/password.h"
#include "panel/screens/presets.h"
#include "panel/screens/program_editor.h"
#include "panel/screens/reference.h"
#include "panel/screens/service.h"
#include "util/utf8.h"

#include <algorithm>

namespace k528::panel {

namespace {
// Our line for an F key refused because the PLC sets the mode (Z1000.8-10).
constexpr std::string_view kModeFromPlc = "РЕЖИМ ЗАДАН ПЛК";
} // namespace

Panel::Panel(engine::Positioner& controller)
    : engine_(controller), ctx_(controller),
      auto_(std::make_unique<AutoManualScreens>(engine::Mode::Auto)),
      manual_(std::make_unique<AutoManualScreens>(engine::Mode::Manual)),
      reference_(std::make_unique<ReferenceScreen>()), presets_(std::make_unique<PresetScreens>()),
      cparams_(std::make_unique<CParamScreen>()), programs_(std::make_unique<ProgramEditScreens>()),
      data_(std::make_unique<DataControlScreens>()), service_(std::make_unique<ServiceScreens>()),
      password_(std::make_unique<PasswordScreen>()) {
    shown_ = engine_.mode();
    if (passwordProtected(shown_))
        askPassword(shown_, true);
    else
        modeScreen(shown_).enter(ctx_);
}

Panel::~Panel() = default;

Screen& Panel::modeScreen(engine::Mode m) {
    switch (m) {
    case engine::Mode::Auto:
        return *auto_;
    case engine::Mode::Manual:
        return *manual_;
    case engine::Mode::Reference:
        return *reference_;
    case engine::Mode::SetActual:
        return *presets_;
    case engine::Mode::MachineData:
        return *cparams_;
    case engine::Mode::ProgramEdit:
        return *programs_;
    case engine::Mode::DataControl:
        return *data_;
    }
    return *manual_;
}

Screen& Panel::current() {
    if (help_)
        return *service_;
    if (passwordActive_)
        return *password_;
    return modeScreen(shown_);
}

bool Panel::pcLinkReady() const {
    return ctx_.pcLinkReady() && !help_ && !passwordActive_;
}

void Panel::refresh() {
    const engine::Mode m = engine_.mode();
    if (m == shown_)
        return;
    // The mode changed without the panel: the PLC set it (Z1000.8-10).
    modeScreen(shown_).leave(ctx_);
    shown_ = m;
    passwordActive_ = false;
    ctx_.setAccess(Access::Full);
    if (passwordProtected(m))
        askPassword(m, true);
    else
        modeScreen(m).enter(ctx_);
}

void Panel::switchTo(engine::Mode m, Access access) {
    if (m != shown_)
        modeScreen(shown_).leave(ctx_);
    shown_ = m;
    passwordActive_ = false;
    ctx_.setAccess(access);
    modeScreen(m).enter(ctx_);
}

void Panel::askPassword(engine::Mode m, bool imposed) {
    password_->start(m, imposed);
    passwordActive_ = true;
}

void Panel::passwordEntered() {
    const engine::Mode m = password_->target();
    const bool right = password_->typed() == kPassword;
    if (!right && m != engine::Mode::MachineData) {
        password_->setClosed(); // «в режимы «РЕДАКТИРОВАНИЕ УП», «УПРАВЛЕНИЕ ДАННЫМИ» закрыт»
        return;
    }
    if (!password_->imposed()) {
        const engine::OpResult r = engine_.selectMode(m);
        if (!r.ok()) {
            passwordActive_ = false;
            ctx_.note(std::string(kModeFromPlc));
            return;
        }
    }
    switchTo(m, right ? Access::Full : Access::ViewOnly);
}

void Panel::functionKey(int n) {
    if (!engine::validModeKey(n))
        return; // F8: no mode
    help_ = false;
    const auto m = static_cast<engine::Mode>(n);
    if (engine_.programView().modeFromPlc) {
        if (m == shown_ && !passwordActive_)
            modeScreen(m).enter(ctx_);
        else if (m != shown_)
            ctx_.note(std::string(kModeFromPlc));
        return;
    }
    if (passwordProtected(m)) {
        if (m == shown_ && !passwordActive_ && ctx_.access() == Access::Full)
            modeScreen(m).enter(ctx_); // open already: its main screen
        else
            askPassword(m, false); // the mode changes after the password
        return;
    }
    const engine::OpResult r = engine_.selectMode(m);
    if (!r.ok()) {
        ctx_.note(std::string(kModeFromPlc));
        return;
    }
    switchTo(m, Access::Full);
}

void Panel::press(KeyPress in) {
    if (!health_.ramOk || !health_.residentOk)
        return; // the K923 itself is down
    // K keys go to the PLC (Z1300), every other key to the positioner.
    if (isKKey(in.key) ? !health_.plcLink : !health_.positionerLink)
        return;
    refresh();
    ctx_.clearMessage();
    KeyPress k = in;
    if (k.key == Key::Shift) {
        shift_ = !shift_;
        return;
    }
    if (shift_) {
        k.shift = true;
        shift_ = false;
    }
    if (isKKey(k.key)) {
        const engine::ZBit bit{static_cast<std::uint16_t>(engine::z::KeysWord),
                               engine::z::keyBit(functionNumber(k.key))};
        engine_.words().setBit(bit, true);
        return;
    }
    if (isLKey(k.key)) {
        engine_.pressOverrideKey(functionNumber(k.key));
        return;
    }
    if (isFunctionKey(k.key)) {
        functionKey(functionNumber(k.key));
        return;
    }
    if (k.key == Key::Help) {
        help_ = !help_;
        if (help_)
            service_->open();
        return;
    }
    Screen& s = current();
    if (k.key == Key::Esc) {
        if (s.editing()) {
            s.cancelEdit();
            return;
        }
        engine_.escape();
        if (passwordActive_ && !help_) {
            if (!password_->imposed())
                passwordActive_ = false; // back to the mode shown
            return;
        }
        s.escape(ctx_);
        return;
    }
    if (k.key == Key::Mode) {
        s.mode(ctx_);
        return;
    }
    if (passwordActive_ && !help_ && k.key == Key::Enter) {
        passwordEntered();
        return;
    }
    s.key(k, ctx_);
}

Leds Panel::leds() const {
    Leds l;
    const engine::InterfaceWords& w = engine_.words();
    const std::uint16_t green = w.word(engine::z::GreenLedsWord),
                        red = w.word(engine::z::RedLedsWord);
    // K1..K12's LEDs are the PLC's (Z1906/Z1907): dark without its link.
    for (int k = 1; k <= 12 && health_.plcLink; ++k) {
        const unsigned bit = engine::z::keyBit(k);
        if ((green >> bit) & 1u)
            l.green = static_cast<std::uint16_t>(l.green | (1u << (k - 1)));
        if ((red >> bit) & 1u)
            l.red = static_cast<std::uint16_t>(l.red | (1u << (k - 1)));
    }
    // L1..L4: the keys whose code (C139..C142) is the override in effect,
    // none while the PLC sets the override (Z1001.11).
    const engine::ProgramView p = engine_.programView();
    if (!p.overrideFromPlc) {
        const int code = units::overridePercentToCode(p.overridePercent);
        const auto c = engine_.c();
        for (int n = 1; n <= 4; ++n)
            if (std::clamp<std::int64_t>(c[static_cast<std::size_t>(138 + n)], 0, 10) == code)
                l.override = static_cast<std::uint8_t>(l.override | (1u << (n - 1)));
    }
    l.shift = shift_;
    return l;
}

Display Panel::display() {
    using catalog::PanelMessageId;
    const auto text = [](PanelMessageId id) { return std::string(catalog::panelMessage(id).textRu); };
    if (!health_.ramOk || !health_.residentOk) {
        Canvas c;
        c.put(0, 1, text(health_.ramOk ? PanelMessageId::ResidentCorrupt : PanelMessageId::RamFault));
        Display d;
        d.lcd = c.lcd();
        return d; // no LED lights
    }
    if (!health_.positionerLink) {
        Canvas c;
        c.put(0, 1, text(PanelMessageId::NoPositionerLink));
        Display d;
        d.lcd = c.lcd();
        d.leds = leds();
        d.leds.override = 0; // the L keys' LEDs show the positioner's override
        return d;
    }
    refresh();
    Canvas c;
    Screen& s = current();
    s.render(c, ctx_);
    if (s.titleLine())
        if (const char32_t mark = serviceMark(engine_)) {
            std::string m;
            utf8::append(m, mark);
            c.put(0, kLcdColumns, m);
        }
    // Line 2: the message of the last key, else the PLC's state.
    std::string line2 = ctx_.message();
    if (line2.empty() && !health_.plcLink)
        line2 = text(PanelMessageId::NoPlcLink);
    else if (line2.empty() && health_.plcStopped)
        line2 = text(PanelMessageId::PlcStop);
    if (!line2.empty()) {
        c.clearRow(1);
        c.put(1, 1, line2);
        if (c.blinkRow() == 1)
            c.noBlink();
    }
    Display d;
    d.lcd = c.lcd();
    d.leds = leds();
    return d;
}

} // namespace k528::panel
