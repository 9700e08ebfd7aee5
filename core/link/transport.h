// The register transport the client procedures talk through: four Modbus
// exchanges on holding registers. The RS485 plugin implements it over Qt
// SerialBus (QModbusRtuSerialClient); the tests over a ControllerImage in
// the same process (ImageTransport). A transport reports each exchange; the
// Link above it checks, retries and counts.
#pragma once

#include "link/image.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace k528::link {

struct Reply {
    enum class Kind {
        Ok,
        Exception, // the controller answered with an exception code
        NoAnswer,  // timeout (a frame with a bad CRC is dropped and ends here too)
        BadReply,  // an answer that does not fit the request (count, echoed address)
    };
    Kind kind = Kind::Ok;
    int exception = 0;
    std::string detail;
    bool ok() const { return kind == Kind::Ok; }
    static Reply good() { return {}; }
    static Reply exceptionCode(int code) { return {Kind::Exception, code, {}}; }
    static Reply lost(std::string why = {}) { return {Kind::NoAnswer, 0, std::move(why)}; }
    static Reply bad(std::string why) { return {Kind::BadReply, 0, std::move(why)}; }
};

class RegisterTransport {
public:
    virtual ~RegisterTransport() = default;
    // FC 3.
    virtual Reply read(int first, int count, std::vector<std::uint16_t>& out) = 0;
    // FC 16 (FC 6 for one register, as a transport chooses).
    virtual Reply write(int first, std::span<const std::uint16_t> values) = 0;
    // FC 23: the write first, then the read, in one exchange.
    virtual Reply writeRead(int writeFirst, std::span<const std::uint16_t> values, int readFirst,
                            int readCount, std::vector<std::uint16_t>& out) = 0;
    // FC 8 sub-function 0: the controller echoes `value`.
    virtual Reply echo(std::uint16_t value) = 0;
};

// Modbus RTU frame sizes in bytes (address, function, data, CRC) of each
// exchange, request and reply: what a transport's wire meter counts.
struct FrameBytes {
    int request = 0, reply = 0;
};
inline FrameBytes readFrameBytes(int count) { return {8, 5 + 2 * count}; }
// FC 6 for one register, FC 16 otherwise.
inline FrameBytes writeFrameBytes(int count) { return count == 1 ? FrameBytes{8, 8} : FrameBytes{9 + 2 * count, 8}; }
inline FrameBytes writeReadFrameBytes(int writeCount, int readCount) { return {13 + 2 * writeCount, 5 + 2 * readCount}; }
inline FrameBytes echoFrameBytes() { return {8, 8}; }
// The request, and a 5-byte exception reply.
inline FrameBytes exceptionFrameBytes(FrameBytes request) { return {request.request, 5}; }

// The in-process transport: each exchange goes straight to a ControllerImage
// (tests, benchmarks), counting the RTU bytes the same exchange would put on
// a line.
class ImageTransport : public RegisterTransport {
public:
    explicit ImageTransport(ControllerImage& image) : image_(image) {}
    Reply read(int first, int count, std::vector<std::uint16_t>& out) override;
    Reply write(int first, std::span<const std::uint16_t> values) override;
    Reply writeRead(int writeFirst, std::span<const std::uint16_t> values, int readFirst,
                    int readCount, std::vector<std::uint16_t>& out) override;
    Reply echo(std::uint16_t value) override;

    std::int64_t bytes() const { return bytes_; }
    std::int64_t frames() const { return frames_; }
    std::int64_t transactions() const { return transactions_; }

private:
    Reply account(FrameBytes f, Exception e);
    ControllerImage& image_;
    std::int64_t bytes_ = 0, frames_ = 0, transactions_ = 0;
};

// Wire time of `bytes` in `frames` at `baud`, 10 bits a byte (8N1), plus a
// 1.75 ms gap per frame (the 3.5-character gap above 19200 baud).
inline double wireSeconds(std::int64_t bytes, std::int64_t frames, int baud = 115200) {
    return static_cast<double>(bytes) * 10.0 / baud + static_cast<double>(frames) * 0.00175;
}

} // namespace k528::link
