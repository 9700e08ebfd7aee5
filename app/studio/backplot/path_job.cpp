#include "backplot/path_job.h"

#include "toolpath/programmed_path.h"

#include <QMetaObject>
#include <QMutex>
#include <QMutexLocker>

namespace k528::studio::backplot {

struct PathJob::State {
    std::atomic<bool> cancelled{false};
    std::atomic<int> phase{static_cast<int>(Phase::Preview)};
    std::atomic<std::int64_t> done{0}, total{kMaxFrames};
    std::atomic<bool> reported{false}; // a progressed() waits on the GUI thread
    QMutex mutex; // guards result
    std::optional<k528::backplot::PreparedPath> result;
};

PathJob::PathJob(QObject* parent) : QObject(parent) {
    pool_.setMaxThreadCount(1);
}

PathJob::~PathJob() {
    cancel();
    pool_.waitForDone();
}

void PathJob::request(const profile::MachineProfile& profile, const program::ProgramStore& store, int number,
                      const std::optional<stock::Blank>& blank) {
    if (current_)
        current_->cancelled = true; // its result is dropped (done() sees it is not current)
    auto s = std::make_shared<State>();
    current_ = s;
    pool_.start([this, s, profile, store, number, blank] {
        if (!s->cancelled) {
            toolpath::PathOptions o;
            o.preview.maxFrames = kMaxFrames;
            o.preview.keepGoing = [this, &s](std::int64_t frames) {
                s->done = frames;
                report(s);
                return !s->cancelled.load();
            };
            toolpath::ProgrammedPath path = toolpath::programmedPath(profile, store, number, o);
            if (!s->cancelled && path.run.status != engine::PreviewStatus::Cancelled) {
                s->phase = static_cast<int>(Phase::Stock);
                s->done = 0;
                s->total = static_cast<std::int64_t>(path.segments.size());
                k528::backplot::PreparedPath p = k528::backplot::preparePath(
                    std::move(path), blank, [this, &s](std::size_t done, std::size_t total) {
                        s->done = static_cast<std::int64_t>(done);
                        s->total = static_cast<std::int64_t>(total);
                        report(s);
                        return !s->cancelled.load();
                    });
                p.tools = k528::backplot::toolsInUse(profile, p.path);
                if (!s->cancelled) {
                    QMutexLocker lock(&s->mutex);
                    s->result = std::move(p);
                }
            }
        }
        // Back on the GUI thread (not at all once this object is gone).
        QMetaObject::invokeMethod(this, [this, s] { done(s); }, Qt::QueuedConnection);
    });
}

void PathJob::report(const std::shared_ptr<State>& s) {
    if (s->cancelled || s->reported.exchange(true))
        return; // the one waiting reads the progress when it is handled
    QMetaObject::invokeMethod(
        this,
        [this, s] {
            s->reported = false;
            if (s == current_)
                emit progressed();
        },
        Qt::QueuedConnection);
}

void PathJob::done(const std::shared_ptr<State>& s) {
    if (s != current_)
        return; // a newer request replaced it
    current_.reset();
    {
        QMutexLocker lock(&s->mutex);
        result_ = s->cancelled ? std::nullopt : std::move(s->result);
    }
    emit finished();
}

void PathJob::cancel() {
    if (current_)
        current_->cancelled = true;
}

PathJob::Progress PathJob::progress() const {
    Progress p;
    if (const std::shared_ptr<State> s = current_) {
        p.phase = static_cast<Phase>(s->phase.load());
        p.done = s->done;
        p.total = s->total;
    }
    return p;
}

std::optional<k528::backplot::PreparedPath> PathJob::take() {
    std::optional<k528::backplot::PreparedPath> r = std::move(result_);
    result_.reset();
    return r;
}

} // namespace k528::studio::backplot
