#include "dsp/stereo_reach.h"

#include <cstdint>
#include <cstdlib>

#include "dsp/int_bounds.h"

namespace dsp {

namespace {

uint32_t min_u32(uint32_t a, uint32_t b) {
    return a < b ? a : b;
}

// One side's band of lines (columns past a left or right side, rows past
// the top or bottom) in the image whose camera sees past that side (`ref`),
// matched in the other image at column x + sign * d, counted by distance
// from `start` outwards (`dir`).
struct side_probe {
    gray_cplane ref, other;
    int sign;   // +1: ref is the right image; -1: the left one
    int start;  // the first line read outwards (dir +1), or one past it (dir -1)
    int dir;
    int band_y, band_height;  // the band across the lines (its columns, reading rows)
    bool rows = false;        // reads rows (above or below the object), not columns

    int column(int distance) const { return dir < 0 ? start - 1 - distance : start + distance; }
    int lines() const { return rows ? ref.height : ref.width; }
    bool in_ref(int from, int to) const {
        const int a = column(from), b = column(to - 1);
        return min_int(a, b) >= 0 && max_int(a, b) < lines();
    }
    // Lines [from, to) by distance inside ref, and inside `other` at d.
    bool fits(int from, int to, int d) const {
        if (rows)
            return in_ref(from, to) && band_y + sign * d >= 0 &&
                   band_y + band_height + sign * d <= other.width;
        const int a = column(from), b = column(to - 1);
        const int lo = min_int(a, b), hi = max_int(a, b);
        return lo >= 0 && hi < ref.width && lo + sign * d >= 0 && hi + sign * d < other.width;
    }
    uint32_t sad(int distance, int d) const {
        const int line = column(distance);
        uint32_t sum = 0;
        for (int a = band_y; a < band_y + band_height; ++a) {
            const int x = rows ? a : line, y = rows ? line : a;
            sum += static_cast<uint32_t>(std::abs(ref.at(x, y) - other.at(x + sign * d, y)));
        }
        return sum;
    }
    uint32_t tile_sad(int from, int width, int d) const {
        uint32_t sum = 0;
        for (int j = from; j < from + width; ++j) sum += sad(j, d);
        return sum;
    }
};

struct tile_reading {
    bool object = false;
    bool background = false;  // clearly matched elsewhere than at the object's disparity
    int positions = 0;
    int d_in = -1;   // its best disparity within the object's span (-1: none searched)
    int d_out = -1;  // ... and elsewhere
};

// Whether the tile of columns [from, from + width) matches clearly at the
// object's disparity (see the header).
tile_reading read_tile(const side_probe& p, int from, const object_match& match, uint64_t gate,
                       const stereo_params& search, const stereo_reach_params& params) {
    tile_reading t;
    uint32_t best_in = UINT32_MAX, best_out = UINT32_MAX;
    for (int d = search.min_disparity; d <= search.max_disparity; ++d) {
        if (!p.fits(from, from + params.tile_width, d)) continue;
        const uint32_t s = p.tile_sad(from, params.tile_width, d);
        ++t.positions;
        const bool in = std::abs(d - match.disparity) <= match.spread;
        uint32_t& best = in ? best_in : best_out;
        if (s < best) {
            best = s;
            (in ? t.d_in : t.d_out) = d;
        }
    }
    t.object = best_in <= gate && best_out != UINT32_MAX &&
               static_cast<uint64_t>(best_in) * params.clear_den <
                   static_cast<uint64_t>(best_out) * params.clear_num;
    t.background = best_out <= gate && best_in != UINT32_MAX &&
                   static_cast<uint64_t>(best_out) * params.clear_den <
                       static_cast<uint64_t>(best_in) * params.clear_num;
    return t;
}

// Where the object ends between distances `from` and `to`: the split whose
// columns nearer the box match best at d_in and the others as background,
// a column of background costing its SAD at d_out, at most column_gate.
// Past an end a row is charged as the object's as clearly as a tile must
// be (clear_num / clear_den): a flat background matches about as well at
// d_in as at d_out, and with equal charges its noise carried the split
// up to a tile past the object (held-out round 22's 130 px throw over
// venus at pair 15: 5 rows, SAD 39-51 at d_in against 41-52 at d_out).
// Past a side the charges stay equal: weighed so, the split stopped short
// of the rim on many cases (docs/firmware.md).
int split_at(const side_probe& p, int from, int to, int d_in, int d_out, uint32_t column_gate,
             const stereo_reach_params& params) {
    // The cost of columns [from, at) read as the object's less as
    // background: each column read once at each disparity.
    const int64_t background_weight = p.rows ? params.clear_num : params.clear_den;
    int64_t gain = 0, best = 0;
    int at = from;
    for (int j = from; j < to; ++j) {
        gain += int64_t{p.sad(j, d_in)} * params.clear_den -
                int64_t{min_u32(p.sad(j, d_out), column_gate)} * background_weight;
        if (gain < best) {
            best = gain;
            at = j + 1;
        }
    }
    return at;
}

// The gate (Q8 a pixel) over a tile and over one line of a band.
struct probe_gates {
    uint64_t tile;
    uint32_t line;
};

probe_gates gates_of(uint32_t gate_q8, const stereo_reach_params& params) {
    return {(uint64_t{gate_q8} * params.tile_width * params.band_height) >> 8,
            static_cast<uint32_t>((uint64_t{gate_q8} * params.band_height) >> 8)};
}

// Read outwards (find_end): where the object ends, and the last object
// tile's best disparity (the rim's). Read inwards (find_start): where it
// starts, and the disparity its lines were split at. -1: no tile taken.
struct object_end {
    int distance = -1;  // from the probe's start
    int disparity = 0;
};

// Tiles outwards while they are the object's; the object's end is then
// split between the last of them and the first that is not. Where every
// tile to max_distance is the object's its end was not met: asked at a
// wrong disparity (the background's), the background's tiles match there,
// and the side would be moved out by its whole bound; it is not (-1). At
// the image's edge the object ends there.
// An end is taken only where the next tile is not the object's either
// (where there is a next one within the bound and the image): past an
// object's end the background goes on. One tile not the object's between
// two that are is a flat patch (of the object, or of a background within
// its disparity span, which the reach cannot tell from it: then it runs to
// the bound and moves nothing).
object_end find_end(const side_probe& p, const object_match& match, int max_distance,
                    uint32_t gate_q8, const stereo_params& search,
                    const stereo_reach_params& params, stereo_reach* r) {
    const int w = params.tile_width;
    const probe_gates gates = gates_of(gate_q8, params);
    object_end end;
    int first_not = -1, first_not_d_out = -1;  // the first tile after end not the object's
    for (int k = 0; k * params.step < max_distance; ++k) {
        const int from = k * params.step;
        if (!p.in_ref(from, from + w)) return end;
        const tile_reading t = read_tile(p, from, match, gates.tile, search, params);
        ++r->tiles;
        r->positions += t.positions;
        if (t.object) {
            end.distance = from + w;
            end.disparity = t.d_in;
            first_not = -1;
            continue;
        }
        if (end.distance < 0) return end;
        const int next = from + params.step;
        if (first_not < 0 && next < max_distance && p.in_ref(next, next + w)) {
            first_not = from;
            first_not_d_out = t.d_out;
            continue;
        }
        const int at = first_not >= 0 ? first_not : from;
        const int d_out = first_not >= 0 ? first_not_d_out : t.d_out;
        if (d_out < 0 || !p.fits(at - params.step, at + w, end.disparity)) return end;
        r->split_columns += params.step + w;
        end.distance =
            split_at(p, at - params.step, at + w, end.disparity, d_out, gates.line, params);
        return end;
    }
    return object_end{};
}

// Tiles inwards from the box's side while they are clearly background; the
// object then starts between the last of them and the first that is not,
// split as an end is with the roles turned (background first). Where every
// tile to max_distance is background the object was not met: asked at a
// wrong disparity, the object's own tiles match clearly elsewhere, and the
// side would be moved in by its whole bound; it is not moved (-1).
object_end find_start(const side_probe& p, const object_match& match, int max_distance,
                      uint32_t gate_q8, const stereo_params& search,
                      const stereo_reach_params& params, stereo_reach* r) {
    const int w = params.tile_width;
    const probe_gates gates = gates_of(gate_q8, params);
    object_end start;
    start.disparity = match.disparity;
    int background_disparity = 0;
    for (int k = 0; k * params.step < max_distance; ++k) {
        const int from = k * params.step;
        if (!p.in_ref(from, from + w)) break;
        const tile_reading t = read_tile(p, from, match, gates.tile, search, params);
        ++r->tiles;
        r->positions += t.positions;
        if (t.background) {
            start.distance = from + w;
            background_disparity = t.d_out;
            continue;
        }
        if (start.distance < 0) break;
        if (t.object) start.disparity = t.d_in;
        if (!p.fits(from - params.step, from + w, background_disparity) ||
            !p.fits(from - params.step, from + w, start.disparity))
            return start;  // met, but not to be split: at the last background tile
        r->split_columns += params.step + w;
        start.distance = split_at(p, from - params.step, from + w, background_disparity,
                                  start.disparity, gates.line, params);
        return start;
    }
    return object_end{};
}

// Whether the tile `distance` px out, past the object's bound, is the
// object's: the background beside it lies within its disparity span.
bool beside_at_object_depth(const side_probe& p, int distance, const object_match& match,
                            uint32_t gate_q8, const stereo_params& search,
                            const stereo_reach_params& params, stereo_reach* r) {
    if (!p.in_ref(distance, distance + params.tile_width)) return false;
    const tile_reading t =
        read_tile(p, distance, match, gates_of(gate_q8, params).tile, search, params);
    ++r->tiles;
    r->positions += t.positions;
    return t.object;
}

// A band of band_height px on a round object's centre rows (columns) lies
// within 1.4 px of its sides when the object is 3 bands across; on a
// smaller one its rows past the object are background at every side.
bool too_small_to_trim(box object, const stereo_reach_params& params) {
    const int smallest = 3 * params.band_height;
    return object.width < smallest || object.height < smallest;
}

uint32_t gate_of(const object_match& match, const stereo_reach_params& params) {
    return params.gate_factor * match.sad_per_pixel_q8 + params.gate_floor_per_pixel * 256u;
}

}  // namespace

stereo_reach reach_past_sides(gray_cplane right, gray_cplane left, box object,
                              const object_match& match, int max_reach, const stereo_params& search,
                              const stereo_reach_params& params) {
    stereo_reach r;
    const int band_y = object.y + (object.height - params.band_height) / 2;
    if (object.empty() || band_y < 0 || band_y + params.band_height > right.height ||
        right.height != left.height)
        return r;
    const uint32_t gate_q8 = gate_of(match, params);
    // Both probes start `inset` px inside the box, on the object where the
    // box is short of it.
    const int inset = match.spread;
    const int max_distance = inset + max_reach + match.spread + params.tile_width;
    // Left of the object: the right camera sees past it (x + d in the left).
    const side_probe left_side{right, left, +1, object.x + inset, -1, band_y, params.band_height};
    const object_end l = find_end(left_side, match, max_distance, gate_q8, search, params, &r);
    if (l.distance >= 0) r.left = max_int(0, min_int(max_reach, l.distance - inset));
    if (r.left > 0 &&
        beside_at_object_depth(left_side, max_distance, match, gate_q8, search, params, &r))
        r.left = 0;
    // Right of it: the left camera (x - d in the right); its end there,
    // less the rim's disparity, is the end in the right image.
    const int start = object.right() + match.disparity - inset;
    const side_probe right_side{left, right, -1, start, +1, band_y, params.band_height};
    const object_end e = find_end(right_side, match, max_distance, gate_q8, search, params, &r);
    if (e.distance >= 0)
        r.right = max_int(0, min_int(max_reach, start + e.distance - e.disparity - object.right()));
    if (r.right > 0 &&
        beside_at_object_depth(right_side, max_distance, match, gate_q8, search, params, &r))
        r.right = 0;
    return r;
}

stereo_reach reach_past_ends(gray_cplane right, gray_cplane left, box object,
                             const object_match& match, int max_reach, const stereo_params& search,
                             const stereo_reach_params& params) {
    stereo_reach r;
    const int band_x = object.x + (object.width - params.band_height) / 2;
    if (object.empty() || band_x < 0 || band_x + params.band_height > right.width ||
        right.height != left.height)
        return r;
    const uint32_t gate_q8 = gate_of(match, params);
    const int inset = match.spread;
    const int max_distance = inset + max_reach + match.spread + params.tile_width;
    // Both read in the right image: along a column neither camera sees
    // more of what is behind than the other.
    const side_probe top{right, left, +1, object.y + inset, -1, band_x, params.band_height, true};
    const object_end t = find_end(top, match, max_distance, gate_q8, search, params, &r);
    if (t.distance >= 0) r.up = max_int(0, min_int(max_reach, t.distance - inset));
    if (r.up > 0 && beside_at_object_depth(top, max_distance, match, gate_q8, search, params, &r))
        r.up = 0;
    const int start = object.bottom() - inset;
    const side_probe bottom{right, left, +1, start, +1, band_x, params.band_height, true};
    const object_end b = find_end(bottom, match, max_distance, gate_q8, search, params, &r);
    if (b.distance >= 0)
        r.down = max_int(0, min_int(max_reach, start + b.distance - object.bottom()));
    if (r.down > 0 &&
        beside_at_object_depth(bottom, max_distance, match, gate_q8, search, params, &r))
        r.down = 0;
    return r;
}

stereo_reach short_of_sides(gray_cplane right, gray_cplane left, box object,
                            const object_match& match, int max_trim, const stereo_params& search,
                            const stereo_reach_params& params) {
    stereo_reach r;
    const int band_y = object.y + (object.height - params.band_height) / 2;
    if (too_small_to_trim(object, params) || band_y < 0 ||
        band_y + params.band_height > right.height || right.height != left.height)
        return r;
    const uint32_t gate_q8 = gate_of(match, params);
    // Both probes start `outset` px outside the box: a tile from the side
    // in takes in the object where the box is less than a tile too large,
    // and is over the gate.
    const int outset = params.step;
    const int max_distance = outset + max_trim + params.tile_width;
    // Inside the left side, the right image (its background seen past the
    // object in the left one).
    const side_probe left_side{right, left, +1, object.x - outset, +1, band_y, params.band_height};
    const object_end l = find_start(left_side, match, max_distance, gate_q8, search, params, &r);
    if (l.distance >= 0) r.left = max_int(0, min_int(max_trim, l.distance - outset));
    // Inside the right side, the left image from the side's column there;
    // the object's start, less its rim's disparity, brought to the right.
    const int start = object.right() + match.disparity + outset;
    const side_probe right_side{left, right, -1, start, -1, band_y, params.band_height};
    object_end e = find_start(right_side, match, max_distance, gate_q8, search, params, &r);
    if (e.distance < 0) return r;
    // The rim's disparity, read on the tile just inside the object's start
    // (a round object's rim stands farther than its core: a 320 px ball's
    // 9 px less than the core's 80).
    if (!right_side.in_ref(e.distance, e.distance + params.tile_width)) return r;
    const tile_reading rim =
        read_tile(right_side, e.distance, match, gates_of(gate_q8, params).tile, search, params);
    ++r.tiles;
    r.positions += rim.positions;
    if (rim.d_in < 0 || rim.background) return r;
    r.right = max_int(0, min_int(max_trim, object.right() - (start - e.distance - rim.d_in)));
    return r;
}

stereo_reach short_of_ends(gray_cplane right, gray_cplane left, box object,
                           const object_match& match, int max_trim, const stereo_params& search,
                           const stereo_reach_params& params) {
    stereo_reach r;
    const int band_x = object.x + (object.width - params.band_height) / 2;
    if (too_small_to_trim(object, params) || band_x < 0 ||
        band_x + params.band_height > right.width || right.height != left.height)
        return r;
    const uint32_t gate_q8 = gate_of(match, params);
    const int outset = params.step;
    const int max_distance = outset + max_trim + params.tile_width;
    const side_probe top{right, left, +1, object.y - outset, +1, band_x, params.band_height, true};
    const object_end t = find_start(top, match, max_distance, gate_q8, search, params, &r);
    if (t.distance >= 0) r.up = max_int(0, min_int(max_trim, t.distance - outset));
    const int start = object.bottom() + outset;
    const side_probe bottom{right, left, +1, start, -1, band_x, params.band_height, true};
    const object_end b = find_start(bottom, match, max_distance, gate_q8, search, params, &r);
    if (b.distance >= 0) r.down = max_int(0, min_int(max_trim, b.distance - outset));
    return r;
}

}  // namespace dsp
