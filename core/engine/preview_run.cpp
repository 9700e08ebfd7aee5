#include "engine/preview_run.h"

#include "engine/controller.h"
#include "engine/ideal_machine.h"

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
    Controller ctl(profile);
    IdealMachine machine(ctl);
    PreviewResult res;
    ctl.powerOn();
    if (program::ProgramStore* store = ctl.editablePrograms()) {
        for (const program::Program& p : programs.programs())
            store->insert(p);
        for (const program::Message& m : programs.messages.entries)
            store->messages.set(m.number, m.text);
        ctl.programsEdited();
    }
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
        if (s == ProgramState::Ended)
            return finish(PreviewStatus::Completed);
        if (s == ProgramState::Alarm || (ctl.alarmRegistry().anyLatched() && !programActive(s)))
            return finish(PreviewStatus::Alarm);
        if (ctl.framesExecuted() >= options.maxFrames)
            return finish(PreviewStatus::Limit);
    }
    return finish(PreviewStatus::Limit);
}

} // namespace k528::engine
