// What the backplot shows, computed away from the GUI thread: a program's
// preview (core's interpreter, toolpath::programmedPath), its geometry and
// the blank cut by it (backplot::preparePath), on a worker thread of its own.
// The window never waits for it:
//   - a newer request cancels the one under way (its result is dropped; the
//     preview and the cut stop within a few hundred frames or legs);
//   - progress (frames previewed, legs cut) can be read at any time and
//     is signalled (progressed) as the worker goes on;
//   - the preview stops after kMaxFrames frames, so that a program that never
//     ends (an endless GOTO) still shows — the result says it was cut off.
// Only the VTK buffers are filled on the GUI thread, bounded by the view.
#pragma once

#include "backplot/backplot_scene.h"
#include "profile/profile.h"
#include "program/model.h"

#include <QObject>
#include <QThreadPool>

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>

namespace k528::studio::backplot {

class PathJob : public QObject {
    Q_OBJECT
public:
    // The preview's bound: 100 000 frames is minutes of any real program
    // (a 999-frame program run a hundred times) and a fraction of a second
    // of the interpreter; the blank is cut by what they drew.
    static constexpr std::int64_t kMaxFrames = 100'000;
    // A job shows its progress once it has previewed this many frames or
    // has this many legs to cut (counted, not timed: a short program's path
    // comes without the progress row flashing).
    static constexpr std::int64_t kShowProgressAfter = 4096;

    enum class Phase { Preview, Stock };
    struct Progress {
        Phase phase = Phase::Preview;
        std::int64_t done = 0, total = 0; // frames of kMaxFrames; legs of the path
    };

    explicit PathJob(QObject* parent = nullptr);
    ~PathJob() override; // cancels the job under way and waits for it

    // Starts computing program `number` of `store` on `profile` (copies:
    // the caller may change its own meanwhile). A job under way is cancelled.
    void request(const profile::MachineProfile& profile, const program::ProgramStore& store, int number,
                 const std::optional<stock::Blank>& blank);
    // Cancels the job under way (finished() follows, with no result).
    void cancel();
    bool busy() const { return current_ != nullptr; }
    Progress progress() const;
    // The result of the last finished job, once (nullopt: cancelled).
    std::optional<k528::backplot::PreparedPath> take();

signals:
    // The job under way went on (progress() changed); queued from the
    // worker, at most one waiting at a time, always before finished().
    void progressed();
    // The job under way ended: its result is ready (take()), or it was cancelled.
    void finished();

private:
    struct State;
    void done(const std::shared_ptr<State>& s);
    void report(const std::shared_ptr<State>& s); // on the worker: progressed() queued

    QThreadPool pool_; // one thread: a cancelled job ends before the next starts
    std::shared_ptr<State> current_;
    std::optional<k528::backplot::PreparedPath> result_;
};

} // namespace k528::studio::backplot
