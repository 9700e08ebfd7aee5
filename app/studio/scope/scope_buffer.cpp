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

void ScopeBuffer::record(const engine::Controller& ctl) {
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
    out.clear();
    if (size_ == 0 || t1Ms <= t0Ms || columns <= 0)
        return;
    const std::size_t begin = lowerBound(t0Ms), end = lowerBound(t1Ms + 1);
    if (begin >= end)
        return;
    const double msPerColumn = static_cast<double>(t1Ms - t0Ms) / columns;
    if (end - begin <= static_cast<std::size_t>(columns) * 4) {
        for (std::size_t i = begin; i < end; ++i)
            out.append(QPointF(at(i).tMs / 1000.0, scopeValue(at(i), axis, sig)));
        return;
    }
    std::size_t i = begin;
    while (i < end) {
        const int col = static_cast<int>((at(i).tMs - t0Ms) / msPerColumn);
        const machine::TraceSample& first = at(i);
        double vFirst = scopeValue(first, axis, sig), vMin = vFirst, vMax = vFirst, vLast = vFirst;
        std::int64_t tMin = first.tMs, tMax = first.tMs, tLast = first.tMs;
        for (++i; i < end && static_cast<int>((at(i).tMs - t0Ms) / msPerColumn) == col; ++i) {
            const double v = scopeValue(at(i), axis, sig);
            if (v < vMin) {
                vMin = v;
                tMin = at(i).tMs;
            }
            if (v > vMax) {
                vMax = v;
                tMax = at(i).tMs;
            }
            vLast = v;
            tLast = at(i).tMs;
        }
        out.append(QPointF(first.tMs / 1000.0, vFirst));
        if (tMin < tMax) {
            out.append(QPointF(tMin / 1000.0, vMin));
            out.append(QPointF(tMax / 1000.0, vMax));
        } else {
            out.append(QPointF(tMax / 1000.0, vMax));
            out.append(QPointF(tMin / 1000.0, vMin));
        }
        out.append(QPointF(tLast / 1000.0, vLast));
    }
}

} // namespace k528::studio
