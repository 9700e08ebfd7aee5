#include "link/transport.h"

namespace k528::link {

Reply ImageTransport::account(FrameBytes f, Exception e) {
    if (e != Exception::None) {
        f = exceptionFrameBytes(f);
        ++busExceptions_;
    }
    ++busMessages_;
    bytes_ += f.request + f.reply;
    frames_ += 2;
    ++transactions_;
    Reply r = e == Exception::None ? Reply::good() : Reply::exceptionCode(static_cast<int>(e));
    r.roundTripMs = wireSeconds(f.request + f.reply, 2) * 1000.0; // what the exchange takes on a line
    return r;
}

Reply ImageTransport::read(int first, int count, std::vector<std::uint16_t>& out) {
    return account(readFrameBytes(count), image_.read(first, count, out));
}

Reply ImageTransport::write(int first, std::span<const std::uint16_t> values) {
    return account(writeFrameBytes(static_cast<int>(values.size())), image_.write(first, values));
}

Reply ImageTransport::writeRead(int writeFirst, std::span<const std::uint16_t> values, int readFirst,
                                int readCount, std::vector<std::uint16_t>& out) {
    Exception e = image_.write(writeFirst, values);
    if (e == Exception::None)
        e = image_.read(readFirst, readCount, out);
    return account(writeReadFrameBytes(static_cast<int>(values.size()), readCount), e);
}

Reply ImageTransport::echo(std::uint16_t) {
    return account(echoFrameBytes(), Exception::None);
}

Reply ImageTransport::diagnostics(std::uint16_t sub, std::uint16_t data, std::uint16_t& out) {
    // Counted as the request it is, before the counter is read (as a server does).
    const Reply r = account(diagnosticsFrameBytes(), sub == 0 || sub == 10 || (sub >= 11 && sub <= 18)
                                                         ? Exception::None
                                                         : Exception::IllegalValue);
    if (!r.ok())
        return r;
    switch (sub) {
    case 0:
        out = data;
        break;
    case 10:
        busMessages_ = busExceptions_ = 0;
        out = data;
        break;
    case 11:
    case 14: // every message on this "bus" is addressed to this server
        out = busMessages_;
        break;
    case 13:
        out = busExceptions_;
        break;
    default: // no CRC errors, no unanswered, NAK, busy or overrun in one process
        out = 0;
        break;
    }
    return r;
}

Reply ImageTransport::serverId(ServerId& out) {
    out = {0x28, true, "K528-05, in process (" + image_.map().name + ")"};
    return account({4, 5 + static_cast<int>(out.data.size()) + 2}, Exception::None);
}

} // namespace k528::link
