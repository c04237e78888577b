#pragma once

#include <cstdint>
#include <cstring>

namespace scene {

// cos(x) for the moderate arguments a ball's texture sums (|x| up to a few
// hundred), inline and without branches. glibc's cos, a call per term, was
// more than half of a rendered frame's time; this one is within 1.2e-16 of
// it (tests/scene/test_cosine.cpp), far below the 8-bit step a rendered
// pixel is quantized to. The reduction is fdlibm's medium one (pi/2 in
// two parts, the first 33 bits so n * pio2_hi is exact), the kernels are
// fdlibm's __kernel_sin and __kernel_cos (FreeBSD's form of the latter).
inline double cosine(double x) {
    constexpr double inv_pio2 = 6.36619772367581382433e-01;
    constexpr double pio2_hi = 1.57079632673412561417e+00;
    constexpr double pio2_lo = 6.07710050650619224932e-11;
    constexpr double round_magic = 6755399441055744.0;  // 1.5 * 2^52
    const double shifted = x * inv_pio2 + round_magic;
    const double n = shifted - round_magic;  // x / (pi / 2), to nearest
    std::int64_t bits;
    std::memcpy(&bits, &shifted, sizeof bits);
    const unsigned quadrant = static_cast<unsigned>(bits) & 3u;
    const double r = (x - n * pio2_hi) - n * pio2_lo;

    const double z = r * r;
    const double sin_tail =
        8.33333333332248946124e-03 +
        z * (-1.98412698298579493134e-04 +
             z * (2.75573137070700676789e-06 +
                  z * (-2.50507602534068634195e-08 + z * 1.58969099521155010221e-10)));
    const double sin_r = r + (z * r) * (-1.66666666666666324348e-01 + z * sin_tail);
    const double cos_tail =
        z * (4.16666666666666019037e-02 +
             z * (-1.38888888888741095749e-03 +
                  z * (2.48015872894767294178e-05 +
                       z * (-2.75573143513906633035e-07 +
                            z * (2.08757232129817482790e-09 + z * -1.13596475577881948265e-11)))));
    const double half_z = 0.5 * z;
    const double w = 1.0 - half_z;
    const double cos_r = w + (((1.0 - w) - half_z) + z * cos_tail);

    // cos(n pi/2 + r): cos r, -sin r, -cos r, sin r by quadrant.
    const double value = (quadrant & 1u) ? sin_r : cos_r;
    return ((quadrant + 1u) & 2u) ? -value : value;
}

}  // namespace scene
