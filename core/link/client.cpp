#include "link/client.h"

#include "link/image.h"
#include "link/modbus.h"

#include "catalog/cparams.h"
#include "engine/program_check.h"
#include "program/diagnostic_texts.h"
#include "profile/text_format.h"
#include "profile/validate.h"
#include "program/formatter.h"
#include "program/parser.h"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <set>

namespace k528::link {

Said exceptionSaid(int code) {
    switch (code) {
    case 1:
    case 2:
    case 3:
    case 6:
        return say("link.exception-" + std::to_string(code));
    default:
        return say("link.exception", {std::to_string(code)});
    }
}

Said statusSaid(int status) {
    switch (status) {
    case 0:
    case 1:
    case 2:
    case 16:
    case 17:
    case 18:
    case 19:
    case 20:
        return say("link.status-" + std::to_string(status));
    default:
        return say("link.status", {std::to_string(status)});
    }
}

void RoundTrips::add(double ms) {
    last_ = ms;
    ++count_;
    if (ring_.size() < kCapacity) {
        ring_.push_back(static_cast<float>(ms));
        return;
    }
    ring_[next_] = static_cast<float>(ms);
    next_ = (next_ + 1) % kCapacity;
}

double RoundTrips::quantile(double q) const {
    if (ring_.empty())
        return 0;
    std::vector<float> v = ring_;
    const auto k = static_cast<std::size_t>(std::min<double>(static_cast<double>(v.size()) - 1,
                                                             std::ceil(q * static_cast<double>(v.size())) - 1));
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
    return v[k];
}

std::string describe(const LineStats& s, bool ru) {
    auto n = [&](std::int64_t v, const char* one, const char* many) {
        return render(say(v == 1 ? one : many, {std::to_string(v)}), ru);
    };
    std::string t = n(s.exchanges, "link.stats-answer", "link.stats-answers") + ", " +
                    n(s.noAnswer, "link.stats-timeout", "link.stats-timeouts") + ", " +
                    n(s.crcErrors, "link.stats-crc-error", "link.stats-crc-errors") + ", " +
                    n(s.badReplies, "link.stats-bad-reply", "link.stats-bad-replies") + ", " +
                    n(s.exceptions, "link.stats-exception", "link.stats-exceptions");
    if (!s.exceptionsByCode.empty()) {
        t += " (";
        bool first = true;
        for (const auto& [code, count] : s.exceptionsByCode) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%s%02d×%lld", first ? "" : ", ", code, static_cast<long long>(count));
            t += buf;
            first = false;
        }
        t += ")";
    }
    t += ", " + n(s.retries, "link.stats-retry", "link.stats-retries");
    if (s.splits > 0)
        t += ", " + n(s.splits, "link.stats-split", "link.stats-splits");
    if (s.roundTrip.count() > 0) {
        char median[32], p95[32];
        std::snprintf(median, sizeof median, "%.1f", s.roundTrip.median());
        std::snprintf(p95, sizeof p95, "%.1f", s.roundTrip.p95());
        t += render(say("link.stats-round-trip", {median, p95}), ru);
    }
    return t;
}

void Link::count(const Reply& r, bool again) {
    for (LineStats* s : {&total_, &stations_[t_.station()]}) {
        if (again)
            ++s->retries;
        switch (r.kind) {
        case Reply::Kind::Ok:
            ++s->exchanges;
            break;
        case Reply::Kind::Exception:
            ++s->exchanges;
            ++s->exceptions;
            ++s->exceptionsByCode[r.exception];
            break;
        case Reply::Kind::NoAnswer:
            ++s->noAnswer;
            break;
        case Reply::Kind::Damaged:
            ++s->crcErrors;
            break;
        case Reply::Kind::BadReply:
            ++s->badReplies;
            break;
        }
        if ((r.kind == Reply::Kind::Ok || r.kind == Reply::Kind::Exception) && r.roundTripMs >= 0)
            s->roundTrip.add(r.roundTripMs);
    }
}

namespace {

// A transport's word on the last attempt (English: the frame log's): the
// fixed ones by their ids, the port's or the connection's failure with the
// line's failure after it (a plugin's id, else the system's own words), any
// other said by its kind in Russian.
Said detailSaid(const Reply& r) {
    static const std::pair<const char*, const char*> kFixed[] = {
        {"timeout", "link.timeout"},
        {"CRC error", "link.crc-error"},
        {"the port is closed", "link.port-closed"},
        {"the connection is closed", "link.connection-closed"},
        {"the echo differs", "link.echo-differs"},
        {"an empty answer", "link.empty-answer"},
    };
    static const std::pair<const char*, const char*> kPrefixed[] = {
        {"the port is closed and does not open again: ", "link.port-reopen"},
        {"the port failed: ", "link.port-failed"},
        {"the connection is closed and does not open again: ", "link.connection-reopen"},
        {"the connection failed: ", "link.connection-failed"},
    };
    for (const auto& [en, id] : kFixed)
        if (r.detail == en)
            return say(id);
    for (const auto& [en, id] : kPrefixed)
        if (r.detail.rfind(en, 0) == 0)
            return say(id, {decodeSaid(std::string_view(r.detail).substr(std::char_traits<char>::length(en)))});
    switch (r.kind) {
    case Reply::Kind::Damaged:
        return say("link.damaged", {r.detail});
    case Reply::Kind::BadReply:
        return say("link.bad-reply", {r.detail});
    default:
        return say("link.lost", {r.detail});
    }
}

} // namespace

template <class F> LinkError Link::retry(const Said& what, F&& f) {
    Reply last;
    lastDamaged_ = false;
    for (int attempt = 0; attempt < attempts_; ++attempt) {
        last = f();
        count(last, attempt > 0);
        lastDamaged_ = lastDamaged_ || last.kind == Reply::Kind::Damaged || last.kind == Reply::Kind::BadReply;
        switch (last.kind) {
        case Reply::Kind::Ok:
            return {};
        case Reply::Kind::Exception:
            return linkError(last.exception == 6 ? LinkError::Kind::NotReady : LinkError::Kind::Exception,
                             last.exception, say("link.join", {what, exceptionSaid(last.exception)}));
        default:
            break;
        }
    }
    const std::string n = std::to_string(attempts_);
    if (last.detail.empty())
        return linkError(LinkError::Kind::NoAnswer, 0,
                         attempts_ == 1 ? say("link.no-answer-1", {what}) : say("link.no-answer", {what, n}));
    return linkError(LinkError::Kind::NoAnswer, 0,
                     attempts_ == 1 ? say("link.no-answer-1-last", {what, detailSaid(last)})
                                    : say("link.no-answer-last", {what, n, detailSaid(last)}));
}

// A piece of a request that every attempt lost, while the line did answer
// (damaged frames, not only silence), goes again as two halves: on a line
// that damages one frame in a few, a long frame fails four times far more
// often than two short ones (at least kMinPiece registers each).
namespace {
constexpr int kMinPiece = 8;
bool worthSplitting(const LinkError& e, bool damaged, int n) {
    return e.kind == LinkError::Kind::NoAnswer && damaged && n >= 2 * kMinPiece;
}
} // namespace

LinkError Link::readPiece(int at, int n, std::vector<std::uint16_t>& out) {
    std::vector<std::uint16_t> part;
    const std::string range = std::to_string(at) + ".." + std::to_string(at + n - 1);
    LinkError e = retry(say("link.reading", {range}), [&] {
        Reply r = t_.read(at, n, part);
        if (r.ok() && static_cast<int>(part.size()) != n)
            return Reply::bad("reply of " + std::to_string(part.size()) + " registers, " + std::to_string(n) + " asked");
        return r;
    });
    if (worthSplitting(e, lastDamaged_, n)) {
        ++total_.splits;
        const int half = (n / 2) & ~1;
        if (LinkError h = readPiece(at, half, out))
            return h;
        return readPiece(at + half, n - half, out);
    }
    if (!e)
        out.insert(out.end(), part.begin(), part.end());
    return e;
}

LinkError Link::read(int first, int count, std::vector<std::uint16_t>& out) {
    out.clear();
    for (int at = first; at < first + count; at += map_.maxRead)
        if (LinkError e = readPiece(at, std::min(map_.maxRead, first + count - at), out))
            return e;
    return {};
}

LinkError Link::writePiece(int first, std::span<const std::uint16_t> values) {
    const int n = static_cast<int>(values.size());
    const std::string range = std::to_string(first) + ".." + std::to_string(first + n - 1);
    LinkError e = retry(say("link.writing", {range}),
                        [&] { return t_.write(first, values); });
    if (worthSplitting(e, lastDamaged_, n)) {
        ++total_.splits;
        const int half = (n / 2) & ~1; // even: a 32-bit value stays in one write
        if (LinkError h = writePiece(first, values.first(static_cast<std::size_t>(half))))
            return h;
        return writePiece(first + half, values.subspan(static_cast<std::size_t>(half)));
    }
    return e;
}

LinkError Link::write(int first, std::span<const std::uint16_t> values) {
    // Chunks of an even count, so a 32-bit value never splits across two writes.
    const int chunk = map_.maxWrite - map_.maxWrite % 2;
    const int count = static_cast<int>(values.size());
    for (int i = 0; i < count; i += chunk) {
        const int n = std::min(chunk, count - i);
        if (LinkError e = writePiece(first + i, values.subspan(static_cast<std::size_t>(i), static_cast<std::size_t>(n))))
            return e;
    }
    return {};
}

LinkError Link::writeRead(int writeFirst, std::span<const std::uint16_t> values, int readFirst,
                          int readCount, std::vector<std::uint16_t>& out) {
    std::vector<std::uint16_t> part;
    const std::string range = std::to_string(readFirst) + ".." + std::to_string(readFirst + readCount - 1);
    LinkError e = retry(say("link.reading", {range}), [&] {
        Reply r = t_.writeRead(writeFirst, values, readFirst, readCount, part);
        if (r.ok() && static_cast<int>(part.size()) != readCount)
            return Reply::bad("reply of " + std::to_string(part.size()) + " registers, " + std::to_string(readCount) + " asked");
        return r;
    });
    if (worthSplitting(e, lastDamaged_, readCount)) {
        // The same write before each half of the read (a window's offset, then part of the window).
        ++total_.splits;
        const int half = readCount / 2;
        std::vector<std::uint16_t> a, b;
        if (LinkError h = writeRead(writeFirst, values, readFirst, half, a))
            return h;
        if (LinkError h = writeRead(writeFirst, values, readFirst + half, readCount - half, b))
            return h;
        out = std::move(a);
        out.insert(out.end(), b.begin(), b.end());
        return {};
    }
    if (!e)
        out = std::move(part);
    return e;
}

LinkError Link::echo(std::uint16_t value) {
    return retry(say("link.echo"), [&] { return t_.echo(value); });
}

LinkError Link::diagnostics(std::uint16_t sub, std::uint16_t data, std::uint16_t& out) {
    return retry(say("link.diagnostics", {std::to_string(sub)}),
                 [&] { return t_.diagnostics(sub, data, out); });
}

LinkError Link::serverId(ServerId& out) {
    return retry(say("link.server-id"), [&] { return t_.serverId(out); });
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

Said notReadySaid(const LiveState& live, const Said& what) {
    if (live.mode == 7)
        return say("link.not-ready-menu", {what});
    if (live.mode >= 1 && live.mode <= 7)
        return say("link.not-ready-mode", {what, std::to_string(live.mode)});
    return say("link.not-ready-power", {what});
}

namespace {

// The part a transfer moves, in both languages.
Said textName(bool messages, int program) {
    return messages ? say("link.part-messages") : say("link.part-program", {std::to_string(program)});
}

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
        return linkError(LinkError::Kind::Refused, status, say("link.join", {textName(messages, program), statusSaid(status)}));
    const auto length = static_cast<std::uint32_t>(joinSigned(head[static_cast<std::size_t>(T.length - T.status)],
                                                              head[static_cast<std::size_t>(T.length + 1 - T.status)]));
    const auto crc = static_cast<std::uint32_t>(joinSigned(head[static_cast<std::size_t>(T.crc - T.status)],
                                                           head[static_cast<std::size_t>(T.crc + 1 - T.status)]));
    if (length > T.capacityBytes)
        return linkError(LinkError::Kind::Verify, 0,
                         say("link.text-length", {std::to_string(length)}));
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
        return linkError(LinkError::Kind::Verify, 19,
                         say("link.text-crc"));
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

// Sends the commit (7000 = 5) and reads the status it left. `commitSent`
// is set once the commit may have reached the controller; `committed` once
// the status says it took the transfer.
LinkError commitTransfer(Link& link, const Said& what, bool& commitSent, bool& committed) {
    const TransferLayout& T = link.map().transfer;
    const std::uint16_t commit[] = {static_cast<std::uint16_t>(TransferCommand::Commit)};
    const std::int64_t retriesBefore = link.stats().retries;
    commitSent = true;
    LinkError ce = link.write(T.command, commit);
    // A commit whose answer was lost and was sent again finds nothing to
    // commit (exception 03): the status tells what the first one did.
    if (ce && !(ce.kind == LinkError::Kind::Exception && ce.code == 3 && link.stats().retries > retriesBefore))
        return ce;
    std::vector<std::uint16_t> st;
    if (LinkError e = link.read(T.status, 2, st))
        return e;
    if (st[0] != static_cast<int>(TransferStatus::Committed)) {
        Said m = say("link.join", {what, statusSaid(st[0])});
        if (st[0] == static_cast<int>(TransferStatus::TextRefused))
            m = say("link.refused-at-line", {m, std::to_string(st[1])});
        LinkError e = linkError(LinkError::Kind::Refused, st[0], m);
        e.line = st[0] == static_cast<int>(TransferStatus::TextRefused) ? st[1] : 0;
        return e;
    }
    committed = true;
    return {};
}

// Begins a transfer into the controller (the text's or block's length and
// CRC, then `command`), sends `bytes` window by window (offset and text in
// one write), commits it and reads the status.
LinkError sendTransfer(Link& link, const Said& what, TransferCommand command, int program,
                       const std::string& bytes, bool& commitSent, bool& committed) {
    const TransferLayout& T = link.map().transfer;
    const auto length = static_cast<std::uint32_t>(bytes.size());
    const std::uint32_t crc = crc32(bytes);
    const std::uint16_t head[] = {lowWord(length), highWord(length), lowWord(crc), highWord(crc)};
    if (LinkError e = link.write(T.length, head))
        return e;
    std::vector<std::uint16_t> begin = {static_cast<std::uint16_t>(command)};
    if (command == TransferCommand::WriteProgram || command == TransferCommand::WriteMessages)
        begin.push_back(static_cast<std::uint16_t>(program));
    if (LinkError e = link.write(T.command, begin))
        return e;
    std::vector<std::uint16_t> st;
    if (LinkError e = link.read(T.status, 2, st))
        return e;
    if (st[0] != static_cast<int>(TransferStatus::Ready))
        return linkError(LinkError::Kind::Refused, st[0], say("link.join", {what, statusSaid(st[0])}));
    if (T.window != T.offset + 2)
        return linkError(LinkError::Kind::Exception, 0,
                         say("link.window-offset"));
    const std::vector<std::uint16_t> regs = textRegisters(bytes);
    std::vector<std::uint16_t> frame;
    for (std::uint32_t off = 0; off < length; off += static_cast<std::uint32_t>(T.windowBytes)) {
        const std::size_t first = off / 2;
        const std::size_t n = std::min<std::size_t>(static_cast<std::size_t>(T.windowRegisters()), regs.size() - first);
        frame.assign({lowWord(off), highWord(off)});
        frame.insert(frame.end(), regs.begin() + static_cast<std::ptrdiff_t>(first),
                     regs.begin() + static_cast<std::ptrdiff_t>(first + n));
        if (LinkError e = link.write(T.offset, frame))
            return e;
    }
    return commitTransfer(link, what, commitSent, committed);
}

LinkError writeTextOnce(Link& link, bool messages, int program, const std::string& text, bool& commitSent,
                        bool& committed) {
    const Said what = textName(messages, program);
    if (LinkError e = sendTransfer(link, what, messages ? TransferCommand::WriteMessages : TransferCommand::WriteProgram,
                                   messages ? 1 : program, text, commitSent, committed))
        return e;
    std::string back;
    if (LinkError e = readText(link, messages, program, back))
        return e;
    if (back != text)
        return linkError(LinkError::Kind::Verify, 0,
                         say("link.text-differs", {what}));
    return {};
}

// A damaged transfer (status 19) is sent again; anything else is final.
bool sendAgain(const LinkError& e) {
    return e.kind == LinkError::Kind::Refused && e.code == static_cast<int>(TransferStatus::CrcMismatch);
}

LinkError writeText(Link& link, bool messages, int program, const std::string& text, bool& commitSent,
                    bool& committed) {
    LinkError e;
    for (int attempt = 0; attempt < 3; ++attempt) {
        commitSent = committed = false;
        e = writeTextOnce(link, messages, program, text, commitSent, committed);
        if (!sendAgain(e))
            return e;
    }
    return e;
}

LinkError writeBlockOnce(Link& link, BlockKind kind, std::span<const std::uint16_t> whole, bool& commitSent,
                         bool& committed) {
    const RegisterMap& map = link.map();
    const Said what = say(kind == BlockKind::C ? "link.part-c" : "link.part-r");
    const std::vector<std::uint16_t> sent = stagedRegisters(map, kind, whole);
    if (LinkError e = sendTransfer(link, what, kind == BlockKind::C ? TransferCommand::StageC : TransferCommand::StageR,
                                   0, registerBytes(sent), commitSent, committed)) {
        if (e.kind == LinkError::Kind::Refused && e.code == static_cast<int>(TransferStatus::TextRefused)) {
            const Said m = kind == BlockKind::C && e.line > 0
                               ? say("link.block-refused-at", {what, std::to_string(e.line)})
                               : say("link.block-refused", {what});
            const int line = e.line;
            e = linkError(e.kind, e.code, m);
            e.line = line;
        }
        return e;
    }
    std::vector<std::uint16_t> back;
    const int first = kind == BlockKind::C ? map.block(BlockKind::C).first : map.rFirst;
    const int count = kind == BlockKind::C ? map.block(BlockKind::C).count() : 2 * (map.rWritableLast + 1);
    if (LinkError e = link.read(first, count, back))
        return e;
    if (stagedRegisters(map, kind, back) != sent)
        return linkError(LinkError::Kind::Verify, 0,
                         say("link.block-differs", {what}));
    return {};
}

} // namespace

LinkError writeText(Link& link, bool messages, int program, const std::string& text) {
    bool sent = false, committed = false;
    return writeText(link, messages, program, text, sent, committed);
}

LinkError writeBlock(Link& link, BlockKind kind, std::span<const std::uint16_t> whole, bool& committed,
                     bool& commitSent) {
    LinkError e;
    for (int attempt = 0; attempt < 3; ++attempt) {
        commitSent = committed = false;
        e = writeBlockOnce(link, kind, whole, commitSent, committed);
        if (!sendAgain(e))
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
    // The R-parameters the PC may write back (the memory a push restores);
    // the positioner's own and its status are not presets.
    for (int i = 0; i < 300; ++i)
        if (p.r[static_cast<std::size_t>(i)] != 0 && k528Map().rWritable(i))
            m.r[i] = p.r[static_cast<std::size_t>(i)];
    m.programs = p.programs;
    const program::ParseResult msg = program::parse(p.messagesText);
    for (const program::Message& e : msg.store.messages.entries)
        m.messages[e.number] = e.text;
    return m;
}

// --- push ------------------------------------------------------------------

Said PushReport::summary() const {
    Said out;
    for (State st : {State::New, State::InDoubt, State::AsItWas}) {
        Said names;
        for (const Part& p : parts)
            if (p.state == st)
                names = names.empty() ? p.said : say("link.list", {names, p.said});
        if (names.empty())
            continue;
        const Said part = say(st == State::New       ? "link.push-new"
                              : st == State::InDoubt ? "link.push-in-doubt"
                                                     : "link.push-as-it-was",
                              {names});
        out = out.empty() ? part : say("link.then", {out, part});
    }
    return out;
}

bool PushReport::anyNew() const {
    for (const Part& p : parts)
        if (p.state != State::AsItWas)
            return true;
    return false;
}

namespace {

std::string canonicalProgram(const program::Program& p) {
    program::ProgramStore one;
    one.insert(p);
    return program::format(one);
}

std::string canonicalMessages(const program::MessageTable& m) {
    program::ProgramStore only;
    only.messages = m;
    only.messages.present = true;
    return program::format(only);
}

// The programs in the order they can be committed: a program after those
// of the push it calls (the controller checks each text against the
// programs it holds at that moment), else by number.
std::vector<int> commitOrder(const std::map<int, std::string>& programs) {
    std::map<int, std::vector<int>> calls;
    for (const auto& [n, text] : programs) {
        program::ParseOptions po;
        po.programNumber = n;
        const program::ParseResult parsed = program::parse(text, po);
        for (const program::Program& p : parsed.store.programs())
            for (const program::Frame& f : p.frames)
                if (const auto t = f.body.callTarget(); t && *t != n && programs.count(*t))
                    calls[n].push_back(*t);
    }
    std::vector<int> order;
    std::set<int> done, visiting;
    std::function<void(int)> visit = [&](int n) {
        if (done.count(n) || visiting.count(n))
            return; // a cycle: the controller names it
        visiting.insert(n);
        for (int t : calls[n])
            visit(t);
        visiting.erase(n);
        done.insert(n);
        order.push_back(n);
    };
    for (const auto& [n, text] : programs)
        visit(n);
    return order;
}

LinkError inputError(int line, const Said& message) {
    return linkError(LinkError::Kind::Input, line, say("link.nothing-sent", {message}));
}

} // namespace

LinkError planMachineFile(const RegisterMap& map, const profile::MachineProfile& file, PushPlan& plan) {
    plan = {};
    for (int n = 1; n <= catalog::kCParamCount; ++n)
        if (const std::string e = profile::checkCValue(n, file.c[static_cast<std::size_t>(n)]); !e.empty())
            return inputError(0, say("link.c-table", {std::to_string(n), std::string(catalog::cParam(n).name),
                                                      saidProblem(profile::cValueProblem(n, file.c[static_cast<std::size_t>(n)]))}));
    plan.hasC = true;
    plan.c.assign(file.c.begin(), file.c.end());
    plan.hasR = true;
    for (const auto& [n, v] : file.r) {
        if (v < INT32_MIN || v > INT32_MAX)
            return inputError(0, say("link.r-outside", {std::to_string(n)}));
        if (n >= 0 && n < 300 && map.rWritable(n))
            plan.r[static_cast<std::size_t>(n)] = static_cast<std::int32_t>(v);
    }
    for (const auto& [n, text] : file.programs) {
        program::ParseOptions po;
        po.programNumber = n;
        const program::ParseResult parsed = program::parse(text, po);
        for (const program::Diagnostic& d : parsed.diagnostics)
            if (d.isError())
                return inputError(d.line, say("link.program-line",
                                              {std::to_string(n), std::to_string(d.line), saidDiagnostic(d)}));
        if (parsed.store.size() != 1 || parsed.store.programs()[0].number != n)
            return inputError(0, say("link.program-not-one", {std::to_string(n)}));
        plan.programs[n] = canonicalProgram(parsed.store.programs()[0]);
    }
    {
        program::ProgramStore none;
        const engine::FileCheck check = engine::checkFileForMachine(profile::programsFileText(file), {}, file, none);
        for (const program::Diagnostic& d : check.diagnostics)
            if (d.isError())
                return inputError(d.line, say("link.program-says", {std::to_string(d.program), saidDiagnostic(d)}));
    }
    if (!file.messages.empty()) {
        program::MessageTable m;
        for (const auto& [k, t] : file.messages)
            m.set(k, t);
        plan.hasMessages = true;
        plan.messagesText = canonicalMessages(m);
    }
    return {};
}

LinkError planProgramFile(Link& link, std::string_view text, const std::string& source, PushPlan& plan) {
    plan = {};
    const program::ParseResult parsed = program::parse(text);
    for (const program::Diagnostic& d : parsed.diagnostics)
        if (d.isError())
            return inputError(d.line, say("link.file-line", {source, std::to_string(d.line), saidDiagnostic(d)}));
    if (parsed.store.empty() && !parsed.store.messages.present)
        return inputError(0, say("link.file-empty", {source}));
    for (const program::Program& p : parsed.store.programs()) {
        if (p.headerLine == 0)
            return inputError(1, say("link.file-before-header", {source}));
        plan.programs[p.number] = canonicalProgram(p);
    }
    if (parsed.store.messages.present) {
        plan.hasMessages = true;
        plan.messagesText = canonicalMessages(parsed.store.messages);
    }
    // The controller checks each text at commit with its own constants,
    // R-parameters and programs: check the file the same way first, so a
    // file it would refuse sends nothing.
    const RegisterMap& map = link.map();
    const Block& cb = map.block(BlockKind::C);
    std::vector<std::uint16_t> regs;
    if (LinkError e = link.read(cb.first, cb.count(), regs))
        return e;
    profile::MachineProfile machine;
    const std::vector<std::int64_t> c = unpackC(map, regs);
    for (std::size_t n = 1; n < c.size() && n < machine.c.size(); ++n)
        machine.c[n] = c[n];
    if (LinkError e = link.read(map.rFirst, 2 * (map.rWritableLast + 1), regs))
        return e;
    for (int i = 0; i <= map.rWritableLast; ++i)
        if (const std::int32_t v = joinSigned(regs[2 * static_cast<std::size_t>(i)], regs[2 * static_cast<std::size_t>(i) + 1]))
            machine.r[i] = v;
    LiveState live;
    if (LinkError e = readLive(link, live))
        return e;
    program::ProgramStore store; // the controller's programs the file calls, and its messages
    std::set<int> called;
    for (const program::Program& p : parsed.store.programs())
        for (const program::Frame& f : p.frames)
            if (const auto target = f.body.callTarget(); target && !plan.programs.count(*target))
                called.insert(*target);
    for (int n : called) {
        if (std::find(live.programs.begin(), live.programs.end(), n) == live.programs.end())
            continue; // absent there too: the check names it
        std::string t;
        if (LinkError e = readText(link, false, n, t))
            return e;
        program::ParseOptions po;
        po.programNumber = n;
        const program::ParseResult theirs = program::parse(t, po);
        for (const program::Program& p : theirs.store.programs())
            store.insert(p);
    }
    if (!plan.hasMessages) {
        std::string t;
        if (LinkError e = readText(link, true, 0, t))
            return e;
        store.messages = program::parse(t).store.messages;
    }
    const engine::FileCheck check = engine::checkFileForMachine(text, {}, machine, store);
    for (const program::Diagnostic& d : check.diagnostics)
        if (d.isError())
            return inputError(d.line, say("link.file-controller", {source, std::to_string(d.line), saidDiagnostic(d)}));
    return {};
}

LinkError push(Link& link, const PushPlan& plan, PushReport& report, const Progress& progress) {
    const RegisterMap& map = link.map();
    auto step = [&](const std::string& what, int done, int total) {
        if (progress)
            progress(what, done, total);
    };
    report = {};
    if (plan.hasC)
        report.parts.push_back({"C-parameters", PushReport::State::AsItWas, say("link.part-c")});
    if (plan.hasR)
        report.parts.push_back({"R-parameters (" + map.rWritableText() + ")", PushReport::State::AsItWas,
                                say("link.part-r-range", {map.rWritableText()})});
    if (plan.hasMessages)
        report.parts.push_back({"messages", PushReport::State::AsItWas, say("link.part-messages")});
    const std::vector<int> order = commitOrder(plan.programs);
    for (int n : order)
        report.parts.push_back({"program " + std::to_string(n), PushReport::State::AsItWas,
                                say("link.part-program", {std::to_string(n)})});

    // Only in F7 «РАБОТА С ПЭВМ».
    LiveState live;
    if (LinkError e = identify(link, live))
        return e;
    if (!live.pcReady)
        return linkError(LinkError::Kind::NotReady, 6, notReadySaid(live, say("link.action-push")));

    std::size_t part = 0;
    // Where the part under way ended, then the error as it came.
    auto settle = [&](const LinkError& e, bool commitSent, bool committed) {
        PushReport::State& st = report.parts[part].state;
        st = committed                                                  ? PushReport::State::New
             : commitSent && e && e.kind == LinkError::Kind::NoAnswer ? PushReport::State::InDoubt
                                                                        : PushReport::State::AsItWas;
        ++part;
        return e;
    };
    bool sent = false, committed = false;
    if (plan.hasC) {
        step("C-parameters", 0, 1);
        const std::vector<std::uint16_t> regs = packC(map, plan.c);
        if (LinkError e = writeBlock(link, BlockKind::C, regs, committed, sent); settle(e, sent, committed))
            return e;
        report.constants = true;
    }
    if (plan.hasR) {
        step("R-parameters", 0, 1);
        std::vector<std::uint16_t> regs;
        for (int i = 0; i < map.rCount; ++i) {
            const std::int32_t v = i < 300 ? plan.r[static_cast<std::size_t>(i)] : 0;
            regs.push_back(lowWord(v));
            regs.push_back(highWord(v));
        }
        if (LinkError e = writeBlock(link, BlockKind::R, regs, committed, sent); settle(e, sent, committed))
            return e;
        report.rParameters = true;
    }
    // The messages (programs may show them), then each program.
    if (plan.hasMessages) {
        step("messages", 0, 1);
        if (LinkError e = writeText(link, true, 0, plan.messagesText, sent, committed); settle(e, sent, committed))
            return e;
        report.messages = true;
    }
    int done = 0;
    for (int n : order) {
        step("program " + std::to_string(n), done++, static_cast<int>(order.size()));
        if (LinkError e = writeText(link, false, n, plan.programs.at(n), sent, committed); settle(e, sent, committed))
            return e;
        report.programs.push_back(n);
    }
    return {};
}

LinkError push(Link& link, const profile::MachineProfile& file, PushReport& report, const Progress& progress) {
    PushPlan plan;
    if (LinkError e = planMachineFile(link.map(), file, plan))
        return e;
    return push(link, plan, report, progress);
}

LinkError clearArea(Link& link, BlockKind kind) {
    const RegisterMap& map = link.map();
    const Said what = say(kind == BlockKind::C ? "link.action-clear-c" : "link.action-clear-r");
    LiveState live;
    if (LinkError e = identify(link, live))
        return e;
    if (!live.pcReady)
        return linkError(LinkError::Kind::NotReady, 6, notReadySaid(live, what));
    const std::uint16_t cmd[] = {
        static_cast<std::uint16_t>(kind == BlockKind::C ? TransferCommand::ClearC : TransferCommand::ClearR)};
    if (LinkError e = link.write(map.transfer.command, cmd))
        return e;
    std::vector<std::uint16_t> st;
    if (LinkError e = link.read(map.transfer.status, 1, st))
        return e;
    if (st[0] != static_cast<int>(TransferStatus::Committed))
        return linkError(LinkError::Kind::Refused, st[0],
                         say("link.join", {say(kind == BlockKind::C ? "link.clear-c" : "link.clear-r"), statusSaid(st[0])}));
    if (kind == BlockKind::C) { // every constant 0 now
        const Block& cb = map.block(BlockKind::C);
        std::vector<std::uint16_t> back;
        if (LinkError e = link.read(cb.first, cb.count(), back))
            return e;
        if (std::any_of(back.begin(), back.end(), [](std::uint16_t v) { return v != 0; }))
            return linkError(LinkError::Kind::Verify, 0,
                             say("link.clear-c-not-zero"));
    }
    return {};
}

LinkError setConstant(Link& link, int number, std::int64_t value) {
    const RegisterMap& map = link.map();
    const std::string what = "C" + std::to_string(number);
    const auto place = std::find_if(map.c.begin(), map.c.end(), [&](const CPlacement& p) { return p.number == number; });
    if (place == map.c.end())
        return linkError(LinkError::Kind::Input, 0,
                         say("link.c-no-address", {std::to_string(number)}));
    LiveState live;
    if (LinkError e = readLive(link, live))
        return e;
    if (!live.pcReady)
        return linkError(LinkError::Kind::NotReady, 6, notReadySaid(live, say("link.action-set", {what})));
    // The registers the constant lies in, from the block as it is now (a
    // bit or a byte shares its word with others).
    const Block& cb = map.block(BlockKind::C);
    std::vector<std::uint16_t> regs;
    if (LinkError e = link.read(cb.first, cb.count(), regs))
        return e;
    std::vector<std::int64_t> c = unpackC(map, regs);
    c[static_cast<std::size_t>(number)] = value;
    const std::vector<std::uint16_t> next = packC(map, c);
    const int first = place->word - cb.first;
    const int count = place->form == CForm::TwoWords ? 2 : 1;
    const std::span<const std::uint16_t> words(next.data() + first, static_cast<std::size_t>(count));
    if (LinkError e = link.write(place->word, words))
        return e.kind == LinkError::Kind::Exception && e.code == 3
                   ? linkError(LinkError::Kind::Exception, 3,
                               say("link.c-value-refused", {std::to_string(number), std::to_string(value)}))
                   : e;
    std::vector<std::uint16_t> back;
    if (LinkError e = link.read(place->word, count, back))
        return e;
    if (!std::equal(back.begin(), back.end(), words.begin()))
        return linkError(LinkError::Kind::Verify, 0,
                         say("link.read-back-differs", {what}));
    return {};
}

LinkError setRParameter(Link& link, int number, std::int64_t value) {
    const RegisterMap& map = link.map();
    const std::string what = "R" + std::to_string(number);
    if (number < 0 || number >= map.rCount || !map.rWritable(number))
        return linkError(LinkError::Kind::Input, 2,
                         say("link.r-read-only", {std::to_string(number), map.rWritableText()}));
    if (value < INT32_MIN || value > INT32_MAX)
        return linkError(LinkError::Kind::Input, 3,
                         say("link.r-32-bits", {std::to_string(number), std::to_string(value)}));
    LiveState live;
    if (LinkError e = readLive(link, live))
        return e;
    if (!live.pcReady)
        return linkError(LinkError::Kind::NotReady, 6, notReadySaid(live, say("link.action-set", {what})));
    const std::uint16_t words[] = {lowWord(value), highWord(value)};
    if (LinkError e = link.write(map.rRegister(number), words))
        return e;
    std::vector<std::uint16_t> back;
    if (LinkError e = link.read(map.rRegister(number), 2, back))
        return e;
    if (back[0] != words[0] || back[1] != words[1])
        return linkError(LinkError::Kind::Verify, 0,
                         say("link.read-back-differs", {what}));
    return {};
}

LinkError readBusCounters(Link& link, BusCounters& out) {
    for (std::size_t i = 0; i < std::size(modbus::kCounters); ++i)
        if (LinkError e = link.diagnostics(modbus::kCounters[i], 0, out.values[i]))
            return e;
    return {};
}

LinkError clearBusCounters(Link& link) {
    std::uint16_t echo = 0;
    return link.diagnostics(modbus::ClearCounters, 0, echo);
}

StationInfo probeStation(Link& link, int address) {
    StationInfo s;
    s.address = address;
    if (!link.transport().setStation(address))
        return s;
    const int attempts = link.attempts();
    link.setAttempts(1);
    const std::int64_t damagedBefore = link.stations().count(address) ? link.stations().at(address).crcErrors : 0;
    const LinkError e = link.echo(0x4B35);
    const LineStats& st = link.stations().at(address);
    if (!e) {
        s.answers = true;
        s.echo = "echo ok";
    } else if (e.kind == LinkError::Kind::Exception || e.kind == LinkError::Kind::NotReady) {
        s.answers = true;
        s.echoException = e.code;
        char buf[48];
        std::snprintf(buf, sizeof buf, "exception %02d to the echo", e.code);
        s.echo = buf;
    } else if (st.crcErrors > damagedBefore) {
        s.garbled = true;
        s.echo = "a damaged answer (another baud rate or parity?)";
    }
    if (s.answers) {
        s.roundTripMs = st.roundTrip.last();
        ServerId id;
        if (!link.serverId(id))
            s.id = id;
        LiveState live;
        if (!readLive(link, live) && live.mode >= 0 && live.mode <= 7)
            s.live = live;
    }
    link.setAttempts(attempts);
    return s;
}

std::string describe(const StationInfo& s, bool ru) {
    const auto in = [ru](const Said& said) { return render(said, ru); };
    std::string t;
    if (!s.answers)
        return in(say("link.scan-station", {std::to_string(s.address),
                                            say(s.garbled ? "link.scan-garbled" : "link.scan-no-answer")}));
    if (s.echoException > 0) {
        char code[16];
        std::snprintf(code, sizeof code, "%02d", s.echoException);
        t = in(say("link.scan-echo-exception", {std::string(code)}));
    } else {
        t = in(say("link.scan-echo-ok"));
    }
    if (s.id) {
        char id[16];
        std::snprintf(id, sizeof id, "0x%02X", s.id->id);
        t += in(say("link.scan-server-id", {std::string(id)}));
        if (s.id->running)
            t += in(say("link.scan-running"));
        std::string data;
        for (char ch : s.id->data)
            data += (static_cast<unsigned char>(ch) >= 0x20 || (ch & 0x80)) ? ch : '.';
        if (!data.empty())
            t += " «" + data + "»";
    } else {
        t += in(say("link.scan-no-server-id"));
    }
    if (s.live) {
        t += in(say("link.scan-map", {std::to_string(s.live->mode)})) + (s.live->pcReady ? " «РАБОТА С ПЭВМ»" : "");
        if (s.live->program > 0)
            t += in(say("link.scan-program", {std::to_string(s.live->program)}));
        t += in(say("link.scan-programs", {std::to_string(s.live->programs.size())}));
        if (!s.live->alarms.empty())
            t += in(say("link.scan-alarms"));
    }
    char ms[32];
    std::snprintf(ms, sizeof ms, "%.1f", s.roundTripMs);
    t += in(say("link.scan-round-trip", {std::string(ms)}));
    return in(say("link.scan-station", {std::to_string(s.address), t}));
}

} // namespace k528::link
