// The campaign's job slots as tokens in a pipe (like make's jobserver): a
// process holds one token while it computes (a spawned run, a snapshot
// group's leader, each run forked from a snapshot), so at most --jobs of
// them compute at a time however the campaign's process tree is shaped.
// The read end is non-blocking for everyone; take() waits with poll().
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>

namespace faults {

struct job_tokens {
    int read_fd = -1;
    int write_fd = -1;

    // A pool of `count` tokens; an invalid pool (fds -1) if the pipe fails.
    static job_tokens make(int count) {
        job_tokens t;
        int fds[2];
        if (pipe(fds) != 0) return t;
        t.read_fd = fds[0];
        t.write_fd = fds[1];
        fcntl(t.read_fd, F_SETFL, fcntl(t.read_fd, F_GETFL) | O_NONBLOCK);
        for (int i = 0; i < count; ++i) t.put();
        return t;
    }
    bool valid() const { return read_fd >= 0; }
    // A token if one is free now.
    bool try_take() const {
        char token = 0;
        return read(read_fd, &token, 1) == 1;
    }
    // Waits for a token.
    void take() const {
        while (!try_take()) {
            pollfd p{read_fd, POLLIN, 0};
            if (poll(&p, 1, -1) < 0 && errno != EINTR) return;
        }
    }
    // Waits at most timeout_ms for a token to be free (not taking it).
    void wait_free(int timeout_ms) const {
        pollfd p{read_fd, POLLIN, 0};
        poll(&p, 1, timeout_ms);
    }
    void put() const {
        const char token = 't';
        while (write(write_fd, &token, 1) < 0 && errno == EINTR) {
        }
    }
    void close_fds() {
        if (read_fd >= 0) close(read_fd);
        if (write_fd >= 0) close(write_fd);
        read_fd = write_fd = -1;
    }
};

}  // namespace faults
