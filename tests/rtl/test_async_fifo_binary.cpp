// Negative control: the same stress as test_async_fifo.cpp on a FIFO whose
// pointers cross in BINARY (tests/rtl/async_fifo_binary.v). With the
// metastability model, a multi-bit pointer change caught half old, half new
// shows the other side a pointer value that never existed; the stress test's
// held-value check and the synchronizer model's RTL assertion must both see
// it. If this test passed the variant, the FIFO test would prove nothing.
#include <gtest/gtest.h>

#include <cstdio>

#include "Vasync_fifo_binary.h"
#include "tests/rtl/fifo_stress.h"

namespace {

TEST(AsyncFifoBinaryPointers, FailsTheHeldValueCheck) {
    rtl_test::fifo_stress_config cfg;
    cfg.write_period = rtl_test::ticks_eclk_v3;  // 125 MHz -> 120 MHz: many multi-bit changes
    cfg.read_period = rtl_test::ticks_eclk_v2;
    cfg.write_phase = 37;
    cfg.words = 50000 / rtl_test::stress_divisor;
    cfg.seed = 3;
    rtl_test::fifo_stress_result r;
    {
        rtl_test::stdout_muted quiet;  // thousands of assertion messages
        r = rtl_test::run_fifo_stress<Vasync_fifo_binary>(cfg, 4, 1u << 30);
    }
    std::printf(
        "binary pointers: %llu of %llu synchronized pointer values were never held, "
        "%llu RTL assertion failures, %llu data errors, %llu flag errors over %llu words\n",
        (unsigned long long)r.held_violations, (unsigned long long)r.held_checks,
        (unsigned long long)r.rtl_errors, (unsigned long long)r.data_errors,
        (unsigned long long)r.flag_errors, (unsigned long long)r.read);
    EXPECT_GT(r.held_violations, 0u) << "the held-value check missed binary pointer crossings";
    EXPECT_GT(r.rtl_errors, 0u) << "the synchronizer model's assertion never fired";
}

}  // namespace
