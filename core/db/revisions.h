// The rules of revisions, the same for every backend (internal to core/db):
// what a write is checked against, the changes a revision records (profile::diff
// and the order of the simulation keys), its summary, the keys of recorded
// items, and the state at a revision rebuilt from recorded changes.
#pragma once

#include "catalog/messages.h"
#include "profile/diff.h"
#include "profile/profile.h"
#include "profile/validate.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace k528::db::revision {

// The recorded key of simulation keys that only moved.
inline constexpr std::string_view kOrderKey = "(order)";

// "A01", "W12", "S03".
std::string plcKey(catalog::PlcGroup g, int number);
std::optional<catalog::PlcGroup> plcGroupOf(char letter);
std::optional<profile::DiffSection> sectionFromName(std::string_view name);
// The number after a one-character prefix ("C022" -> 22, "#3" -> 3).
std::optional<int> keyNumber(std::string_view key);
// The simulation keys in order, `sep` between them.
std::string joinKeys(const profile::Settings& s, char sep);

// Checks `neu` before it is written over `old` (nullptr: a new machine):
// returns its findings (warnings and tolerated errors) or throws
// ValidationError (values outside their definitions always; cross-check
// errors the stored machine did not have, unless allowed).
std::vector<profile::Finding> checkWrite(const profile::MachineProfile* old,
                                         const profile::MachineProfile& neu, bool allowErrors);
// The changes that turn `old` (nullptr: nothing) into `neu`. A new machine
// records its name, title and all 152 constants explicitly; keys of the
// simulation section that only moved are recorded as kOrderKey.
std::vector<profile::Change> computeChanges(const profile::MachineProfile* old,
                                            const profile::MachineProfile& neu);
// (A revision's default summary: db/notes.h, changedNote.)

// Applies one recorded change (not a program's) to `p`, rebuilding a state;
// false when the record cannot be read.
bool applyRecorded(profile::MachineProfile& p, profile::DiffSection section, const std::string& key,
                   const std::optional<std::string>& after);
// Puts the simulation keys of `p` in the recorded `order` ("\n" between
// keys); "" or what is wrong: an id of the database's catalog
// ("corrupt.settings-order-key" with the key as its argument, or
// "corrupt.settings-order-incomplete").
std::pair<std::string, std::vector<std::string>> orderSettings(profile::MachineProfile& p,
                                                               const std::string& order);

} // namespace k528::db::revision
