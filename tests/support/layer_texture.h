// A fixed pseudo-random grey value per layer and pixel, for synthetic
// stereo pairs whose layers (an object, a background) are each their own
// texture and whose layout is known by construction.
#pragma once

#include <cstdint>

namespace test_support {

inline uint8_t layer_texture(int layer, int x, int y) {
    // Unsigned arithmetic: wraps, where int products would overflow.
    uint32_t h = static_cast<uint32_t>(layer) * 73856093u ^ static_cast<uint32_t>(x) * 19349663u ^
                 static_cast<uint32_t>(y) * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return static_cast<uint8_t>(h & 0xff);
}

}  // namespace test_support
