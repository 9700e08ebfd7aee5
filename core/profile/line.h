// Where a machine's controller is: the `line` setting of a machine of the
// database (shared/spec/cli.md, docs/shop.md):
//   tcp://HOST:PORT/UNIT        Modbus TCP (a serial-to-Ethernet gateway, or
//                               `k528 serve --tcp`); UNIT is the station
//                               address behind the gateway (1..247, default 1)
//   serial:DEVICE?baud=115200&parity=none&address=1
//                               RS485 / Modbus RTU; the query is optional
//                               (defaults 115200, none, 1 stop bit, address 1),
//                               keys baud, parity (none|even|odd), stop_bits
//                               (1|2), address.
#pragma once

#include "profile/problem.h"

#include <optional>
#include <string>
#include <string_view>

namespace k528::profile {

struct LineAddress {
    enum class Kind { Serial, Tcp } kind = Kind::Serial;
    std::string device; // Serial
    int baud = 115200;
    char parity = 'N'; // N, E, O
    int stopBits = 1;
    std::string host; // Tcp
    int port = 0;
    int address = 1; // the station address; the unit id on TCP
    bool operator==(const LineAddress&) const = default;
};

// The address of `text`, or nullopt with `problem` saying what is wrong (a
// line.* id of problem.cpp's catalog, the value as its first argument: the
// command line says it in its --lang, the desktop in the window's language).
std::optional<LineAddress> parseLine(std::string_view text, Problem& problem);
// The same with what is wrong in English.
std::optional<LineAddress> parseLine(std::string_view text, std::string& error);
// Nothing when `text` is a line, else what is wrong (the settings' check).
Problem lineProblem(std::string_view text);
// lineProblem in English, "" when `text` is a line.
std::string lineError(std::string_view text);
// The canonical text: tcp://HOST:PORT/UNIT, serial:DEVICE?baud=…&parity=…&address=…
// (stop_bits only when 2).
std::string formatLine(const LineAddress& a);
// HOST:PORT of a TCP line (an IPv6 host in brackets); the device of a serial one.
std::string lineEndpoint(const LineAddress& a);

} // namespace k528::profile
