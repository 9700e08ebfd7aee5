// Errors of the database module. Every message says what is wrong and where
// (the file, the machine, the item).
#pragma once

#include "profile/validate.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace k528::db {

enum class ErrorKind {
    Io,            // the file cannot be opened, created, read or written
    Foreign,       // not a K528 Studio database (another program's SQLite file, or not SQLite)
    Corrupt,       // integrity_check failed, or stored data break their own rules
    TooNew,        // written by a newer K528 Studio (schema version above ours)
    Busy,          // another process held the database longer than the busy timeout
    NoMachine,     // no machine of that name
    MachineExists, // a machine of that name already exists
    NoRevision,    // the machine has no such revision
    Conflict,      // the machine changed since the caller read it (expected revision)
    Invalid,       // a value, an edit or a file is rejected (see ValidationError)
    Sql,           // an unexpected SQLite error (a bug: please report it)
};

std::string_view errorKindName(ErrorKind k); // "io", "foreign", ...

class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
    ErrorKind kind() const { return kind_; }

private:
    ErrorKind kind_;
};

// A write rejected by validation: values outside their definitions, or
// cross-check errors of the machine constants (with the manual's message
// numbers). Nothing was written.
class ValidationError : public Error {
public:
    ValidationError(const std::string& message, std::vector<profile::Finding> findings)
        : Error(ErrorKind::Invalid, message), findings_(std::move(findings)) {}
    // The errors that caused the rejection (severity Error).
    const std::vector<profile::Finding>& findings() const { return findings_; }

private:
    std::vector<profile::Finding> findings_;
};

} // namespace k528::db
