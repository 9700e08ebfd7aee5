// A small, strict option parser for the subcommands: long options only
// (--name, --name VALUE, --name=VALUE), positional arguments, `--` ends
// options. Every problem becomes one clear message.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace k528::cli {

class Args {
public:
    // `flags` take no value; `options` take one value and may repeat.
    Args(std::span<const std::string> args, std::vector<std::string_view> flags,
         std::vector<std::string_view> options);

    // False if an unknown option or a missing value was met; see error().
    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }

    bool has(std::string_view flag) const;
    // The last value given for `option`, if any.
    std::optional<std::string> value(std::string_view option) const;
    // Every value given for `option`, in order.
    std::vector<std::string> values(std::string_view option) const;
    const std::vector<std::string>& positional() const { return positional_; }

private:
    std::vector<std::pair<std::string, std::string>> given_; // option -> value ("" for flags)
    std::vector<std::string> positional_;
    std::string error_;
};

// Parses a whole decimal integer ("12", "-5"); nullopt on anything else.
std::optional<long long> parseInt(std::string_view s);
// Parses a finite decimal number ("12", "-0.5", "3600"); nullopt on anything
// else (also "nan", "inf").
std::optional<double> parseNumber(std::string_view s);
// "N=V" with whole integers (--param, --r); false if malformed.
bool parseAssignment(const std::string& text, long long& n, long long& v);

} // namespace k528::cli
