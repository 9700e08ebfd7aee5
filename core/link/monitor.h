// What the studio's views read of a controller on a line, every tick (100
// ms), all together: the live state every tick (mode, program and frame,
// positions and following errors, alarms, programs present: the K923, the
// Program tab, the axes, the backplot's actual path, the history, the
// oscilloscope); the interface words in two halves in turn (the K923's LEDs,
// the PLC's messages, the machine's signals); the R-parameters, a read of
// 124 registers every 5th tick (all 300 every 2.5 s: the R dock, the
// constants' presets); the C block at the 4th tick and every 10 s (a
// constant changed on the panel in F5), and both at once after
// memoryChanged() (a push, a clear).
// Each value set carries a revision that changes only when a value does, so
// a view redraws on change. The plan keeps the line under 30 % busy at
// 115 200 bit/s (bench/run link).
#pragma once

#include "engine/interface_words.h"
#include "link/client.h"

#include <array>
#include <cstdint>
#include <vector>

namespace k528::link {

class Monitor {
public:
    static constexpr int kTickMs = 100;
    static constexpr int kRPieceEvery = 5;  // ticks between two reads of the R block's pieces
    static constexpr int kCEvery = 100;     // ticks between two reads of the C block

    explicit Monitor(const RegisterMap& map = k528Map());

    struct Changes {
        bool live = false, words = false, r = false, c = false;
        bool any() const { return live || words || r || c; }
    };
    // One tick's reads. On an error nothing of this tick is taken.
    LinkError tick(Link& link, Changes& changed);
    // The memory was written (push, clear): read C and all of R at the next ticks.
    void memoryChanged();

    const LiveState& live() const { return live_; }
    bool haveLive() const { return haveLive_; }
    const engine::InterfaceWords& words() const { return words_; }
    bool haveWords() const { return wordsSeen_ == 3; } // both halves read
    // R0..R299 and C (index = number, 153 values), with revisions (0: not read yet).
    const std::array<std::int32_t, 300>& r() const { return r_; }
    std::uint64_t rRevision() const { return rComplete_ ? rRevision_ : 0; }
    const std::vector<std::int64_t>& c() const { return c_; }
    std::uint64_t cRevision() const { return cRevision_; }
    std::int64_t ticks() const { return ticks_; }

private:
    int pieceRegisters() const;
    int pieces() const;
    LinkError readR(Link& link, int piece, bool& changed);
    LinkError readC(Link& link, bool& changed);

    const RegisterMap& map_;
    std::int64_t ticks_ = 0;
    LiveState live_;
    bool haveLive_ = false;
    engine::InterfaceWords words_;
    int wordsSeen_ = 0; // bit 0: half A read, bit 1: half B
    std::array<std::int32_t, 300> r_{};
    std::uint64_t rRevision_ = 0;
    int rSeen_ = 0; // pieces read, as bits
    bool rComplete_ = false;
    std::vector<std::int64_t> c_;
    std::uint64_t cRevision_ = 0;
    bool memoryDue_ = false; // read all of R and C at the next ticks (after a write)
    int memoryStep_ = 0;
};

} // namespace k528::link
