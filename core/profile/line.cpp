#include "profile/line.h"

#include <charconv>

namespace k528::profile {

namespace {

std::optional<int> number(std::string_view s) {
    int v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || s.empty())
        return std::nullopt;
    return v;
}

} // namespace

std::optional<LineAddress> parseLine(std::string_view text, Problem& problem) {
    // What is wrong as problem.cpp's line.* id, the value as given first.
    const auto fail = [&](const char* id, std::string_view what = {}) -> std::optional<LineAddress> {
        problem = profile::problem(id, {std::string(text)});
        if (!what.empty())
            problem.args.emplace_back(what);
        return std::nullopt;
    };
    LineAddress a;
    if (text.starts_with("tcp://")) {
        a.kind = LineAddress::Kind::Tcp;
        std::string_view rest = text.substr(6);
        const std::size_t slash = rest.find('/');
        const std::string_view hostPort = rest.substr(0, slash);
        if (slash != std::string_view::npos) {
            const auto unit = number(rest.substr(slash + 1));
            if (!unit || *unit < 1 || *unit > 247)
                return fail("line.unit");
            a.address = *unit;
        }
        const std::size_t colon = hostPort.rfind(':');
        if (colon == std::string_view::npos || colon == 0)
            return fail("line.host-port");
        std::string_view host = hostPort.substr(0, colon);
        if (host.size() >= 2 && host.front() == '[' && host.back() == ']')
            host = host.substr(1, host.size() - 2);
        const auto port = number(hostPort.substr(colon + 1));
        if (host.empty() || !port || *port < 1 || *port > 65535)
            return fail("line.port");
        for (const char c : host)
            if (c == ' ' || c == '/' || c == '?' || c == '@')
                return fail("line.host", host);
        a.host = std::string(host);
        a.port = *port;
        return a;
    }
    if (text.starts_with("serial:")) {
        std::string_view rest = text.substr(7);
        const std::size_t q = rest.find('?');
        a.device = std::string(rest.substr(0, q));
        if (a.device.empty())
            return fail("line.device");
        std::string_view query = q == std::string_view::npos ? std::string_view() : rest.substr(q + 1);
        while (!query.empty()) {
            const std::size_t amp = query.find('&');
            const std::string_view item = query.substr(0, amp);
            query = amp == std::string_view::npos ? std::string_view() : query.substr(amp + 1);
            const std::size_t eq = item.find('=');
            const std::string_view key = item.substr(0, eq);
            const std::string_view value = eq == std::string_view::npos ? std::string_view() : item.substr(eq + 1);
            const auto n = number(value);
            if (key == "baud") {
                if (!n || *n < 1200 || *n > 4000000)
                    return fail("line.baud");
                a.baud = *n;
            } else if (key == "parity") {
                if (value == "none")
                    a.parity = 'N';
                else if (value == "even")
                    a.parity = 'E';
                else if (value == "odd")
                    a.parity = 'O';
                else
                    return fail("line.parity");
            } else if (key == "stop_bits") {
                if (!n || (*n != 1 && *n != 2))
                    return fail("line.stop-bits");
                a.stopBits = *n;
            } else if (key == "address") {
                if (!n || *n < 1 || *n > 247)
                    return fail("line.address");
                a.address = *n;
            } else {
                return fail("line.key", key);
            }
        }
        return a;
    }
    return fail("line.form");
}

std::optional<LineAddress> parseLine(std::string_view text, std::string& error) {
    Problem p;
    const std::optional<LineAddress> a = parseLine(text, p);
    if (!a)
        error = p.text();
    return a;
}

Problem lineProblem(std::string_view text) {
    Problem p;
    return parseLine(text, p) ? Problem() : p;
}

std::string lineError(std::string_view text) { return lineProblem(text).text(); }

std::string lineEndpoint(const LineAddress& a) {
    if (a.kind == LineAddress::Kind::Serial)
        return a.device;
    const bool v6 = a.host.find(':') != std::string::npos;
    return (v6 ? "[" + a.host + "]" : a.host) + ":" + std::to_string(a.port);
}

std::string formatLine(const LineAddress& a) {
    if (a.kind == LineAddress::Kind::Tcp)
        return "tcp://" + lineEndpoint(a) + "/" + std::to_string(a.address);
    const char* parity = a.parity == 'E' ? "even" : a.parity == 'O' ? "odd" : "none";
    return "serial:" + a.device + "?baud=" + std::to_string(a.baud) + "&parity=" + parity +
           (a.stopBits == 2 ? "&stop_bits=2" : "") + "&address=" + std::to_string(a.address);
}

} // namespace k528::profile
