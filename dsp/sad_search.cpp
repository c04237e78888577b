#include "dsp/sad_search.h"

#include <algorithm>

namespace dsp {
namespace {

// One step of n pixels (n = 8 on the C64x: two SUBABS4 give the eight
// |a - b| bytes, two DOTPU4 with 0x01010101 add them up). Written plainly
// with a fixed count, so the host compiler uses its own SIMD for it.
template <int n>
inline uint32_t sad_pixels(const uint8_t* a, const uint8_t* b) {
    uint32_t sum = 0;
    for (int i = 0; i < n; ++i) {
        const int d = static_cast<int>(a[i]) - static_cast<int>(b[i]);
        sum += static_cast<uint32_t>(d < 0 ? -d : d);
    }
    return sum;
}

inline uint32_t sad_row(const uint8_t* a, const uint8_t* b, int width) {
    uint32_t sum = 0;
    int x = 0;
    for (; x + 16 <= width; x += 16) sum += sad_pixels<16>(a + x, b + x);
    for (; x + 8 <= width; x += 8) sum += sad_pixels<8>(a + x, b + x);
    for (; x < width; ++x) sum += sad_pixels<1>(a + x, b + x);
    return sum;
}

}  // namespace

uint32_t sad_at(gray_cplane image, int x, int y, gray_cplane pattern) {
    uint32_t sum = 0;
    for (int j = 0; j < pattern.height; ++j) {
        sum += sad_row(image.row(y + j) + x, pattern.row(j), pattern.width);
    }
    return sum;
}

box clip_positions(box positions, int image_width, int image_height, int pattern_width,
                   int pattern_height) {
    const int x0 = std::max(positions.x, 0);
    const int y0 = std::max(positions.y, 0);
    const int x1 = std::min(positions.right(), image_width - pattern_width + 1);
    const int y1 = std::min(positions.bottom(), image_height - pattern_height + 1);
    if (x1 <= x0 || y1 <= y0) return box{x0, y0, 0, 0};
    return box{x0, y0, x1 - x0, y1 - y0};
}

sad_result sad_search(gray_cplane image, gray_cplane pattern, box positions) {
    sad_result result;
    if (image.empty() || pattern.empty()) return result;
    const box clipped =
        clip_positions(positions, image.width, image.height, pattern.width, pattern.height);
    if (clipped.empty()) return result;

    result.valid = true;
    result.x = clipped.x;
    result.y = clipped.y;
    result.sad = UINT32_MAX;
    for (int y = clipped.y; y < clipped.bottom(); ++y) {
        for (int x = clipped.x; x < clipped.right(); ++x) {
            const uint32_t sad = sad_at(image, x, y, pattern);
            // Strictly smaller: the first minimum in raster order wins ties.
            if (sad < result.sad) {
                result.sad = sad;
                result.x = x;
                result.y = y;
            }
        }
    }
    result.positions = clipped.width * clipped.height;
    return result;
}

}  // namespace dsp
