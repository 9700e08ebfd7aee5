#include "scope/scope_buffer.h"

#include <algorithm>

namespace k528::studio {

double scopeValue(const machine::TraceSample& s, int axis, ScopeSignal sig) {
    const machine::TraceAxisSample& a = s.axes[static_cast<std::size_t>(axis)];
    switch (sig) {
    case ScopeSignal::Setpoint: return a.setpointMm;
    case ScopeSignal::Position: return a.positionMm;
    case ScopeSignal::Velocity: return a.velocityMmMin;
    case ScopeSignal::FollowingError: return a.followingErrorMm;
    case ScopeSignal::Dac: return a.dac;
    }
    return 0;
}

void ScopeBuffer::clear() {
    head_ = size_ = 0;
    haveLast_ = false;
}

void ScopeBuffer::add(const machine::TraceSample& s) {
    ring_[head_] = s;
    head_ = (head_ + 1) % ring_.size();
    size_ = std::min(size_ + 1, ring_.size());
}

void ScopeBuffer::record(const engine::Positioner& ctl) {
    lastSample_ = machine::sampleAxes(ctl, haveLast_ ? &lastSample_ : nullptr);
    haveLast_ = true;
    add(lastSample_);
}

std::size_t ScopeBuffer::lowerBound(std::int64_t tMs) const {
    std::size_t lo = 0, hi = size_;
    while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (at(mid).tMs < tMs)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

void ScopeBuffer::decimate(int axis, ScopeSignal sig, std::int64_t t0Ms, std::int64_t t1Ms,
                           int columns, QList<QPointF>& out) const {
    QList<QPointF>* outs[1] = {&out};
    decimate(axis, &sig, 1, t0Ms, t1Ms, columns, outs);
}

void ScopeBuffer::decimate(int axis, const ScopeSignal* sigs, int count, std::int64_t t0Ms,
                           std::int64_t t1Ms, int columns, QList<QPointF>* const* out,
                           std::int64_t originMs) const {
    constexpr int kMax = kScopeSignalCount;
    count = std::min(count, kMax);
    for (int k = 0; k < count; ++k)
        out[k]->clear();
    if (size_ == 0 || t1Ms <= t0Ms || columns <= 0)
        return;
    const std::size_t begin = lowerBound(t0Ms), end = lowerBound(t1Ms + 1);
    if (begin >= end)
        return;
    const bool raw = end - begin <= static_cast<std::size_t>(columns) * 2;
    for (int k = 0; k < count; ++k)
        out[k]->reserve(raw ? static_cast<qsizetype>(end - begin) : columns * 2 + 2);
    const double columnsPerMs = columns / static_cast<double>(t1Ms - t0Ms);
    double vMin[kMax], vMax[kMax];
    std::int64_t tMin[kMax], tMax[kMax];
    int col = -1;
    const auto flush = [&] {
        for (int k = 0; k < count; ++k) {
            // The smallest and the largest of the column, in their order: the
            // line through them covers every sample of the column.
            const bool minFirst = tMin[k] <= tMax[k];
            const double xMin = static_cast<double>(tMin[k] - originMs) / 1000.0;
            const double xMax = static_cast<double>(tMax[k] - originMs) / 1000.0;
            out[k]->append(minFirst ? QPointF(xMin, vMin[k]) : QPointF(xMax, vMax[k]));
            if (tMin[k] != tMax[k])
                out[k]->append(minFirst ? QPointF(xMax, vMax[k]) : QPointF(xMin, vMin[k]));
        }
    };
    // The ring as (at most) two contiguous runs.
    const std::size_t n = ring_.size();
    const std::size_t first = (head_ + n - size_ + begin) % n;
    std::size_t left = end - begin;
    for (std::size_t run = first; left > 0; run = 0) {
        const std::size_t len = std::min(left, n - run);
        for (const machine::TraceSample* p = ring_.data() + run; p != ring_.data() + run + len; ++p) {
            if (raw) {
                for (int k = 0; k < count; ++k)
                    out[k]->append(QPointF(static_cast<double>(p->tMs - originMs) / 1000.0,
                                           scopeValue(*p, axis, sigs[k])));
                continue;
            }
            const int c = static_cast<int>(static_cast<double>(p->tMs - t0Ms) * columnsPerMs);
            if (c != col) {
                if (col >= 0)
                    flush();
                col = c;
                for (int k = 0; k < count; ++k) {
                    vMin[k] = vMax[k] = scopeValue(*p, axis, sigs[k]);
                    tMin[k] = tMax[k] = p->tMs;
                }
                continue;
            }
            for (int k = 0; k < count; ++k) {
                const double v = scopeValue(*p, axis, sigs[k]);
                if (v < vMin[k]) {
                    vMin[k] = v;
                    tMin[k] = p->tMs;
                }
                if (v > vMax[k]) {
                    vMax[k] = v;
                    tMax[k] = p->tMs;
                }
            }
        }
        left -= len;
    }
    if (!raw && col >= 0)
        flush();
}

} // namespace k528::studio
