// The K923 model over a Positioner on the ideal machine (as `k528 panel`
// builds it): a built-in profile (tweaked by the test), keys given as in
// `--keys` ("F2 MODE 1 2 ENTER WAIT:2"), the four lines read back.
#pragma once

#include "panel/lcd_font.h"
#include "panel/panel.h"
#include "panel/screens/cparams.h"
#include "panel/screens/password.h"
#include "panel/screens/presets.h"
#include "panel/screens/program_editor.h"
#include "rig/engine_rig.h"
#include "util/utf8.h"

#include <QtTest>
#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>

namespace k528::testrig {

using panel::Key;
using panel::KeyPress;

// The engine tests' rig with the K923 model over its controller.
class PanelRig : public EngineRig {
public:
    std::unique_ptr<panel::Panel> p;

    explicit PanelRig(const ProfileTweak& tweak = {}, std::string_view name = "training-lathe")
        : EngineRig(name, tweak), p(std::make_unique<panel::Panel>(*ctl)) {}

    // Presses the keys of a --keys string; WAIT:S lets S seconds pass.
    void keys(std::string_view text) {
        for (const std::string& t : panel::splitKeys(text)) {
            if (t.rfind("WAIT:", 0) == 0) {
                m->advance(static_cast<std::int64_t>(std::stod(t.substr(5)) * 1000.0));
                continue;
            }
            const auto k = panel::parseKey(t);
            QVERIFY2(k.has_value(), t.c_str());
            p->press(*k);
        }
    }

    panel::Display display() { return p->display(); }

    // The four lines, trailing blanks removed (each is checked to be
    // exactly 20 characters the LCD can show).
    QStringList lines() {
        const panel::Display d = p->display();
        QStringList out;
        for (const std::string& l : d.lcd.lines) {
            if (utf8::length(l) != 20)
                qWarning("line is not 20 characters: [%s]", l.c_str());
            if (const auto bad = panel::lcdFirstUnsupported(l))
                qWarning("the LCD cannot show U+%04X in [%s]", static_cast<unsigned>(*bad),
                         l.c_str());
            QString s = QString::fromStdString(l);
            while (s.endsWith(' '))
                s.chop(1);
            out << s;
        }
        return out;
    }
    QString line(int row) { return lines().at(row); }

    // Homes the present axes as EngineRig does, then a second for the displays.
    bool home() {
        if (!EngineRig::home())
            return false;
        m->advance(1000);
        return ctl->axisView(X).referenced && ctl->axisView(Z).referenced;
    }
};

// Trailing blanks removed, as PanelRig::lines() gives them.
inline QStringList expect(std::initializer_list<const char*> l) {
    QStringList out;
    for (const char* s : l) {
        QString q = QString::fromUtf8(s);
        while (q.endsWith(' '))
            q.chop(1);
        out << q;
    }
    return out;
}

} // namespace k528::testrig
