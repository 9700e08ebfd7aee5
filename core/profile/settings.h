// The `simulation` section of a machine profile: an ordered key=value map the
// simulation reads (tick, nesting limit, the physical data of each axis ...).
//
// The engine, axis and machine code decide which keys they read; this class
// stores them, keeps their order (files and the database show them as
// written), and converts values with clear errors. Known keys are listed in
// `simulationKeys()` and in docs/profile-format.md: a known key's value is
// checked when a file is read; other keys are kept as they are (validate()
// warns about them, they may be typos).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace k528::profile {

// A value that cannot be converted to the type asked for, or a key/value
// that cannot be stored.
struct SettingError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class Settings {
public:
    using Entry = std::pair<std::string, std::string>;

    // Sets `key` to `value`: replaces the value in place if the key exists,
    // appends it otherwise. Throws SettingError for a bad key (see
    // keyError()) or value (see valueError()).
    void set(std::string_view key, std::string_view value);
    void setInt(std::string_view key, std::int64_t value);
    void setDouble(std::string_view key, double value); // shortest exact text
    void setBool(std::string_view key, bool value);     // "true" / "false"
    // Removes `key`; false if it was not there.
    bool erase(std::string_view key);
    void clear() { entries_.clear(); }

    bool has(std::string_view key) const;
    std::optional<std::string> find(std::string_view key) const;
    std::string getString(std::string_view key, std::string_view fallback) const;
    // The value of `key`, or `fallback` when the key is absent. A present
    // value that is not of the type throws SettingError naming key and value.
    std::int64_t getInt(std::string_view key, std::int64_t fallback) const;
    double getDouble(std::string_view key, double fallback) const;
    // true/false, also 1/0, yes/no, on/off.
    bool getBool(std::string_view key, bool fallback) const;
    // As above, but an absent key throws SettingError too.
    std::int64_t requireInt(std::string_view key) const;
    double requireDouble(std::string_view key) const;

    const std::vector<Entry>& entries() const { return entries_; }
    std::size_t size() const { return entries_.size(); }
    bool empty() const { return entries_.empty(); }

    bool operator==(const Settings&) const = default;

    // "" if `key` is a valid key: 1..64 characters of a-z, 0-9, '_', '.',
    // starting with a letter; otherwise what is wrong.
    static std::string keyError(std::string_view key);
    // "" if `value` can be stored: one line of valid UTF-8, at most 200
    // characters, no ';' (comments), no leading or trailing blanks.
    static std::string valueError(std::string_view value);

private:
    std::vector<Entry> entries_;
};

// Conversions used by the getters (no exceptions): nullopt when `text` is not
// a whole number / a decimal number / a boolean word.
std::optional<std::int64_t> parseInt(std::string_view text);
std::optional<double> parseDouble(std::string_view text);
std::optional<bool> parseBool(std::string_view text);
// Shortest decimal text that reads back to exactly `v` ("0.5", "10", "1e-07").
std::string formatDouble(double v);

// The registry of known simulation keys (docs/profile-format.md has the same
// table). Axis keys exist for "x." and "z.".
enum class SettingType { Int, Double, Bool, String };

struct SimulationKey {
    std::string_view key; // e.g. "tick_ms", "x.screw_lead_mm"
    SettingType type;
    double min; // for Int / Double
    double max;
    std::string_view defaultValue; // what the reader assumes when absent ("" none)
    std::string_view unit;
    std::string_view description;
    std::string_view readBy; // module that reads it
};

std::span<const SimulationKey> simulationKeys();
const SimulationKey* findSimulationKey(std::string_view key);
// "" if `value` fits `key`'s registered type and range (or `key` is unknown),
// otherwise what is wrong.
std::string checkSimulationValue(std::string_view key, std::string_view value);

} // namespace k528::profile
