#include "tb/platform/firmware_crash.h"

#include <dirent.h>
#include <fcntl.h>
#include <pthread.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstring>
#include <initializer_list>
#include <thread>

#include "model/time/ticks.h"

namespace platform {

namespace {

std::atomic<bool> g_in_firmware{false};
std::atomic<int64_t> g_tick{0};
std::atomic<int> g_stage{-1};
std::atomic<const char* const*> g_stage_names{nullptr};
std::atomic<int> g_stage_count{0};

// The folders to remove at a crash, as fixed buffers a signal handler reads.
char g_staging[4096] = "";
char g_created_out[4096] = "";

// Removes a folder tree with system calls only (async-signal-safe): the
// entries of each pass are unlinked, then the folder is read again from its
// start until it is empty.
void remove_tree_at(int parent, const char* name, int depth) {
    const int fd = openat(parent, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd >= 0) {
        alignas(8) char buffer[4096];
        for (int pass = 0; pass < 64 && depth < 16; ++pass) {
            bool removed = false;
            for (;;) {
                const long n = syscall(SYS_getdents64, fd, buffer, sizeof buffer);
                if (n <= 0) break;
                for (long at = 0; at < n;) {
                    const auto* entry = reinterpret_cast<const dirent64*>(buffer + at);
                    at += entry->d_reclen;
                    const char* e = entry->d_name;
                    if (e[0] == '.' && (e[1] == 0 || (e[1] == '.' && e[2] == 0))) continue;
                    if (entry->d_type == DT_DIR)
                        remove_tree_at(fd, e, depth + 1);
                    else
                        unlinkat(fd, e, 0);
                    removed = true;
                }
            }
            if (!removed) break;
            lseek(fd, 0, SEEK_SET);
        }
        close(fd);
    }
    unlinkat(parent, name, AT_REMOVEDIR);
}

void remove_half_written() {
    if (g_staging[0]) remove_tree_at(AT_FDCWD, g_staging, 0);
    if (g_created_out[0]) unlinkat(AT_FDCWD, g_created_out, AT_REMOVEDIR);  // only if empty
}

// Async-signal-safe text: a fixed buffer and write(2).
struct line {
    char text[256];
    size_t n = 0;
    void add(const char* s) {
        while (*s && n + 1 < sizeof text) text[n++] = *s++;
    }
    void add_number(int64_t v, int decimals) {
        char digits[32];
        int k = 0;
        if (v < 0) {
            add("-");
            v = -v;
        }
        do {
            digits[k++] = static_cast<char>('0' + v % 10);
            v /= 10;
        } while (v > 0 || k <= decimals);
        while (k-- > 0) {
            if (k == decimals - 1) add(".");
            const char c[2] = {digits[k], 0};
            add(c);
        }
    }
};

// " at T ms in stage S": where the firmware is.
void add_whereabouts(line& l) {
    // Ticks to microseconds, shown in ms with three decimals.
    const int64_t us = g_tick.load() / (simtime::ticks_per_ns * 1000);
    l.add(" at ");
    l.add_number(us, 3);
    l.add(" ms");
    const int stage = g_stage.load();
    const char* const* names = g_stage_names.load();
    if (names && stage >= 0 && stage < g_stage_count.load()) {
        l.add(" in stage ");
        l.add(names[stage]);
    } else {
        l.add(" outside its stages");
    }
}

void report_crash(int signo) {
    line l;
    const bool firmware = g_in_firmware.load();
    l.add(firmware ? "stereosim: error: firmware crashed (signal "
                   : "stereosim: error: the simulator crashed (signal ");
    l.add_number(signo, 0);
    l.add(")");
    if (firmware) add_whereabouts(l);
    l.add("\n");
    remove_half_written();
    const ssize_t ignored = write(STDERR_FILENO, l.text, l.n);
    (void)ignored;
    _exit(3);
}

// Once a second: control in the firmware at the same simulated time as the
// last look counts towards the bound, anything else starts it again.
void guard_hangs() {
    int64_t last_tick = -1;
    int still = 0;
    for (;;) {
        std::this_thread::sleep_for(std::chrono::seconds(1));
        const int64_t tick = g_tick.load();
        still = g_in_firmware.load() && tick == last_tick ? still + 1 : 0;
        last_tick = tick;
        if (still < hang_guard_seconds) continue;
        line l;
        l.add(firmware_hung_prefix);
        l.add(" for ");
        l.add_number(hang_guard_seconds, 0);
        l.add(" s of wall time");
        add_whereabouts(l);
        l.add(" (a loop that neither charges cycles nor waits)\n");
        remove_half_written();
        const ssize_t ignored = write(STDERR_FILENO, l.text, l.n);
        (void)ignored;
        _exit(3);
    }
}

void start_guard() {
    std::thread(guard_hangs).detach();
}

}  // namespace

void install_firmware_crash_report() {
    static bool guarded = false;  // one guard per process; a forked child starts its own
    if (!guarded) {
        guarded = true;
        start_guard();
        pthread_atfork(nullptr, nullptr, start_guard);
    }
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_handler = report_crash;
    sigemptyset(&action.sa_mask);
    for (int signo : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) sigaction(signo, &action, nullptr);
}

void firmware_entered(int64_t tick, int stage, const char* const* stage_names, int stage_count) {
    g_tick.store(tick);
    g_stage.store(stage);
    g_stage_names.store(stage_names);
    g_stage_count.store(stage_count);
    g_in_firmware.store(true);
}

void firmware_left() {
    g_in_firmware.store(false);
}

void firmware_broke_abi(const std::string& what) {
    line l;
    l.add(firmware_broke_abi_prefix);
    l.add(": ");
    l.add(what.c_str());
    add_whereabouts(l);
    l.add("\n");
    remove_half_written();
    const ssize_t ignored = write(STDERR_FILENO, l.text, l.n);
    (void)ignored;
    _exit(3);
}

void remove_on_firmware_failure(const std::string& staging, const std::string& created_out) {
    // Cleared first, so that a crash meanwhile never reads half a path.
    g_staging[0] = 0;
    g_created_out[0] = 0;
    if (staging.size() >= sizeof g_staging || created_out.size() >= sizeof g_created_out) return;
    std::memcpy(g_created_out, created_out.c_str(), created_out.size() + 1);
    std::memcpy(g_staging, staging.c_str(), staging.size() + 1);
}

}  // namespace platform
