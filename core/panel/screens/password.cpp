#include "panel/screens/password.h"

namespace k528::panel {

void PasswordScreen::start(engine::Mode target, bool imposed) {
    target_ = target;
    imposed_ = imposed;
    closed_ = false;
    entry_.start(Entry::Kind::Digits, kMaxTyped);
}

void PasswordScreen::setClosed() {
    closed_ = true;
    entry_.start(Entry::Kind::Digits, kMaxTyped);
}

void PasswordScreen::render(Canvas& c, const Context&) const {
    // Printed «П А Р О Л Ь ?» and «>».
    c.put(0, 1, "ПАРОЛЬ?");
    const std::string stars(entry_.text().size(), '*');
    c.put(1, 1, ">" + stars);
    c.blink(1, 2 + static_cast<int>(stars.size()), 1);
    if (closed_)
        c.put(2, 1, "ДОСТУП ЗАКРЫТ");
}

void PasswordScreen::key(KeyPress k, Context&) {
    if (k.key == Key::Del) {
        entry_.backspace();
        return;
    }
    if (digitOf(k.key) >= 0) {
        if (entry_.text().empty())
            closed_ = false;
        entry_.type(k.key);
    }
}

} // namespace k528::panel
