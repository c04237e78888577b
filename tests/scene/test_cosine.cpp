// The renderer's cosine against the C library's, which is the oracle: within
// a unit in the last place of 1 over the arguments a ball's texture sums, and
// exact where the answer is a known constant.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "model/scene/cosine.h"

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double one_ulp_of_one = 2.220446049250313e-16;

TEST(Cosine, WithinAUnitInTheLastPlaceOfTheLibrarysOverTheTexturesArguments) {
    // Wave numbers up to 9 a radius, a phase up to 2 pi, and far beyond.
    double worst = 0.0, worst_at = 0.0;
    const int64_t steps = 4000000;
    for (int64_t i = 0; i <= steps; ++i) {
        const double x = -400.0 + 800.0 * static_cast<double>(i) / steps + 1e-7 * (i % 7);
        const double error = std::fabs(scene::cosine(x) - std::cos(x));
        if (error > worst) {
            worst = error;
            worst_at = x;
        }
    }
    EXPECT_LE(worst, one_ulp_of_one) << "at x = " << worst_at;
}

TEST(Cosine, EveryQuadrantHasItsSignAndItsKernel) {
    // Near each multiple of pi / 2 the answer is +-1 or +-(x - n pi / 2):
    // a wrong quadrant gives the wrong sign or the other kernel.
    for (int n = -40; n <= 40; ++n) {
        for (const double offset : {-0.3, -1e-3, 0.0, 1e-3, 0.3}) {
            const double x = n * (pi / 2) + offset;
            EXPECT_NEAR(scene::cosine(x), std::cos(x), one_ulp_of_one)
                << "n = " << n << ", offset " << offset;
        }
    }
    EXPECT_EQ(scene::cosine(0.0), 1.0);
    EXPECT_EQ(scene::cosine(-0.0), 1.0);
}

TEST(Cosine, Even) {
    for (double x = 0.0; x < 60.0; x += 0.37) EXPECT_EQ(scene::cosine(x), scene::cosine(-x)) << x;
}

}  // namespace
