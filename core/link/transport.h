// The register transport the client procedures talk through: the Modbus
// exchanges of the map on holding registers, diagnostics (FC 8) and the
// server id (FC 17), to one station at a time. The RS485 plugin implements
// it with core's RtuMaster (link/modbus.h) over its serial port; the tests
// over a ControllerImage in the same process (ImageTransport). A transport
// reports each exchange; the Link above it checks, retries and counts.
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
        NoAnswer,  // timeout: nothing came
        Damaged,   // a frame came with a bad CRC, or stopped short of its length
        BadReply,  // an answer that does not fit the request (count, echoed address)
    };
    Kind kind = Kind::Ok;
    int exception = 0;
    std::string detail;
    double roundTripMs = -1; // request sent to answer received, when the transport measured it
    bool ok() const { return kind == Kind::Ok; }
    static Reply good() { return {}; }
    static Reply exceptionCode(int code) { return {Kind::Exception, code, {}}; }
    static Reply lost(std::string why = {}) { return {Kind::NoAnswer, 0, std::move(why)}; }
    static Reply damaged(std::string why) { return {Kind::Damaged, 0, std::move(why)}; }
    static Reply bad(std::string why) { return {Kind::BadReply, 0, std::move(why)}; }
};

// A station's answer to FC 17 (report server id): its id byte, run
// indicator and additional data (the K528-05 served by `k528 serve` names
// itself there).
struct ServerId {
    int id = 0;
    bool running = false;
    std::string data;
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
    // FC 8, another sub-function (the bus counters 11..18, clear 10): the word answered.
    virtual Reply diagnostics(std::uint16_t sub, std::uint16_t data, std::uint16_t& out) {
        (void)sub, (void)data, (void)out;
        return Reply::exceptionCode(1);
    }
    // FC 17.
    virtual Reply serverId(ServerId& out) {
        (void)out;
        return Reply::exceptionCode(1);
    }
    // The station (address) the exchanges go to; a bus scan moves it.
    virtual int station() const { return 1; }
    virtual bool setStation(int address) { return address == station(); }
};

// The controller's side of a line (a server): each returns a Modbus
// exception code, 0 for none.
class RegisterHandler {
public:
    virtual ~RegisterHandler() = default;
    virtual int read(int first, int count, std::vector<std::uint16_t>& out) = 0;
    virtual int write(int first, std::span<const std::uint16_t> values) = 0;
};

// A ControllerImage as the server of a line (`k528 serve`, the tests).
class ImageHandler final : public RegisterHandler {
public:
    explicit ImageHandler(ControllerImage& image) : image_(image) {}
    int read(int first, int count, std::vector<std::uint16_t>& out) override {
        return static_cast<int>(image_.read(first, count, out));
    }
    int write(int first, std::span<const std::uint16_t> values) override {
        return static_cast<int>(image_.write(first, values));
    }

private:
    ControllerImage& image_;
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
inline FrameBytes diagnosticsFrameBytes() { return {8, 8}; }
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
    // The bus counters of a server that answers every request it gets.
    Reply diagnostics(std::uint16_t sub, std::uint16_t data, std::uint16_t& out) override;
    Reply serverId(ServerId& out) override;

    std::int64_t bytes() const { return bytes_; }
    std::int64_t frames() const { return frames_; }
    std::int64_t transactions() const { return transactions_; }

private:
    Reply account(FrameBytes f, Exception e);
    ControllerImage& image_;
    std::int64_t bytes_ = 0, frames_ = 0, transactions_ = 0;
    std::uint16_t busMessages_ = 0, busExceptions_ = 0; // since the last clear (FC 8 sub-function 10)
};

// Wire time of `bytes` in `frames` at `baud`, 10 bits a byte (8N1), plus a
// 1.75 ms gap per frame (the 3.5-character gap above 19200 baud).
inline double wireSeconds(std::int64_t bytes, std::int64_t frames, int baud = 115200) {
    return static_cast<double>(bytes) * 10.0 / baud + static_cast<double>(frames) * 0.00175;
}

} // namespace k528::link
