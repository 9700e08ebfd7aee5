#include "link/modbus.h"

#include "link/line_error.h"

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <optional>
#include <thread>

namespace k528::link {

namespace modbus {

namespace {

void put16(Bytes& b, int v) {
    b.push_back(static_cast<std::uint8_t>((v >> 8) & 0xFF));
    b.push_back(static_cast<std::uint8_t>(v & 0xFF));
}

int get16(std::span<const std::uint8_t> b, std::size_t at) {
    return (b[at] << 8) | b[at + 1];
}

std::string hexByte(int v) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "%02X", v & 0xFF);
    return buf;
}

// The response's function is the request's, or its exception (function | 0x80).
Reply checkFunction(std::span<const std::uint8_t> request, std::span<const std::uint8_t> response) {
    if (response.empty())
        return Reply::bad("an empty answer");
    if (response[0] == (request[0] | 0x80)) {
        if (response.size() != 2)
            return Reply::bad("an exception answer of " + std::to_string(response.size()) + " bytes");
        return Reply::exceptionCode(response[1]);
    }
    if (response[0] != request[0])
        return Reply::bad("an answer of function " + std::to_string(response[0]) + " to function " +
                          std::to_string(request[0]));
    return Reply::good();
}

} // namespace

const char* counterName(Diagnostic d) {
    switch (d) {
    case BusMessages:
        return "bus messages";
    case BusCommunicationErrors:
        return "bus CRC errors";
    case BusExceptions:
        return "exceptions answered";
    case ServerMessages:
        return "messages to this station";
    case ServerNoResponse:
        return "messages not answered";
    case ServerNak:
        return "NAK answers";
    case ServerBusy:
        return "busy answers";
    case BusCharacterOverrun:
        return "character overruns";
    default:
        return "counter";
    }
}

std::uint16_t crc16(std::span<const std::uint8_t> bytes) {
    std::uint16_t crc = 0xFFFF;
    for (std::uint8_t b : bytes) {
        crc ^= b;
        for (int i = 0; i < 8; ++i)
            crc = (crc & 1u) ? static_cast<std::uint16_t>((crc >> 1) ^ 0xA001u) : static_cast<std::uint16_t>(crc >> 1);
    }
    return crc;
}

Bytes readRequest(int first, int count) {
    Bytes b{ReadHolding};
    put16(b, first);
    put16(b, count);
    return b;
}

Bytes writeRequest(int first, std::span<const std::uint16_t> values) {
    Bytes b;
    if (values.size() == 1) {
        b.push_back(WriteSingle);
        put16(b, first);
        put16(b, values[0]);
        return b;
    }
    b.push_back(WriteMultiple);
    put16(b, first);
    put16(b, static_cast<int>(values.size()));
    b.push_back(static_cast<std::uint8_t>(2 * values.size()));
    for (std::uint16_t v : values)
        put16(b, v);
    return b;
}

Bytes writeReadRequest(int writeFirst, std::span<const std::uint16_t> values, int readFirst, int readCount) {
    Bytes b{ReadWrite};
    put16(b, readFirst);
    put16(b, readCount);
    put16(b, writeFirst);
    put16(b, static_cast<int>(values.size()));
    b.push_back(static_cast<std::uint8_t>(2 * values.size()));
    for (std::uint16_t v : values)
        put16(b, v);
    return b;
}

Bytes diagnosticsRequest(std::uint16_t sub, std::uint16_t data) {
    Bytes b{Diagnostics};
    put16(b, sub);
    put16(b, data);
    return b;
}

Bytes serverIdRequest() { return Bytes{ReportServerId}; }

int responseLength(std::span<const std::uint8_t> pdu) {
    if (pdu.empty())
        return -1;
    const std::uint8_t fc = pdu[0];
    if (fc & 0x80)
        return 2;
    switch (fc) {
    case ReadHolding:
    case ReadWrite:
    case ReportServerId:
        return pdu.size() < 2 ? -1 : 2 + pdu[1];
    case WriteSingle:
    case WriteMultiple:
    case Diagnostics:
        return 5;
    default:
        return 0;
    }
}

int requestLength(std::span<const std::uint8_t> pdu) {
    if (pdu.empty())
        return -1;
    switch (pdu[0]) {
    case ReadHolding:
    case WriteSingle:
    case Diagnostics:
        return 5;
    case ReportServerId:
        return 1;
    case WriteMultiple:
        return pdu.size() < 6 ? -1 : 6 + pdu[5];
    case ReadWrite:
        return pdu.size() < 10 ? -1 : 10 + pdu[9];
    default:
        return 0;
    }
}

Reply decodeRegisters(std::span<const std::uint8_t> request, std::span<const std::uint8_t> response,
                      std::vector<std::uint16_t>& out) {
    out.clear();
    Reply r = checkFunction(request, response);
    if (!r.ok())
        return r;
    const int asked = get16(request, 3);
    if (response.size() < 2 || response[1] != 2 * asked || static_cast<int>(response.size()) != 2 + response[1])
        return Reply::bad("an answer of " + std::to_string(response.size() < 2 ? 0 : response[1] / 2) +
                          " registers, " + std::to_string(asked) + " asked");
    out.reserve(static_cast<std::size_t>(asked));
    for (int i = 0; i < asked; ++i)
        out.push_back(static_cast<std::uint16_t>(get16(response, 2 + 2 * static_cast<std::size_t>(i))));
    return r;
}

Reply decodeWrite(std::span<const std::uint8_t> request, std::span<const std::uint8_t> response) {
    Reply r = checkFunction(request, response);
    if (!r.ok())
        return r;
    // FC 6 echoes the request; FC 16 its address and count.
    if (response.size() != 5 || !std::equal(response.begin(), response.end(), request.begin()))
        return Reply::bad(std::string("FC ") + (request[0] == WriteSingle ? "06" : "16") +
                          " echo does not match the request");
    return r;
}

Reply decodeDiagnostics(std::span<const std::uint8_t> request, std::span<const std::uint8_t> response,
                        std::uint16_t& data) {
    Reply r = checkFunction(request, response);
    if (!r.ok())
        return r;
    if (response.size() != 5 || get16(response, 1) != get16(request, 1))
        return Reply::bad("a diagnostics answer to another sub-function");
    data = static_cast<std::uint16_t>(get16(response, 3));
    return r;
}

Reply decodeServerId(std::span<const std::uint8_t> response, ServerId& out) {
    const std::uint8_t req[] = {ReportServerId};
    Reply r = checkFunction(req, response);
    if (!r.ok())
        return r;
    if (response.size() < 4 || static_cast<int>(response.size()) != 2 + response[1])
        return Reply::bad("a server id answer of " + std::to_string(response.size()) + " bytes");
    out.id = response[2];
    out.running = response[3] == 0xFF;
    out.data.assign(response.begin() + 4, response.end());
    return r;
}

Bytes exceptionResponse(std::uint8_t function, int code) {
    return Bytes{static_cast<std::uint8_t>(function | 0x80), static_cast<std::uint8_t>(code)};
}

Bytes serveRegisters(std::span<const std::uint8_t> req, RegisterHandler& handler) {
    if (req.empty())
        return exceptionResponse(0, 1);
    const std::uint8_t fc = req[0];
    const int length = requestLength(req);
    if (length == 0)
        return exceptionResponse(fc, 1);
    if (length < 0 || static_cast<int>(req.size()) != length)
        return exceptionResponse(fc, 3);
    auto words = [&](std::size_t at, int n) {
        std::vector<std::uint16_t> v;
        for (int i = 0; i < n; ++i)
            v.push_back(static_cast<std::uint16_t>(get16(req, at + 2 * static_cast<std::size_t>(i))));
        return v;
    };
    auto registers = [&](const std::vector<std::uint16_t>& v) {
        Bytes out{fc, static_cast<std::uint8_t>(2 * v.size())};
        for (std::uint16_t w : v)
            put16(out, w);
        return out;
    };
    std::vector<std::uint16_t> v;
    switch (fc) {
    case ReadHolding:
        if (const int e = handler.read(get16(req, 1), get16(req, 3), v))
            return exceptionResponse(fc, e);
        return registers(v);
    case WriteSingle: {
        const std::uint16_t one[] = {static_cast<std::uint16_t>(get16(req, 3))};
        if (const int e = handler.write(get16(req, 1), one))
            return exceptionResponse(fc, e);
        return Bytes(req.begin(), req.end());
    }
    case WriteMultiple: {
        const int n = get16(req, 3);
        if (req[5] != 2 * n)
            return exceptionResponse(fc, 3);
        if (const int e = handler.write(get16(req, 1), words(6, n)))
            return exceptionResponse(fc, e);
        return Bytes(req.begin(), req.begin() + 5);
    }
    case ReadWrite: {
        const int n = get16(req, 7);
        if (req[9] != 2 * n)
            return exceptionResponse(fc, 3);
        if (const int e = handler.write(get16(req, 5), words(10, n))) // the write first (Modbus spec)
            return exceptionResponse(fc, e);
        if (const int e = handler.read(get16(req, 1), get16(req, 3), v))
            return exceptionResponse(fc, e);
        return registers(v);
    }
    default:
        return exceptionResponse(fc, 1);
    }
}

Bytes rtuFrame(int address, std::span<const std::uint8_t> pdu) {
    Bytes f;
    f.reserve(pdu.size() + 3);
    f.push_back(static_cast<std::uint8_t>(address));
    f.insert(f.end(), pdu.begin(), pdu.end());
    const std::uint16_t crc = crc16(f);
    f.push_back(static_cast<std::uint8_t>(crc & 0xFF));
    f.push_back(static_cast<std::uint8_t>(crc >> 8));
    return f;
}

bool rtuCrcOk(std::span<const std::uint8_t> frame) {
    if (frame.size() < 4)
        return false;
    const std::uint16_t crc = crc16(frame.first(frame.size() - 2));
    return frame[frame.size() - 2] == (crc & 0xFF) && frame[frame.size() - 1] == (crc >> 8);
}

} // namespace modbus

void FrameLog::add(Frame f) {
    if (capacity_ == 0) {
        ++dropped_;
        return;
    }
    frames_.push_back(std::move(f));
    while (frames_.size() > capacity_) {
        frames_.pop_front();
        ++dropped_;
    }
}

std::string formatFrame(const Frame& f) {
    const std::time_t secs = static_cast<std::time_t>(f.unixMicros / 1000000);
    std::tm tm{};
    localtime_r(&secs, &tm);
    char when[64];
    std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S", &tm);
    char line[128];
    std::snprintf(line, sizeof line, "%s.%06lld  %s  station %3d  ", when,
                  static_cast<long long>(f.unixMicros % 1000000), f.sent ? "TX" : "RX", f.station);
    std::string out = line;
    for (std::size_t i = 0; i < f.bytes.size(); ++i) {
        if (i)
            out += ' ';
        out += modbus::hexByte(f.bytes[i]);
    }
    if (!f.bytes.empty())
        out += f.check == Frame::Check::Ok     ? "  CRC ok"
               : f.check == Frame::Check::Bad  ? "  CRC BAD"
               : f.check == Frame::Check::Mbap ? "  MBAP"
                                               : "  SHORT";
    if (!f.note.empty())
        out += (f.bytes.empty() ? "" : "  ") + f.note;
    return out;
}

std::string formatFrameLog(const FrameLog& log) {
    std::string out = "# K528 Studio frame log: time (the PC's), direction, station, bytes, CRC\n";
    if (log.dropped() > 0)
        out += "# " + std::to_string(log.dropped()) + " older frames are no longer kept\n";
    for (const Frame& f : log.frames()) {
        out += formatFrame(f);
        out += '\n';
    }
    return out;
}

// --- ModbusMaster -----------------------------------------------------------

template <class Decode> Reply ModbusMaster::ask(const Bytes& request, Decode&& decode) {
    Bytes response;
    const Reply r = exchange(request, response);
    if (!r.ok())
        return r;
    Reply d = decode(response);
    d.roundTripMs = r.roundTripMs;
    return d;
}

Reply ModbusMaster::read(int first, int count, std::vector<std::uint16_t>& out) {
    const Bytes req = modbus::readRequest(first, count);
    return ask(req, [&](const Bytes& resp) { return modbus::decodeRegisters(req, resp, out); });
}

Reply ModbusMaster::write(int first, std::span<const std::uint16_t> values) {
    const Bytes req = modbus::writeRequest(first, values);
    return ask(req, [&](const Bytes& resp) { return modbus::decodeWrite(req, resp); });
}

Reply ModbusMaster::writeRead(int writeFirst, std::span<const std::uint16_t> values, int readFirst, int readCount,
                              std::vector<std::uint16_t>& out) {
    const Bytes req = modbus::writeReadRequest(writeFirst, values, readFirst, readCount);
    return ask(req, [&](const Bytes& resp) { return modbus::decodeRegisters(req, resp, out); });
}

Reply ModbusMaster::diagnostics(std::uint16_t sub, std::uint16_t data, std::uint16_t& out) {
    const Bytes req = modbus::diagnosticsRequest(sub, data);
    return ask(req, [&](const Bytes& resp) { return modbus::decodeDiagnostics(req, resp, out); });
}

Reply ModbusMaster::echo(std::uint16_t value) {
    std::uint16_t back = 0;
    Reply r = diagnostics(modbus::ReturnQueryData, value, back);
    if (r.ok() && back != value) {
        const double ms = r.roundTripMs;
        r = Reply::bad("the echo differs");
        r.roundTripMs = ms;
    }
    return r;
}

Reply ModbusMaster::serverId(ServerId& out) {
    return ask(modbus::serverIdRequest(), [&](const Bytes& resp) { return modbus::decodeServerId(resp, out); });
}

bool ModbusMaster::setStation(int address) {
    if (address < 1 || address > 247)
        return false;
    station_ = address;
    stationChanged();
    return true;
}

// --- RtuMaster ---------------------------------------------------------------

namespace {

using Clock = std::chrono::steady_clock;

std::int64_t unixMicrosNow() {
    return std::chrono::duration_cast<std::chrono::microseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}

int msUntil(Clock::time_point t) {
    const auto left = std::chrono::duration_cast<std::chrono::microseconds>(t - Clock::now()).count();
    return left <= 0 ? 0 : static_cast<int>((left + 999) / 1000);
}

} // namespace

std::chrono::microseconds RtuMaster::gap() const {
    if (s_.baud > 19200)
        return std::chrono::microseconds(1750);
    return std::chrono::microseconds(static_cast<std::int64_t>(3.5 * s_.bitsPerChar * 1e6 / s_.baud + 0.5));
}

void RtuMaster::log(bool sent, const Bytes& bytes, Frame::Check check, std::string note) {
    log_.add(Frame{unixMicrosNow(), sent, station_, bytes, check, std::move(note)});
}

void RtuMaster::drain() {
    Bytes junk;
    std::string error;
    if (!port_.read(junk, 0, error) || junk.empty())
        return;
    wire_.bytes += static_cast<std::int64_t>(junk.size());
    ++wire_.frames;
    lastActivity_ = Clock::now();
    log(false, junk, modbus::rtuCrcOk(junk) ? Frame::Check::Ok : Frame::Check::Bad,
        "unexpected between exchanges (a late answer, or noise): dropped");
}

Reply RtuMaster::exchange(const Bytes& request, Bytes& response) {
    response.clear();
    std::string error;
    if (!port_.isOpen()) {
        const Clock::time_point now = Clock::now();
        if (now < nextReopen_)
            return Reply::lost("the port is closed");
        nextReopen_ = now + std::chrono::seconds(1);
        if (!port_.reopen(error))
            return Reply::lost("the port is closed and does not open again: " + error);
        log(true, {}, Frame::Check::Ok, "the port opened again");
    }
    drain();
    const Clock::time_point quietUntil = lastActivity_ + gap();
    if (Clock::now() < quietUntil)
        std::this_thread::sleep_until(quietUntil);

    const Bytes frame = modbus::rtuFrame(station_, request);
    const Clock::time_point start = Clock::now();
    if (!port_.write(frame, error)) {
        log(true, frame, Frame::Check::Ok, "not sent: " + lineErrorPlain(error));
        return Reply::lost("the port failed: " + error);
    }
    log(true, frame, Frame::Check::Ok);
    wire_.bytes += static_cast<std::int64_t>(frame.size());
    ++wire_.frames;
    ++wire_.transactions;
    const auto sendTime = std::chrono::microseconds(
        static_cast<std::int64_t>(static_cast<double>(frame.size()) * s_.bitsPerChar * 1e6 / s_.baud));
    // After a timeout the next wait is longer (twice, up to four times the
    // timeout): a line whose answers come late — a busy gateway, a slow
    // converter — is still read; any answer brings it back.
    const int waitMs = s_.timeoutMs * patience_;
    const Clock::time_point deadline = start + sendTime + std::chrono::milliseconds(waitMs);

    const std::uint8_t fc = request[0];
    // The answer is the frame for this station and function whose CRC holds,
    // wherever it begins in what came: a late answer's tail or noise before
    // it is dropped (RTU has no transaction number; the CRC and the length
    // its function gives delimit a frame). What never forms one ends at the
    // timeout, or once the line is quiet after a whole frame that is damaged.
    struct Found {
        std::size_t at = 0, total = 0;
    };
    const auto findFrame = [&](const Bytes& b) -> std::optional<Found> {
        for (std::size_t k = 0; k + 4 <= b.size(); ++k) {
            if (b[k] != station_ || (b[k + 1] != fc && b[k + 1] != (fc | 0x80)))
                continue;
            const int len = modbus::responseLength(std::span<const std::uint8_t>(b).subspan(k + 1));
            if (len <= 0 || k + 3 + static_cast<std::size_t>(len) > b.size())
                continue;
            const std::span<const std::uint8_t> f(b.data() + k, 3 + static_cast<std::size_t>(len));
            if (modbus::rtuCrcOk(f))
                return Found{k, f.size()};
        }
        return std::nullopt;
    };
    // The length the first bytes announce (0 when they do not tell).
    const auto announced = [&](const Bytes& b) -> std::size_t {
        if (b.size() < 2 || (b[1] != fc && b[1] != (fc | 0x80)))
            return 0;
        const int len = modbus::responseLength(std::span<const std::uint8_t>(b).subspan(1));
        return len > 0 ? 3 + static_cast<std::size_t>(len) : 0;
    };
    const auto quiet = std::max<std::chrono::microseconds>(2 * gap(), std::chrono::milliseconds(5));
    Bytes got;
    std::optional<Found> found;
    Clock::time_point lastByte = start;
    for (;;) {
        if ((found = findFrame(got)))
            break;
        int wait = msUntil(deadline);
        const std::size_t want = announced(got);
        // The beginning of an answer of ours (its station, and its function
        // once two bytes came) waits for the rest until the deadline.
        const bool ours = !got.empty() && got[0] == station_ && (got.size() == 1 || want > 0);
        if (!got.empty() && (!ours || (want > 0 && got.size() >= want))) {
            // A whole frame that is not good, or bytes of no function of ours:
            // what comes is over once the line is quiet.
            const Clock::time_point over = lastByte + quiet;
            if (Clock::now() >= over)
                break;
            wait = std::min(wait, msUntil(over));
        }
        if (wait <= 0)
            break;
        const std::size_t before = got.size();
        if (!port_.read(got, wait, error)) {
            if (!got.empty())
                log(false, got, Frame::Check::Short, "the port failed: " + lineErrorPlain(error));
            return Reply::lost("the port failed: " + error);
        }
        if (got.size() > before)
            lastByte = Clock::now();
    }
    const Clock::time_point end = Clock::now();
    lastActivity_ = end;
    const double ms = std::chrono::duration<double, std::milli>(lastByte - start).count();
    if (got.empty()) {
        log(false, {}, Frame::Check::Ok, "no answer within " + std::to_string(waitMs) + " ms");
        patience_ = std::min(patience_ * 2, 4);
        return Reply::lost("timeout");
    }
    patience_ = 1;
    wire_.bytes += static_cast<std::int64_t>(got.size());
    ++wire_.frames;
    Reply r;
    if (found) {
        const Bytes before(got.begin(), got.begin() + static_cast<std::ptrdiff_t>(found->at));
        const Bytes frame(got.begin() + static_cast<std::ptrdiff_t>(found->at),
                          got.begin() + static_cast<std::ptrdiff_t>(found->at + found->total));
        const Bytes after(got.begin() + static_cast<std::ptrdiff_t>(found->at + found->total), got.end());
        if (!before.empty())
            log(false, before, modbus::rtuCrcOk(before) ? Frame::Check::Ok : Frame::Check::Bad,
                "before the answer (a late answer's rest, or noise): dropped");
        log(false, frame, Frame::Check::Ok);
        if (!after.empty())
            log(false, after, modbus::rtuCrcOk(after) ? Frame::Check::Ok : Frame::Check::Bad,
                "after the answer (noise, or another station): dropped");
        response.assign(frame.begin() + 1, frame.end() - 2);
        r.roundTripMs = ms;
        return r;
    }
    const std::size_t want = announced(got);
    if (want > 0 && got.size() < want) {
        log(false, got, Frame::Check::Short, "cut short: " + std::to_string(got.size()) + " of " +
                                                 std::to_string(want) + " bytes");
        r = Reply::damaged("a frame cut short (" + std::to_string(got.size()) + " of " + std::to_string(want) +
                           " bytes)");
    } else if (!modbus::rtuCrcOk(got)) {
        log(false, got, Frame::Check::Bad);
        r = Reply::damaged("CRC error");
    } else if (got[0] != station_) {
        log(false, got, Frame::Check::Ok, "from another station");
        r = Reply::bad("an answer from station " + std::to_string(got[0]));
    } else {
        log(false, got, Frame::Check::Ok, "not an answer to this request");
        r = Reply::bad("an answer of function " + std::to_string(got[1]) + " to function " + std::to_string(fc));
    }
    r.roundTripMs = ms;
    return r;
}

} // namespace k528::link
