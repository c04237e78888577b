#include "dsp/stereo_sad.h"

#include <algorithm>
#include <cstdlib>

#include "dsp/int_bounds.h"

namespace dsp {

namespace {

// The sum over two w x h boxes (or each row's span of them when `spans`
// is given) of pixel_cost(row of a, row of b, column).
template <typename PixelCost>
uint32_t sum_over_box(const uint8_t* a, int a_stride, const uint8_t* b, int b_stride, int w, int h,
                      const row_span* spans, PixelCost pixel_cost) {
    uint32_t sum = 0;
    for (int j = 0; j < h; ++j) {
        const uint8_t* ra = a + static_cast<std::ptrdiff_t>(j) * a_stride;
        const uint8_t* rb = b + static_cast<std::ptrdiff_t>(j) * b_stride;
        const int begin = spans ? spans[j].begin : 0;
        const int end = spans ? spans[j].end : w;
        for (int i = begin; i < end; ++i) sum += pixel_cost(ra, rb, i);
    }
    return sum;
}

// SAD of two boxes. The byte loop is the C form of the C64x SUBABS4 +
// DOTPU4 kernel (four pixels per instruction there).
uint32_t box_sad(const uint8_t* a, int a_stride, const uint8_t* b, int b_stride, int w, int h,
                 const row_span* spans) {
    return sum_over_box(a, a_stride, b, b_stride, w, h, spans,
                        [](const uint8_t* ra, const uint8_t* rb, int i) {
                            return static_cast<uint32_t>(std::abs(ra[i] - rb[i]));
                        });
}

// The SAD a half pixel from `a` towards a + dir, doubled: each pixel
// |2 b - (a[i] + a[i + dir])| (exact).
uint32_t half_pel_sad(const uint8_t* a, int a_stride, int dir, const uint8_t* b, int b_stride,
                      int w, int h, const row_span* spans) {
    return sum_over_box(
        a, a_stride, b, b_stride, w, h, spans, [dir](const uint8_t* ra, const uint8_t* rb, int i) {
            return static_cast<uint32_t>(std::abs(2 * rb[i] - (ra[i] + ra[i + dir])));
        });
}

// Signed division rounded to nearest (halves away from zero); den > 0.
int64_t divide_rounded(int64_t num, int64_t den) {
    return num >= 0 ? (num + den / 2) / den : -((-num + den / 2) / den);
}

bool box_inside(const box& b, int width, int height) {
    return b.x >= 0 && b.y >= 0 && b.right() <= width && b.bottom() <= height;
}

}  // namespace

int32_t subpixel_offset_q8(uint32_t s_minus, uint32_t s0, uint32_t s_plus) {
    // Curvature of the parabola (twice its second coefficient); <= 0 means
    // the three points are flat or s0 is not a minimum: no refinement.
    const int64_t curvature =
        static_cast<int64_t>(s_minus) + static_cast<int64_t>(s_plus) - 2 * static_cast<int64_t>(s0);
    if (curvature <= 0) return 0;
    const int64_t slope = static_cast<int64_t>(s_minus) - static_cast<int64_t>(s_plus);
    int64_t offset = divide_rounded(slope * 256, 2 * curvature);
    if (offset > 128) offset = 128;
    if (offset < -128) offset = -128;
    return static_cast<int32_t>(offset);
}

int32_t subpixel_offset_equiangular_q8(uint32_t s_minus, uint32_t s0, uint32_t s_plus) {
    // Slope of the V: the rise from the minimum to the higher neighbour.
    const uint32_t higher = s_minus > s_plus ? s_minus : s_plus;
    if (higher <= s0) return 0;
    const int64_t slope = static_cast<int64_t>(higher) - static_cast<int64_t>(s0);
    const int64_t difference = static_cast<int64_t>(s_minus) - static_cast<int64_t>(s_plus);
    int64_t offset = divide_rounded(difference * 256, 2 * slope);
    if (offset > 128) offset = 128;
    if (offset < -128) offset = -128;
    return static_cast<int32_t>(offset);
}

int32_t subpixel_offset_half_pel_q8(const uint32_t doubled[5]) {
    // The least of the three middle samples (the integer minimum on a tie)
    // and the V through it and its neighbours, a half pixel apart.
    int k = 2;
    if (doubled[1] < doubled[k]) k = 1;
    if (doubled[3] < doubled[k]) k = 3;
    const int32_t offset =
        (k - 2) * 128 +
        subpixel_offset_equiangular_q8(doubled[k - 1], doubled[k], doubled[k + 1]) / 2;
    return offset > 128 ? 128 : offset < -128 ? -128 : offset;
}

namespace {

stereo_result match(gray_cplane right, gray_cplane left, box pattern, const row_span* spans,
                    const stereo_params& params) {
    stereo_result result;
    if (pattern.empty() || right.empty() || left.empty()) return result;
    if (!box_inside(pattern, right.width, right.height)) return result;

    const uint8_t* pattern_origin = &right.at(pattern.x, pattern.y);
    // Columns where the box fits in the left image: x + d in [0, left.width - w].
    int d_first = params.min_disparity;
    int d_last = params.max_disparity;
    if (pattern.x + d_first < 0) d_first = -pattern.x;
    if (pattern.x + d_last > left.width - pattern.width)
        d_last = left.width - pattern.width - pattern.x;

    // The minimum and, for the sub-pixel step, its neighbours on the same row.
    uint32_t best = 0;
    uint32_t best_minus = 0;
    uint32_t best_plus = 0;
    bool have_minus = false;
    bool have_plus = false;
    bool plus_pending = false;  // the next position on this row is the best's d+1

    // Rows in order of |dy| (0, -1, +1, -2, +2, ...): with a strict '<' the
    // first of equal SADs wins, which gives the documented tie rule.
    for (int k = 0; k <= 2 * params.row_slack; ++k) {
        const int dy = (k + 1) / 2 * (k % 2 == 1 ? -1 : 1);
        const int y = pattern.y + dy;
        if (y < 0 || y + pattern.height > left.height) continue;
        const uint8_t* left_row = left.row(y);
        plus_pending = false;
        bool have_previous = false;
        uint32_t previous = 0;
        for (int d = d_first; d <= d_last; ++d) {
            const uint32_t sad = box_sad(left_row + pattern.x + d, left.stride, pattern_origin,
                                         right.stride, pattern.width, pattern.height, spans);
            ++result.positions;
            if (plus_pending) {
                best_plus = sad;
                have_plus = true;
                plus_pending = false;
            }
            const bool better =
                !result.valid || sad < best ||
                (sad == best && std::abs(dy) == std::abs(result.dy) && d < result.disparity);
            if (better) {
                result.valid = true;
                result.disparity = d;
                result.dy = dy;
                best = sad;
                have_minus = have_previous;
                best_minus = previous;
                have_plus = false;
                plus_pending = true;
            }
            previous = sad;
            have_previous = true;
        }
    }
    if (!result.valid) return result;

    result.sad = best;
    int32_t offset_q8 = 0;
    if (params.subpixel && have_minus && have_plus) {
        if (params.fit == subpixel_fit::half_pel) {
            const uint8_t* at = left.row(pattern.y + result.dy) + pattern.x + result.disparity;
            const uint32_t doubled[5] = {
                2 * best_minus,
                half_pel_sad(at, left.stride, -1, pattern_origin, right.stride, pattern.width,
                             pattern.height, spans),
                2 * best,
                half_pel_sad(at, left.stride, +1, pattern_origin, right.stride, pattern.width,
                             pattern.height, spans),
                2 * best_plus};
            offset_q8 = subpixel_offset_half_pel_q8(doubled);
        } else {
            offset_q8 = params.fit == subpixel_fit::parabola
                            ? subpixel_offset_q8(best_minus, best, best_plus)
                            : subpixel_offset_equiangular_q8(best_minus, best, best_plus);
        }
    }
    result.disparity_q8 = result.disparity * 256 + offset_q8;
    return result;
}

}  // namespace

stereo_result stereo_match_sad(gray_cplane right, gray_cplane left, box pattern,
                               const stereo_params& params) {
    return match(right, left, pattern, nullptr, params);
}

// The columns [begin, end) of row y (absolute) whose pixel centres lie in
// the ellipse inscribed in `object`: (2x + 1 - cx)^2 h^2 + (2y + 1 - cy)^2 w^2
// <= w^2 h^2 with cx = 2 object.x + w, cy = 2 object.y + h (doubled units).
row_span ellipse_row(box object, int y) {
    const int64_t w = object.width, h = object.height;
    const int64_t dy = 2 * int64_t{y} + 1 - (2 * int64_t{object.y} + h);
    if (dy * dy > h * h) return {};
    const int64_t half = isqrt64((h * h - dy * dy) * w * w) / h;  // doubled units
    const int64_t cx = 2 * int64_t{object.x} + w;
    // 2x + 1 in [cx - half, cx + half]; cx - half >= 2 object.x >= 0.
    row_span span;
    span.begin = static_cast<int>((cx - half) / 2);  // ceil((cx - half - 1) / 2)
    span.end = static_cast<int>((cx + half - 1) / 2 + 1);
    if (span.end < span.begin) span.end = span.begin;
    return span;
}

stereo_result stereo_match_sad_masked(gray_cplane right, gray_cplane left, box pattern,
                                      const row_span* spans, const stereo_params& params) {
    return match(right, left, pattern, spans, params);
}

bool at_range_end(const stereo_result& match, box pattern, int min_disparity, int max_disparity,
                  int image_width) {
    const int upper = std::min(max_disparity, image_width - pattern.right());
    return match.valid && (match.disparity <= min_disparity || match.disparity >= upper);
}

}  // namespace dsp
