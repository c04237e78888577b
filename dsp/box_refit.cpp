#include "dsp/box_refit.h"

#include "dsp/int_bounds.h"
#include "dsp/key_frame.h"

namespace dsp {

span previous_axis(span before, span after, int size) {
    const bool same_start = before.start - after.start <= 1 && after.start - before.start <= 1;
    const bool same_end = before.end() - after.end() <= 1 && after.end() - before.end() <= 1;
    if (same_start != same_end)
        return same_end ? span{after.end() - size, size} : span{after.start, size};
    const int start = max_int(before.start, after.start);
    return span{start, max_int(0, min_int(before.end(), after.end()) - start)};
}

bool returned_axis(span earlier, span before, span after, span last, span* previous) {
    const int size = last.size, tolerance = max_int(2, size / 8);
    const bool shared =
        abs_int(before.start - after.start) <= 1 && abs_int(before.end() - after.end()) <= 1;
    const int motion = after.size - size;
    if (!shared || motion <= tolerance) return false;
    const bool at_start = abs_int(last.start - after.start) <= tolerance;
    const bool at_end = abs_int(last.end() - after.end()) <= tolerance;
    if (at_start == at_end) return false;
    const bool came = at_end ? earlier.end() <= after.end() - motion + tolerance
                             : earlier.start >= after.start + motion - tolerance;
    if (!came) return false;
    *previous = at_end ? span{after.end() - size, size} : span{after.start, size};
    return true;
}

span held_at_extent_end(span placed, span found, span both) {
    constexpr int most_past = 2, read_within = 2;
    if (found.size != placed.size) return placed;
    if (placed.end() - both.end() > most_past && abs_int(found.end() - both.end()) <= read_within)
        return span{both.end() - placed.size, placed.size};
    if (both.start - placed.start > most_past && abs_int(found.start - both.start) <= read_within)
        return span{both.start, placed.size};
    return placed;
}

span follow_axis(span previous, span both, span last, int size) {
    if (both.size < size)
        return span{max_int(min_int(last.start, both.start), both.end() - size), size};
    const int past_end = both.end() - previous.end();
    const int past_start = previous.start - both.start;
    const int motion = both.size - size;
    // Centres in Q1 as start + end (twice the centre, pixel edges).
    int centre2 = both.start + both.end();
    if (past_end > past_start) {
        centre2 += motion;  // moved towards the end: object(t) ends where both does
    } else if (past_start > past_end) {
        centre2 -= motion;
    }
    return span{(centre2 - size) >> 1, size};  // floor, also below 0
}

bool across_motion(int moved, int moved_other) {
    return moved_other >= key_frame::min_shift && 4 * moved <= moved_other;
}

bool is_part(span both, span last) {
    return 2 * both.size < last.size;
}

span part_axis(span both, span last) {
    const bool towards_end = both.start + both.end() > last.start + last.end();
    return towards_end ? span{both.end() - last.size, last.size} : span{both.start, last.size};
}

span keyed_axis(span both, int shift) {
    const int moved = shift < 0 ? -shift : shift;
    return span{shift > 0 ? both.start + shift : both.start, both.size - moved};
}

bool difference_shift(span both, span key, int* shift) {
    const int past_end = both.end() - key.end(), past_start = key.start - both.start;
    if (min_int(past_end, past_start) > 2) return false;  // past the box on both sides
    *shift = past_end > past_start ? past_end : past_start > past_end ? -past_start : 0;
    return true;
}

int key_reach(span both, span key) {
    return max_int(both.end() - key.end(), key.start - both.start);
}

bool holds_key_box(span both, span key) {
    return both.size + 2 >= key.size;
}

bool contradicted_shift(span both, span key, int most, int* shift) {
    int read = 0;
    if (!holds_key_box(both, key) || !difference_shift(both, key, &read)) return false;
    if (read > most || read < -most) return false;
    if (read - *shift <= key_frame::max_step && *shift - read <= key_frame::max_step) return false;
    *shift = read;
    return true;
}

bool first_extent_shift(span both, span first, int most, bool* usable, int* shift) {
    int read = 0;
    if (!*usable) return false;
    if (!difference_shift(both, first, &read) || read > most || read < -most) {
        *usable = false;
        return false;
    }
    *shift = read;
    return true;
}

int bounded_shift(span both, span key, int shift, bool* bounded) {
    const int limit = max_int(0, both.size - key.size) + 1;
    // A part of the outline bounds the shift but cannot stand for the object.
    *bounded = holds_key_box(both, key) && (shift > limit || shift < -limit);
    return max_int(-limit, min_int(limit, shift));
}

span outline_key_axis(span both, span key, int size, bool across, span first, int toward) {
    const int lo = min_int(both.start, key.start), hi = max_int(both.end(), key.end());
    if (across) {
        // Grown further at one end than at the other since the first reading.
        const int drift = (both.end() - first.end()) - (first.start - both.start);
        const int from = toward > 0 && drift > 0 ? min_int(lo + drift, hi - key.size) : lo;
        const int to = toward < 0 && drift < 0 ? max_int(hi + drift, lo + key.size) : hi;
        return span{from, min_int(to - from, key.size + key.size / 4 + 1)};
    }
    const int past_start = key.start - lo, past_end = hi - key.end();
    size = max_int(size, key.size + 2 * min_int(past_start, past_end));
    if (hi - lo <= size || past_start == past_end) return span{lo + (hi - lo - size) / 2, size};
    return past_end > past_start ? span{hi - size, size} : span{lo, size};
}

int step_size(int size, int target, int min_size, int max_size, int limit) {
    const int step = max_int(1, max_int(size, target) / 8);
    const int moved = max_int(size - step, min_int(size + step, target));
    return min_int(limit, max_int(min_size, min_int(max_size, moved)));
}

span pull_axis(span found, span last, span mask, int min_size, int max_size, int limit) {
    const int step = max_int(1, max_int(found.size, mask.size) / 8);
    const int new_size = step_size(found.size, mask.size, min_size, max_size, limit);
    // Centres in Q1 as 2 * start + size (twice the centre, plus one).
    const int offset2 = (2 * last.start + last.size) - (2 * mask.start + mask.size);
    const int shift2 = max_int(-2 * step, min_int(2 * step, offset2 / 2));
    const int centre2 = 2 * found.start + found.size - shift2;
    const int new_start = (centre2 - new_size) >> 1;  // floor, also below 0
    return span{max_int(0, min_int(limit - new_size, new_start)), new_size};
}

span hold_axis(span found, span mask, int size, int limit) {
    const int step = max_int(1, max_int(size, mask.size) / 8);
    const int centred = (2 * found.start + found.size - size) >> 1;  // floor, also below 0
    // The starts that leave least of the mask outside the box lie between
    // these two (all of it inside when it is the smaller); the nearest to the
    // centred start, within a step of it.
    const int lo = min_int(mask.start, mask.end() - size);
    const int hi = max_int(mask.start, mask.end() - size);
    int start = max_int(lo, min_int(hi, centred));
    start = max_int(centred - step, min_int(centred + step, start));
    return span{max_int(0, min_int(limit - size, start)), size};
}

}  // namespace dsp
