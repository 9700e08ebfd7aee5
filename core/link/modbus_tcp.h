// Modbus TCP without Qt: the MBAP framing (transaction id, protocol 0,
// length, unit id, then the PDU) of core's ModbusMaster over a BytePort that
// is a TCP connection — to a serial-to-Ethernet gateway in Modbus TCP mode
// (Moxa NPort and the like) whose RS485 line reaches the K528-05, or to
// `k528 serve --tcp`. The unit id is the station address behind the gateway.
// The procedures of client.h, the wire count and the frame log are those of
// RtuMaster; only the framing differs (docs/link.md, *Modbus TCP*).
//
// The TCP plugin (plugins/modbus-tcp) compiles this file into itself.
#pragma once

#include "link/modbus.h"

#include <chrono>
#include <cstdint>
#include <span>

namespace k528::link {

namespace modbus {
// MBAP header (7 bytes, big-endian: transaction, protocol 0, length of unit
// id + PDU, unit id) and the PDU.
Bytes mbapFrame(std::uint16_t transaction, int unit, std::span<const std::uint8_t> pdu);
} // namespace modbus

struct TcpSettings {
    int station = 1;     // the unit id
    int timeoutMs = 200; // for the answer after the request left
};

// The answer is the frame whose transaction id is the request's: an answer
// that came after its request timed out is logged and dropped when it
// arrives. A header that cannot be Modbus TCP (protocol not 0, a length
// outside 2..254) leaves the stream out of step: the answer is damaged and
// the connection is closed, to be opened again at the next exchange. An
// answer from another unit is a bad reply. A timeout makes the next wait
// longer (twice, at most 4 × the timeout) until an answer comes. A closed
// connection is opened again at the next exchange, at most every 250 ms.
class TcpMaster : public ModbusMaster {
public:
    TcpMaster(BytePort& port, TcpSettings s) : ModbusMaster(s.station), port_(port), s_(s) {}
    const TcpSettings& settings() const { return s_; }

protected:
    Reply exchange(const Bytes& request, Bytes& response) override;
    void stationChanged() override { patience_ = 1; }

private:
    void log(bool sent, const Bytes& bytes, Frame::Check check, std::string note = {});
    BytePort& port_;
    TcpSettings s_;
    std::uint16_t transaction_ = 0;
    Bytes pending_; // bytes received after the last whole frame
    std::chrono::steady_clock::time_point nextReopen_{};
    int patience_ = 1;
};

} // namespace k528::link
