// The transfer log of `k528 link push` and `pull` (docs/database.md,
// *Transfers*): each writes an entry in the shop's database — `--db
// LOCATION`, else $K528_DB, else the data folder's file (created on first
// use) — naming the database's machine (`--machine NAME`; for a machine file
// of a database machine, that machine), the line and what moved. A push for
// a database machine takes released programs only (transfer::checkReleased).
#pragma once

#include "args.h"
#include "db/database.h"
#include "link/client.h"
#include "transfer/transfer.h"

#include <optional>
#include <string>

namespace k528::cli {

class TransferRecord {
public:
    // The database of the log, and the machine: nullopt after printing why
    // (exit 2). `fileMachine`: the name a machine file gives.
    static std::optional<TransferRecord> open(const Args& args, const std::string& fileMachine,
                                              const std::string& line);
    // A push for a database machine: false after printing which programs are
    // not released (nothing is sent then).
    bool mayPush(const link::PushPlan& plan);
    void recordPush(const link::RegisterMap& map, const link::PushPlan& plan,
                    const link::PushReport& report, const link::LinkError& error);
    void recordPull(const link::RegisterMap& map, const link::PullResult& pulled,
                    const link::LinkError& error);

private:
    TransferRecord(db::Database db, transfer::Context where)
        : db_(std::move(db)), where_(std::move(where)) {}
    void record(const db::TransferEntry& e);
    db::Database db_;
    transfer::Context where_;
};

} // namespace k528::cli
