#include "link/modbus_tcp.h"

#include "link/line_error.h"

#include <algorithm>
#include <string>

namespace k528::link {

namespace modbus {

Bytes mbapFrame(std::uint16_t transaction, int unit, std::span<const std::uint8_t> pdu) {
    const std::size_t length = pdu.size() + 1;
    Bytes f;
    f.reserve(7 + pdu.size());
    for (const std::size_t v : {std::size_t(transaction) >> 8, std::size_t(transaction) & 0xFF, std::size_t(0),
                                std::size_t(0), length >> 8, length & 0xFF, std::size_t(unit)})
        f.push_back(static_cast<std::uint8_t>(v));
    for (const std::uint8_t b : pdu)
        f.push_back(b);
    return f;
}

} // namespace modbus

namespace {

using Clock = std::chrono::steady_clock;

std::int64_t unixMicrosNow() {
    return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
        .count();
}

int msUntil(Clock::time_point t) {
    const auto left = std::chrono::duration_cast<std::chrono::microseconds>(t - Clock::now()).count();
    return left <= 0 ? 0 : static_cast<int>((left + 999) / 1000);
}

constexpr std::size_t kHeader = 7;

int get16(const Bytes& b, std::size_t at) { return (b[at] << 8) | b[at + 1]; }

} // namespace

void TcpMaster::log(bool sent, const Bytes& bytes, Frame::Check check, std::string note) {
    log_.add(Frame{unixMicrosNow(), sent, station_, bytes, check, std::move(note)});
}

Reply TcpMaster::exchange(const Bytes& request, Bytes& response) {
    response.clear();
    std::string error;
    if (!port_.isOpen()) {
        const Clock::time_point now = Clock::now();
        if (now < nextReopen_)
            return Reply::lost("the connection is closed");
        nextReopen_ = now + std::chrono::milliseconds(250);
        pending_.clear();
        if (!port_.reopen(error))
            return Reply::lost("the connection is closed and does not open again: " + error);
        log(true, {}, Frame::Check::Mbap, "connected again");
    }
    const std::uint16_t tid = ++transaction_;
    const Bytes frame = modbus::mbapFrame(tid, station_, request);
    const Clock::time_point start = Clock::now();
    if (!port_.write(frame, error)) {
        log(true, frame, Frame::Check::Mbap, "not sent: " + lineErrorPlain(error));
        pending_.clear();
        return Reply::lost("the connection failed: " + error);
    }
    log(true, frame, Frame::Check::Mbap);
    wire_.bytes += static_cast<std::int64_t>(frame.size());
    ++wire_.frames;
    ++wire_.transactions;
    const int waitMs = s_.timeoutMs * patience_;
    const Clock::time_point deadline = start + std::chrono::milliseconds(waitMs);
    for (;;) {
        // Every whole frame that came: the answer, or a late one dropped.
        while (pending_.size() >= kHeader) {
            const int protocol = get16(pending_, 2);
            const int length = get16(pending_, 4);
            if (protocol != 0 || length < 2 || length > 254) {
                log(false, pending_, Frame::Check::Bad,
                    "not a Modbus TCP header (protocol " + std::to_string(protocol) + ", length " +
                        std::to_string(length) + "): the connection is closed");
                wire_.bytes += static_cast<std::int64_t>(pending_.size());
                pending_.clear();
                std::string ignored;
                port_.reopen(ignored); // back in step: a new connection
                return Reply::damaged("a frame that is not Modbus TCP");
            }
            const std::size_t total = kHeader - 1 + static_cast<std::size_t>(length);
            if (pending_.size() < total)
                break;
            const Bytes got(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(total));
            pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(total));
            wire_.bytes += static_cast<std::int64_t>(got.size());
            ++wire_.frames;
            const int answerTid = get16(got, 0);
            if (answerTid != tid) {
                log(false, got, Frame::Check::Mbap,
                    "transaction " + std::to_string(answerTid) + ", not " + std::to_string(tid) +
                        " (a late answer): dropped");
                continue;
            }
            const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
            patience_ = 1;
            Reply r;
            if (got[6] != station_) {
                log(false, got, Frame::Check::Mbap, "from another unit");
                r = Reply::bad("an answer from unit " + std::to_string(got[6]));
            } else if (got[7] != request[0] && got[7] != (request[0] | 0x80)) {
                log(false, got, Frame::Check::Mbap, "not an answer to this request");
                r = Reply::bad("an answer of function " + std::to_string(got[7]) + " to function " +
                               std::to_string(request[0]));
            } else {
                log(false, got, Frame::Check::Mbap);
                response.assign(got.begin() + kHeader, got.end());
            }
            r.roundTripMs = ms;
            return r;
        }
        const int wait = msUntil(deadline);
        if (wait <= 0)
            break;
        if (!port_.read(pending_, wait, error)) {
            if (!pending_.empty())
                log(false, pending_, Frame::Check::Short, "the connection failed: " + lineErrorPlain(error));
            pending_.clear();
            return Reply::lost("the connection failed: " + error);
        }
    }
    if (!pending_.empty()) {
        // Part of a frame: the rest may still come (it is dropped then, by
        // its transaction id).
        log(false, pending_, Frame::Check::Short, "no whole answer within " + std::to_string(waitMs) + " ms");
        patience_ = std::min(patience_ * 2, 4);
        return Reply::damaged("an answer cut short");
    }
    log(false, {}, Frame::Check::Mbap, "no answer within " + std::to_string(waitMs) + " ms");
    patience_ = std::min(patience_ * 2, 4);
    return Reply::lost("timeout");
}

} // namespace k528::link
