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

#include "util/system_texts.h"

#include <cstddef>
#include <cstdio>
#include <string>

namespace k528::util {

inline constexpr std::size_t kMaxInputBytes = std::size_t{16} << 20;

// Reads the regular file `path` into `contents`. On failure returns false and
// sets `error` to io.cannot-open or io.cannot-read of system_texts.h with the
// path and, as its one `within`, why (a text of the catalog or the system's
// reason, systemError). `contents` is left unchanged then.
bool readInputFile(const std::string& path, std::string& contents, Message& error,
                   std::size_t maxBytes = kMaxInputBytes);
// The same with the error in English: "cannot open|read <path>: <why>".
bool readInputFile(const std::string& path, std::string& contents, std::string& error,
                   std::size_t maxBytes = kMaxInputBytes);

// Reads standard input (`in`) to its end, up to `maxBytes`; the error is
// io.cannot-read-stdin with why.
bool readInputStream(std::FILE* in, std::string& contents, Message& error, std::size_t maxBytes = kMaxInputBytes);

} // namespace k528::util
