// The body of sc_main for the bench programs that run the platform: SystemC
// at the platform's time resolution, then Google Benchmark.
#pragma once

#include <benchmark/benchmark.h>

#include <systemc>

namespace bench {

inline int run_sc_benchmarks(int argc, char* argv[]) {
    sc_core::sc_set_time_resolution(1, sc_core::SC_FS);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

}  // namespace bench
