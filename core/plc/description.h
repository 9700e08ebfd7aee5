// The machine description (resources/machines/<name>.json): what the
// simulated PLC does on one machine, as data — its inputs and outputs, the
// logic of segment 2, the M functions, interlocks, the K923 keys and LEDs,
// which PLC messages it raises — and the machine's equipment, which
// core/machine reads. The full schema and both shipped machines are in
// docs/machine-description.md.
//
// Reading checks the structure, the value ranges and the names; conditions
// are compiled (and their names resolved) by plc::Plc. Every error is a
// DescriptionError naming the file, the path in the document and what is
// wrong.
#pragma once

#include "plc/json_reader.h"
#include "util/json_fwd.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace k528::plc {

struct InputDef {
    std::string name;   // PLC name used by conditions
    std::string signal; // the machine signal wired to it (core/machine, e.g. "door.closed")
    bool normallyClosed = false; // NC contact: the input reads 1 while the signal is 0
    int module = 0;              // place of the I/O module (0..15)
    int debounceMs = 8;          // GOST 26642 6.1.7: 5..10 ms
    std::string text;
    std::string path; // in the document, for messages
};

struct OutputDef {
    std::string name;
    std::string signal; // the actuator or lamp it drives (e.g. "spindle.fwd")
    int module = 0;
    std::string text;
    std::string path;
};

struct FlagDef {
    std::string name;
    std::string text;
    std::string path;
};

enum class RungKind : std::uint8_t { Coil, Set, Reset, OnDelay, OffDelay, Pulse };

struct RungDef {
    RungKind kind = RungKind::Coil;
    std::string target; // output, flag, Z bit — or the timer's name
    std::string when;   // condition
    int ms = 0;         // timers
    std::string path;
};

// Actions on signals (outputs, flags, writable Z bits).
struct Actions {
    std::vector<std::string> set, reset, toggle, pulse;
    std::string path;
    bool empty() const { return set.empty() && reset.empty() && toggle.empty() && pulse.empty(); }
};

struct MFunctionDef {
    int m = 0;
    // What it does, for people (the editor's completion): {"ru", "en"} in
    // the document, both required; a plain string is one text written in one
    // language, shown as written in both windows (a user's own description).
    std::string textRu, textEn;
    Actions actions;  // done at the strobe
    std::string done; // acknowledge when this holds ("" = at once, after T3)
    int waitWork = 0; // work message shown while waiting (0 none)
    int timeoutMs = 0;
    int timeoutAlarm = 0; // alarm raised when `done` does not come within timeoutMs
    std::string path;
};

struct InterlockDef {
    std::string name;
    std::string when;
    int alarm = 0, work = 0;
    bool feedHold = false, dataHold = false, startInhibit = false;
    bool stopProgram = false, resetProgram = false, estop = false;
    bool latch = false;           // stays until acknowledged (Z1000.7) once the cause is gone
    std::vector<std::string> off; // outputs/flags forced to 0 while active
    int overrideMaxCode = -1;     // caps the PLC override code (0..10), -1 none
    std::string path;
};

struct KeyDef {
    int key = 0; // K1..K12
    std::string text;
    std::string when; // "" = always
    Actions actions;
    std::string path;
};

struct LedDef {
    int key = 0;
    std::string green, red; // conditions ("" = off)
    std::string path;
};

struct MessageDef {
    int k = 0; // 1..32
    std::string when;
    std::string path;
};

// A bit of a word the PLC writes to the positioner (Z1000..Z1013), with its
// condition — the positioner section, resolved to addresses.
struct SlotDef {
    int word = 0, bit = 0;
    std::string key; // as written ("feed_enable", "x.jog_plus", "Z1011.3")
    std::string when;
    std::string path;
};

struct ModeRule {
    int code = 0; // Z1000.8-10
    std::string when;
    std::string path;
};

struct OverrideDef {
    std::string fromPlc;             // Z1001.11 condition ("" = never)
    std::array<std::string, 4> code; // the four code bits, least significant first
    bool present = false;
    std::string path;
};

struct ModuleDef {
    int place = 0;
    std::string title;
};

struct PlcTiming {
    int debounceMs = 8;                             // default input debounce (GOST 26642 6.1.7)
    int pulseMs = 20;                               // pulses of keys and logic
    int t1Ms = 20, t2Ms = 20, t3Ms = 40, t4Ms = 80; // GOST 26642 6.4
};

struct UnknownMDef {
    bool acknowledge = true; // false: raise `alarm` and hold the frame until «Сброс»
    int alarm = 0;
};

struct MachineDescription {
    std::string source; // file name or resource path, for messages
    std::string name, title;
    PlcTiming timing;
    std::vector<ModuleDef> modules;
    std::vector<InputDef> inputs;
    std::vector<OutputDef> outputs;
    std::vector<FlagDef> flags;
    std::vector<RungDef> logic;
    std::vector<MFunctionDef> mFunctions;
    UnknownMDef unknownM;
    std::vector<InterlockDef> interlocks;
    std::vector<KeyDef> keys;
    std::vector<LedDef> leds;
    std::vector<MessageDef> alarms, work;
    std::vector<SlotDef> slotDefs;
    std::vector<ModeRule> modeRules;
    OverrideDef override_;
    // Shared by the copies of a description (pointers: this header only declares Json).
    std::shared_ptr<const Json> equipment; // for core/machine ({} without "equipment")
    std::shared_ptr<const Json> document;  // the whole document (kept for paths in later checks)

    const MFunctionDef* mFunction(int m) const;
};

// Reads a description; throws DescriptionError.
MachineDescription readDescription(std::string_view text, const std::string& source);

// The description of machine `name`: the embedded resources/machines/<name>.json,
// or a file when `nameOrPath` ends in ".json". Throws DescriptionError
// (an unknown name lists the embedded ones).
MachineDescription loadDescription(std::string_view nameOrPath);
bool descriptionExists(std::string_view name); // embedded
std::vector<std::string> descriptionNames();   // embedded, sorted

// The addresses a slot key names: "estop_ok" -> Z1000.0, "x.jog_plus" -> Z1005.7 ...
// nullopt for an unknown key.
struct ZAddress {
    int word = 0, bit = 0;
};
std::optional<ZAddress> slotAddress(std::string_view key);
// Every slot key, for messages and docs.
std::vector<std::string> slotKeys();
// Parses "Z1005.7"; nullopt when malformed.
std::optional<ZAddress> parseZ(std::string_view text);

} // namespace k528::plc
