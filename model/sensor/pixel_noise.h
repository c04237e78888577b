// Seeded sensor noise in integer arithmetic per pixel: shot noise (variance
// proportional to the signal) plus read noise, as one Gaussian draw per pixel:
//   sigma(s)^2 = read_dn^2 + shot_dn2_per_dn * s        (s = signal in DN)
//   noise      = round(z * sigma(s)),   z ~ N(0, 1)
// z comes from a fixed table of 65536 standard-normal quantiles (Q10) indexed
// by a splitmix64 stream; sigma(s) is tabulated (Q8) per signal level when the
// noise is configured. Per pixel: one 64-bit RNG step, two loads, one multiply.
#pragma once

#include <array>
#include <cstdint>

namespace sensor {

// splitmix64 (Steele, Lea, Flood 2014): tiny, fast, well distributed; one
// stream per purpose (start-up delays, noise) so they do not interact.
class splitmix64 {
  public:
    explicit splitmix64(uint64_t seed = 0) : m_state(seed) {}
    uint64_t next() {
        uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    // Uniform in [0, n) for n > 0 (modulo bias < n / 2^64, negligible here).
    uint64_t below(uint64_t n) { return next() % n; }

  private:
    uint64_t m_state;
};

class pixel_noise {
  public:
    static constexpr int max_signal = 1023;  // sigma table range (signal clamped to it)

    void configure(bool enabled, double read_dn, double shot_dn2_per_dn, uint64_t seed);
    bool enabled() const { return m_enabled; }

    // Noise in DN for a pixel of signal s (>= 0), 0 when disabled.
    int sample(int s) {
        const int idx = s > max_signal ? max_signal : s;
        const int32_t z = normal_table()[m_rng.next() >> 48];
        const int64_t prod = static_cast<int64_t>(z) * m_sigma_q8[idx];
        return static_cast<int>((prod + (int64_t{1} << 17)) >> 18);  // Q10 * Q8 -> DN
    }

    // Standard-normal quantiles at (i + 0.5) / 65536, in Q10 (z * 1024).
    static const std::array<int16_t, 65536>& normal_table();

  private:
    bool m_enabled = false;
    splitmix64 m_rng{0};
    std::array<int32_t, max_signal + 1> m_sigma_q8{};
};

}  // namespace sensor
