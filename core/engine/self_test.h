// The power-on test of the positioner (manual 2.6.1) as far as a simulation
// can have it: «проверка на сохранность всех введенных ранее параметров» —
// the machine constants against their definitions and cross-checks
// (messages 15, 13/29, 37, 38, 39), the program store (31); «целостность
// цепей датчиков обратной связи» and «наличие связи с модулями» are checked
// by the tick from the machine I/O (4/5/20/21, 2, 3, 14, 18, 19, 25, 30).
#pragma once

#include "profile/profile.h"
#include "program/model.h"

#include <array>
#include <cstdint>
#include <span>

namespace k528::engine {

// Messages the machine constants give (index = message number): a value
// outside its definition or a cross-check error with a message of its own
// (13/29 L/N, 37 N ДОС, 38 N ЦАП, 39 N маховика) gives that message; any
// other error (a discrete flag, soft limits in the wrong order, ...) gives
// 15 «Разрушены С-параметры».
std::array<bool, 65> configurationMessages(std::span<const std::int64_t> c);

// The store of a profile: its programs (each text parsed on its own) and
// technological messages (marked the machine file's, Message::machineFile).
// `intact` is false when a text did not parse.
program::ProgramStore loadStore(const profile::MachineProfile& p, bool& intact);

// True if every frame of the store was read without a syntax error.
bool storeIntact(const program::ProgramStore& store);

// The inverse of loadStore for a whole memory: `base` (the machine's name,
// title, PLC texts and simulation settings) with the C-parameters `c`, the
// writable R-parameters that are not 0 as presets (the read-only R232..R262
// are the machine's state, not settings), and every program of `store` in
// canonical text with the store's messages (a message's English only while
// its Russian is the machine's). What «keep the controller's memory» writes
// to the database.
profile::MachineProfile memoryProfile(const profile::MachineProfile& base,
                                      std::span<const std::int64_t> c,
                                      std::span<const std::int32_t> r,
                                      const program::ProgramStore& store);

} // namespace k528::engine
