#include "link/transport.h"

namespace k528::link {

Reply ImageTransport::account(FrameBytes f, Exception e) {
    if (e != Exception::None)
        f = exceptionFrameBytes(f);
    bytes_ += f.request + f.reply;
    frames_ += 2;
    ++transactions_;
    return e == Exception::None ? Reply::good() : Reply::exceptionCode(static_cast<int>(e));
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

} // namespace k528::link
