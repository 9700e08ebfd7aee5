#include "link/monitor.h"

#include <algorithm>

namespace k528::link {

namespace {

// The interface words, in two halves read in turn.
struct Range {
    int first, count;
};
constexpr Range kHalfA[] = {{1000, 14}, {2000, 9}}; // PLC -> positioner, positioner -> PLC
constexpr Range kHalfB[] = {{1300, 8}, {1900, 8}};  // keys, LEDs, messages, faults; message words

} // namespace

Monitor::Monitor(const RegisterMap& map) : map_(map) {}

void Monitor::memoryChanged() {
    memoryDue_ = true;
    memoryStep_ = 0;
}

int Monitor::pieceRegisters() const { return map_.maxRead - map_.maxRead % 2; } // whole R-parameters
int Monitor::pieces() const { return (2 * map_.rCount + pieceRegisters() - 1) / pieceRegisters(); }

LinkError Monitor::readR(Link& link, int piece, bool& changed) {
    const int regs = 2 * map_.rCount;
    const int first = piece * pieceRegisters();
    if (first >= regs)
        return {};
    const int count = std::min(pieceRegisters(), regs - first);
    std::vector<std::uint16_t> v;
    if (LinkError e = link.read(map_.rFirst + first, count, v))
        return e;
    for (int i = 0; i + 1 < count; i += 2) {
        const int n = (first + i) / 2;
        const std::int32_t value = joinSigned(v[static_cast<std::size_t>(i)], v[static_cast<std::size_t>(i) + 1]);
        if (n < 300 && r_[static_cast<std::size_t>(n)] != value) {
            r_[static_cast<std::size_t>(n)] = value;
            changed = true;
        }
    }
    rSeen_ |= 1 << piece;
    if (!rComplete_ && rSeen_ == (1 << pieces()) - 1) {
        rComplete_ = true;
        changed = true;
    }
    return {};
}

LinkError Monitor::readC(Link& link, bool& changed) {
    const Block& cb = map_.block(BlockKind::C);
    std::vector<std::uint16_t> v;
    if (LinkError e = link.read(cb.first, cb.count(), v))
        return e;
    std::vector<std::int64_t> c = unpackC(map_, v);
    if (c != c_ || cRevision_ == 0) {
        c_ = std::move(c);
        changed = true;
    }
    return {};
}

LinkError Monitor::tick(Link& link, Changes& changed) {
    changed = {};
    const std::int64_t t = ticks_++;
    LiveState live;
    if (LinkError e = readLive(link, live))
        return e;
    if (!haveLive_ || !(live == live_)) {
        live_ = std::move(live);
        haveLive_ = true;
        changed.live = true;
    }
    const bool a = t % 2 == 0;
    std::vector<std::uint16_t> v;
    for (const Range& range : a ? kHalfA : kHalfB) {
        if (LinkError e = link.read(range.first, range.count, v))
            return e;
        for (int i = 0; i < range.count; ++i)
            if (words_.word(range.first + i) != v[static_cast<std::size_t>(i)] || !(wordsSeen_ & (a ? 1 : 2))) {
                words_.setWord(range.first + i, v[static_cast<std::size_t>(i)]);
                changed.words = true;
            }
    }
    wordsSeen_ |= a ? 1 : 2;
    const int pieces = this->pieces();
    if (memoryDue_) { // at the start, or after a write of the memory: all of R and C, one read a tick
        if (memoryStep_ < pieces) {
            if (LinkError e = readR(link, memoryStep_, changed.r))
                return e;
        } else {
            if (LinkError e = readC(link, changed.c))
                return e;
            memoryDue_ = false;
        }
        ++memoryStep_;
    } else if (t % kRPieceEvery == 1) {
        if (LinkError e = readR(link, static_cast<int>((t / kRPieceEvery) % pieces), changed.r))
            return e;
    } else if (t % kCEvery == 3) {
        if (LinkError e = readC(link, changed.c))
            return e;
    }
    if (changed.r)
        ++rRevision_;
    if (changed.c)
        ++cRevision_;
    return {};
}

} // namespace k528::link
