#include "dsp/size_at_depth.h"

#include "dsp/int_bounds.h"

namespace dsp {

namespace {

// size * num / den rounded to the nearest pixel, at least 1.
int scaled_size(int size, int64_t num, int64_t den) {
    const int64_t s = (2 * static_cast<int64_t>(size) * num + den) / (2 * den);
    return s < 1 ? 1 : static_cast<int>(s);
}

// A span of `size` about the centre (Q1) of [start, start + old_size).
int centred_start(int start, int old_size, int size) {
    const int centre2 = 2 * start + old_size;
    return (centre2 - size) >> 1;  // floor: a 1 px odd difference goes to the start
}

int64_t change_of(int64_t from_q8, int64_t to_q8) {
    return to_q8 > from_q8 ? to_q8 - from_q8 : from_q8 - to_q8;
}

// `outline` is the object that shrank by `shrank` px inside the key's box
// and stands at `at` if moved as read: it is that size (within 2 px or an
// eighth) and its centre at most half the shrink, + 1 px, from at's.
bool outlines_shrunk(span outline, span at, int shrank) {
    if (abs_int(outline.size - at.size) > max_int(2, at.size / 8)) return false;
    const int off2 = (2 * outline.start + outline.size) - (2 * at.start + at.size);
    return abs_int(off2) <= shrank + 2;
}

}  // namespace

box resized_about_centre(box b, int width, int height) {
    return box{centred_start(b.x, b.width, width), centred_start(b.y, b.height, height), width,
               height};
}

box at_disparity(box b, int64_t from_q8, int64_t to_q8) {
    if (from_q8 <= 0 || to_q8 <= 0 || 100 * change_of(from_q8, to_q8) < from_q8) return b;
    return resized_about_centre(b, scaled_size(b.width, to_q8, from_q8),
                                scaled_size(b.height, to_q8, from_q8));
}

void extents_at_depth(const span* extents, const int64_t* depth_q8, int count, int size,
                      int64_t now_q8, span* out) {
    for (int k = 0; k < count; ++k) {
        out[k] = extents[k];
        const int64_t then_q8 = depth_q8[k];
        if (now_q8 <= 0 || 100 * (then_q8 - now_q8) < now_q8) continue;  // not 1 % larger then
        // How much larger the object was then, rounded to the nearest pixel.
        const int64_t larger =
            (2 * static_cast<int64_t>(size) * (then_q8 - now_q8) + now_q8) / (2 * now_q8);
        const int narrowed = larger < out[k].size ? static_cast<int>(larger) : out[k].size - 1;
        out[k].start += narrowed / 2;
        out[k].size -= narrowed;
    }
}

span keyed_span_at_depth(span read, int shift, int key_size, int64_t key_q8, int64_t now_q8,
                         const span* outline) {
    if (key_q8 <= 0 || now_q8 <= 0 || 100 * change_of(key_q8, now_q8) < key_q8) return read;
    const int moved = abs_int(shift);
    const int now = scaled_size(key_size, now_q8, key_q8);
    if (2 * moved >= abs_int(now - key_size))  // an end each
        return shift > 0 ? span{read.end() - now, now} : span{read.start, now};
    // Both ends the object's now (it grew past the key's) or the key's (it
    // shrank inside it): the whole extent, or it at the depth now about its
    // centre moved by the displacement, or on the outline.
    const span both{read.start - (shift > 0 ? shift : 0), read.size + moved};
    if (now_q8 > key_q8) return both;
    const int size = scaled_size(both.size, now_q8, key_q8);
    const span moved_key{centred_start(both.start + shift, both.size, size), size};
    if (!outline || !outlines_shrunk(*outline, moved_key, key_size - now)) return moved_key;
    return span{centred_start(outline->start, outline->size, size), size};
}

bool disparity_jumped(int64_t from_q8, int64_t to_q8) {
    return from_q8 > 0 && to_q8 > 0 && 8 * change_of(from_q8, to_q8) > from_q8;
}

bool size_still_stands(box kept, box silhouette, int64_t sized_q8, int64_t now_q8) {
    return sized_q8 > 0 && now_q8 > 0 && now_q8 < sized_q8 && !disparity_jumped(sized_q8, now_q8) &&
           silhouette.width < kept.width && silhouette.height < kept.height;
}

}  // namespace dsp
