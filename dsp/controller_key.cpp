// A slow object's key frame in TRACK (dsp/key_frame.h): the box from the
// displacement since the key and from Dif(key, t).
#include "dsp/controller_impl.h"

namespace dsp {

using namespace controller_parts;

namespace {

// A displacement since the key that came back towards it by more than a
// slow object moves in a pair (max_step, + 1): the key's pattern matched
// elsewhere, not the object. A 73 px ball at 3 px a pair spinning 1 rev/s
// about y read 3, 6, 9 px, then 0 where its texture came round, and the box
// stayed there (12 px behind; co-simulated, 34 px as the ball went on).
bool falls_back(int last, int now) {
    const int back = key_frame::max_step + 1;
    return (last > 0 && now < last - back) || (last < 0 && now > last + back);
}

}  // namespace

// A slow object's box from the key (dsp/key_frame.h): while the key's
// pattern is found within max_step px of where it was last, the box is the
// key's moved by the displacement since; once that is min_shift px, its
// size and place are object(t)'s from Dif(key, t) (keyed_axis), when that
// extent is one the object's size and the displacement can explain. A new
// key is taken when there is none, the SAD moved at most max_step px and a
// silhouette confirms the box (a box left on the background by a fast
// object has a still pattern too, and its silhouette lies elsewhere), and
// after max_shift px. Once keyed, one pair's silhouette does not overrule
// the key: across a slow motion it is the measurement the key improves on
// (a 30 px ball's jumped 10 px in one pair). The key's pattern lost (a
// turning, spinning or faster object): the box of track_object stands, and
// where the silhouette still moved at most max_step px a key of the outline
// is taken (follow_outline_key).
// Runs after update_motion_mask: f(t-1)'s buffer is scratch by then.
// (take_key: the key at the tracker's box, its ring's and pattern's copy charged.)
void controller::impl::take_key(uint64_t* cycles, sdram_traffic* traffic, int grow) {
    key.take(history(0), tracker.position(), tracker.pattern_box(), grow);
    // The key's size stands for the depth the box's does (a size kept may
    // stand for an earlier pair's: size_still_stands).
    key_sized_q8 = sized_disparity_q8 > 0 ? sized_disparity_q8 : measured_disparity_q8;
    key_x = key_y = key_axis{};
    key_first_seen = false;
    const box r = key.region(), hole = key.hole(), kp = key.pattern();
    *cycles += cycles_of(cost::pattern_copy_profile(r.width, r.height - hole.height)) +
               cycles_of(cost::pattern_copy_profile(r.width - hole.width, hole.height)) +
               cycles_of(cost::pattern_copy_profile(kp.width, kp.height));
    traffic->bytes_written += key.stored_bytes();
}

// The key's pattern searched in f(t) (key_frame::displacement), charged:
// whether it was found within max_step px of its last place. Its copy
// borrows f(t-1)'s buffer, dead once Dif(t-1,t) is made.
bool controller::impl::search_key(uint64_t* cycles, sdram_traffic* traffic) {
    int positions = 0;
    const bool still = key.displacement(history(0), right_gray[1 - newest],
                                        config.track.lost_mean_sad, &positions);
    const box kp = key.pattern();
    *cycles += cycles_of(cost::pattern_copy_profile(kp.width, kp.height)) +
               cycles_of(cost::sad_search_profile(kp.width, kp.height, positions));
    traffic->bytes_read += static_cast<uint64_t>(kp.width) * kp.height;
    return still;
}

// Dif(key, t)'s extent (key_frame::moved_extent), charged.
block_group controller::impl::keyed_extent(uint64_t* cycles, sdram_traffic* traffic) {
    const block_group u =
        key.moved_extent(history(0), config.detect.threshold, later_blocks, refit_rows);
    const box r = key.region(), hole = key.hole();
    const c64x::kernel_profile difference =
        cost::key_difference_profile(r.width, r.height, hole.width, hole.height);
    *cycles += cycles_of(difference) + cycles_of(cost::motion_blocks_profile(r.width, r.height));
    *traffic += cost::sdram_traffic_of(difference);
    return u;
}

// object(t) from Dif(key, t)'s extent `u` and the displacement since the
// key (keyed_axis), when that extent is one the key's object can explain:
// within half and twice its size (else the difference held more than the
// object, another mover or a light change, or too little), or, for a key
// taken on a detection that may be a part of its object (`of_part`), any
// size inside the key's region.
bool controller::impl::keyed_object(const block_group& u, int dx, int dy, bool of_part,
                                    box* object) const {
    const box o = from_spans(keyed_axis(x_span(u.bbox), dx), keyed_axis(y_span(u.bbox), dy));
    const box k = key.object();
    if (!u.found || o.width < config.track.min_size || o.height < config.track.min_size)
        return false;
    if (!of_part && (2 * o.width < k.width || o.width > 2 * k.width || 2 * o.height < k.height ||
                     o.height > 2 * k.height))
        return false;
    *object = o;
    return true;
}

// The displacement since the key (dx, dy): the pattern's, or on each axis
// what Dif(key, t) reads instead (key_axis_shift). False when the pattern was
// lost and the difference does not read both axes (the key is of no more use).
bool controller::impl::key_displacement(const block_group& u, bool matched, key_reading* r) {
    const box k = key.object();
    r->dx = key.dx();
    r->dy = key.dy();
    if (!u.found) return matched;
    const bool first_pair = !key_first_seen;
    key_first_seen = true;
    const bool read_x =
        key_axis_shift(key_x, x_span(u.bbox), x_span(k), first_pair, &r->dx, &r->outline_x);
    const bool read_y =
        key_axis_shift(key_y, y_span(u.bbox), y_span(k), first_pair, &r->dy, &r->outline_y);
    return matched || (read_x && read_y);
}

// One axis, from Dif(key, t)'s extent `both`. Where it reached past the key's
// box further than a slow object could have moved by then (max_step px a
// pair, + 1), the key's box did not outline the object there (its texture's
// silhouette when taken): for the key's life the displacement is read
// against the extent's first reading while that reads one
// (first_extent_shift; once not, the first reading was a part and is
// dropped), that axis then outlined from Dif(key, t); without one it stays
// the pattern's (a ball moving 2 px a pair, its extent 1 px further by
// noise, was read as unfit at its fifth pair: a first reading replaced there
// lost the 10 px moved, and the box fell 6 px behind). Elsewhere
// a turned pattern's is the difference's (difference_shift), and a pattern
// the difference contradicts gives way to it (contradicted_shift). Either
// at most what Dif(key, t)'s size leaves for a motion (bounded_shift: where
// the pattern read more, the axis is outlined from Dif(key, t)). True when
// the difference read the displacement.
bool controller::impl::key_axis_shift(key_axis& axis, span both, span key_box, bool first_pair,
                                      int* shift, bool* outline) {
    const int reach = key_frame::max_step * key.pairs() + 1;
    axis.unfit = axis.unfit || key_reach(both, key_box) > reach;
    if (first_pair) {
        axis.has_first = holds_key_box(both, key_box);
        axis.first = both;
    }
    bool read = false;
    if (axis.unfit) {
        read = first_extent_shift(both, axis.first, reach, &axis.has_first, shift);
    } else if (key.turned()) {
        read = difference_shift(both, key_box, shift);
    } else {
        read = contradicted_shift(both, key_box, reach, shift);
    }
    bool bounded = false;
    *shift = bounded_shift(both, key_box, *shift, &bounded);
    *outline = (axis.unfit && read) || bounded;
    return read;
}

void controller::impl::follow_slow_object(track_motion seen, uint64_t* cycles,
                                          sdram_traffic* traffic) {
    // Not slow: the window reads a motion and the silhouette moved further
    // than a slow object does in this pair. A key kept then held its top
    // while a thrown ball fell from its apex (its box grew 127 -> 141 px in
    // four pairs, and the fast rule kept that size); one taken held a 100 px
    // ball moving 5 px a pair whose pattern matched where it had been.
    // Nor where the depth moved a side of the box by more than max_step px
    // since the last pair: a key holds its object's size where it was taken
    // (a key of the outline spans Dif(key, t)'s hull, the key's object at
    // its size), which an object going away or coming nearer outgrows. A
    // 227 px ball going away over teddy was held at 180 x 180 px for four
    // pairs while its image shrank by 4 px a pair, its box then 9-12 px too
    // large; a 174 px ball at 153 x 151 px when it was 106 px.
    if ((seen.window_moving && !seen.outline_slow) || seen.depth_resized) {
        key.drop();
        size_from_key = false;
        return;
    }
    if (key.valid() && key.outline_only()) {
        follow_outline_key(seen, cycles, traffic);
        return;
    }
    const bool matched = key.valid() && search_key(cycles, traffic);
    if (key.valid() && !matched && !key.turned()) key.drop();
    if (!key.valid()) {
        if (seen.sad_slow && seen.confirmed) {
            take_key(cycles, traffic);
        } else if (seen.outline_slow) {
            take_outline_key(cycles, traffic);
        }
        return;
    }
    const box k = key.object();
    const block_group u = keyed_extent(cycles, traffic);
    key_reading r;
    if (!key_displacement(u, matched, &r) || falls_back(key_x.last, r.dx) ||
        falls_back(key_y.last, r.dy)) {
        key.drop();
        return;
    }
    key_x.last = r.dx;
    key_y.last = r.dy;
    const int dx = r.dx, dy = r.dy;
    // The key's box moved as its pattern did, at the latest pair's depth.
    box b = at_disparity(shifted(k, dx, dy), key_sized_q8, measured_disparity_q8);
    const int moved = max_int(max_int(dx, -dx), max_int(dy, -dy));
    // Outlined once the object moved min_shift px; an axis key_axis_shift
    // says to at once (its extent, not the pattern, holds the object there);
    // an axis the key's box did not outline as soon as Dif(key, t) holds that
    // box (the whole outline).
    const bool shifted_enough = moved >= key_frame::min_shift;
    const bool outline_x =
        shifted_enough || r.outline_x || (key_x.unfit && covers(x_span(u.bbox), x_span(k)));
    const bool outline_y =
        shifted_enough || r.outline_y || (key_y.unfit && covers(y_span(u.bbox), y_span(k)));
    box outlined;
    if ((outline_x || outline_y) && keyed_object(u, dx, dy, false, &outlined)) {
        // Where it shrank inside the key's box, the silhouette places it.
        const box s = tracker.position();
        const span sx = x_span(s), sy = y_span(s);
        outlined =
            from_spans(keyed_span_at_depth(x_span(outlined), dx, k.width, key_sized_q8,
                                           measured_disparity_q8, seen.outlined ? &sx : nullptr),
                       keyed_span_at_depth(y_span(outlined), dy, k.height, key_sized_q8,
                                           measured_disparity_q8, seen.outlined ? &sy : nullptr));
        // At most two divides an axis (the key's size, and a shrunk extent's).
        *cycles += cycles_of(cost::size_at_depth_profile(4));
        if (outline_x) b = from_spans(x_span(outlined), y_span(b));
        if (outline_y) b = from_spans(x_span(b), y_span(outlined));
    }
    b.x = max_int(0, min_int(b.x, width - b.width));
    b.y = max_int(0, min_int(b.y, height - b.height));
    size_from_key = true;
    // The box placed from the key stands for the last pair's depth. Carried
    // at the key's depth where it kept the key's size, it cost a 93 px ball
    // going away its depth (0.56 -> 1.19 %) and gained no case
    // (docs/firmware.md, "A size's depth kept while the object goes away").
    if (key_sized_q8 > 0) sized_disparity_q8 = measured_disparity_q8;
    if (!same_box(b, tracker.position())) {
        tracker.start(history(0), b);
        *cycles += cycles_of(
            cost::pattern_copy_profile(tracker.pattern_box().width, tracker.pattern_box().height));
    }
    if (moved >= key_frame::max_shift) take_key(cycles, traffic);
}

// A slow object whose texture outruns it (a ball spinning 1 rev/s or more:
// its silhouette moved at most max_step px, its SAD pattern further): the
// key's pattern would be lost at once, Dif(key, t) still holds the outline.
// The box from it per axis (outline_key_axis): along the motion the
// silhouette's size (its crescents outline it), more where the hull says the
// key's box was short, at the hull's leading end;
// across it the hull (the silhouette misses a slow ball's poles). Re-taken
// once Dif(key, t) reaches max_shift px past the key's box; dropped when it
// reaches the key region's edge (no longer slow).
void controller::impl::follow_outline_key(track_motion seen, uint64_t* cycles,
                                          sdram_traffic* traffic) {
    const box s = tracker.position();  // track_object's: the silhouette's, else the SAD's
    const box k = key.object();
    // The key's object holds its size where it was taken, which an object
    // going away or coming nearer leaves a side at a time: a 59 px ball
    // going away at 2 % a pair was held at 58 px, each pair's change of
    // depth under max_step, while it shrank to 34 px. Dropped once the depth
    // since the key moves a side by more than max_step.
    const box at_depth = at_disparity(k, key_sized_q8, measured_disparity_q8);
    if (key_sized_q8 > 0 && measured_disparity_q8 > 0)  // its two sizes, a divide each
        *cycles += cycles_of(cost::size_at_depth_profile(2));
    if (abs_int(at_depth.width - k.width) > key_frame::max_step ||
        abs_int(at_depth.height - k.height) > key_frame::max_step) {
        key.drop();
        return;
    }
    const block_group u = keyed_extent(cycles, traffic);
    if (!u.found) {
        key.drop();
        return;
    }
    judge_across(seen, s);
    // Under half the key's box: a part of the object changed, not its outline.
    if (2 * u.bbox.width < k.width || 2 * u.bbox.height < k.height) return;
    const int size_x = max_int(s.width, k.width), size_y = max_int(s.height, k.height);
    const span first_x = first_outline(key_x, x_span(u.bbox), x_span(k));
    const span first_y = first_outline(key_y, y_span(u.bbox), y_span(k));
    box b = from_spans(outline_key_axis(x_span(u.bbox), x_span(k), size_x,
                                        outline_key_across == 'x', first_x, outline_key_drift),
                       outline_key_axis(y_span(u.bbox), y_span(k), size_y,
                                        outline_key_across == 'y', first_y, outline_key_drift));
    b.x = max_int(0, min_int(b.x, width - b.width));
    b.y = max_int(0, min_int(b.y, height - b.height));
    // At least the key's size: of an object going away, the box stands for
    // the key's depth, and so does a key re-taken at it, until the depth's
    // change since moves a side by more than max_step (the drop above).
    // Re-taken at each pair's depth instead, a 34 px ball thrown at the wall
    // was held at 34 x 35 px while it shrank to 28 px.
    if (key_sized_q8 > 0)
        sized_disparity_q8 =
            measured_disparity_q8 < key_sized_q8 ? key_sized_q8 : measured_disparity_q8;
    if (!same_box(b, s)) {
        tracker.start(history(0), b);
        *cycles += cycles_of(
            cost::pattern_copy_profile(tracker.pattern_box().width, tracker.pattern_box().height));
    }
    if (max_int(key_reach(x_span(u.bbox), x_span(k)), key_reach(y_span(u.bbox), y_span(k))) >=
        key_frame::max_shift)
        take_outline_key(cycles, traffic);
}

// Dif(key, t)'s first extent on an axis that held the key's box there: a
// partial one is the turning texture filling in, no place to drift from
// (until then the extent itself: no drift read).
span controller::impl::first_outline(key_axis& axis, span both, span key_box) {
    if (!axis.has_first && holds_key_box(both, key_box)) {
        axis.has_first = true;
        axis.first = both;
    }
    return axis.has_first ? axis.first : both;
}

// The axis across the motion for a key of the outline: the one along which
// the silhouette's centre moved at most half as far since the key as along
// the other, that one at least min_shift px; none before (both axes then
// take the object's size at the hull's leading end, or centred). With it,
// which way the silhouette's centre moved across since the key, once
// min_shift px (outline_key_axis); both kept on a pair without a silhouette.
void controller::impl::judge_across(track_motion seen, box silhouette) {
    if (!seen.outlined) return;
    const box k = key.object();
    const int x2 = silhouette.center_x2() - k.center_x2();  // half pixels
    const int y2 = silhouette.center_y2() - k.center_y2();
    const int move_x = abs_int(x2) / 2, move_y = abs_int(y2) / 2;
    if (2 * move_y <= move_x && move_x >= key_frame::min_shift) outline_key_across = 'y';
    if (2 * move_x <= move_y && move_y >= key_frame::min_shift) outline_key_across = 'x';
    const int across2 = outline_key_across == 'x' ? x2 : outline_key_across == 'y' ? y2 : 0;
    outline_key_drift = across2 >= 2 * key_frame::min_shift    ? 1
                        : across2 <= -2 * key_frame::min_shift ? -1
                                                               : 0;
}

void controller::impl::take_outline_key(uint64_t* cycles, sdram_traffic* traffic) {
    take_key(cycles, traffic);
    key.set_outline_only();
    outline_key_across = 0;  // its drift is read again with it (judge_across)
}

}  // namespace dsp
