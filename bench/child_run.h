// One simulation in a forked child process. SystemC elaborates once per
// process, so a bench program that runs several platforms (both
// arrangements, repetitions) runs each in a child and takes its figures back
// through a pipe; the parent never elaborates.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <exception>
#include <optional>
#include <type_traits>

namespace bench {

// This process's CPU seconds (user + system): less sensitive to other load
// than the wall clock.
inline double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// `run()` in a child; its result, or nothing if the child failed (it returned
// nothing, crashed or exited non-zero).
template <class Result, class Run>
std::optional<Result> in_child(Run&& run) {
    static_assert(std::is_trivially_copyable_v<Result>, "the result crosses a pipe as bytes");
    int fd[2];
    if (pipe(fd) != 0) return std::nullopt;
    const pid_t pid = fork();
    if (pid < 0) {
        close(fd[0]);
        close(fd[1]);
        return std::nullopt;
    }
    if (pid == 0) {
        // The child never returns into the benchmark program: an exception
        // would otherwise carry on running the parent's other benchmarks.
        close(fd[0]);
        try {
            const std::optional<Result> r = run();
            if (!r) _exit(4);
            const ssize_t written = write(fd[1], &*r, sizeof(Result));
            _exit(written == static_cast<ssize_t>(sizeof(Result)) ? 0 : 3);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "bench child: %s\n", e.what());
        } catch (...) {
        }
        _exit(5);
    }
    close(fd[1]);
    Result r{};
    const bool got = read(fd[0], &r, sizeof r) == static_cast<ssize_t>(sizeof r);
    close(fd[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (!got || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return std::nullopt;
    return r;
}

}  // namespace bench
