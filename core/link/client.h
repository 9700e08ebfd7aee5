// The workstation's side of the link (shared/spec/link.md): the procedures
// `k528 link` and the studio run — identify, status, pull, push with read-
// back — over any RegisterTransport. The Link checks every reply (count),
// retries a lost exchange (every register of the map is safe to write twice)
// and keeps the line's state.
#pragma once

#include "link/register_map.h"
#include "link/transport.h"
#include "profile/profile.h"

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace k528::link {

struct LineStats {
    std::int64_t exchanges = 0; // answered
    std::int64_t noAnswer = 0;  // timeouts (a damaged frame ends as one)
    std::int64_t badReplies = 0;
    std::int64_t exceptions = 0;
    std::int64_t retries = 0;
};

// What went wrong, for the user.
struct LinkError {
    enum class Kind {
        None,
        NoAnswer,   // the line does not answer (exit 2)
        Exception,  // the controller refused (exit 1)
        NotReady,   // not in F7 «РАБОТА С ПЭВМ» (exit 1)
        Refused,    // a transfer status: text refused, CRC, memory full, no such program
        Verify,     // the read-back differs
        Input,      // the file to push is wrong; nothing was sent
    };
    Kind kind = Kind::None;
    int code = 0; // exception code or transfer status
    std::string message;
    explicit operator bool() const { return kind != Kind::None; }
};

// The text of a Modbus exception of the map: 02 «адрес вне карты» ...
std::string exceptionText(int code);
std::string statusText(int status);

class Link {
public:
    explicit Link(RegisterTransport& t, const RegisterMap& map = k528Map(), int attempts = 4)
        : t_(t), map_(map), attempts_(attempts) {}

    // Each returns an empty error on success.
    LinkError read(int first, int count, std::vector<std::uint16_t>& out);
    LinkError write(int first, std::span<const std::uint16_t> values);
    LinkError writeRead(int writeFirst, std::span<const std::uint16_t> values, int readFirst,
                        int readCount, std::vector<std::uint16_t>& out);
    LinkError echo(std::uint16_t value);

    const LineStats& stats() const { return stats_; }
    const RegisterMap& map() const { return map_; }

private:
    template <class F> LinkError retry(const std::string& what, F&& f);
    RegisterTransport& t_;
    const RegisterMap& map_;
    int attempts_;
    LineStats stats_;
};

struct AlarmBit {
    int number = 0;
};

// The live state (registers 6000..6031).
struct LiveState {
    int mode = 0; // 1..7 = F1..F7, 0 power-on
    bool pcReady = false, running = false, alarm = false, homedX = false, homedZ = false;
    int program = 0, frame = 0, overridePercent = 0;
    std::int32_t xCurrent = 0, zCurrent = 0, xMachine = 0, zMachine = 0, xError = 0, zError = 0;
    std::vector<int> alarms;   // numbers 1..64
    int message = 0;           // technological message shown
    std::vector<int> programs; // present in the controller
};

LinkError readLive(Link& link, LiveState& out);
LiveState decodeLive(const RegisterMap& map, std::span<const std::uint16_t> regs); // from the live block

// ping: the echo, then the live state.
LinkError identify(Link& link, LiveState& out);

// One text through the transfer registers.
LinkError readText(Link& link, bool messages, int program, std::string& text);
// Writes, commits and reads back one text; all or nothing on the controller.
LinkError writeText(Link& link, bool messages, int program, const std::string& text);

struct PullResult {
    std::vector<std::int64_t> c;          // index = number, 153 values
    std::array<std::int32_t, 300> r{};    // R0..R299
    std::map<int, std::string> programs;  // canonical texts
    std::string messagesText;             // the %MESSAGES section
};
using Progress = std::function<void(const std::string& what, int done, int total)>;

LinkError pull(Link& link, PullResult& out, const Progress& progress = {});
// The pulled memory as a machine profile (the format of `k528 db export`):
// the writable R-parameters that are not 0 as presets, as the studio keeps a memory.
profile::MachineProfile pulledProfile(const PullResult& p, const std::string& name, const std::string& title);

struct PushReport {
    bool constants = false, rParameters = false, messages = false;
    std::vector<int> programs; // committed and verified
};
// Checks the file first (every constant against table Е.1, every program and
// the messages parsed and checked for the machine): nothing is sent when it
// fails. Then, only in F7 «РАБОТА С ПЭВМ»: C-parameters, R0..R149, each
// program and the messages, each written, committed and read back.
LinkError push(Link& link, const profile::MachineProfile& file, PushReport& report,
               const Progress& progress = {});

} // namespace k528::link
