#include "model/sensor/pixel_noise.h"

#include <cmath>

namespace sensor {

namespace {

// Inverse of the standard normal CDF (P. J. Acklam's rational approximation,
// relative error < 1.2e-9), computed once to fill the quantile table.
double normal_quantile(double p) {
    static constexpr double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,
                                   -2.759285104469687e+02, 1.383577518672690e+02,
                                   -3.066479806614716e+01, 2.506628277459239e+00};
    static constexpr double b[] = {-5.447609879822406e+01, 1.615858368580409e+02,
                                   -1.556989798598866e+02, 6.680131188771972e+01,
                                   -1.328068155288572e+01};
    static constexpr double c[] = {-7.784894002430293e-03, -3.223964580411365e-01,
                                   -2.400758277161838e+00, -2.549732539343734e+00,
                                   4.374664141464968e+00,  2.938163982698783e+00};
    static constexpr double d[] = {7.784695709041462e-03, 3.224671290700398e-01,
                                   2.445134137142996e+00, 3.754408661907416e+00};
    const double p_low = 0.02425;
    if (p < p_low) {
        const double q = std::sqrt(-2.0 * std::log(p));
        return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
               ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
    }
    if (p > 1.0 - p_low) return -normal_quantile(1.0 - p);
    const double q = p - 0.5;
    const double r = q * q;
    return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
           (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
}

}  // namespace

const std::array<int16_t, 65536>& pixel_noise::normal_table() {
    static const std::array<int16_t, 65536> table = [] {
        std::array<int16_t, 65536> t{};
        for (int i = 0; i < 65536; ++i) {
            const double z = normal_quantile((i + 0.5) / 65536.0);
            t[i] = static_cast<int16_t>(std::lround(z * 1024.0));
        }
        return t;
    }();
    return table;
}

void pixel_noise::configure(bool enabled, double read_dn, double shot_dn2_per_dn, uint64_t seed) {
    m_enabled = enabled;
    m_rng = splitmix64(seed);
    for (int s = 0; s <= max_signal; ++s) {
        const double sigma = enabled ? std::sqrt(read_dn * read_dn + shot_dn2_per_dn * s) : 0.0;
        m_sigma_q8[s] = static_cast<int32_t>(std::lround(sigma * 256.0));
    }
}

}  // namespace sensor
