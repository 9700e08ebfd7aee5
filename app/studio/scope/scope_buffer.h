// The oscilloscope's memory: the last window of servo-tick samples of both
// axes (machine::sampleAxes, the same sampling as `k528 run --trace`), kept
// in a ring, and their reduction to what a chart can draw — per pixel column
// the smallest and the largest value (min/max decimation keeps every peak
// of the following error visible).
#pragma once

#include "machine/trace.h"

#include <QList>
#include <QPointF>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace k528::studio {

enum class ScopeSignal { Setpoint, Position, Velocity, FollowingError, Dac };
inline constexpr int kScopeSignalCount = 5;

double scopeValue(const machine::TraceSample& s, int axis, ScopeSignal sig);

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

private:
    std::vector<machine::TraceSample> ring_;
    std::size_t head_ = 0, size_ = 0;
    machine::TraceSample lastSample_;
    bool haveLast_ = false;
};

} // namespace k528::studio
