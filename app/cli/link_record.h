// The transfer log of `k528 link push` and `pull` (docs/database.md,
// *Transfers on record*): each writes an entry in the shop's database —
// `--db LOCATION`, else $K528_DB, else the data folder's file (created on
// first use) — naming the line, the database's machine (`--machine NAME`)
// and what moved. A push for a database machine (`--machine`) takes its
// released programs only (transfer::checkReleased); `push --machine NAME`
// without a file pushes the machine as released (transfer::releasedPlan).
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
    // The log's database and the machine. A database the user named (--db,
    // $K528_DB) or a machine (--machine) must be usable: false after saying
    // why (nothing may be sent then). The default database that cannot be
    // opened only costs the record: a warning, `record` stays empty, true.
    // `ru`: the command's --lang.
    static bool open(const Args& args, const std::string& line, bool ru, std::optional<TransferRecord>& record);

    const std::string& machine() const { return where_.machine; }
    // The database machine as released, for `push --machine NAME` without a
    // file: false after saying why.
    bool releasedPlan(link::PushPlan& plan);
    // A push for a database machine: false after printing which programs are
    // not released (nothing is sent then).
    bool mayPush(const link::PushPlan& plan);
    // The entry of a transfer as it ended (transfer::identify names the
    // controller), written like the studio's link writes its own.
    void recordPush(link::Link& l, const link::PushPlan& plan, const link::PushReport& report,
                    const link::LinkError& error);
    void recordPull(link::Link& l, const link::PullResult& pulled, const link::LinkError& error);

private:
    TransferRecord(db::Database db, transfer::Context where, bool ru)
        : db_(std::move(db)), where_(std::move(where)), ru_(ru) {}
    void record(const db::TransferEntry& e);
    db::Database db_;
    transfer::Context where_;
    bool ru_ = true;
};

} // namespace k528::cli
