// The preview run (shared/spec/cli.md `k528 path`): the engine's interpreter
// runs a program with instant axes (engine/preview.h) on the engine's ideal
// machine and PLC, from the machine's power-on position, without homing
// (АВТ.БЕЗ ПБТ is set for the preview, so the soft limits do not stop it:
// the caller marks what leaves them). Stops at the program's end, at a
// message that stops it, after `maxFrames` executed frames, or when
// `keepGoing` says no (a caller on another thread cancels it so).
#pragma once

#include "engine/preview.h"
#include "engine/start_point.h"
#include "engine/views.h"
#include "profile/profile.h"
#include "program/model.h"

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <vector>

namespace k528::engine {

class Positioner;
struct PreviewResult;

struct PreviewOptions {
    std::map<int, std::int64_t> rPresets; // writable R, checked by the caller
    std::int64_t maxFrames = 1'000'000;
    // Start at the reference point of every axis (ЗНАЧЕНИЕ БТ), where `k528
    // run` starts after homing, instead of the power-on position.
    bool fromReferencePoint = false;
    // Called once the machine stands ready, before «Пуск» (axes: the start).
    std::function<void(const PreviewResult&)> onStart;
    // Asked every kKeepGoingFrames executed frames with their count so far
    // (progress); false stops the preview (status Cancelled).
    std::function<bool(std::int64_t frames)> keepGoing;
    static constexpr std::int64_t kKeepGoingFrames = 1024;
    // Stop before this frame (start from a frame, findStartPoint below):
    // `onStopped` sees the controller held before it and the R-parameters
    // as they were at «Пуск»; the result's `stopped` is true.
    std::optional<FrameTarget> stopBefore;
    std::function<void(const Positioner&, std::span<const std::int32_t> rAtStart)> onStopped;
};

enum class PreviewStatus { Completed, Alarm, Limit, Cancelled };
std::string_view previewStatusName(PreviewStatus s); // "completed", "alarm", "limit", "cancelled"

struct PreviewAxisStart {
    bool present = false;
    units::AxisScale scale;
    std::int64_t machineDisc = 0, currentDisc = 0; // at the start (power-on position)
    std::int64_t endCurrentDisc = 0, endMachineDisc = 0;
};

struct PreviewResult {
    PreviewStatus status = PreviewStatus::Completed;
    std::vector<AlarmView> alarms;
    std::int64_t frames = 0;
    std::array<PreviewAxisStart, 2> axes{};
    int program = 0, line = 0, frameNumber = 0; // where it stopped
    bool stopped = false; // held before PreviewOptions::stopBefore
};

PreviewResult runPreview(const profile::MachineProfile& profile,
                         const program::ProgramStore& programs, int number,
                         const PreviewOptions& options, PreviewSink& sink);

// Start from a frame: the state before `target` (program `number` started
// as `options` say: R presets, from the reference point when the run homes)
// rebuilt by the preview. Not found: the frame is never reached (the
// preview ended first, `preview` says how), or it runs while an axis
// oscillates (Gx81 up to its Gx80): the oscillation's turning points are
// not part of the rebuilt state, so such a frame is no start frame.
struct StartSearch {
    enum class Outcome { Found, NotReached, Oscillating };
    Outcome outcome = Outcome::NotReached;
    StartPoint point; // Found (Oscillating: where it stood)
    PreviewResult preview;
    int oscillatingAxis = -1; // Oscillating: 0 X, 1 Z
};
StartSearch findStartPoint(const profile::MachineProfile& profile,
                           const program::ProgramStore& programs, int number,
                           const FrameTarget& target, const PreviewOptions& options);

} // namespace k528::engine
