// The studio's CPU while idle and while a program runs: the real
// k528studio process on its own X server (Xvfb, 1366×768, Mesa's llvmpipe:
// every OpenGL view drawn by the CPU, as on a shop PC without a GPU
// driver), its CPU time (utime + stime of /proc/PID/stat, children
// excluded) over `seconds` of real time as a share of one core.
//   idle:    the training lathe after start-up (the first seconds skipped),
//            nobody touching it;
//   program: the same with a program running, in each workspace (`--run FILE`: the editor's
//            debugger runs its first program as the operator would — drives
//            on, homing, АВТОМАТ, «Пуск»), both axes moving all the time.
// Fresh HOME and database each run (no saved layout, no shop database).
// The program runs on the training lathe's machine file with АВТ.БЕЗ ПБТ
// (C8, C60 = 1): no homing, the loop starts a second after start-up.
//   bench_studio_cpu PATH_TO_K528STUDIO TRAINING_LATHE.k528m [SECONDS] [WIDTHxHEIGHT]
#include "report.h"
#include "rig/loop_program.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace {

pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env,
            posix_spawn_file_actions_t* actions) {
    std::vector<char*> a, e;
    for (const std::string& s : argv)
        a.push_back(const_cast<char*>(s.c_str()));
    a.push_back(nullptr);
    for (const std::string& s : env)
        e.push_back(const_cast<char*>(s.c_str()));
    e.push_back(nullptr);
    pid_t pid = -1;
    if (posix_spawnp(&pid, a[0], actions, nullptr, a.data(), e.data()) != 0)
        return -1;
    return pid;
}

// utime + stime of `pid` in clock ticks; -1 when it is gone.
long long cpuTicks(pid_t pid) {
    std::ifstream f("/proc/" + std::to_string(pid) + "/stat");
    std::string all;
    if (!std::getline(f, all))
        return -1;
    // The command may hold spaces: the fields start after the last ')'.
    const std::size_t close = all.rfind(')');
    if (close == std::string::npos)
        return -1;
    std::istringstream in(all.substr(close + 2));
    std::string field;
    long long utime = 0, stime = 0;
    for (int i = 3; i <= 15 && in >> field; ++i) {
        if (i == 14)
            utime = std::stoll(field);
        if (i == 15)
            stime = std::stoll(field);
    }
    return utime + stime;
}

void stop(pid_t pid) {
    if (pid <= 0)
        return;
    kill(pid, SIGTERM);
    for (int i = 0; i < 50; ++i) {
        int status = 0;
        if (waitpid(pid, &status, WNOHANG) == pid)
            return;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
}

struct Xserver {
    pid_t pid = -1;
    std::string display;
    // Xvfb on a free display it picks itself (-displayfd).
    bool start(const std::string& geometry) {
        int fds[2];
        if (pipe(fds) != 0)
            return false;
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addclose(&actions, fds[0]);
        posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
        std::vector<std::string> env;
        for (char** e = environ; *e; ++e)
            env.emplace_back(*e);
        pid = spawn({"Xvfb", "-displayfd", std::to_string(fds[1]), "-screen", "0", geometry + "x24",
                     "-nolisten", "tcp", "-noreset"},
                    env, &actions);
        posix_spawn_file_actions_destroy(&actions);
        close(fds[1]);
        if (pid < 0) {
            close(fds[0]);
            return false;
        }
        std::string number;
        pollfd p{fds[0], POLLIN, 0};
        char c = 0;
        while (poll(&p, 1, 10000) > 0 && read(fds[0], &c, 1) == 1 && c != '\n')
            number += c;
        close(fds[0]);
        if (number.empty())
            return false;
        display = ":" + number;
        return true;
    }
    ~Xserver() { stop(pid); }
};

struct Measured {
    double share = -1; // of one core
    std::string error;
    std::string log; // what the studio printed
};

std::string readAll(const std::string& path) {
    std::ifstream f(path);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

Measured measure(const std::string& studio, const std::string& display, const std::string& home,
                 const std::vector<std::string>& extra, double warmS, double seconds) {
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e) {
        const std::string v = *e;
        for (const char* drop : {"DISPLAY=", "HOME=", "K528_DB=", "QT_QPA_PLATFORM=", "XDG_CONFIG_HOME=",
                                 "WAYLAND_DISPLAY=", "LIBGL_ALWAYS_SOFTWARE=", "GALLIUM_DRIVER="})
            if (v.rfind(drop, 0) == 0)
                goto skip;
        env.push_back(v);
    skip:;
    }
    env.push_back("DISPLAY=" + display);
    env.push_back("HOME=" + home);
    env.push_back("XDG_CONFIG_HOME=" + home + "/.config");
    env.push_back("K528_DB=" + home + "/k528.db");
    env.push_back("QT_QPA_PLATFORM=xcb");
    env.push_back("LIBGL_ALWAYS_SOFTWARE=1");
    env.push_back("GALLIUM_DRIVER=llvmpipe");
    mkdir(home.c_str(), 0700);
    std::vector<std::string> argv = {studio, "--lang", "ru"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    const std::string log = home + "/studio.log";
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    const pid_t pid = spawn(argv, env, &actions);
    posix_spawn_file_actions_destroy(&actions);
    Measured m;
    if (pid < 0) {
        m.error = "cannot start " + studio;
        return m;
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(warmS));
    const long long c0 = cpuTicks(pid);
    const double t0 = k528::bench::nowSeconds();
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    const long long c1 = cpuTicks(pid);
    const double t1 = k528::bench::nowSeconds();
    if (c0 < 0 || c1 < 0) {
        m.error = "k528studio ended early (see " + log + ")";
        waitpid(pid, nullptr, 0);
        return m;
    }
    m.log = readAll(log);
    stop(pid);
    m.share = static_cast<double>(c1 - c0) / static_cast<double>(sysconf(_SC_CLK_TCK)) / (t1 - t0);
    return m;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: bench_studio_cpu PATH_TO_K528STUDIO TRAINING_LATHE.k528m [SECONDS] "
                             "[WIDTHxHEIGHT]\n");
        return 2;
    }
    const std::string studio = argv[1];
    const std::string lathe = readAll(argv[2]);
    const double seconds = argc > 3 ? std::atof(argv[3]) : 10.0;
    const std::string geometry = argc > 4 ? argv[4] : "1366x768";
    if (lathe.find("C008=0") == std::string::npos || lathe.find("C060=0") == std::string::npos) {
        std::fprintf(stderr, "bench_studio_cpu: %s is not the training lathe's machine file\n", argv[2]);
        return 2;
    }
    char dirTemplate[] = "/tmp/k528-studio-cpu-XXXXXX";
    if (!mkdtemp(dirTemplate)) {
        std::perror("mkdtemp");
        return 2;
    }
    const std::string dir = dirTemplate;
    Xserver x;
    if (!x.start(geometry)) {
        std::fprintf(stderr, "bench_studio_cpu: cannot start Xvfb\n");
        return 2;
    }
    const std::string program = dir + "/cpu-benchmark.k528";
    std::ofstream(program) << k528::testrig::kLoopProgram; // rig/loop_program.h
    std::string noHoming = lathe;
    noHoming.replace(noHoming.find("C008=0"), 6, "C008=1");
    noHoming.replace(noHoming.find("C060=0"), 6, "C060=1");
    const std::string machine = dir + "/training-lathe.k528m";
    std::ofstream(machine) << noHoming;

    k528::bench::Report report;
    const Measured idle = measure(studio, x.display, dir + "/idle", {"--profile", "training-lathe"}, 5.0, seconds);
    if (idle.share < 0) {
        std::fprintf(stderr, "bench_studio_cpu: %s\n", idle.error.c_str());
        return 2;
    }
    report.figure("studio.idle_cpu (" + geometry + ", llvmpipe)", idle.share * 100.0, "%", 3,
                  k528::bench::Better::Lower);
    // In each workspace (they show different views): start-up, drives on,
    // the loop runs after a few seconds.
    for (const char* workspace : {"operator", "technologist", "training"}) {
        const Measured run = measure(studio, x.display, dir + "/" + workspace,
                                     {"--workspace", workspace, "--profile", machine, "--run", program}, 6.0,
                                     seconds);
        if (run.share < 0) {
            std::fprintf(stderr, "bench_studio_cpu: %s\n", run.error.c_str());
            return 2;
        }
        // The studio says when --run's program is under way (main.cpp).
        if (run.log.find("--run: L1 runs") == std::string::npos) {
            std::fprintf(stderr, "bench_studio_cpu: the program did not run:\n%s\n", run.log.c_str());
            return 2;
        }
        report.figure(std::string("studio.program_cpu.") + workspace + " (" + geometry + ", llvmpipe)",
                      run.share * 100.0, "%", 30, k528::bench::Better::Lower);
    }
    std::string rm = "rm -rf '" + dir + "'";
    if (std::system(rm.c_str()) != 0)
        std::fprintf(stderr, "bench_studio_cpu: %s not removed\n", dir.c_str());
    return report.exitCode();
}
