// The oscilloscope's memory: the last window of servo-tick samples of both
// axes (machine::sampleAxes, the same sampling as `k528 run --trace`), kept
// in a ring, and their reduction to what a chart can draw — per pixel column
// the smallest and the largest value (min/max decimation keeps every peak
// of the following error visible).
//
// Columns are aligned to absolute time, not to the window's start: with
// `columns` columns over a window of W ms, a sample at t ms is in column
// floor(t · columns / W). A moving window then keeps its columns where they
// were, and the live picture (ScopeDecimator) folds in only the samples that
// arrived since the last frame instead of the whole window every frame.
#pragma once

#include "machine/trace.h"

#include <QList>
#include <QPointF>
#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

namespace k528::studio {

enum class ScopeSignal { Setpoint, Position, Velocity, FollowingError, Dac };
inline constexpr int kScopeSignalCount = 5;

double scopeValue(const machine::TraceSample& s, int axis, ScopeSignal sig);

// The column of a sample at tMs when `columns` columns span windowMs.
inline std::int64_t scopeColumn(std::int64_t tMs, int columns, std::int64_t windowMs) {
    const std::int64_t x = tMs * columns;
    return x / windowMs - (x % windowMs < 0 ? 1 : 0); // floor, also before 0 ms
}

// One column of the decimation: per signal its smallest and its largest
// value and when they were (the first time each, as read in time order).
struct ScopeColumn {
    std::int64_t column = 0;
    std::array<double, kScopeSignalCount> vMin{}, vMax{};
    std::array<std::int64_t, kScopeSignalCount> tMin{}, tMax{};

    void start(std::int64_t col, const machine::TraceSample& s, int axis, const ScopeSignal* sigs, int count);
    void fold(const machine::TraceSample& s, int axis, const ScopeSignal* sigs, int count);
    // Its one or two points per signal, x in seconds after originMs.
    void appendTo(QList<QPointF>* const* out, int count, std::int64_t originMs) const;
};

class ScopeBuffer {
public:
    explicit ScopeBuffer(std::size_t capacity = 60000) : ring_(capacity) {}
    void clear();
    void add(const machine::TraceSample& s);
    void record(const engine::Positioner& ctl);
    std::size_t size() const { return size_; }
    std::size_t capacity() const { return ring_.size(); }
    // i = 0 the oldest kept.
    const machine::TraceSample& at(std::size_t i) const {
        return ring_[(head_ + ring_.size() - size_ + i) % ring_.size()];
    }
    const machine::TraceSample& last() const { return at(size_ - 1); }
    // Points of `sig` of `axis` over [t0Ms, t1Ms] reduced to at most 2 per
    // column of `columns` (x in seconds). Fills `out` (its memory reused).
    void decimate(int axis, ScopeSignal sig, std::int64_t t0Ms, std::int64_t t1Ms, int columns,
                  QList<QPointF>& out) const;
    // The same for several signals of one axis in one pass over the samples;
    // x in seconds after `originMs` (the live chart: 0 = the newest sample).
    void decimate(int axis, const ScopeSignal* sigs, int count, std::int64_t t0Ms,
                  std::int64_t t1Ms, int columns, QList<QPointF>* const* out,
                  std::int64_t originMs = 0) const;
    // First index with tMs >= t (binary search over the ring).
    std::size_t lowerBound(std::int64_t tMs) const;
    // Changes on clear(): what was read of the samples before is void.
    std::uint64_t generation() const { return generation_; }

private:
    std::vector<machine::TraceSample> ring_;
    std::size_t head_ = 0, size_ = 0;
    std::uint64_t generation_ = 0;
    machine::TraceSample lastSample_;
    bool haveLast_ = false;
};

// ScopeBuffer::decimate of a window that moves on, kept from frame to frame:
// the columns the window still shows are kept, the one it now starts in is
// read again (part of it has left the window), and only the samples newer
// than the last call are folded in. The points are those ScopeBuffer::decimate
// gives for the same call. A change of the signals, the columns, the window's
// length, a cleared buffer or a window that goes back in time starts afresh.
class ScopeDecimator {
public:
    void decimate(const ScopeBuffer& b, int axis, const ScopeSignal* sigs, int count, std::int64_t t0Ms,
                  std::int64_t t1Ms, int columns, QList<QPointF>* const* out, std::int64_t originMs = 0);

private:
    std::deque<ScopeColumn> kept_;
    bool valid_ = false;
    // What kept_ was made of and for.
    std::uint64_t generation_ = 0;
    int axis_ = 0, count_ = 0, columns_ = 0;
    std::array<ScopeSignal, kScopeSignalCount> sigs_{};
    std::int64_t windowMs_ = 0, t1Ms_ = 0;
    std::int64_t foldedMs_ = 0; // the newest sample folded in
};

} // namespace k528::studio
