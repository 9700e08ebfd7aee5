// Why a file could not be written, in the window's language: the reason a
// SaveFile kept (core's catalog, util/system_texts.h: «доступ запрещён»,
// «на устройстве не осталось места»), never Qt's errorString() — the C
// library's English in a Russian window. A file read whole is read by
// readTextFile() (core_texts.h: core's reader, its reasons in the same
// catalog).
#pragma once

#include "session/save_file.h"

#include <QString>

namespace k528::studio {

QString fileProblem(const SaveFile& f);

} // namespace k528::studio
