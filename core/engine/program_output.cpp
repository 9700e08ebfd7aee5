#include "engine/program_output.h"

#include "engine/coordinates.h"
#include "engine/core.h"
#include "engine/debug_gate.h"

namespace k528::engine {

// --- the machine -------------------------------------------------------------

bool RunOutput::mFunctions(const FrameRef&, std::span<const int> codes) {
    c_.mhs.begin(codes.data(), static_cast<int>(codes.size()), c_.nowMs);
    return !codes.empty();
}

bool RunOutput::move(AxisUnit& u, double, double to, double speed, std::int64_t, bool handwheel) {
    if (handwheel)
        return true; // the operator's handwheel drives the axis (controller.cpp, handwheels)
    return u.servo.moveTo(to, speed);
}

bool RunOutput::oscillate(AxisUnit& u, Oscillation& osc, double lo, double hi, double speed,
                          bool towardsHi, const OscillationPresets& presets, std::int64_t) {
    if (!osc.start(u.servo, lo, hi, speed, towardsHi, presets))
        return false;
    u.owner = MotionOwner::Oscillation;
    u.rapid = false;
    return true;
}

// --- the machine with the debugger -----------------------------------------

void DebugOutput::started() {
    gate_->started();
}

void DebugOutput::resumed() {
    gate_->resumed(); // a frame the gate held runs now
}

bool DebugOutput::holdBefore(int program, int frameIndex, int line) {
    return gate_->beforeFrame(program, frameIndex, line);
}

// --- instant axes ------------------------------------------------------------

void PreviewOutput::message(const FrameRef& f, int k) {
    sink_->message(PreviewMessage{f.program, f.line, f.n, k});
}

bool PreviewOutput::mFunctions(const FrameRef& f, std::span<const int> codes) {
    if (!codes.empty()) {
        PreviewMFunctions m{f.program, f.line, f.n, {}, static_cast<int>(codes.size())};
        for (std::size_t i = 0; i < codes.size() && i < m.codes.size(); ++i)
            m.codes[i] = codes[i];
        sink_->mFunctions(m);
    }
    return false; // acknowledged at once
}

bool PreviewOutput::move(AxisUnit& u, double from, double to, double speed, std::int64_t feedDisc,
                         bool) {
    PreviewAxisMotion& m = frame_.axes[static_cast<std::size_t>(u.index)];
    m.moves = true;
    m.fromDisc = u.toDisc(from);
    m.toDisc = u.toDisc(to);
    m.components = components(c_.r, u.index);
    m.offsetDisc = activeOffset(m.components, c_.programExclusion);
    m.speedDiscPerMin = u.discPerMinFromSpeed(speed);
    m.feedDiscPerMin = feedDisc < 0 ? -1.0 : static_cast<double>(feedDisc);
    u.servo.place(to);
    return true;
}

bool PreviewOutput::oscillate(AxisUnit& u, Oscillation&, double lo, double hi, double speed, bool,
                              const OscillationPresets&, std::int64_t feedDisc) {
    // The strokes are drawn; the axis stays where it is.
    PreviewAxisMotion& m = frame_.axes[static_cast<std::size_t>(u.index)];
    const double cur = u.servo.target();
    m.moves = true;
    m.fromDisc = m.toDisc = u.toDisc(cur);
    m.oscLoDisc = u.toDisc(lo);
    m.oscHiDisc = u.toDisc(hi);
    m.components = components(c_.r, u.index);
    m.offsetDisc = activeOffset(m.components, c_.programExclusion);
    m.speedDiscPerMin = u.discPerMinFromSpeed(speed);
    m.feedDiscPerMin = static_cast<double>(feedDisc);
    frame_.kind = PreviewKind::Oscillation;
    return true;
}

bool PreviewOutput::dwell(const FrameRef& f, std::int64_t ms) {
    sink_->dwell(PreviewDwell{f.program, f.line, f.n, ms});
    return false; // no waiting
}

void PreviewOutput::motionEnds(const FrameRef& f, PreviewKind kind) {
    if (!frame_.axes[0].moves && !frame_.axes[1].moves)
        return;
    for (int a = 0; a < kAxisCount; ++a) { // where the other axis stands (after a Gx92, too)
        PreviewAxisMotion& m = frame_.axes[static_cast<std::size_t>(a)];
        const AxisUnit& u = c_.axes[static_cast<std::size_t>(a)];
        if (m.moves || !u.present)
            continue;
        m.fromDisc = m.toDisc = u.toDisc(u.servo.target());
        m.components = components(c_.r, a);
        m.offsetDisc = activeOffset(m.components, c_.programExclusion);
    }
    frame_.program = f.program;
    frame_.line = f.line;
    frame_.n = f.n;
    frame_.wheelDiameterDisc = c_.r.get(r::WheelCurrent);
    if (frame_.kind != PreviewKind::Oscillation)
        frame_.kind = kind;
    sink_->motion(frame_);
}

} // namespace k528::engine
