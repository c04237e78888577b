#include "tb/platform/firmware_crash.h"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>
#include <initializer_list>

#include "model/time/ticks.h"

namespace platform {

namespace {

std::atomic<bool> g_in_firmware{false};
std::atomic<int64_t> g_tick{0};
std::atomic<int> g_stage{-1};
std::atomic<const char* const*> g_stage_names{nullptr};
std::atomic<int> g_stage_count{0};

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

void report_crash(int signo) {
    line l;
    const bool firmware = g_in_firmware.load();
    l.add(firmware ? "stereosim: error: firmware crashed (signal "
                   : "stereosim: error: the simulator crashed (signal ");
    l.add_number(signo, 0);
    l.add(")");
    if (firmware) {
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
    l.add("\n");
    const ssize_t ignored = write(STDERR_FILENO, l.text, l.n);
    (void)ignored;
    _exit(3);
}

}  // namespace

void install_firmware_crash_report() {
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

}  // namespace platform
