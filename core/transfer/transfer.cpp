#include "transfer/transfer.h"

#include "db/db_texts.h"

#include "db/sha256.h"

#include <cstdio>
#include <stdexcept>

namespace k528::transfer {

std::string crcText(std::uint32_t crc) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%08x", crc);
    return buf;
}

std::string lineText(const std::string& port, int baud, int address, bool tcp) {
    if (tcp)
        return "tcp://" + port + "/" + std::to_string(address);
    return "serial:" + port + "?baud=" + std::to_string(baud) + "&address=" + std::to_string(address);
}

std::string controllerIdentity(link::Link& link) {
    link::ServerId id;
    if (link.serverId(id))
        return {};
    return id.data;
}

void identify(Context& where, link::Link& link, const link::LinkError& error) {
    if (error.kind == link::LinkError::Kind::NoAnswer)
        return;
    const std::string identity = controllerIdentity(link);
    if (!identity.empty())
        where.controller += " (" + identity + ")";
}

namespace {

std::string stateText(link::PushReport::State s) {
    switch (s) {
    case link::PushReport::State::New: return "new";
    case link::PushReport::State::InDoubt: return "in-doubt";
    case link::PushReport::State::AsItWas: break;
    }
    return "as-it-was";
}

// The CRC-32 of a block as its staged registers go to the controller.
std::string blockCrc(const link::RegisterMap& map, link::BlockKind kind,
                     const std::vector<std::uint16_t>& whole) {
    return crcText(link::registersCrc(link::stagedRegisters(map, kind, whole)));
}

std::vector<std::uint16_t> rRegisters(const link::RegisterMap& map,
                                      const std::array<std::int32_t, 300>& r) {
    std::vector<std::uint16_t> regs;
    for (int i = 0; i < map.rCount; ++i) {
        const std::int32_t v = i < 300 ? r[static_cast<std::size_t>(i)] : 0;
        regs.push_back(link::lowWord(v));
        regs.push_back(link::highWord(v));
    }
    return regs;
}

db::TransferItem programItem(int n, const std::string& text, std::string state) {
    return db::TransferItem{"program", n, crcText(link::crc32(text)), db::sha256Hex(text),
                            std::move(state)};
}

db::TransferEntry entry(const Context& where, const char* direction) {
    db::TransferEntry e;
    e.machine = where.machine;
    e.revision = where.revision;
    e.controller = where.controller;
    e.direction = direction;
    return e;
}

} // namespace

db::TransferEntry pushEntry(const Context& where, const link::RegisterMap& map,
                            const link::PushPlan& plan, const link::PushReport& report,
                            const link::LinkError& error) {
    db::TransferEntry e = entry(where, "push");
    for (const link::PushReport::Part& part : report.parts) {
        const std::string state = stateText(part.state);
        if (part.name == "C-parameters")
            e.items.push_back({"c", 0, blockCrc(map, link::BlockKind::C, link::packC(map, plan.c)),
                               std::nullopt, state});
        else if (part.name.rfind("R-parameters", 0) == 0)
            e.items.push_back({"r", 0, blockCrc(map, link::BlockKind::R, rRegisters(map, plan.r)),
                               std::nullopt, state});
        else if (part.name == "messages")
            e.items.push_back({"messages", 0, crcText(link::crc32(plan.messagesText)), std::nullopt, state});
        else if (part.name.rfind("program ", 0) == 0) {
            const int n = std::stoi(part.name.substr(8));
            e.items.push_back(programItem(n, plan.programs.at(n), state));
        }
    }
    e.result = !error ? "ok" : report.anyNew() ? "partial" : "failed";
    e.detail = !error ? "written and verified" : error.text(false) + (report.parts.empty() ? "" : "; " + link::render(report.summary(), false));
    return e;
}

db::TransferEntry pullEntry(const Context& where, const link::RegisterMap& map,
                            const link::PullResult& pulled, const link::LinkError& error) {
    db::TransferEntry e = entry(where, "pull");
    if (error) {
        e.result = "failed";
        e.detail = error.text(false);
        return e;
    }
    e.items.push_back({"c", 0, blockCrc(map, link::BlockKind::C, link::packC(map, pulled.c)),
                       std::nullopt, "read"});
    e.items.push_back({"r", 0, blockCrc(map, link::BlockKind::R, rRegisters(map, pulled.r)),
                       std::nullopt, "read"});
    e.items.push_back({"messages", 0, crcText(link::crc32(pulled.messagesText)), std::nullopt, "read"});
    for (const auto& [n, text] : pulled.programs)
        e.items.push_back(programItem(n, text, "read"));
    e.result = "ok";
    e.detail = "read " + std::to_string(pulled.programs.size()) + " programs, C, R and the messages";
    return e;
}

ReleaseCheck checkReleased(const db::Database& db, const std::string& machine,
                           const link::PushPlan& plan) {
    ReleaseCheck check;
    const auto releases = db.programReleases(machine);
    std::vector<db::ErrorText> lines;
    for (const auto& [n, text] : plan.programs) {
        const db::ProgramRelease* r = nullptr;
        for (const auto& p : releases)
            if (p.number == n)
                r = &p;
        if (r && r->releasedSha256 && *r->releasedSha256 == db::sha256Hex(text))
            continue;
        check.unreleased.push_back(n);
        const std::string number = std::to_string(n);
        if (!r)
            lines.push_back({"push.not-in-database", {number}});
        else if (!r->releasedRevision)
            lines.push_back({r->state == db::ProgramState::Withdrawn ? "push.withdrawn" : "push.draft", {number}});
        else
            lines.push_back({"push.not-released-version", {number, std::to_string(*r->releasedRevision)}});
    }
    if (check.unreleased.empty())
        return check;
    const profile::MachineProfile p = db.loadMachine(machine);
    bool settingAllows = false;
    try {
        settingAllows = p.simulation.getBool("push.unreleased", false);
    } catch (const profile::SettingError&) {
    }
    if (settingAllows && db.mayActAs("k528_technologist")) {
        check.overridden = true;
        return check;
    }
    check.allowed = false;
    check.why.push_back({"push.unreleased", {machine}});
    check.why.insert(check.why.end(), lines.begin(), lines.end());
    check.why.push_back({settingAllows ? "push.release-them.technologist" : "push.release-them", {machine}});
    return check;
}

std::string ReleaseCheck::message(bool russian) const {
    std::string s;
    for (std::size_t i = 0; i < why.size(); ++i) {
        // The programs indented under the first line, the way out on the last.
        s += i == 0 ? "" : i + 1 == why.size() ? "\n" : "\n  ";
        s += db::renderText(why[i], russian);
    }
    return s;
}

PlanError::PlanError(std::string machine, link::LinkError error)
    : std::runtime_error(db::dbText("machine.said", std::vector<std::string>{machine, error.text(false)}, false)),
      machine_(std::move(machine)), error_(std::move(error)) {}

std::string PlanError::text(bool russian) const {
    return db::dbText("machine.said", std::vector<std::string>{machine_, error_.text(russian)}, russian);
}

link::PushPlan releasedPlan(const db::Database& db, const std::string& machine,
                            const link::RegisterMap& map, int* revision) {
    profile::MachineProfile p = db.loadMachine(machine);
    const int rev = db.machine(machine)->revision;
    p.programs.clear();
    for (const db::ProgramRelease& r : db.programReleases(machine))
        if (r.releasedRevision)
            if (const auto text = db.programText(machine, r.number, *r.releasedRevision))
                p.programs[r.number] = *text;
    link::PushPlan plan;
    if (const link::LinkError e = link::planMachineFile(map, p, plan))
        throw PlanError(machine, e);
    if (revision)
        *revision = rev;
    return plan;
}

} // namespace k528::transfer
