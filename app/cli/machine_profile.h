// The machine profile a command runs or checks against: `--profile NAME|PATH`
// (default training-lathe) with `--db PATH` (default db::defaultDatabasePath()).
// A machine of that name in the database comes first — the shop's constants,
// as `k528 db set` left them —, then a built-in profile, then a machine file
// (db::loadProfile). A missing database is not an error; a damaged one is.
#pragma once

#include "args.h"
#include "profile/profile.h"

#include <optional>

namespace k528::cli {

// The profile, or nullopt after printing "k528: <why>" on stderr.
std::optional<profile::MachineProfile> machineProfile(const Args& args);

} // namespace k528::cli
