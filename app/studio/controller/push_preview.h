// What a push changes in a controller's memory, shown before it is sent:
// the Controller dock's push of a machine file or a database machine and
// the editor's Send to controller (a program file) show the same preview —
// core's profile diff of the memory just read against the memory as the
// push would leave it (programs in the canonical text the controller keeps).
#pragma once

#include "profile/diff.h"
#include "profile/profile.h"

#include <QString>
#include <functional>
#include <string>
#include <vector>

class QDialog;
class QWidget;

namespace k528::studio {

// The memory after a push of a machine file: C, the R-parameters the PC
// writes (R0..R231 but R158, R222, R223), the messages when it has any, its
// programs.
profile::MachineProfile afterPush(const profile::MachineProfile& memory, const profile::MachineProfile& file);
// The memory after a push of a program file's text (its programs and
// %MESSAGES; C and R as they are).
profile::MachineProfile afterPrograms(const profile::MachineProfile& memory, const std::string& text);

// Core's profile diff as the window shows it, one line per change in its
// language («C022 УСКОРЕНИЕ 1: 2000 -> 2133», «L5: добавлена» and its lines).
QString diffText(const std::vector<profile::Change>& changes);

// Opens (window-modal) the preview of `what` going into the controller,
// whose memory is `before`; `done(true)` when the user chose to send.
// Object names: "controller.pushPreview", its diff "controller.pushPreview.diff".
QDialog* showPushPreview(QWidget* parent, const QString& what, const profile::MachineProfile& before,
                         const profile::MachineProfile& after, const QString& sendText,
                         std::function<void(bool send)> done);

} // namespace k528::studio
