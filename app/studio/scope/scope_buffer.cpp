#include "scope/scope_buffer.h"

#include <algorithm>
#include <limits>

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

void ScopeColumn::start(std::int64_t col, const machine::TraceSample& s, int axis, const ScopeSignal* sigs,
                        int count) {
    column = col;
    for (int k = 0; k < count; ++k) {
        vMin[k] = vMax[k] = scopeValue(s, axis, sigs[k]);
        tMin[k] = tMax[k] = s.tMs;
    }
}

void ScopeColumn::fold(const machine::TraceSample& s, int axis, const ScopeSignal* sigs, int count) {
    for (int k = 0; k < count; ++k) {
        const double v = scopeValue(s, axis, sigs[k]);
        if (v < vMin[k]) {
            vMin[k] = v;
            tMin[k] = s.tMs;
        }
        if (v > vMax[k]) {
            vMax[k] = v;
            tMax[k] = s.tMs;
        }
    }
}

void ScopeColumn::appendTo(QList<QPointF>* const* out, int count, std::int64_t originMs) const {
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
}

void ScopeBuffer::clear() {
    head_ = size_ = 0;
    haveLast_ = false;
    ++generation_;
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
    count = std::min(count, kScopeSignalCount);
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
    const std::int64_t windowMs = t1Ms - t0Ms;
    ScopeColumn column;
    bool open = false;
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
            const std::int64_t c = scopeColumn(p->tMs, columns, windowMs);
            if (open && c == column.column) {
                column.fold(*p, axis, sigs, count);
                continue;
            }
            if (open)
                column.appendTo(out, count, originMs);
            column.start(c, *p, axis, sigs, count);
            open = true;
        }
        left -= len;
    }
    if (open)
        column.appendTo(out, count, originMs);
}

void ScopeDecimator::decimate(const ScopeBuffer& b, int axis, const ScopeSignal* sigs, int count,
                              std::int64_t t0Ms, std::int64_t t1Ms, int columns, QList<QPointF>* const* out,
                              std::int64_t originMs) {
    count = std::min(count, kScopeSignalCount);
    const std::size_t begin = b.lowerBound(t0Ms), end = b.lowerBound(t1Ms + 1);
    // Nothing to draw, or few enough samples to draw each: as read.
    if (b.size() == 0 || t1Ms <= t0Ms || columns <= 0 || begin >= end ||
        end - begin <= static_cast<std::size_t>(columns) * 2) {
        valid_ = false;
        b.decimate(axis, sigs, count, t0Ms, t1Ms, columns, out, originMs);
        return;
    }
    const std::int64_t windowMs = t1Ms - t0Ms;
    if (!valid_ || generation_ != b.generation() || axis_ != axis || count_ != count || columns_ != columns ||
        windowMs_ != windowMs || !std::equal(sigs, sigs + count, sigs_.begin()) || t1Ms < t1Ms_) {
        kept_.clear();
        valid_ = true;
        generation_ = b.generation();
        axis_ = axis;
        count_ = count;
        columns_ = columns;
        windowMs_ = windowMs;
        std::copy(sigs, sigs + count, sigs_.begin());
        foldedMs_ = std::numeric_limits<std::int64_t>::min();
    }
    // The window now starts in this column: the ones before it have left,
    // and it is read again from the window's first sample.
    const std::int64_t firstColumn = scopeColumn(b.at(begin).tMs, columns, windowMs);
    while (!kept_.empty() && kept_.front().column <= firstColumn)
        kept_.pop_front();
    // The kept columns hold every sample after the first column up to
    // foldedMs_; with none kept, every sample after it is still to read.
    const bool afresh = kept_.empty();
    ScopeColumn& front = kept_.emplace_front();
    front.start(firstColumn, b.at(begin), axis, sigs, count);
    std::size_t i = begin + 1;
    for (; i < end && scopeColumn(b.at(i).tMs, columns, windowMs) == firstColumn; ++i)
        front.fold(b.at(i), axis, sigs, count);
    for (i = afresh ? i : std::max(i, b.lowerBound(foldedMs_ + 1)); i < end; ++i) {
        const machine::TraceSample& s = b.at(i);
        const std::int64_t c = scopeColumn(s.tMs, columns, windowMs);
        if (c == kept_.back().column)
            kept_.back().fold(s, axis, sigs, count);
        else
            kept_.emplace_back().start(c, s, axis, sigs, count);
    }
    foldedMs_ = b.at(end - 1).tMs;
    t1Ms_ = t1Ms;
    for (int k = 0; k < count; ++k) {
        out[k]->clear();
        out[k]->reserve(static_cast<qsizetype>(kept_.size()) * 2);
    }
    for (const ScopeColumn& c : kept_)
        c.appendTo(out, count, originMs);
}

} // namespace k528::studio
