// English texts of a machine file (docs/profile-format.md, "English texts").
#pragma once

#include "catalog/messages.h"
#include "profile/problem.h"
#include "profile/profile.h"
#include "profile/tools.h"

#include <string>
#include <string_view>

namespace k528::profile {

// English texts (docs/profile-format.md, "English texts"). The machine file
// may give an English beside each text for people: `title.en=`, `#k.en=`,
// `A01.en=`, `tool.n.name.en=`. The Russian is the controller's (the K923
// shows it, the database and the CLI's --lang ru print it); the English is
// what a window or the CLI in English shows, the Russian when none is given.
// They are kept with the settings (`text.en.title`, `text.en.m<k>`,
// `text.en.a01`, …; `tool.n.name.en`), so the database, its revisions and
// diffs keep them as every setting.
//
// The setting that holds the English of `item` ("title", "#3", "A01", "W12",
// "S01"); "" when `item` names no such text.
std::string englishKey(std::string_view item);
// The item whose English the setting `key` holds ("title", "#3", "A01"); ""
// when `key` is not `text.en.<item>` of a text that may have one.
std::string englishItem(std::string_view key);
// The text for a reader of English (`english`) or Russian: the English when
// the file gives one, else the Russian; "" when there is neither.
std::string titleText(const MachineProfile& p, bool english);
std::string messageText(const MachineProfile& p, int number, bool english);
std::string plcText(const MachineProfile& p, catalog::PlcGroup g, int k, bool english);
// The tool's name (tool.n.name, its English tool.n.name.en).
std::string toolName(const MachineProfile& p, const Tool& t, bool english);

// The English of `item` ("title", "#3", "A01"): the rules of its Russian.
Problem englishTextProblem(std::string_view item, std::string_view text);

} // namespace k528::profile
