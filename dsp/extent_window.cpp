#include "dsp/extent_window.h"

#include "dsp/int_bounds.h"
#include "dsp/key_frame.h"

namespace dsp {
namespace {

int distance(int a, int b) {
    return a > b ? a - b : b - a;
}

// The median of `n` values, sorted in place (an insertion sort of at most 6).
int median_of(int* values, int n) {
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && values[j - 1] > values[j]; --j) {
            const int value = values[j];
            values[j] = values[j - 1];
            values[j - 1] = value;
        }
    return (values[(n - 1) / 2] + values[n / 2]) / 2;
}

// The median of the steps of both edges between consecutive extents, in
// half pixels (2 (n - 1) steps).
int median_step2(const span* extents, int count) {
    if (count < 2) return 0;
    int steps[2 * (extent_window::capacity - 1)];
    int n = 0;
    for (int k = 0; k + 1 < count; ++k) {
        steps[n++] = 2 * (extents[k].start - extents[k + 1].start);
        steps[n++] = 2 * (extents[k].end() - extents[k + 1].end());
    }
    return median_of(steps, n);
}

// The bounds on object(t)'s start (in half pixels) at velocity v2.
struct start_bounds {
    int low = 0, high = 0;
};

// The change of the object's velocity from pair to pair on one axis (newer
// minus older, half pixels), read over a full window: the median of both
// edges' second differences where every one of them changes the same way
// by 1 px or more and their median by more than 1 px, else 0. One edge's
// second difference holds the rounding of three extents, up to 2 px: a
// change of 1 px every pair is within it (a 21 px ball on a circle read
// 1-2 px, and placed so its box stood 2.5 px past the ball).
int acceleration2(const span* extents, int count) {
    constexpr int min_change2 = 2, min_median2 = 3;
    if (count < extent_window::capacity) return 0;
    int changes[2 * (extent_window::capacity - 2)];
    int n = 0;
    for (int k = 0; k + 2 < count; ++k) {
        const span a = extents[k], b = extents[k + 1], c = extents[k + 2];
        changes[n++] = 2 * (a.start - 2 * b.start + c.start);
        changes[n++] = 2 * (a.end() - 2 * b.end() + c.end());
    }
    bool faster = true, slower = true;
    for (int i = 0; i < n; ++i) {
        faster = faster && changes[i] >= min_change2;
        slower = slower && changes[i] <= -min_change2;
    }
    if (!faster && !slower) return 0;
    const int a2 = median_of(changes, n);
    return abs_int(a2) >= min_median2 ? a2 : 0;
}

// Extent k's own bounds on object(t)'s start at velocity v2 in the last
// pair, changing by a2 a pair (half pixels): object(t-k) stood
// k v - a k (k - 1) / 2 behind object(t), and moved v - k a in pair t-k.
start_bounds extent_bounds(span extent, int k, int size, int v2, int a2) {
    const int behind = k * v2 - a2 * k * (k - 1) / 2, vk = v2 - k * a2;
    return start_bounds{2 * (extent.end() - size) + behind + min_int(vk, 0),
                        2 * extent.start + behind + max_int(vk, 0)};
}

start_bounds bounds_at(const span* extents, int count, int size, int v2, int a2) {
    start_bounds b{-(1 << 30), 1 << 30};
    for (int k = 0; k < count; ++k) {
        const start_bounds e = extent_bounds(extents[k], k, size, v2, a2);
        b.low = max_int(b.low, e.low);
        b.high = min_int(b.high, e.high);
    }
    return b;
}

// Where every extent's bound on one side agrees within `tight` half pixels at
// velocity v2 while the other side's spread is over twice that, that side
// read object(t)'s rim in every pair and the other missed it in some: object(t)
// is placed on the agreeing side's bound. False where neither does (both
// agree, or both spread).
bool steady_side(const span* extents, int count, int size, int v2, int a2, start_bounds b,
                 int* start2) {
    constexpr int tight = 2;  // 1 px: the rounding of one rim read twice
    int high_min = 1 << 30, high_max = -(1 << 30), low_min = 1 << 30, low_max = -(1 << 30);
    for (int k = 0; k < count; ++k) {
        const start_bounds e = extent_bounds(extents[k], k, size, v2, a2);
        high_min = min_int(high_min, e.high);
        high_max = max_int(high_max, e.high);
        low_min = min_int(low_min, e.low);
        low_max = max_int(low_max, e.low);
    }
    const int high_spread = high_max - high_min, low_spread = low_max - low_min;
    if (high_spread <= tight && low_spread > 2 * tight) {
        *start2 = b.high;
        return true;
    }
    if (low_spread <= tight && high_spread > 2 * tight) {
        *start2 = b.low;
        return true;
    }
    return false;
}

}  // namespace

int window_step2(const span* extents, int count, int size) {
    if (count < 3) return 0;
    for (int k = 0; k < count; ++k)
        if (2 * extents[k].size < size) return 0;
    return median_step2(extents, count);
}

void extent_window::push(span new_x, span new_y, int64_t disparity_q8) {
    for (int k = capacity - 1; k > 0; --k) {
        x[k] = x[k - 1];
        y[k] = y[k - 1];
        depth_q8[k] = depth_q8[k - 1];
    }
    x[0] = new_x;
    y[0] = new_y;
    depth_q8[0] = disparity_q8;
    if (count < capacity) ++count;
}

void extent_window::give_depth(int64_t disparity_q8) {
    for (int k = 0; k < count; ++k)
        if (depth_q8[k] <= 0) depth_q8[k] = disparity_q8;
}

bool window_axis(const span* extents, int count, int size, span last, span* object) {
    if (count < 3) return false;
    const int a2 = acceleration2(extents, count);
    // The steps' median is the velocity a pair before the last (the middle
    // of a full window's three steps, the only window a2 is read over).
    const int median2 = median_step2(extents, count) + a2;
    constexpr int search2 = 16;  // +-8 px around the median
    int best_v2 = median2, best_crossing = 1 << 30;
    start_bounds best;
    for (int v2 = median2 - search2; v2 <= median2 + search2; ++v2) {
        const start_bounds b = bounds_at(extents, count, size, v2, a2);
        const int crossing = max_int(0, b.low - b.high);
        if (crossing < best_crossing ||
            (crossing == best_crossing && distance(v2, median2) < distance(best_v2, median2))) {
            best_v2 = v2;
            best_crossing = crossing;
            best = b;
        }
    }
    int start2 = 2 * last.start + best_v2;
    if (best.low > best.high) {
        start2 = (best.low + best.high) / 2;
    } else if (!steady_side(extents, count, size, best_v2, a2, best, &start2)) {
        start2 = max_int(best.low, min_int(best.high, start2));
    }
    *object = span{(start2 + 1) >> 1, size};  // half pixels rounded, also below 0
    return true;
}

int fading_rim_step2(const span* extents, const int64_t* depth_q8, int count, span last) {
    constexpr int min_step = key_frame::max_step + 1;  // more than a slow object, every pair
    constexpr int near = key_frame::min_shift;         // the last box a step off object(t-1)
    if (count < 3) return 0;
    bool towards_end = true, towards_start = true;
    for (int k = 0; k + 1 < count; ++k) {
        towards_end = towards_end && extents[k].start - extents[k + 1].start >= min_step;
        towards_start = towards_start && extents[k].end() - extents[k + 1].end() <= -min_step;
    }
    if (towards_end == towards_start) return 0;
    const int sign = towards_end ? 1 : -1;
    auto trailing = [&](int k) { return towards_end ? extents[k].start : extents[k].end(); };
    auto leading = [&](int k) { return towards_end ? extents[k].end() : extents[k].start; };
    if (distance(trailing(0), towards_end ? last.start : last.end()) > near) return 0;
    // Extent k spans object(t-1-k) and object(t-k): its leading edge's step
    // from extent k+1 is the object's motion in pair t-k, which the trailing
    // edge repeats a pair later (from extent k to k-1), plus the object's
    // growth in that pair. The lag of the leading edge behind it is the rim
    // missed more; a speed that changes (a throw near its apex) moves both.
    int lag = 0;
    for (int k = 1; k + 1 < count; ++k)
        lag += sign * (trailing(k - 1) - trailing(k)) - sign * (leading(k) - leading(k + 1));
    const int pairs = count - 2;
    int64_t growth = 0;  // px over those pairs, from the disparities
    if (depth_q8[0] > 0 && depth_q8[pairs] > 0)
        growth = last.size * (depth_q8[0] - depth_q8[pairs]) / depth_q8[pairs];
    if (lag + growth < pairs) return 0;  // under 1 px a pair
    return 2 * (trailing(0) - trailing(count - 1)) / (count - 1);
}

span from_trailing_edge(span now, int step2, int size) {
    return step2 > 0 ? span{(2 * now.start + step2 + 1) >> 1, size}
                     : span{(2 * (now.end() - size) + step2 + 1) >> 1, size};
}

}  // namespace dsp
