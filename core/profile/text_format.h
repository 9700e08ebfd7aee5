// The machine file (.k528m): a machine profile as readable text, the same
// text the database exports and imports. The format is documented in
// docs/profile-format.md. In short:
//
//   ; comment
//   [machine]
//   format=1
//   name=grinder-205
//   title=...
//   [c]
//   C022=2000 ; УСКОРЕНИЕ 1          (all 152; the comment is the panel name, ignored)
//   [r]
//   R204=20000 ; ДИАМЕТР НОВ.КРУГА
//   [program 11]
//   %L11 (...)                      (the program text, verbatim)
//   [end program]
//   [messages]
//   #1=ПОДВОД
//   [plc-messages]
//   A01=...   W01=...   S01=...
//   [simulation]
//   tick_ms=1
//
// readMachineText(writeMachineText(p)) == p for every profile the reader
// accepts, and writeMachineText(readMachineText(t)) == t for every text
// writeMachineText produced. Reading checks every line and every value against
// its definition and rejects the whole file at the first error, naming its line.
// Cross-checks between constants (validate()) do not reject a file: a trainer
// may prepare a machine with a wrong N ДОС on purpose.
#pragma once

#include "profile/problem.h"
#include "profile/profile.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace k528::profile {

inline constexpr int kMachineFileFormat = 1;

// A machine file (or CSV) that cannot be read. what() is
// "<source>:<line>: <message>" (or "<source>: <message>" when line is 0);
// problem() is the message as an id and its arguments (problem.h).
class FileError : public std::runtime_error {
public:
    FileError(std::string source, int line, Problem problem);
    const std::string& source() const { return source_; }
    int line() const { return line_; } // 1-based, 0 when not about one line
    const std::string& message() const { return message_; } // English
    const Problem& problem() const { return problem_; }

private:
    std::string source_;
    int line_;
    std::string message_;
    Problem problem_;
};

// `source` names the text in errors (a file name, "grinder-205", "<db>").
MachineProfile readMachineText(std::string_view text, std::string_view source = "<text>");
std::string writeMachineText(const MachineProfile& p);

// File helpers: UTF-8, written with LF line ends. I/O failures throw FileError
// with line 0.
MachineProfile readMachineFile(const std::filesystem::path& path);
void writeMachineFile(const std::filesystem::path& path, const MachineProfile& p);

// All programs as one program-language file (the headers of the programs
// followed by a %MESSAGES section with the technological messages), as
// program::parse and `k528 check` read it.
std::string programsFileText(const MachineProfile& p);

} // namespace k528::profile
