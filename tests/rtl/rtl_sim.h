// Shared plumbing of the rtl tests: two unrelated clocks on the integer tick
// time base (1 tick = 1/18 ns, docs/design-brief.md "Time"), coverage dumps for
// `make coverage-rtl`, and a way to mute Verilator's own printing.
#pragma once

#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <string>

#include "verilated.h"
#ifdef STEREOSIM_RTL_COVERAGE_DIR
#include <sys/stat.h>

#include "verilated_cov.h"
#endif

namespace rtl_test {

// Clock periods in ticks of 1/18 ns (docs/design-brief.md): every edge is exact.
constexpr uint64_t ticks_pclk_default = 1050;  // 120/7 MHz master pixel clock
constexpr uint64_t ticks_eclk_v1 = 180;        // 100 MHz ECLKOUT, DSK v1
constexpr uint64_t ticks_eclk_v2 = 150;        // 120 MHz, DSK v2
constexpr uint64_t ticks_eclk_v3 = 144;        // 125 MHz, C6416T DSK
constexpr double ns_per_tick = 1.0 / 18.0;

// Rising edges of two clocks, A and B. Coincident edges are ONE event (both
// bits set): the harness raises both clocks before a single eval, so each
// domain's flops sample the other's pre-edge values, as in the RTL's
// semantics (docs/card.md, "Clocks").
class two_clocks {
  public:
    static constexpr unsigned edge_a = 1;
    static constexpr unsigned edge_b = 2;

    two_clocks(uint64_t period_a, uint64_t period_b, uint64_t phase_a = 0, uint64_t phase_b = 0)
        : m_period_a(period_a), m_period_b(period_b), m_next_a(phase_a), m_next_b(phase_b) {}

    // Advances to the next edge(s); returns which clocks rise at now().
    unsigned advance() {
        m_now = m_next_a < m_next_b ? m_next_a : m_next_b;
        unsigned edges = 0;
        if (m_next_a == m_now) {
            edges |= edge_a;
            m_next_a += m_period_a;
        }
        if (m_next_b == m_now) {
            edges |= edge_b;
            m_next_b += m_period_b;
        }
        return edges;
    }
    uint64_t now() const { return m_now; }
    uint64_t period_a() const { return m_period_a; }
    uint64_t period_b() const { return m_period_b; }

  private:
    uint64_t m_period_a, m_period_b;
    uint64_t m_next_a, m_next_b;
    uint64_t m_now = 0;
};

// Under AddressSanitizer (Debug + ASan in CI) the long stress loops run a
// tenth of their length: that pass looks for memory errors, the full-length
// runs are the RelWithDebInfo ones.
#if defined(__SANITIZE_ADDRESS__)
constexpr uint64_t stress_divisor = 10;
#else
constexpr uint64_t stress_divisor = 1;
#endif

// Writes the context's coverage counters (coverage builds only). Call while
// the model still exists: the counters live inside it.
inline void write_coverage(VerilatedContext& context, const char* design) {
#ifdef STEREOSIM_RTL_COVERAGE_DIR
    static std::atomic<int> serial{0};
    ::mkdir(STEREOSIM_RTL_COVERAGE_DIR, 0755);
    const std::string path = std::string(STEREOSIM_RTL_COVERAGE_DIR) + "/" + design + "_" +
                             std::to_string(::getpid()) + "_" + std::to_string(serial++) + ".dat";
    context.coveragep()->write(path.c_str());
#else
    (void)context;
    (void)design;
#endif
}

// Redirects stdout to /dev/null while alive (Verilator prints every failed
// assertion; the negative-control test expects thousands of them).
class stdout_muted {
  public:
    stdout_muted() {
        std::fflush(stdout);
        m_saved = ::dup(1);
        std::FILE* null_file = std::fopen("/dev/null", "w");
        if (null_file) {
            ::dup2(::fileno(null_file), 1);
            std::fclose(null_file);
        }
    }
    ~stdout_muted() {
        std::fflush(stdout);
        if (m_saved >= 0) {
            ::dup2(m_saved, 1);
            ::close(m_saved);
        }
    }
    stdout_muted(const stdout_muted&) = delete;
    stdout_muted& operator=(const stdout_muted&) = delete;

  private:
    int m_saved = -1;
};

}  // namespace rtl_test
