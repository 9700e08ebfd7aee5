#include "engine/preview_run.h"

#include "engine/positioner.h"
#include "engine/ideal_machine.h"
#include "engine/load_programs.h"

#include <algorithm>

namespace k528::engine {

std::string_view previewStatusName(PreviewStatus s) {
    switch (s) {
    case PreviewStatus::Completed:
        return "completed";
    case PreviewStatus::Alarm:
        return "alarm";
    case PreviewStatus::Limit:
        return "limit";
    case PreviewStatus::Cancelled:
        return "cancelled";
    }
    return "";
}

namespace {
constexpr int kAutoWithoutHomingX = 8, kAutoWithoutHomingZ = 60; // АВТ.БЕЗ ПБТ
constexpr std::int64_t kSwitchOnMs = 10; // the PLC's first scans: loops closed
} // namespace

PreviewResult runPreview(const profile::MachineProfile& profileIn,
                         const program::ProgramStore& programs, int number,
                         const PreviewOptions& options, PreviewSink& sink) {
    profile::MachineProfile profile = profileIn;
    profile.c[kAutoWithoutHomingX] = 1;
    profile.c[kAutoWithoutHomingZ] = 1;
    Positioner ctl(profile);
    IdealMachine machine(ctl);
    PreviewResult res;
    ctl.powerOn();
    loadPrograms(ctl, programs); // a fresh controller: no program runs
    for (const auto& [n, v] : options.rPresets)
        ctl.setR(n, v);
    machine.setMAckDelayMs(0);
    machine.advance(kSwitchOnMs);
    if (options.fromReferencePoint)
        ctl.placeAtReferencePoint();
    const auto snapshot = [&](bool start) {
        for (int i = 0; i < kAxisCount; ++i) {
            const AxisView v = ctl.axisView(axisAt(i));
            PreviewAxisStart& a = res.axes[static_cast<std::size_t>(i)];
            a.present = v.present;
            a.scale = v.scale;
            if (start) {
                a.machineDisc = v.machineDisc;
                a.currentDisc = v.currentDisc;
            }
            a.endMachineDisc = v.machineDisc;
            a.endCurrentDisc = v.currentDisc;
        }
    };
    snapshot(true);
    std::array<std::int32_t, kRCount> rAtStart{};
    {
        const std::span<const std::int32_t> r = ctl.r().values();
        std::copy(r.begin(), r.end(), rAtStart.begin());
    }
    if (options.stopBefore)
        ctl.setPreviewStopBefore(*options.stopBefore);
    if (options.onStart)
        options.onStart(res);
    const auto finish = [&](PreviewStatus s) {
        ctl.setPreview(nullptr);
        res.status = s;
        res.alarms = ctl.alarms();
        res.frames = ctl.framesExecuted();
        const ProgramView p = ctl.programView();
        res.program = p.program;
        res.line = p.line;
        res.frameNumber = p.frameNumber;
        snapshot(false);
        return res;
    };
    if (ctl.alarmRegistry().anyLatched())
        return finish(PreviewStatus::Alarm);
    ctl.setPreview(&sink);
    ctl.selectMode(Mode::Auto);
    ctl.selectProgram(number);
    machine.pressStart();
    // «Пуск» reaches the positioner after the PLC's scan; then every tick
    // runs up to kFramesPerTick frames. A guard against a machine that never
    // starts: as many ticks as frames allowed, plus the start.
    const std::int64_t guard = options.maxFrames + 1000;
    std::int64_t asked = 0; // frames at the last keepGoing
    for (std::int64_t t = 0; t < guard; ++t) {
        if (options.keepGoing && ctl.framesExecuted() - asked >= PreviewOptions::kKeepGoingFrames) {
            asked = ctl.framesExecuted();
            if (!options.keepGoing(asked))
                return finish(PreviewStatus::Cancelled);
        }
        machine.tick();
        const ProgramState s = ctl.state();
        if (s == ProgramState::Interrupted && options.stopBefore) {
            res.stopped = true;
            if (options.onStopped)
                options.onStopped(ctl, rAtStart);
            return finish(PreviewStatus::Completed);
        }
        if (s == ProgramState::Ended)
            return finish(PreviewStatus::Completed);
        if (s == ProgramState::Alarm || (ctl.alarmRegistry().anyLatched() && !programActive(s)))
            return finish(PreviewStatus::Alarm);
        if (ctl.framesExecuted() >= options.maxFrames)
            return finish(PreviewStatus::Limit);
    }
    return finish(PreviewStatus::Limit);
}

namespace {

// What a start needs of the frames before it: the M functions handed to
// the PLC and the last motion of each axis.
class StartSink final : public PreviewSink {
public:
    void motion(const PreviewFrame& f) override {
        for (int a = 0; a < kAxisCount; ++a)
            if (f.axes[static_cast<std::size_t>(a)].moves) {
                const bool unknown = f.kind == PreviewKind::Signal || f.kind == PreviewKind::Handwheel;
                last[static_cast<std::size_t>(a)] =
                    unknown ? std::optional<StartPoint::Uncertain>({f.program, f.line, f.n, a})
                            : std::nullopt;
            }
    }
    void dwell(const PreviewDwell&) override {}
    void mFunctions(const PreviewMFunctions& m) override {
        for (int i = 0; i < m.count; ++i)
            codes.push_back(m.codes[static_cast<std::size_t>(i)]);
    }
    std::vector<int> codes;
    std::array<std::optional<StartPoint::Uncertain>, kAxisCount> last;
};

} // namespace

StartSearch findStartPoint(const profile::MachineProfile& profile,
                           const program::ProgramStore& programs, int number,
                           const FrameTarget& target, const PreviewOptions& optionsIn) {
    StartSearch out;
    StartSink sink;
    PreviewOptions options = optionsIn;
    options.stopBefore = target;
    options.onStopped = [&](const Positioner& ctl, std::span<const std::int32_t> rAtStart) {
        StartPoint& p = out.point;
        ctl.captureStartPoint(p);
        p.pass = target.pass;
        p.framesBefore = ctl.framesExecuted();
        const std::span<const std::int32_t> now = ctl.r().values();
        for (int n = 0; n < kRCount; ++n) {
            const std::size_t i = static_cast<std::size_t>(n);
            if (now[i] != rAtStart[i] && !rReadOnly(n) && n != r::PlcBit && n != r::NestingLevel)
                p.r.emplace_back(n, now[i]);
        }
        for (int m : sink.codes)
            if (replayedMFunction(m))
                p.mFunctions.push_back(m);
        for (const auto& u : sink.last)
            if (u)
                p.uncertain.push_back(*u);
        out.outcome = StartSearch::Outcome::Found;
        if (p.oscillatingAxis >= 0) {
            out.outcome = StartSearch::Outcome::Oscillating;
            out.oscillatingAxis = p.oscillatingAxis;
        }
    };
    out.preview = runPreview(profile, programs, number, options, sink);
    return out;
}

} // namespace k528::engine
