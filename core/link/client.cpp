#include "link/client.h"

#include "catalog/cparams.h"
#include "engine/program_check.h"
#include "profile/text_format.h"
#include "profile/validate.h"
#include "program/formatter.h"
#include "program/parser.h"

#include <algorithm>

namespace k528::link {

std::string exceptionText(int code) {
    switch (code) {
    case 1:
        return "exception 01: the controller does not know this function";
    case 2:
        return "exception 02: a register outside the controller's map (or a read-only one written)";
    case 3:
        return "exception 03: a value outside its range; nothing of the request was written";
    case 6:
        return "exception 06: the controller is not in F7 «РАБОТА С ПЭВМ» (УПРАВЛЕНИЕ ДАННЫМИ): "
               "select it on the K923 to write";
    default:
        return "exception " + std::to_string(code);
    }
}

std::string statusText(int status) {
    switch (status) {
    case 0:
        return "idle";
    case 1:
        return "ready";
    case 2:
        return "committed";
    case 16:
        return "the controller is not in F7 «РАБОТА С ПЭВМ»";
    case 17:
        return "no such program in the controller";
    case 18:
        return "the controller refused the text";
    case 19:
        return "CRC or length mismatch: the text arrived damaged and was not stored";
    case 20:
        return "the controller's memory is full";
    default:
        return "status " + std::to_string(status);
    }
}

template <class F> LinkError Link::retry(const std::string& what, F&& f) {
    Reply last;
    for (int attempt = 0; attempt < attempts_; ++attempt) {
        if (attempt > 0)
            ++stats_.retries;
        last = f();
        switch (last.kind) {
        case Reply::Kind::Ok:
            ++stats_.exchanges;
            return {};
        case Reply::Kind::Exception:
            ++stats_.exchanges;
            ++stats_.exceptions;
            return {last.exception == 6 ? LinkError::Kind::NotReady : LinkError::Kind::Exception,
                    last.exception, what + ": " + exceptionText(last.exception)};
        case Reply::Kind::NoAnswer:
            ++stats_.noAnswer;
            break;
        case Reply::Kind::BadReply:
            ++stats_.badReplies;
            break;
        }
    }
    return {LinkError::Kind::NoAnswer, 0,
            what + ": the controller does not answer (" + std::to_string(attempts_) + " attempts" +
                (last.detail.empty() ? "" : ", last: " + last.detail) + ")"};
}

LinkError Link::read(int first, int count, std::vector<std::uint16_t>& out) {
    out.clear();
    std::vector<std::uint16_t> part;
    for (int at = first; at < first + count; at += map_.maxRead) {
        const int n = std::min(map_.maxRead, first + count - at);
        LinkError e = retry("reading registers " + std::to_string(at) + ".." + std::to_string(at + n - 1), [&] {
            Reply r = t_.read(at, n, part);
            if (r.ok() && static_cast<int>(part.size()) != n)
                return Reply::bad("reply of " + std::to_string(part.size()) + " registers, " + std::to_string(n) + " asked");
            return r;
        });
        if (e)
            return e;
        out.insert(out.end(), part.begin(), part.end());
    }
    return {};
}

LinkError Link::write(int first, std::span<const std::uint16_t> values) {
    // Chunks of an even count, so a 32-bit value never splits across two writes.
    const int chunk = map_.maxWrite - map_.maxWrite % 2;
    const int count = static_cast<int>(values.size());
    for (int i = 0; i < count; i += chunk) {
        const int n = std::min(chunk, count - i);
        LinkError e = retry("writing registers " + std::to_string(first + i) + ".." + std::to_string(first + i + n - 1),
                            [&] { return t_.write(first + i, values.subspan(static_cast<std::size_t>(i), static_cast<std::size_t>(n))); });
        if (e)
            return e;
    }
    return {};
}

LinkError Link::writeRead(int writeFirst, std::span<const std::uint16_t> values, int readFirst,
                          int readCount, std::vector<std::uint16_t>& out) {
    return retry("reading registers " + std::to_string(readFirst) + ".." + std::to_string(readFirst + readCount - 1), [&] {
        Reply r = t_.writeRead(writeFirst, values, readFirst, readCount, out);
        if (r.ok() && static_cast<int>(out.size()) != readCount)
            return Reply::bad("reply of " + std::to_string(out.size()) + " registers, " + std::to_string(readCount) + " asked");
        return r;
    });
}

LinkError Link::echo(std::uint16_t value) {
    return retry("echo", [&] { return t_.echo(value); });
}

LiveState decodeLive(const RegisterMap& map, std::span<const std::uint16_t> regs) {
    const LiveLayout& L = map.live;
    const int base = map.block(BlockKind::Live).first;
    auto at = [&](int reg) -> std::uint16_t {
        const auto i = static_cast<std::size_t>(reg - base);
        return i < regs.size() ? regs[i] : 0;
    };
    auto i32 = [&](int reg) { return joinSigned(at(reg), at(reg + 1)); };
    LiveState s;
    s.mode = at(L.mode);
    const std::uint16_t f = at(L.flags);
    s.pcReady = f & 1u;
    s.running = f & 2u;
    s.alarm = f & 4u;
    s.homedX = f & 8u;
    s.homedZ = f & 16u;
    s.program = at(L.program);
    s.frame = at(L.frame);
    s.overridePercent = at(L.overridePct);
    s.xCurrent = i32(L.xCurrent);
    s.zCurrent = i32(L.zCurrent);
    s.xMachine = i32(L.xMachine);
    s.zMachine = i32(L.zMachine);
    s.xError = i32(L.xError);
    s.zError = i32(L.zError);
    for (int w = 0; w < L.alarmWords; ++w)
        for (int b = 0; b < 16; ++b)
            if ((at(L.alarms + w) >> b) & 1u)
                s.alarms.push_back(w * 16 + b + 1);
    s.message = at(L.message);
    for (int w = 0; w < L.programWords; ++w)
        for (int b = 0; b < 16; ++b)
            if (((at(L.programs + w) >> b) & 1u) && w * 16 + b + 1 <= 99)
                s.programs.push_back(w * 16 + b + 1);
    return s;
}

LinkError readLive(Link& link, LiveState& out) {
    const Block& lb = link.map().block(BlockKind::Live);
    std::vector<std::uint16_t> regs;
    if (LinkError e = link.read(lb.first, lb.count(), regs))
        return e;
    out = decodeLive(link.map(), regs);
    return {};
}

LinkError identify(Link& link, LiveState& out) {
    if (LinkError e = link.echo(0x4B35))
        return e;
    return readLive(link, out);
}

namespace {

LinkError readTextOnce(Link& link, bool messages, int program, std::string& text) {
    const TransferLayout& T = link.map().transfer;
    if (messages) {
        const std::uint16_t cmd[] = {static_cast<std::uint16_t>(TransferCommand::ReadMessages)};
        if (LinkError e = link.write(T.command, cmd))
            return e;
    } else {
        const std::uint16_t cmd[] = {static_cast<std::uint16_t>(TransferCommand::ReadProgram),
                                     static_cast<std::uint16_t>(program)};
        if (LinkError e = link.write(T.command, cmd))
            return e;
    }
    std::vector<std::uint16_t> head;
    if (LinkError e = link.read(T.status, T.offset + 2 - T.status, head))
        return e;
    const int status = head[0];
    if (status != static_cast<int>(TransferStatus::Ready))
        return {LinkError::Kind::Refused, status,
                (messages ? std::string("messages") : "program " + std::to_string(program)) + ": " + statusText(status)};
    const auto length = static_cast<std::uint32_t>(joinSigned(head[static_cast<std::size_t>(T.length - T.status)],
                                                              head[static_cast<std::size_t>(T.length + 1 - T.status)]));
    const auto crc = static_cast<std::uint32_t>(joinSigned(head[static_cast<std::size_t>(T.crc - T.status)],
                                                           head[static_cast<std::size_t>(T.crc + 1 - T.status)]));
    if (length > T.capacityBytes)
        return {LinkError::Kind::Verify, 0, "the controller announces a text of " + std::to_string(length) + " bytes"};
    text.clear();
    text.reserve(length);
    std::vector<std::uint16_t> window;
    for (std::uint32_t off = 0; off < length; off += static_cast<std::uint32_t>(T.windowBytes)) {
        const std::size_t bytes = std::min<std::size_t>(static_cast<std::size_t>(T.windowBytes), length - off);
        const std::uint16_t offReg[] = {lowWord(off), highWord(off)};
        if (LinkError e = link.writeRead(T.offset, offReg, T.window, static_cast<int>((bytes + 1) / 2), window))
            return e;
        appendRegisterText(text, window, bytes);
    }
    if (crc32(text) != crc)
        return {LinkError::Kind::Verify, 19, "the text read does not match its CRC-32"};
    return {};
}

} // namespace

LinkError readText(Link& link, bool messages, int program, std::string& text) {
    LinkError e;
    for (int attempt = 0; attempt < 3; ++attempt) {
        e = readTextOnce(link, messages, program, text);
        if (e.kind != LinkError::Kind::Verify)
            return e;
    }
    return e;
}

namespace {

LinkError writeTextOnce(Link& link, bool messages, int program, const std::string& text) {
    const TransferLayout& T = link.map().transfer;
    const std::string what = messages ? std::string("messages") : "program " + std::to_string(program);
    const auto length = static_cast<std::uint32_t>(text.size());
    const std::uint32_t crc = crc32(text);
    const std::uint16_t head[] = {lowWord(length), highWord(length), lowWord(crc), highWord(crc)};
    if (LinkError e = link.write(T.length, head))
        return e;
    const std::uint16_t begin[] = {
        static_cast<std::uint16_t>(messages ? TransferCommand::WriteMessages : TransferCommand::WriteProgram),
        static_cast<std::uint16_t>(messages ? 1 : program)};
    if (LinkError e = link.write(T.command, begin))
        return e;
    std::vector<std::uint16_t> st;
    if (LinkError e = link.read(T.status, 2, st))
        return e;
    if (st[0] != static_cast<int>(TransferStatus::Ready))
        return {LinkError::Kind::Refused, st[0], what + ": " + statusText(st[0])};
    const std::vector<std::uint16_t> regs = textRegisters(text);
    std::vector<std::uint16_t> frame;
    for (std::uint32_t off = 0; off < length; off += static_cast<std::uint32_t>(T.windowBytes)) {
        const std::size_t first = off / 2;
        const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(T.windowRegisters()), regs.size() - first);
        frame.assign({lowWord(off), highWord(off)});
        frame.insert(frame.end(), regs.begin() + static_cast<std::ptrdiff_t>(first),
                     regs.begin() + static_cast<std::ptrdiff_t>(first + n));
        if (T.window != T.offset + 2)
            return {LinkError::Kind::Exception, 0, "the map's window does not follow its offset"};
        if (LinkError e = link.write(T.offset, frame))
            return e;
    }
    const std::uint16_t commit[] = {static_cast<std::uint16_t>(TransferCommand::Commit)};
    const std::int64_t retriesBefore = link.stats().retries;
    LinkError ce = link.write(T.command, commit);
    // A commit whose answer was lost and was sent again finds nothing to
    // commit (exception 03): the status tells what the first one did.
    if (ce && !(ce.kind == LinkError::Kind::Exception && ce.code == 3 && link.stats().retries > retriesBefore))
        return ce;
    if (LinkError e = link.read(T.status, 2, st))
        return e;
    if (st[0] != static_cast<int>(TransferStatus::Committed)) {
        std::string m = what + ": " + statusText(st[0]);
        if (st[0] == static_cast<int>(TransferStatus::TextRefused))
            m += " at line " + std::to_string(st[1]);
        return {LinkError::Kind::Refused, st[0], m};
    }
    std::string back;
    if (LinkError e = readText(link, messages, program, back))
        return e;
    if (back != text)
        return {LinkError::Kind::Verify, 0, what + ": the text read back differs from the text sent"};
    return {};
}

} // namespace

LinkError writeText(Link& link, bool messages, int program, const std::string& text) {
    LinkError e;
    for (int attempt = 0; attempt < 3; ++attempt) {
        e = writeTextOnce(link, messages, program, text);
        // A damaged text (19) is sent again; anything else is final.
        if (!(e.kind == LinkError::Kind::Refused && e.code == static_cast<int>(TransferStatus::CrcMismatch)))
            return e;
    }
    return e;
}

LinkError pull(Link& link, PullResult& out, const Progress& progress) {
    const RegisterMap& map = link.map();
    auto step = [&](const std::string& what, int done, int total) {
        if (progress)
            progress(what, done, total);
    };
    const Block& cb = map.block(BlockKind::C);
    std::vector<std::uint16_t> regs;
    step("C-parameters", 0, 1);
    if (LinkError e = link.read(cb.first, cb.count(), regs))
        return e;
    out.c = unpackC(map, regs);
    step("R-parameters", 0, 1);
    if (LinkError e = link.read(map.rFirst, 2 * map.rCount, regs))
        return e;
    out.r.fill(0);
    for (int i = 0; i < map.rCount && i < 300; ++i)
        out.r[static_cast<std::size_t>(i)] = joinSigned(regs[static_cast<std::size_t>(2 * i)], regs[static_cast<std::size_t>(2 * i + 1)]);
    LiveState live;
    if (LinkError e = readLive(link, live))
        return e;
    out.programs.clear();
    const int total = static_cast<int>(live.programs.size());
    int done = 0;
    for (int p : live.programs) {
        step("program " + std::to_string(p), done++, total);
        std::string text;
        if (LinkError e = readText(link, false, p, text))
            return e;
        out.programs[p] = std::move(text);
    }
    step("messages", 0, 1);
    return readText(link, true, 0, out.messagesText);
}

profile::MachineProfile pulledProfile(const PullResult& p, const std::string& name, const std::string& title) {
    profile::MachineProfile m;
    m.name = name;
    m.title = title;
    for (int n = 1; n <= catalog::kCParamCount && n < static_cast<int>(p.c.size()); ++n)
        m.c[static_cast<std::size_t>(n)] = p.c[static_cast<std::size_t>(n)];
    for (int i = 0; i < 300; ++i)
        if (p.r[static_cast<std::size_t>(i)] != 0 && !(i >= program::kFirstReadOnlyR && i <= program::kLastReadOnlyR))
            m.r[i] = p.r[static_cast<std::size_t>(i)];
    m.programs = p.programs;
    const program::ParseResult msg = program::parse(p.messagesText);
    for (const program::Message& e : msg.store.messages.entries)
        m.messages[e.number] = e.text;
    return m;
}

LinkError push(Link& link, const profile::MachineProfile& file, PushReport& report, const Progress& progress) {
    const RegisterMap& map = link.map();
    auto step = [&](const std::string& what, int done, int total) {
        if (progress)
            progress(what, done, total);
    };
    // 1. The file, before anything is sent.
    for (int n = 1; n <= catalog::kCParamCount; ++n)
        if (const std::string e = profile::checkCValue(n, file.c[static_cast<std::size_t>(n)]); !e.empty())
            return {LinkError::Kind::Input, 0, "C" + std::to_string(n) + " (" + std::string(catalog::cParam(n).name) +
                                                   "): " + e + " (table Е.1); nothing was sent"};
    for (const auto& [n, v] : file.r)
        if (n <= map.rWritableLast && (v < INT32_MIN || v > INT32_MAX))
            return {LinkError::Kind::Input, 0, "R" + std::to_string(n) + " is outside the 32-bit range; nothing was sent"};
    std::map<int, std::string> texts;
    for (const auto& [n, text] : file.programs) {
        program::ParseOptions po;
        po.programNumber = n;
        const program::ParseResult parsed = program::parse(text, po);
        for (const program::Diagnostic& d : parsed.diagnostics)
            if (d.isError())
                return {LinkError::Kind::Input, d.line,
                        "program " + std::to_string(n) + ", line " + std::to_string(d.line) + ": " + d.messageEn + "; nothing was sent"};
        if (parsed.store.size() != 1 || parsed.store.programs()[0].number != n)
            return {LinkError::Kind::Input, 0, "program " + std::to_string(n) + " does not hold exactly that program; nothing was sent"};
        program::ProgramStore one;
        one.insert(parsed.store.programs()[0]);
        texts[n] = program::format(one);
    }
    {
        program::ProgramStore none;
        const engine::FileCheck check = engine::checkFileForMachine(profile::programsFileText(file), {}, file, none);
        for (const program::Diagnostic& d : check.diagnostics)
            if (d.isError())
                return {LinkError::Kind::Input, d.line,
                        "program " + std::to_string(d.program) + ": " + d.messageEn + "; nothing was sent"};
    }
    std::string messagesText;
    if (!file.messages.empty()) {
        program::ProgramStore m;
        for (const auto& [k, t] : file.messages)
            m.messages.set(k, t);
        messagesText = program::format(m);
    }

    // 2. Only in F7 «РАБОТА С ПЭВМ».
    LiveState live;
    if (LinkError e = identify(link, live))
        return e;
    if (!live.pcReady)
        return {LinkError::Kind::NotReady, 6,
                "the controller is not in F7 «РАБОТА С ПЭВМ» (УПРАВЛЕНИЕ ДАННЫМИ, mode F" +
                    std::to_string(live.mode) + " now): select it on the K923, then push again; nothing was sent"};

    // 3. C-parameters, written and read back.
    step("C-parameters", 0, 1);
    const Block& cb = map.block(BlockKind::C);
    const std::vector<std::uint16_t> cRegs = packC(map, file.c);
    if (LinkError e = link.write(cb.first, cRegs))
        return e;
    std::vector<std::uint16_t> back;
    if (LinkError e = link.read(cb.first, cb.count(), back))
        return e;
    if (back != cRegs)
        return {LinkError::Kind::Verify, 0, "C-parameters: the values read back differ from those sent"};
    report.constants = true;

    // 4. R0..R149.
    step("R-parameters", 0, 1);
    std::vector<std::uint16_t> rRegs;
    for (int i = 0; i <= map.rWritableLast; ++i) {
        const auto it = file.r.find(i);
        const std::int64_t v = it == file.r.end() ? 0 : it->second;
        rRegs.push_back(lowWord(v));
        rRegs.push_back(highWord(v));
    }
    if (LinkError e = link.write(map.rFirst, rRegs))
        return e;
    if (LinkError e = link.read(map.rFirst, static_cast<int>(rRegs.size()), back))
        return e;
    if (back != rRegs)
        return {LinkError::Kind::Verify, 0, "R-parameters: the values read back differ from those sent"};
    report.rParameters = true;

    // 5. The messages (programs may show them), then each program.
    if (!messagesText.empty()) {
        step("messages", 0, 1);
        if (LinkError e = writeText(link, true, 0, messagesText))
            return e;
        report.messages = true;
    }
    int done = 0;
    for (const auto& [n, text] : texts) {
        step("program " + std::to_string(n), done++, static_cast<int>(texts.size()));
        if (LinkError e = writeText(link, false, n, text))
            return e;
        report.programs.push_back(n);
    }
    return {};
}

} // namespace k528::link
