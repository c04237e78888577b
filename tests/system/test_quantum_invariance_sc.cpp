// The island's quantum must change only how often it syncs with SystemC,
// never a result (tb/platform/arrangements/fast/fast_island.h): it never runs past another
// process's next activity and stops at every bus completion and interrupt
// pin change. Here the firmware's card watchdog (30 ms, not a multiple of
// anything the island knows) reads card registers over the EMIF at times set
// by the C6416 timer, racing the EDMA's capture bursts and the firmware's own
// SDRAM line transfers (issue 5: on the bus by default). The same run with a
// 1 us and a 1 ms quantum must give the same pins, timeline and results.
// Negative control (checked by hand, docs/platform.md): an island that runs
// a whole quantum ahead regardless gives a different pin hash per quantum.
//
// Two simulations, one per process: a forked child runs one, the test runs
// the other (SystemC elaborates once per process).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>

#include "tests/system/system_run.h"

namespace {

struct digest {
    uint64_t pin_hash = 0;
    uint64_t pin_changes = 0;
    uint64_t timeline_hash = 0;
    uint64_t timeline_events = 0;
    uint64_t syncs = 0;
    uint64_t captured = 0;
    uint64_t memory_checksums = 0;  // all captured frames, folded
    uint64_t results = 0;
    int64_t first_point_z_um = 0;
    uint64_t cpu_bus_reads = 0;
};

platform::platform_config config_with_quantum(simtime::ticks quantum) {
    platform::platform_config config;
    config.frames = 5;
    platform::set_firmware_key(&config, "watchdog_ms", 30);
    config.quantum = quantum;
    return config;
}

digest run_and_digest(simtime::ticks quantum) {
    platform::platform_top top(config_with_quantum(quantum));
    top.run();
    digest d;
    const platform::island& island = top.cycle_island();
    d.pin_hash = island.pin_hash();
    d.pin_changes = island.stats().pin_changes;
    d.timeline_hash = top.events().hash();
    d.timeline_events = top.events().events().size();
    d.syncs = island.stats().syncs;
    d.captured = top.captured().size();
    for (const platform::captured_pair& c : top.captured())
        d.memory_checksums =
            d.memory_checksums * 31 + c.memory_checksum[0] * 7 + c.memory_checksum[1];
    d.results = top.probe().results().size();
    for (const platform::fw_result& r : top.probe().results()) {
        if (r.out.has_point) {
            d.first_point_z_um = r.out.z_um;
            break;
        }
    }
    d.cpu_bus_reads = top.engine().stats().accesses[static_cast<int>(emif::requester::cpu)];
    return d;
}

TEST(quantum_invariance, one_microsecond_and_one_millisecond_quanta_give_identical_runs) {
    constexpr simtime::ticks one_us = 1000 * simtime::ticks_per_ns;
    constexpr simtime::ticks one_ms = 1000 * one_us;
    int fd[2];
    ASSERT_EQ(pipe(fd), 0);
    std::fflush(stdout);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        close(fd[0]);
        const digest d = run_and_digest(one_ms);
        const ssize_t written = write(fd[1], &d, sizeof d);
        close(fd[1]);
        _exit(written == static_cast<ssize_t>(sizeof d) ? 0 : 1);
    }
    close(fd[1]);
    const digest fine = run_and_digest(one_us);
    digest coarse;
    const ssize_t got = read(fd[0], &coarse, sizeof coarse);
    close(fd[0]);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    ASSERT_EQ(got, static_cast<ssize_t>(sizeof coarse));

    EXPECT_EQ(fine.pin_hash, coarse.pin_hash);
    EXPECT_EQ(fine.pin_changes, coarse.pin_changes);
    EXPECT_EQ(fine.timeline_hash, coarse.timeline_hash);
    EXPECT_EQ(fine.timeline_events, coarse.timeline_events);
    EXPECT_EQ(fine.captured, coarse.captured);
    EXPECT_EQ(fine.memory_checksums, coarse.memory_checksums);
    EXPECT_EQ(fine.results, coarse.results);
    EXPECT_EQ(fine.first_point_z_um, coarse.first_point_z_um);
    EXPECT_EQ(fine.cpu_bus_reads, coarse.cpu_bus_reads);
    // The run exercises what the test is about: timer-driven CPU bus reads
    // beside the capture bursts, and the quanta really differ.
    // Boot makes 24 card accesses; the watchdog reads 3 counters every 30 ms.
    EXPECT_GE(fine.cpu_bus_reads, 24u + 3 * 4);
    EXPECT_GE(fine.captured, 2u);
    // Bus completions (the firmware's SDRAM lines and the capture bursts) stop
    // the island in both runs; the 1 us quantum adds about one sync per
    // microsecond the island would otherwise run ahead (122.5 ms simulated).
    EXPECT_GT(fine.syncs, coarse.syncs + 50000);
    std::printf(
        "1 us quantum: %llu syncs, 1 ms: %llu syncs; pin hash %016llx over %llu changes; "
        "timeline %llu events; %llu CPU bus accesses; %llu pairs captured\n",
        static_cast<unsigned long long>(fine.syncs), static_cast<unsigned long long>(coarse.syncs),
        static_cast<unsigned long long>(fine.pin_hash),
        static_cast<unsigned long long>(fine.pin_changes),
        static_cast<unsigned long long>(fine.timeline_events),
        static_cast<unsigned long long>(fine.cpu_bus_reads),
        static_cast<unsigned long long>(fine.captured));
}

}  // namespace
