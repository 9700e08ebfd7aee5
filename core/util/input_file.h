// Reading an input file whole, with the checks every command needs: one
// function for `k528 check`, `format`, `run`, `panel`, `db import`, the
// machine files of --profile and the desktop's loaders.
//
// A K528-05 holds at most 99 programs of 999 frames, about 3 MB of text, and
// a machine file is far smaller; an input is therefore refused when it is
// larger than kMaxInputBytes (16 MiB, five times the most a controller can
// hold) or when it is not a regular file (a device such as /dev/zero, a FIFO,
// a directory) — such a read might never end. Standard input, which is a
// pipe or a terminal, is read up to the same limit. (docs/cli-decisions.md)
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>

namespace k528::util {

inline constexpr std::size_t kMaxInputBytes = std::size_t{16} << 20;

// Reads the regular file `path` into `contents`. On failure returns false and
// sets `error` to "cannot open|read <path>: <why>" (the reason in words, with
// the system's errno text where there is one) and, if given, `reason` to the
// <why> alone. `contents` is left unchanged then.
bool readInputFile(const std::string& path, std::string& contents, std::string& error,
                   std::size_t maxBytes = kMaxInputBytes, std::string* reason = nullptr);

// Reads the stream `in` (standard input) to its end, named `name` in errors,
// up to `maxBytes`.
bool readInputStream(std::FILE* in, const std::string& name, std::string& contents,
                     std::string& error, std::size_t maxBytes = kMaxInputBytes);

} // namespace k528::util
