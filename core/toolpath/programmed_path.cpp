#include "toolpath/programmed_path.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace k528::toolpath {

std::string_view kindName(SegmentKind k) {
    switch (k) {
    case SegmentKind::Rapid:
        return "rapid";
    case SegmentKind::Feed:
        return "feed";
    case SegmentKind::Oscillation:
        return "oscillation";
    case SegmentKind::Signal:
        return "signal";
    case SegmentKind::Handwheel:
        return "handwheel";
    }
    return "";
}

namespace {

class Recorder final : public engine::PreviewSink {
public:
    Recorder(ProgrammedPath& path, const profile::MachineProfile& p) : path_(path) {
        for (int i = 0; i < 2; ++i) {
            const axis::Constants k = axis::Constants::fromC(p.c, engine::axisAt(i));
            scale_[i] = k.scale;
            dpm_[i] = static_cast<double>(k.scale.discretesPerMm());
            AxisLimits& l = i == 0 ? path.limitX : path.limitZ;
            l.present = k.present;
            l.on = k.softLimitsOn;
            minDisc_[i] = k.softMinusDisc;
            maxDisc_[i] = k.softPlusDisc;
            l.minMm = static_cast<double>(k.softMinusDisc) / dpm_[i];
            l.maxMm = static_cast<double>(k.softPlusDisc) / dpm_[i];
            check_[i] = k.present && k.softLimitsOn;
        }
        path.diameterX = scale_[0].diameter;
    }

    void setStart(const engine::PreviewResult& r) {
        for (int i = 0; i < 2; ++i) {
            pos_[i] = static_cast<double>(r.axes[static_cast<std::size_t>(i)].currentDisc) / dpm_[i];
            AxisLimits& l = i == 0 ? path_.limitX : path_.limitZ;
            const auto& a = r.axes[static_cast<std::size_t>(i)];
            offset_[i] = static_cast<double>(a.machineDisc - a.currentDisc) / dpm_[i];
            l.offsetMm = offset_[i];
        }
        path_.start = {pos_[0], pos_[1]};
    }

    void motion(const engine::PreviewFrame& f) override {
        Segment s;
        s.program = f.program;
        s.line = f.line;
        s.n = f.n;
        s.frameIndex = path_.segments.size();
        s.firstPoint = static_cast<std::uint32_t>(path_.points.size());
        switch (f.kind) {
        case engine::PreviewKind::Rapid:
            s.kind = SegmentKind::Rapid;
            break;
        case engine::PreviewKind::Feed:
            s.kind = SegmentKind::Feed;
            break;
        case engine::PreviewKind::Oscillation:
            s.kind = SegmentKind::Oscillation;
            break;
        case engine::PreviewKind::Signal:
            s.kind = SegmentKind::Signal;
            break;
        case engine::PreviewKind::Handwheel:
            s.kind = SegmentKind::Handwheel;
            break;
        }
        double from[2], to[2], mfrom[2], mto[2], speed[2];
        bool moves[2];
        for (int i = 0; i < 2; ++i) {
            const engine::PreviewAxisMotion& m = f.axes[static_cast<std::size_t>(i)];
            moves[i] = m.moves;
            if (!m.moves) {
                offset_[i] = static_cast<double>(m.offsetDisc) / dpm_[i];
                from[i] = to[i] = static_cast<double>(m.fromDisc - m.offsetDisc) / dpm_[i];
                mfrom[i] = mto[i] = static_cast<double>(m.fromDisc) / dpm_[i];
                speed[i] = 0;
                continue;
            }
            offset_[i] = static_cast<double>(m.offsetDisc) / dpm_[i];
            from[i] = static_cast<double>(m.fromDisc - m.offsetDisc) / dpm_[i];
            to[i] = static_cast<double>(m.toDisc - m.offsetDisc) / dpm_[i];
            mfrom[i] = static_cast<double>(m.fromDisc) / dpm_[i];
            mto[i] = static_cast<double>(m.toDisc) / dpm_[i];
            speed[i] = m.speedDiscPerMin / dpm_[i];
            const float feed = m.feedDiscPerMin >= 0
                                   ? static_cast<float>(m.feedDiscPerMin / dpm_[i])
                                   : kNoFeed;
            (i == 0 ? s.feedXMmMin : s.feedZMmMin) = feed;
            if (check_[i]) {
                const double lo = static_cast<double>(minDisc_[i]) / dpm_[i];
                const double hi = static_cast<double>(maxDisc_[i]) / dpm_[i];
                auto out = [&](double v) { return v < lo || v > hi; };
                if (out(mfrom[i]) || out(mto[i]))
                    s.outside = true;
                if (f.kind == engine::PreviewKind::Oscillation &&
                    (out(static_cast<double>(m.oscLoDisc) / dpm_[i]) ||
                     out(static_cast<double>(m.oscHiDisc) / dpm_[i])))
                    s.outside = true;
            }
        }
        for (int i = 0; i < 2; ++i) {
            if (moves[i] || !check_[i])
                continue;
            const double lo = static_cast<double>(minDisc_[i]) / dpm_[i];
            const double hi = static_cast<double>(maxDisc_[i]) / dpm_[i];
            if (mfrom[i] < lo || mfrom[i] > hi)
                s.outside = true; // standing beyond a limit while the other axis moves
        }
        if (path_.segments.empty()) // the limits are drawn in the coordinates of the first motion
            for (int i = 0; i < 2; ++i)
                (i == 0 ? path_.limitX : path_.limitZ).offsetMm = offset_[i];
        const auto push = [&](double x, double z) {
            if (path_.points.size() > s.firstPoint) {
                const PointMm& b = path_.points.back();
                if (b.x == x && b.z == z)
                    return;
            }
            path_.points.push_back({x, z});
        };
        if (f.kind == engine::PreviewKind::Oscillation) {
            // start, the far reverse point, the near one (per oscillating axis)
            double p[2] = {from[0], from[1]};
            push(p[0], p[1]);
            double farP[2] = {p[0], p[1]}, nearP[2] = {p[0], p[1]};
            for (int i = 0; i < 2; ++i) {
                const engine::PreviewAxisMotion& m = f.axes[static_cast<std::size_t>(i)];
                if (!m.moves)
                    continue;
                const double lo = static_cast<double>(m.oscLoDisc - m.offsetDisc) / dpm_[i];
                const double hi = static_cast<double>(m.oscHiDisc - m.offsetDisc) / dpm_[i];
                const bool hiFar = std::fabs(hi - p[i]) >= std::fabs(lo - p[i]);
                farP[i] = hiFar ? hi : lo;
                nearP[i] = hiFar ? lo : hi;
            }
            double t = 0;
            for (int i = 0; i < 2; ++i)
                if (speed[i] > 0)
                    t = std::max(t, (std::fabs(farP[i] - p[i]) + std::fabs(farP[i] - nearP[i]) +
                                     std::fabs(nearP[i] - p[i])) / speed[i]);
            s.durationS = static_cast<float>(t * 60.0);
            push(farP[0], farP[1]);
            push(nearP[0], nearP[1]);
            push(p[0], p[1]);
        } else {
            push(from[0], from[1]);
            double t = 0;
            for (int i = 0; i < 2; ++i)
                if (moves[i] && speed[i] > 0)
                    t = std::max(t, std::fabs(to[i] - from[i]) / speed[i]);
            s.durationS = static_cast<float>(t * 60.0);
            if (moves[0] && moves[1] && speed[0] > 0 && speed[1] > 0) {
                const double dx = to[0] - from[0], dz = to[1] - from[1];
                const double tx = std::fabs(dx) / speed[0], tz = std::fabs(dz) / speed[1];
                if (tx < tz && dx != 0) // X arrives first
                    push(to[0], from[1] + std::copysign(speed[1] * tx, dz));
                else if (tz < tx && dz != 0) // Z arrives first
                    push(from[0] + std::copysign(speed[0] * tz, dx), to[1]);
            }
            push(to[0], to[1]);
        }
        s.pointCount = static_cast<std::uint8_t>(path_.points.size() - s.firstPoint);
        if (s.pointCount < 2) // a move to where the axis stands: a point
            push(to[0], to[1] + 0.0), s.pointCount = static_cast<std::uint8_t>(
                                           path_.points.size() - s.firstPoint);
        pos_[0] = to[0];
        pos_[1] = to[1];
        ComponentsChange cc;
        cc.segment = static_cast<std::uint32_t>(path_.segments.size());
        for (int i = 0; i < 2; ++i) {
            const engine::PreviewAxisMotion& m = f.axes[static_cast<std::size_t>(i)];
            AxisComponentsMm& a = cc.axes[static_cast<std::size_t>(i)];
            a.dressing = static_cast<double>(m.components.dressing) / dpm_[i];
            a.correction = static_cast<double>(m.components.correction) / dpm_[i];
            a.zeroOffset = static_cast<double>(m.components.zeroOffset) / dpm_[i];
            a.drf = static_cast<double>(m.components.drf) / dpm_[i];
            a.active = offset_[i];
        }
        if (path_.components.empty() || path_.components.back().axes != cc.axes)
            path_.components.push_back(cc);
        if (f.wheelDiameterDisc != wheelDisc_) { // R207 is in X discretes (real mm, not halved)
            wheelDisc_ = f.wheelDiameterDisc;
            path_.wheel.push_back({static_cast<std::uint32_t>(path_.segments.size()),
                                   units::discToMm(wheelDisc_, scale_[0])});
        }
        path_.segments.push_back(s);
    }

    void dwell(const engine::PreviewDwell& d) override {
        path_.dwells.push_back({d.program, d.line, d.n, {pos_[0], pos_[1]},
                                static_cast<double>(d.ms) / 1000.0,
                                static_cast<std::uint32_t>(path_.segments.size())});
    }

    void mFunctions(const engine::PreviewMFunctions& m) override {
        MFunctions e;
        e.program = m.program;
        e.line = m.line;
        e.n = m.n;
        e.codes = m.codes;
        e.count = m.count;
        e.segment = static_cast<std::uint32_t>(path_.segments.size());
        path_.mFunctions.push_back(e);
    }

    void message(const engine::PreviewMessage& m) override {
        path_.messages.push_back(
            {m.program, m.line, m.n, m.number, static_cast<std::uint32_t>(path_.segments.size())});
    }

private:
    ProgrammedPath& path_;
    units::AxisScale scale_[2];
    double dpm_[2] = {1000, 1000};
    std::int64_t minDisc_[2] = {}, maxDisc_[2] = {};
    bool check_[2] = {};
    double pos_[2] = {0, 0};
    double offset_[2] = {0, 0};
    std::int64_t wheelDisc_ = 0;
};

} // namespace

double ProgrammedPath::wheelDiameterAt(std::size_t i) const {
    const auto it = std::upper_bound(wheel.begin(), wheel.end(), i,
                                     [](std::size_t k, const WheelChange& c) { return k < c.segment; });
    return it == wheel.begin() ? 0.0 : std::prev(it)->diameterMm;
}

const ComponentsChange& ProgrammedPath::componentsAt(std::size_t i) const {
    static const ComponentsChange none{};
    const auto it =
        std::upper_bound(components.begin(), components.end(), i,
                         [](std::size_t k, const ComponentsChange& c) { return k < c.segment; });
    return it == components.begin() ? none : *std::prev(it);
}

ProgrammedPath programmedPath(const profile::MachineProfile& profile,
                              const program::ProgramStore& programs, int number,
                              const PathOptions& options) {
    ProgrammedPath path;
    path.program = number;
    Recorder rec(path, profile);
    engine::PreviewOptions po = options.preview;
    po.onStart = [&rec](const engine::PreviewResult& r) { rec.setStart(r); };
    path.run = engine::runPreview(profile, programs, number, po, rec);
    if (path.segments.empty())
        rec.setStart(path.run);
    path.end = path.segments.empty() ? path.start : path.points.back();
    return path;
}

} // namespace k528::toolpath
