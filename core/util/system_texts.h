// What core says about files and the system, as ids with their Russian and
// English (a TextCatalog, %1..%9 the arguments): a file that cannot be read
// or written and why — the 16 MiB limit, a device or a folder where a file
// was meant, and the system's own reason (errno) — and an MQTT broker's
// address that is not one (the command line's and the studio's MQTT client
// is app/cli's, its words are here so both say them). The command line renders
// them in its --lang; the desktop says the same ids through its translators
// (app/studio/session/core_texts.cpp: studio.ui_language fails on an id it
// lacks or says differently); profile::problemText renders them inside a
// machine file's problem.
//
// The system's reason is not the C library's strerror() in Russian: that
// needs a Russian locale (ru_RU.UTF-8 and glibc's translations) that a
// workshop PC need not have, and setlocale() would change how every number
// is printed. The reasons a file operation meets are ids here (errno.ENOSPC:
// «На устройстве не осталось места» / "No space left on device", the English
// being glibc's own words); any other errno is said with its number and the
// C library's words quoted, as a library's words are (docs/cli-decisions.md).
#pragma once

#include "util/text_catalog.h"

#include <string>
#include <vector>

namespace k528::util {

// A text of systemTexts() with its arguments; `within` fill the arguments
// after `args` (a reason inside "cannot write %1: %2").
struct Message {
    std::string id;
    std::vector<std::string> args;
    std::vector<Message> within;

    bool empty() const { return id.empty(); }
};

Message message(std::string id, std::vector<std::string> args = {}, std::vector<Message> within = {});

util::TextCatalog systemTexts();
// `m` in a language, its `within` rendered first; an id the catalog lacks
// says the id and its arguments.
std::string systemText(const Message& m, bool russian);
// The system's reason for the error number `errnum`: errno.<NAME> for the
// reasons a file or a line meets, else errno.other with the number and the
// C library's words.
Message systemError(int errnum);

} // namespace k528::util
