// The workstation's side of the link (shared/spec/link.md, docs/link.md):
// the procedures `k528 link` and the studio run — identify, status, pull,
// push (a machine file or a program file) with staged blocks and read-back,
// clear C / R, the station's bus counters, a scan of the bus — over any
// RegisterTransport. The Link checks every reply (count), retries a lost
// exchange (every register of the map is safe to write twice), sends a
// request whose every attempt came back damaged again in halves, and keeps
// the line's counters per station.
#pragma once

#include "link/link_texts.h"
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

// The newest round trips (request sent to answer received), in ms.
class RoundTrips {
public:
    void add(double ms);
    std::int64_t count() const { return count_; }
    double last() const { return last_; }
    double median() const { return quantile(0.5); }
    double p95() const { return quantile(0.95); }
    double quantile(double q) const; // of the newest kCapacity; 0 when none

    static constexpr std::size_t kCapacity = 4096;

private:
    std::vector<float> ring_;
    std::size_t next_ = 0;
    std::int64_t count_ = 0;
    double last_ = 0;
};

// A station's line as a Modbus user reads it.
struct LineStats {
    std::int64_t exchanges = 0;  // answered (an exception is an answer)
    std::int64_t noAnswer = 0;   // timeouts: nothing came
    std::int64_t crcErrors = 0;  // a frame came damaged (bad CRC, or cut short)
    std::int64_t badReplies = 0; // an answer that does not fit the request
    std::int64_t exceptions = 0;
    std::map<int, std::int64_t> exceptionsByCode;
    std::int64_t retries = 0;
    std::int64_t splits = 0; // requests every attempt of which came back damaged, sent again in halves
    RoundTrips roundTrip;
};

// "12 answers, 0 timeouts, 1 CRC error, 0 bad replies, exceptions 06×2, 1 retry; round trip median 4.1 ms, p95 5.0 ms"
std::string describe(const LineStats& s, bool ru = false);

// What went wrong, for the user: an id of link_texts.h with its arguments,
// said by the command line in its --lang and by the desktop in its window's.
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
    Said said;
    int line = 0; // a text the controller refused: its line (a C block's: the constant)
    explicit operator bool() const { return kind != Kind::None; }
    // The message in a language (the command line's --lang).
    std::string text(bool ru) const { return render(said, ru); }
    // "<this>; <more>"
    void append(const Said& more) { said = say("link.then", {said, more}); }
};
inline LinkError linkError(LinkError::Kind kind, int code, Said said) { return {kind, code, std::move(said)}; }

// A Modbus exception of the map: 02 «адрес вне карты» ...; a transfer status.
Said exceptionSaid(int code);
Said statusSaid(int status);

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
    LinkError diagnostics(std::uint16_t sub, std::uint16_t data, std::uint16_t& out);
    LinkError serverId(ServerId& out);

    // The counters of every station together, and per station.
    const LineStats& stats() const { return total_; }
    const std::map<int, LineStats>& stations() const { return stations_; }
    const RegisterMap& map() const { return map_; }
    RegisterTransport& transport() { return t_; }
    int attempts() const { return attempts_; }
    void setAttempts(int n) { attempts_ = n < 1 ? 1 : n; }

private:
    template <class F> LinkError retry(const Said& what, F&& f);
    void count(const Reply& r, bool retry);
    LinkError readPiece(int at, int n, std::vector<std::uint16_t>& out);
    LinkError writePiece(int first, std::span<const std::uint16_t> values);
    bool lastDamaged_ = false; // the last retry() met a damaged or unfitting answer
    RegisterTransport& t_;
    const RegisterMap& map_;
    int attempts_;
    LineStats total_;
    std::map<int, LineStats> stations_;
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
    friend bool operator==(const LiveState&, const LiveState&) = default;
};

LinkError readLive(Link& link, LiveState& out);
LiveState decodeLive(const RegisterMap& map, std::span<const std::uint16_t> regs); // from the live block

// ping: the echo, then the live state.
LinkError identify(Link& link, LiveState& out);

// Why the controller does not take a memory write, naming the K923 screen
// that allows it: «not in F7 … (mode F2 now)», or in F7 УПРАВЛЕНИЕ ДАННЫМИ
// but not on «РАБОТА С ПЭВМ». `what` is the action ("push", "clear C").
Said notReadySaid(const LiveState& live, const Said& what);

// One text through the transfer registers.
LinkError readText(Link& link, bool messages, int program, std::string& text);
// Writes, commits and reads back one text; all or nothing on the controller.
LinkError writeText(Link& link, bool messages, int program, const std::string& text);

// C (117 registers) or the R block (600 registers, R0..R299) staged,
// committed whole by the controller (commands 10 / 11, then 5) and read
// back; `whole` is the block as it is to be (R: only the writable
// R-parameters are sent). `committed` tells whether the controller took it.
LinkError writeBlock(Link& link, BlockKind kind, std::span<const std::uint16_t> whole, bool& committed,
                     bool& commitSent);

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

// What a push sends, checked: from a machine file (C, R, programs, messages)
// or from a program file (its programs and %MESSAGES; C and R untouched).
struct PushPlan {
    bool hasC = false;
    std::vector<std::int64_t> c;       // index = number, 153 values
    bool hasR = false;
    std::array<std::int32_t, 300> r{}; // the writable ones are sent, the rest is not touched
    bool hasMessages = false;
    std::string messagesText;          // canonical %MESSAGES
    std::map<int, std::string> programs; // canonical texts
};

// A machine file: every constant against table Е.1, every R within 32 bits,
// every program parsed and checked for the file's machine. An Input error
// says what is wrong; nothing is sent then.
LinkError planMachineFile(const RegisterMap& map, const profile::MachineProfile& file, PushPlan& plan);
// A program file (`source` names it in messages): parsed here, then checked
// against the controller's own constants and R-parameters and the programs
// of the controller it calls (read over the link), as the controller will
// check it at commit.
LinkError planProgramFile(Link& link, std::string_view text, const std::string& source, PushPlan& plan);

// Where each part of a push ended: new (committed and read back), as it was
// (not sent, or refused whole), or in doubt (the line broke between the
// commit and its answer: pull to see).
struct PushReport {
    enum class State { AsItWas, New, InDoubt };
    struct Part {
        std::string name; // "C-parameters", "R-parameters (R0..R157, …)", "messages", "program 5" (the record's)
        State state = State::AsItWas;
        Said said = {};   // the name for the user
    };
    std::vector<Part> parts; // in the order they are sent
    bool constants = false, rParameters = false, messages = false;
    std::vector<int> programs; // committed and verified
    // "new: C-parameters, program 5; as they were: program 7"
    Said summary() const;
    bool anyNew() const;
};

// Only in F7 «РАБОТА С ПЭВМ»: C, R, the messages and each program, each
// staged, committed whole by the controller and read back. On an error the
// report tells exactly which parts are new and which are as they were.
LinkError push(Link& link, const PushPlan& plan, PushReport& report, const Progress& progress = {});
// planMachineFile, then push.
LinkError push(Link& link, const profile::MachineProfile& file, PushReport& report,
               const Progress& progress = {});

// Clears the C area (all constants 0) or the R area, as the K923's
// «ОЧИСТКА С-ПАРАМ» / «ОЧИСТКА Р-ПАРАМ» (manual 2.6.8; F7 only).
LinkError clearArea(Link& link, BlockKind kind);

// One machine constant or R-parameter written directly (F7 «РАБОТА С
// ПЭВМ» only, as the panel's desktop edit of one value), then read back.
// A constant that shares its word (a bit, a byte) is merged into the word as
// the controller holds it; the controller checks the whole block (exception
// 03 for a value outside table Е.1). An R the PC may not write is refused
// before anything is sent.
LinkError setConstant(Link& link, int number, std::int64_t value);
LinkError setRParameter(Link& link, int number, std::int64_t value);

// The station's bus counters (FC 8 sub-functions 11..18), in kCounters order.
struct BusCounters {
    std::array<std::uint16_t, 8> values{};
};
LinkError readBusCounters(Link& link, BusCounters& out);
LinkError clearBusCounters(Link& link);

// One station of a bus scan: it answered the echo (or answered something),
// and who it is — FC 17's server id, and the live block when it carries the map.
struct StationInfo {
    int address = 0;
    bool answers = false;   // a good echo, or an exception (someone is there)
    bool garbled = false;   // only damaged frames came back (another baud or parity?)
    std::string echo;       // "echo ok", "exception 01", ... (English: --json's)
    int echoException = 0;  // the exception the echo got (0: a good echo)
    std::optional<ServerId> id;
    std::optional<LiveState> live; // when the K528-05 map's live block reads
    double roundTripMs = 0;
};
// Asks station `address` (one attempt each: a scan does not retry silence).
StationInfo probeStation(Link& link, int address);
// "address 7: echo ok; server id 0x28 «…»; K528-05 map: mode F7 …" in a language.
std::string describe(const StationInfo& s, bool ru = false);

} // namespace k528::link
