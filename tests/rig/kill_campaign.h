// A campaign of SIGKILLs: a program started again and again (its output to
// /dev/null) and killed at a moment of its run — a random one within the
// time a whole run takes, or the first moment a sign is seen (a file that
// appears, another session's view of it); a run that ended first is reaped,
// not killed. KillCampaign counts the runs killed and those that completed.
// The kill tests of the database (`k528 db init`, the schema's upgrade) say
// what each run must leave behind.
#pragma once

#include <QElapsedTimer>
#include <QtGlobal>
#include <csignal>
#include <ctime>
#include <fcntl.h>
#include <functional>
#include <random>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace k528::testrig {

// Starts `program` with `args` (argv[1]...), its output to /dev/null: its
// pid, or -1.
inline pid_t startSilenced(const std::string& program, const std::vector<std::string>& args) {
    std::vector<std::string> all = {program};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : all)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    return rc == 0 ? pid : -1;
}

// How one run ended.
struct KillOutcome {
    int status = 0; // waitpid's
    bool killed() const { return WIFSIGNALED(status); }
};

class KillCampaign {
public:
    // `runNs`: how long a whole run takes here (the random moments fall
    // within it; a sign is waited for at most 4 runs + 2 s).
    explicit KillCampaign(qint64 runNs, unsigned seed = 528) : runNs_(runNs), rng_(seed), at_(0, runNs) {}

    // Kills `pid` at a random moment of its run.
    KillOutcome atRandom(pid_t pid) {
        const qint64 ns = at_(rng_);
        struct timespec ts {static_cast<time_t>(ns / 1000000000), static_cast<long>(ns % 1000000000)};
        nanosleep(&ts, nullptr);
        return killAndReap(pid, false, 0);
    }

    // Kills `pid` the first time `seen()` holds (asked over and over; it may
    // also wait for the sign itself), unless the run ends first, or after
    // 4 runs + 2 s without the sign.
    KillOutcome atSign(pid_t pid, const std::function<bool()>& seen) {
        ++atSign_;
        QElapsedTimer t;
        t.start();
        int status = 0;
        bool reaped = false;
        while (!seen() && !(reaped = waitpid(pid, &status, WNOHANG) == pid) &&
               t.nsecsElapsed() < 4 * runNs_ + 2000000000LL) {
        }
        if (!reaped)
            reaped = waitpid(pid, &status, WNOHANG) == pid;
        return killAndReap(pid, reaped, status);
    }

    int killed() const { return killed_; }
    int completed() const { return completed_; } // the runs that ended before their kill
    int atSignRuns() const { return atSign_; }   // the runs of atSign

private:
    KillOutcome killAndReap(pid_t pid, bool reaped, int status) {
        if (!reaped) {
            kill(pid, SIGKILL);
            if (waitpid(pid, &status, 0) != pid)
                qFatal("the killed process %d could not be reaped", static_cast<int>(pid));
        }
        const KillOutcome o{status};
        (o.killed() ? killed_ : completed_) += 1;
        return o;
    }

    qint64 runNs_;
    std::mt19937 rng_;
    std::uniform_int_distribution<qint64> at_;
    int killed_ = 0, completed_ = 0, atSign_ = 0;
};

} // namespace k528::testrig
