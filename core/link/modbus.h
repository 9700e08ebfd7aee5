// Modbus itself, without Qt: the protocol data units of the functions the
// map uses (3, 6, 16, 23, 8, 17), the server's answer to a request over a
// RegisterHandler, and the client (master) that frames them on a line and
// keeps what a Modbus user needs to diagnose it — every frame with its time,
// direction, bytes and CRC (FrameLog), the bytes on the wire (WireCount).
//
// The framing is a subclass of ModbusMaster: RtuMaster (RS485: address, PDU,
// CRC-16, the 3.5-character gaps) over a BytePort, the serial port the
// plugin opens. Modbus TCP (MBAP header, unit id) is another subclass over a
// socket's BytePort; the procedures of client.h run over either, as both are
// RegisterTransports.
//
// The RS485 plugin (plugins/modbus-rtu) compiles this file into itself (it
// links Qt only), the host links it as part of k528_link.
#pragma once

#include "link/transport.h"

#include <chrono>
#include <cstdint>
#include <deque>
#include <span>
#include <string>
#include <vector>

namespace k528::link {

using Bytes = std::vector<std::uint8_t>;

namespace modbus {

enum Function : std::uint8_t {
    ReadHolding = 3,
    WriteSingle = 6,
    Diagnostics = 8,
    WriteMultiple = 16,
    ReportServerId = 17,
    ReadWrite = 23,
};

// Sub-functions of function 8 (Modbus application protocol 6.8).
enum Diagnostic : std::uint16_t {
    ReturnQueryData = 0,
    ClearCounters = 10,
    BusMessages = 11,
    BusCommunicationErrors = 12, // CRC errors
    BusExceptions = 13,
    ServerMessages = 14,
    ServerNoResponse = 15,
    ServerNak = 16,
    ServerBusy = 17,
    BusCharacterOverrun = 18,
};

// The counters of sub-functions 11..18, in that order, with their names.
inline constexpr Diagnostic kCounters[] = {BusMessages,      BusCommunicationErrors, BusExceptions, ServerMessages,
                                           ServerNoResponse, ServerNak,              ServerBusy,    BusCharacterOverrun};
const char* counterName(Diagnostic d); // "bus messages", "bus CRC errors", ...

// CRC-16 of Modbus RTU (polynomial 0xA001, initial 0xFFFF); the low byte
// goes first on the line.
std::uint16_t crc16(std::span<const std::uint8_t> bytes);

// Request PDUs (function code, then data; big-endian words).
Bytes readRequest(int first, int count);
Bytes writeRequest(int first, std::span<const std::uint16_t> values); // FC 6 for one register, else 16
Bytes writeReadRequest(int writeFirst, std::span<const std::uint16_t> values, int readFirst, int readCount);
Bytes diagnosticsRequest(std::uint16_t sub, std::uint16_t data);
Bytes serverIdRequest();

// The whole length of a response PDU from its first bytes: -1 while more
// bytes are needed to tell, 0 when the function is none of ours (the length
// cannot be known).
int responseLength(std::span<const std::uint8_t> pdu);
// The same for a request PDU (a server reading a line).
int requestLength(std::span<const std::uint8_t> pdu);

// A response PDU checked against its request: an exception, a reply that
// does not fit (function, count, echo), or the registers / word read.
Reply decodeRegisters(std::span<const std::uint8_t> request, std::span<const std::uint8_t> response,
                      std::vector<std::uint16_t>& out);
Reply decodeWrite(std::span<const std::uint8_t> request, std::span<const std::uint8_t> response);
Reply decodeDiagnostics(std::span<const std::uint8_t> request, std::span<const std::uint8_t> response,
                        std::uint16_t& data);
// FC 17: the server id, its run indicator and the additional data.
Reply decodeServerId(std::span<const std::uint8_t> response, ServerId& out);

// The controller's side of one request: FC 3, 6, 16 and 23 on `handler`
// (its exception codes answered as Modbus exceptions, FC 23 writing first),
// anything else exception 01. Returns the response PDU.
using link::RegisterHandler;
Bytes serveRegisters(std::span<const std::uint8_t> request, RegisterHandler& handler);
Bytes exceptionResponse(std::uint8_t function, int code);

// RTU: address, PDU, CRC (low byte first).
Bytes rtuFrame(int address, std::span<const std::uint8_t> pdu);
bool rtuCrcOk(std::span<const std::uint8_t> frame);

} // namespace modbus

// Bytes and frames put on the line, both directions, and the exchanges.
struct WireCount {
    std::int64_t bytes = 0, frames = 0, transactions = 0;
};

// The frames a master sent and received (the newest `capacity`), for the
// line's diagnosis: time, direction, station, bytes, CRC.
struct Frame {
    std::int64_t unixMicros = 0; // the PC's clock when the frame was sent / its last byte came
    bool sent = false;
    int station = 0;
    Bytes bytes;
    // Short: cut off before its end; Mbap: a Modbus TCP frame (no CRC, its
    // MBAP header gives its length).
    enum class Check { Ok, Bad, Short, Mbap } check = Check::Ok;
    std::string note; // "timeout", "unexpected (a late answer?)", ...
};

class FrameLog {
public:
    explicit FrameLog(std::size_t capacity = 20000) : capacity_(capacity) {}
    void add(Frame f);
    const std::deque<Frame>& frames() const { return frames_; }
    std::int64_t dropped() const { return dropped_; } // older frames no longer kept
    void clear() {
        frames_.clear();
        dropped_ = 0;
    }

private:
    std::size_t capacity_;
    std::deque<Frame> frames_;
    std::int64_t dropped_ = 0;
};

// One line a frame: "2026-12-03 10:15:02.123456 UTC  TX  st 1  01 03 17 70 00 20 41 A9  CRC ok".
std::string formatFrame(const Frame& f);
std::string formatFrameLog(const FrameLog& log);

// A serial port (or a socket) as a stream of bytes; the plugin gives one.
class BytePort {
public:
    virtual ~BytePort() = default;
    // Sends all of `bytes`; false with `error` when the port fails.
    virtual bool write(std::span<const std::uint8_t> bytes, std::string& error) = 0;
    // Waits up to `ms` (0: only what is there) and appends what came;
    // false with `error` when the port fails.
    virtual bool read(Bytes& into, int ms, std::string& error) = 0;
    virtual bool isOpen() const = 0;
    // Opens the port again after it failed (a USB adapter pulled and put back).
    virtual bool reopen(std::string& error) = 0;
};

// A Modbus client over some framing: the register exchanges of the map,
// diagnostics (FC 8) and the server id (FC 17), to the station of
// setStation (1..247); counts the wire and logs every frame.
class ModbusMaster : public RegisterTransport {
public:
    Reply read(int first, int count, std::vector<std::uint16_t>& out) override;
    Reply write(int first, std::span<const std::uint16_t> values) override;
    Reply writeRead(int writeFirst, std::span<const std::uint16_t> values, int readFirst, int readCount,
                    std::vector<std::uint16_t>& out) override;
    Reply echo(std::uint16_t value) override;
    Reply diagnostics(std::uint16_t sub, std::uint16_t data, std::uint16_t& out) override;
    Reply serverId(ServerId& out) override;
    int station() const override { return station_; }
    bool setStation(int address) override;

    const WireCount& wire() const { return wire_; }
    FrameLog& frameLog() { return log_; }
    const FrameLog& frameLog() const { return log_; }

protected:
    explicit ModbusMaster(int station) : station_(station) {}
    // One request PDU out, its response PDU back (empty unless ok()).
    virtual Reply exchange(const Bytes& request, Bytes& response) = 0;
    virtual void stationChanged() {}
    // The exchange of `request`, its response decoded.
    template <class Decode> Reply ask(const Bytes& request, Decode&& decode);
    WireCount wire_;
    FrameLog log_;
    int station_;
};

struct RtuSettings {
    int station = 1;
    int baud = 115200;
    int bitsPerChar = 10; // start, 8 data, parity if any, stop bits
    int timeoutMs = 200;  // for the answer to begin after the request left
};

// Modbus RTU over a serial BytePort. A frame is complete when it has the
// length its function gives (an answer that stops short ends at the
// timeout); a bad CRC or a short frame is Reply::Damaged. The answer is
// found by its CRC wherever it begins (a late answer's rest before it is
// dropped); bytes between exchanges are logged and dropped before the next
// request; requests keep the 3.5-character gap. After a timeout the next
// wait doubles (at most 4 × the timeout) until an answer comes; a new
// station starts again at the timeout. A port that failed is opened again
// at the next exchange.
class RtuMaster : public ModbusMaster {
public:
    RtuMaster(BytePort& port, RtuSettings s) : ModbusMaster(s.station), port_(port), s_(s) {}
    const RtuSettings& settings() const { return s_; }
    // The silent interval between frames: 3.5 characters, 1.75 ms above 19200 bit/s.
    std::chrono::microseconds gap() const;

protected:
    Reply exchange(const Bytes& request, Bytes& response) override;
    void stationChanged() override { patience_ = 1; }

private:
    void drain();
    void log(bool sent, const Bytes& bytes, Frame::Check check, std::string note = {});
    BytePort& port_;
    RtuSettings s_;
    std::chrono::steady_clock::time_point lastActivity_{};
    std::chrono::steady_clock::time_point nextReopen_{};
    int patience_ = 1; // the wait, in timeouts
};

} // namespace k528::link
