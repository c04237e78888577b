// How a forked child of a campaign ends: _exit, so that nothing of the
// parent's state is flushed or destroyed twice; in a coverage build (make
// coverage) after writing its gcov counters, which only the atexit handler
// _exit skips would write. Elsewhere __gcov_dump is not linked in.
#pragma once

#include <unistd.h>

extern "C" void __gcov_dump(void) __attribute__((weak));

namespace faults {

[[noreturn]] inline void exit_child(int code) {
    if (__gcov_dump != nullptr) __gcov_dump();
    _exit(code);
}

}  // namespace faults
