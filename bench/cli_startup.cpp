// Process start of `k528 --version`: spawns it repeatedly and reports the
// mean and the 95th percentile wall time per run.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fcntl.h>
#include <vector>

#include "report.h"

extern char** environ;

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: bench_cli_startup PATH_TO_K528 [RUNS]\n");
        return 2;
    }
    const int runs = argc > 2 ? std::atoi(argv[2]) : 200;
    char* args[] = {argv[1], const_cast<char*>("--version"), nullptr};
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    std::vector<double> ms;
    for (int i = 0; i < runs + 5; ++i) {
        const double t0 = k528::bench::nowSeconds();
        pid_t pid;
        if (posix_spawn(&pid, argv[1], &actions, nullptr, args, environ) != 0) {
            std::perror("posix_spawn");
            return 2;
        }
        int status = 0;
        waitpid(pid, &status, 0);
        const double t1 = k528::bench::nowSeconds();
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            std::fprintf(stderr, "k528 --version failed\n");
            return 2;
        }
        if (i >= 5) // the first runs warm the page cache
            ms.push_back((t1 - t0) * 1000.0);
    }
    std::sort(ms.begin(), ms.end());
    double sum = 0;
    for (double v : ms)
        sum += v;
    k528::bench::Report r;
    r.figure("cli.startup_mean (k528 --version)", sum / static_cast<double>(ms.size()), "ms", 10, k528::bench::Better::Lower);
    r.figure("cli.startup_p95 (k528 --version)", ms[ms.size() * 95 / 100], "ms", 20, k528::bench::Better::Lower);
    return r.exitCode();
}
