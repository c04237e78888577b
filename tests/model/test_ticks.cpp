// The integer time base (model/time/ticks.h): clock constants, exact tick ->
// fs rounding, and clocks stepped by fractional accumulation that match their
// closed form over 10^9 edges, with and without drift.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "model/time/ticks.h"

using namespace simtime;

namespace {

// Independent rounding: nearest integer of t * 10^6 / 18 in 128-bit.
int64_t fs_reference(int64_t t) {
    const __int128 num = static_cast<__int128>(t) * 2000000 + 18;
    return static_cast<int64_t>(num / 36);
}

}  // namespace

TEST(Ticks, ClockPeriodsFromFrequencies) {
    const rational_ticks pclk = period_of_hz(120000000, 7);
    EXPECT_EQ(pclk.num, 1050);
    EXPECT_EQ(pclk.den, 1);
    EXPECT_EQ(pclk.num, pclk_default_period);
    EXPECT_EQ(period_of_hz(100000000).num, emif_100mhz_period);
    EXPECT_EQ(period_of_hz(120000000).num, emif_120mhz_period);
    EXPECT_EQ(period_of_hz(125000000).num, emif_125mhz_period);
    EXPECT_EQ(period_of_hz(600000000).num, cpu_600mhz_period);
    EXPECT_EQ(period_of_hz(720000000).num, cpu_720mhz_period);
    EXPECT_EQ(period_of_hz(1000000000).num, cpu_1ghz_period);
    // Off-grid clocks are exact fractions: 27 MHz = 2000/3 ticks.
    const rational_ticks xtal = period_of_hz(27000000);
    EXPECT_EQ(xtal.num, 2000);
    EXPECT_EQ(xtal.den, 3);
    // docs/design-brief.md: edges of the 120/7 MHz pixel clock and the 100 MHz EMIF meet
    // every 350 ns = 6300 ticks = lcm(1050, 180).
    EXPECT_EQ(1050 * 180 / gcd_i64(1050, 180), 6300);
    EXPECT_EQ(to_fs(6300), 350000000);
}

TEST(Ticks, TickToFemtosecondsIsExactNearestRounding) {
    for (int64_t t = 0; t < 200000; ++t) ASSERT_EQ(to_fs(t), fs_reference(t)) << t;
    const int64_t big[] = {441000000, 441000000LL * 1000, 987654321987LL, (1LL << 40) + 17};
    for (int64_t t : big) EXPECT_EQ(to_fs(t), fs_reference(t)) << t;
    EXPECT_EQ(to_fs(1050), 58333333);             // one default pclk period, 58.333333 ns
    EXPECT_EQ(to_fs(441000000), 24500000000000);  // one default frame, exactly 24.5 ms
    // 10^6 r mod 18 is never 9: no tie, so the rounding direction never matters.
    for (int r = 0; r < 18; ++r) EXPECT_NE((r * 1000000) % 18, 9);
}

TEST(Ticks, ClosedFormEdgesOfPlainAndDriftingClocks) {
    const tick_clock pclk({1050, 1}, 500);
    for (uint64_t n : {0ull, 1ull, 7ull, 1000000ull, 123456789012ull}) {
        EXPECT_EQ(pclk.rise(n), 500 + static_cast<int64_t>(n) * 1050);
        EXPECT_EQ(pclk.fall(n), 500 + static_cast<int64_t>(n) * 1050 + 525);
    }
    // +100 ppm (slower): rise(n) = n P + floor(n P 100 / 1e6).
    const tick_clock slow({1050, 1}, 0, 100);
    for (uint64_t n : {0ull, 1ull, 9999ull, 10000ull, 1000000ull, 987654321ull}) {
        const int64_t nn = static_cast<int64_t>(n);
        EXPECT_EQ(slow.rise(n), nn * 1050 + (nn * 1050 * 100) / 1000000) << n;
    }
    // One full pixel clock lost every 10^4 clocks at +100 ppm.
    EXPECT_EQ(slow.rise(10000) - pclk.rise(10000) + 500, 1050);
    // -37 ppm (faster): floor of a negative fraction.
    const tick_clock fast({1050, 1}, 0, -37);
    for (uint64_t n : {1ull, 1000ull, 123457ull}) {
        const __int128 exact = static_cast<__int128>(n) * 1050 * (1000000 - 37);
        EXPECT_EQ(fast.rise(n), static_cast<int64_t>(exact / 1000000)) << n;
    }
    // first_rise_at_or_after against a linear search.
    const tick_clock xtal(period_of_hz(27000000), 10, 11);
    for (ticks t = 0; t < 20000; t += 7) {
        uint64_t n = 0;
        while (xtal.rise(n) < t) ++n;
        ASSERT_EQ(xtal.first_rise_at_or_after(t), n) << t;
    }
}

// The accumulator never drifts from the closed form: 10^9 half-edges stepped
// one by one land exactly on half_edge(10^9), for the hardest clock (an
// off-grid 27 MHz crystal with -23 ppm drift), with spot checks on the way.
TEST(Ticks, CursorMatchesClosedFormOverOneBillionEdges) {
    const tick_clock clock(period_of_hz(27000000), 12345, -23);
    clock_cursor cursor(clock);
    const auto t0 = std::chrono::steady_clock::now();
    constexpr uint64_t edges = 1000000000;
    uint64_t mismatches = 0;
    for (uint64_t h = 0; h < edges; ++h) {
        if ((h & 0xFFFFF) == 0 && cursor.tick() != clock.half_edge(h)) ++mismatches;
        cursor.advance();
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(mismatches, 0u);
    EXPECT_EQ(cursor.index(), edges);
    EXPECT_EQ(cursor.tick(), clock.half_edge(edges));
    std::printf("10^9 half-edges stepped in %.2f s; final tick %lld = closed form\n", seconds,
                static_cast<long long>(cursor.tick()));

    // Positioned cursors agree too (what a drift onset uses).
    for (uint64_t h : {0ull, 1ull, 999999937ull}) {
        clock_cursor c(clock, h);
        for (int i = 0; i < 1000; ++i) {
            ASSERT_EQ(c.tick(), clock.half_edge(h + static_cast<uint64_t>(i)));
            c.advance();
        }
    }
}

// Why edges are rounded from ticks and not summed: adding the rounded 1050-tick
// period (58,333,333 fs) 10^9 times is 333 ns short of the exact edge time.
TEST(Ticks, RoundedPeriodsWouldAccumulateError) {
    const int64_t rounded_period_fs = to_fs(1050);
    const int64_t n = 1000000000;
    const int64_t accumulated = rounded_period_fs * n;
    const int64_t exact = to_fs(1050 * n);
    EXPECT_EQ(exact - accumulated, 333333333);  // fs
    std::printf("summing rounded periods: %lld fs behind after 10^9 clocks; per-edge rounding: 0\n",
                static_cast<long long>(exact - accumulated));
    const tick_clock pclk({1050, 1});
    clock_cursor c(pclk);
    for (int64_t i = 0; i < 2 * 1000000; ++i) c.advance();
    EXPECT_EQ(to_fs(c.tick()), to_fs(1050LL * 1000000));
}
