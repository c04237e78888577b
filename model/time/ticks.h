// The integer time base shared by every layer (docs/design-brief.md, "Time").
//
// One tick is 1/18 ns. Every clock of the platform is a whole number of ticks
// (or, for clocks off that grid, an exact fraction of ticks), so edge times are
// exact integers: pixel clock 120/7 MHz = 1050 ticks, EMIF 100/120/125 MHz =
// 180/150/144, CPU 600/720/1000 MHz = 30/25/18.
//
// SystemC runs at 1 fs resolution (tests/support/sc_test_main.cpp). A tick is 55555.5...
// fs, so each edge is rounded to fs ONCE, from its exact tick count
// (to_fs(ticks)); adding up rounded periods would drift by 1/3 fs per 1050-tick
// period, 333 ns after 10^9 edges. Both the fast RTL island and the SystemC pin
// arrangement use these functions, so their edges agree to the femtosecond.
//
// A clock is a rational period N/D ticks (D = 1 for clocks on the grid) and an
// origin tick. Its half-edges h = 0, 1, 2, ... (even = rising, odd = falling)
// fall at  origin + floor(h * N / (2 D)).  Drift (a sensor on its own
// oscillator, docs/design-brief.md "Clocks") multiplies the period by (1e6 + ppm) / 1e6:
// the tick count per period changes by fractional accumulation, never by a
// rounded period. clock_cursor steps the same sequence with an integer
// remainder accumulator (two additions per half-edge, no division) and is
// exact against the closed form for any number of edges.
#pragma once

#include <cstdint>

namespace simtime {

using ticks = int64_t;

inline constexpr ticks ticks_per_ns = 18;
inline constexpr int64_t fs_per_ns = 1000000;

// Periods in ticks of the platform's clocks (docs/design-brief.md "Time"; docs/hardware-facts.md
// section 2: DSK v1 600 MHz / 100 MHz EMIF, v2 720 / 120, v3 1 GHz / 125).
inline constexpr ticks pclk_default_period = 1050;  // 120/7 MHz default pixel clock
inline constexpr ticks emif_100mhz_period = 180;
inline constexpr ticks emif_120mhz_period = 150;
inline constexpr ticks emif_125mhz_period = 144;
inline constexpr ticks cpu_600mhz_period = 30;
inline constexpr ticks cpu_720mhz_period = 25;
inline constexpr ticks cpu_1ghz_period = 18;

// Femtoseconds of a tick count, rounded to nearest. Exact integer arithmetic:
// t = 18 q + r, fs = 10^6 q + round(10^6 r / 18). 10^6 r mod 18 is never 9, so
// there is no tie to break. Valid for t >= 0 up to ~1.8e13 s.
constexpr int64_t to_fs(ticks t) {
    const int64_t q = t / ticks_per_ns;
    const int64_t r = t % ticks_per_ns;
    return q * fs_per_ns + (r * fs_per_ns + ticks_per_ns / 2) / ticks_per_ns;
}

// The first tick whose time (to_fs) is at or after fs femtoseconds; 0 for fs <= 0.
constexpr ticks tick_at_or_after_fs(int64_t fs) {
    if (fs <= 0) return 0;
    // floor(fs * 18 / 10^6), then onto the first tick that is not earlier.
    ticks t = static_cast<ticks>(static_cast<__int128>(fs) * ticks_per_ns / fs_per_ns);
    while (to_fs(t) < fs) ++t;
    while (t > 0 && to_fs(t - 1) >= fs) --t;
    return t;
}

// Ticks of a frequency given as num/den Hz, as a reduced fraction N/D:
// period = 18e9 * den / num ticks. E.g. 120e6/7 Hz -> 1050/1, 27e6 Hz -> 2000/3.
struct rational_ticks {
    int64_t num = 1;
    int64_t den = 1;

    constexpr bool is_integer() const { return den == 1; }
};

constexpr int64_t gcd_i64(int64_t a, int64_t b) {
    while (b != 0) {
        const int64_t t = a % b;
        a = b;
        b = t;
    }
    return a < 0 ? -a : a;
}

constexpr rational_ticks reduce(rational_ticks r) {
    const int64_t g = gcd_i64(r.num, r.den);
    return g > 1 ? rational_ticks{r.num / g, r.den / g} : r;
}

constexpr rational_ticks period_of_hz(int64_t hz_num, int64_t hz_den = 1) {
    return reduce({ticks_per_ns * 1000000000 * hz_den, hz_num});
}

// The closed form: a clock's half-edge times. 128-bit intermediate, so any
// edge index up to 2^62 with periods up to 2^40 ticks is exact.
class tick_clock {
  public:
    tick_clock() = default;
    // period: N/D ticks; drift_ppm: the period is (1e6 + drift_ppm)/1e6 times
    // longer (a positive drift is a SLOWER oscillator).
    constexpr tick_clock(rational_ticks period, ticks origin = 0, int32_t drift_ppm = 0)
        : m_num(period.num * (1000000 + drift_ppm)),
          m_den(period.den * 1000000),
          m_origin(origin),
          m_period(period),
          m_drift_ppm(drift_ppm) {
        reduce_fraction();
    }

    constexpr ticks half_edge(uint64_t h) const {
        // floor(h * N / (2D)) with N, D > 0 and h >= 0.
        const __int128 p = static_cast<__int128>(h) * m_num;
        return m_origin + static_cast<ticks>(p / (2 * static_cast<__int128>(m_den)));
    }
    constexpr ticks rise(uint64_t n) const { return half_edge(2 * n); }
    constexpr ticks fall(uint64_t n) const { return half_edge(2 * n + 1); }

    // Index of the first rising edge at or after tick t (0 if t <= origin).
    constexpr uint64_t first_rise_at_or_after(ticks t) const {
        if (t <= m_origin) return 0;
        // smallest n with floor(n N / D) >= x  <=>  n N >= x D  <=>  n = ceil(x D / N)
        const __int128 x = t - m_origin;
        const __int128 num = x * m_den;
        return static_cast<uint64_t>((num + m_num - 1) / m_num);
    }

    constexpr ticks origin() const { return m_origin; }
    constexpr rational_ticks nominal_period() const { return m_period; }
    constexpr int32_t drift_ppm() const { return m_drift_ppm; }
    // The effective period as a reduced fraction numerator / denominator.
    constexpr int64_t period_num() const { return m_num; }
    constexpr int64_t period_den() const { return m_den; }

  private:
    constexpr void reduce_fraction() {
        const int64_t g = gcd_i64(m_num, m_den);
        if (g > 1) {
            m_num /= g;
            m_den /= g;
        }
    }

    int64_t m_num = 1;  // effective period = m_num / m_den ticks
    int64_t m_den = 1;
    ticks m_origin = 0;
    rational_ticks m_period{};
    int32_t m_drift_ppm = 0;
};

// Steps a tick_clock's half-edges in order with a remainder accumulator:
// per half-edge the tick advances by q = floor(N / 2D) and the remainder by
// r = N mod 2D; a carry adds one tick. After k steps the tick equals
// half_edge(k) exactly (tests/model/test_ticks.cpp checks 10^9 edges).
class clock_cursor {
  public:
    clock_cursor() = default;
    // Positioned on half-edge h of the clock.
    explicit clock_cursor(const tick_clock& clock, uint64_t h = 0) { reset(clock, h); }

    void reset(const tick_clock& clock, uint64_t h = 0) {
        const __int128 two_d = 2 * static_cast<__int128>(clock.period_den());
        m_two_d = static_cast<int64_t>(two_d);
        m_step = static_cast<int64_t>(clock.period_num() / two_d);
        m_step_rem = static_cast<int64_t>(clock.period_num() % two_d);
        const __int128 p = static_cast<__int128>(h) * clock.period_num();
        m_tick = clock.origin() + static_cast<ticks>(p / two_d);
        m_rem = static_cast<int64_t>(p % two_d);
        m_index = h;
    }

    ticks tick() const { return m_tick; }
    uint64_t index() const { return m_index; }

    void advance() {
        m_rem += m_step_rem;
        // The carry without a branch: the fast island advances a cursor at
        // every clock edge, and a drifting clock's carries follow no pattern
        // the branch predictor can learn.
        const int64_t carry = m_rem >= m_two_d ? 1 : 0;
        m_rem -= m_two_d & -carry;
        m_tick += m_step + carry;
        ++m_index;
    }

  private:
    ticks m_tick = 0;
    int64_t m_rem = 0;  // numerator of the fractional tick, in units of 1/(2D)
    int64_t m_step = 0;
    int64_t m_step_rem = 0;
    int64_t m_two_d = 2;
    uint64_t m_index = 0;
};

}  // namespace simtime
