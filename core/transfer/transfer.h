// Every transfer on record (docs/database.md, *Transfers*): the log entries
// of a push to and a pull from a controller, and the rule of what a push may
// take — the small API the command line's `k528 link push/pull` and the
// studio's Controller dock call around link::push / link::pull:
//
//   transfer::Context where{"grinder-205", revision, transfer::lineText(port, baud, 1, false)};
//   const auto check = transfer::checkReleased(db, "grinder-205", plan);
//   if (!check.allowed) refuse(check.message);               // nothing is sent
//   const link::LinkError e = link::push(l, plan, report);
//   transfer::identify(where, l, e);
//   db.recordTransfer(transfer::pushEntry(where, l.map(), plan, report, e));
//
// Pure functions of their inputs (no clock, no I/O) but checkReleased and
// releasedPlan, which read the database.
#pragma once

#include "db/database.h"
#include "link/client.h"
#include "link/register_map.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace k528::transfer {

// Where a transfer went: the database's machine ("" when none was named) and
// its revision, and the controller: its line and what it said it is.
struct Context {
    std::string machine;
    int revision = 0;
    std::string controller;
};

// The line as a database machine's `line` names it (cli.md) and the log
// records it: "serial:/dev/ttyUSB0?baud=115200&address=1", or for Modbus
// TCP (`port` HOST:PORT) "tcp://HOST:PORT/1".
std::string lineText(const std::string& port, int baud, int address, bool tcp);

// What the controller says it is (its FC 17 identity), "" when it does not.
std::string controllerIdentity(link::Link& link);

// After a transfer: the controller's identity added to where.controller
// ("LINE (IDENTITY)") — unless the line never answered (`error` NoAnswer)
// or the controller names none. `k528 link push/pull` and the studio's
// link call it before pushEntry/pullEntry.
void identify(Context& where, link::Link& link, const link::LinkError& error);

// "1a2b3c4d": a CRC-32 as the log keeps it.
std::string crcText(std::uint32_t crc);

// The entry of a push as it ended: each part of the plan (C, R, the
// messages, each program) with the CRC-32 of the bytes the controller checks
// and where the report says it ended (new, as it was, in doubt); result ok
// (no error), partial (an error after some part was new) or failed.
db::TransferEntry pushEntry(const Context& where, const link::RegisterMap& map,
                            const link::PushPlan& plan, const link::PushReport& report,
                            const link::LinkError& error);
// The entry of a pull: C, R, the messages and each program read (state
// "read"), or failed with the link's words.
db::TransferEntry pullEntry(const Context& where, const link::RegisterMap& map,
                            const link::PullResult& pulled, const link::LinkError& error);

// Whether a push of `plan` for the database's `machine` may go: each of its
// programs must be that machine's released version of the program (its
// SHA-256). The machine's setting `push.unreleased=true` lets a user who may
// act as k528_technologist push drafts too (on SQLite: everyone).
struct ReleaseCheck {
    bool allowed = true;
    std::vector<int> unreleased; // programs of the plan that are not released as they are
    bool overridden = false;     // unreleased ones allowed by the machine's setting
    // Why not, naming the programs and the command that releases them: ids
    // of core's database catalog (db/db_texts.h) with their arguments, a
    // line each.
    std::vector<db::ErrorText> why;
    // `why` in a language, its lines joined by "\n  ".
    std::string message(bool russian = false) const;
};
ReleaseCheck checkReleased(const db::Database& db, const std::string& machine,
                           const link::PushPlan& plan);

// A stored machine the controller would refuse (what(): English).
class PlanError : public std::runtime_error {
public:
    PlanError(std::string machine, link::LinkError error);
    // "machine NAME: the link's words" in a language.
    std::string text(bool russian) const;

private:
    std::string machine_;
    link::LinkError error_;
};

// A push of the database's machine as released: its C, R and messages of
// the current revision, its programs in their released versions only
// (drafts and withdrawn ones left out). Throws db::Error; link errors of
// planning (a stored machine the controller would refuse) as PlanError.
link::PushPlan releasedPlan(const db::Database& db, const std::string& machine,
                            const link::RegisterMap& map, int* revision = nullptr);

} // namespace k528::transfer
