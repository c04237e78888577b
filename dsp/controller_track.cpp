// TRACK: the SAD box (paper eq. 5) and its refit from the two frame
// differences around it (dsp/box_refit.h).
#include "dsp/controller_impl.h"
#include "dsp/round_box.h"

namespace dsp {

using namespace controller_parts;

namespace {

// Where the differences are read when the object's box at t-1 was `last`
// (a box that may be a part of its object reads the whole frame instead,
// measure_motion):
// the box grown by its own size and by `reach` (how far the object may have
// moved since) each side, clipped to the frame. A box much smaller than the
// object (an 8-21 px box started on an 80 px ball) sees its object's extent
// only in a region this wide; grown by a quarter of its size, the box shrank
// on such a ball instead of growing.
box size_rule_region(box last, int reach, int width, int height) {
    const int grow_x = max_int(2, last.width) + reach, grow_y = max_int(2, last.height) + reach;
    const int x0 = max_int(0, last.x - grow_x), y0 = max_int(0, last.y - grow_y);
    const int x1 = min_int(width, last.right() + grow_x);
    const int y1 = min_int(height, last.bottom() + grow_y);
    return box{x0, y0, max_int(0, x1 - x0), max_int(0, y1 - y0)};
}

// An axis moves fast where Dif(t-1,t) reaches 2 min_shift px or more past
// object(t-1) (`moved`), or where the window's median step is min_shift px
// a pair or more (a rim missed in this pair shortens the reach, not the
// window's steps: dsp/extent_window.h). The window's step makes an axis
// fast only for an object two motion blocks across or more: on 10 and 20
// px balls thrown it made the fit place boxes whose depth erred by 1.49
// and 1.34 % (0.37 and 0.38 % without it). window_moving: the window reads
// such a step on an axis, at any size (for the key).
struct axis_speed {
    bool fast_x = false, fast_y = false, window_moving = false;
};

axis_speed read_speed(int moved_x, int moved_y, const extent_window& window, box last) {
    const int slow = key_frame::min_shift;
    const int step_x = abs_int(window_step2(window.x, window.count, last.width));
    const int step_y = abs_int(window_step2(window.y, window.count, last.height));
    const bool large = min_int(last.width, last.height) >= 2 * motion_blocks::block_side;
    axis_speed s;
    s.window_moving = max_int(step_x, step_y) >= 2 * slow;  // half pixels
    s.fast_x = moved_x >= 2 * slow || (large && step_x >= 2 * slow);
    s.fast_y = moved_y >= 2 * slow || (large && step_y >= 2 * slow);
    return s;
}

// object(t) placed from Dif(t-1,t)'s (`both`) trailing edge on each axis
// whose leading rim fades and where `both` is narrower than the object.
bool on_trailing_edges(box both, int step_x2, int step_y2, int size_x, int size_y, span* object_x,
                       span* object_y) {
    const bool edge_x = step_x2 != 0 && both.width < size_x;
    const bool edge_y = step_y2 != 0 && both.height < size_y;
    if (edge_x) *object_x = from_trailing_edge(x_span(both), step_x2, size_x);
    if (edge_y) *object_y = from_trailing_edge(y_span(both), step_y2, size_y);
    return edge_x || edge_y;
}

// object(t-1) on one axis: where the motion came back onto object(t-2),
// the last box's end (returned_axis, with the window's extent of the pair
// before, `window[2]`: `window[0]` is `after`'s); else previous_axis.
span previous_of(const span* window, int count, span before, span after, span last) {
    span returned;
    if (count >= 3 && returned_axis(window[2], before, after, last, &returned)) return returned;
    return previous_axis(before, after, last.size);
}

}  // namespace

// Stage track: SAD search around the last position (the tracker keeps the
// size), then the size rule of dsp/tracker.h, applied here with a correctly
// aligned mask: the three-frame mask is object(t-1), the object where it was
// at t-1, i.e. around the LAST box, while sad_tracker's own rule looks for it
// around the NEW box, one frame of motion away (at 15 px per frame that
// shrank the box to a third of the ball). The resized box is handed back to
// the tracker with start(), which re-takes the pattern there.
bool controller::impl::track(frame_output& out) {
    stage_scope scope(*hardware, stage::track, out);
    uint64_t cycles = 0;
    sdram_traffic traffic;
    track_motion seen;
    bool tracking = track_object(&cycles, &traffic, &seen);
    // The refit has used Dif(t-2,t-1); now Dif(t-1,t) for the next pair.
    update_motion_mask(&cycles, &traffic);
    if (tracking && yields_to_mover(seen.no_difference, &cycles)) tracking = false;
    if (tracking) {
        follow_slow_object(seen, &cycles, &traffic);
    } else {
        key.drop();
    }
    scope.charge(cycles, traffic);
    return tracking;
}

// The box follows the object's silhouette where the differences give it
// (follow_object), the SAD search then centred there: the pattern of paper
// eq. 5 follows the object's texture, which a spinning ball moves against
// its outline, and a search around the last position misses an object that
// moved further than the search radius. Where they do not (the object
// stopped, or an extent its size cannot explain), the SAD box is kept,
// refitted towards object(t-1) (pull_box). A silhouette that moved as the
// object does keeps the track when the pattern no longer matches (a texture
// that turned); SAD's own lost rule decides only without one.
bool controller::impl::track_object(uint64_t* cycles, sdram_traffic* traffic, track_motion* seen) {
    const box tracked = tracker.position();
    // The last box at the depth the last pair measured (dsp/size_at_depth.h);
    // from here it stands for that depth.
    const box last = disparity_jumped(sized_disparity_q8, measured_disparity_q8)
                         ? tracked
                         : at_disparity(tracked, sized_disparity_q8, measured_disparity_q8);
    seen->depth_resized = abs_int(last.width - tracked.width) > key_frame::max_step ||
                          abs_int(last.height - tracked.height) > key_frame::max_step;
    const int64_t sized_before = sized_disparity_q8;
    sized_disparity_q8 = measured_disparity_q8;
    const box pattern = tracker.pattern_box();
    const motion_extents motion = measure_motion(last, nullptr, cycles, traffic);
    // No difference to size it and a change of depth that moved no side
    // (at_disparity rounds each to the pixel): the box still stands for the
    // depth it was sized at, and the change adds up until it moves a side.
    // Re-sized each pair, a 19 px ball coming nearer at 2 % a pair (0.4 px)
    // kept its size for five pairs while its disparity grew 8 %.
    if (!motion.found && sized_before > 0 && same_size(last, tracked) &&
        !disparity_jumped(sized_before, measured_disparity_q8))
        sized_disparity_q8 = sized_before;
    if (motion.found) {
        recent_extents.push(x_span(motion.after), y_span(motion.after), measured_disparity_q8);
    } else {
        recent_extents.clear();  // the differences' chain broke
    }
    box followed;
    const bool keyed = key.valid() && !key.outline_only();
    follow_reading reading;
    const bool follows =
        motion.found && follow_object(motion, last, box_may_be_part, keyed, &followed, &reading);
    if (motion.found)  // the window's step on both axes
        *cycles += 2 * cycles_of(cost::window_step_profile(recent_extents.count));
    if (measured_disparity_q8 > 0)  // sizes at the depth, at most: the last box's and a key's
        *cycles += cycles_of(cost::size_at_depth_profile(4 + 2 * recent_extents.count));
    *cycles += reading.fitted_axes * cycles_of(cost::window_fit_profile(recent_extents.count));
    if (reading.round_read) *cycles += cycles_of(cost::round_box_profile());  // is_round
    // A fading rim is read as the window's step is, over the same extents.
    *cycles += reading.edge_axes * cycles_of(cost::window_step_profile(recent_extents.count));
    const track_status status =
        follows ? tracker.update_near(history(0), followed) : tracker.update(history(0));
    *cycles += cycles_of(
        cost::sad_search_profile(pattern.width, pattern.height, tracker.last_match().positions));
    if (status != track_status::tracking && !follows) return false;
    if (status == track_status::tracking)
        *cycles += cycles_of(
            cost::pattern_copy_profile(tracker.pattern_box().width, tracker.pattern_box().height));

    const box found = tracker.position();
    if (follows) {  // the silhouette's box held where the SAD box read its extent's end
        followed =
            from_spans(held_at_extent_end(x_span(followed), x_span(found), x_span(motion.both)),
                       held_at_extent_end(y_span(followed), y_span(found), y_span(motion.both)));
        *cycles += cycles_of(cost::extent_end_profile());
    }
    seen->no_difference = !motion.found;
    const int step = key_frame::max_step;
    seen->sad_slow = status == track_status::tracking && moved_at_most(last, found, step);
    if (follows) {
        const centre_gap off = centre_offset2(followed, found);
        seen->confirmed = 2 * max_int(step, found.width / 8) >= off.x2 &&
                          2 * max_int(step, found.height / 8) >= off.y2;
        const centre_gap moved = centre_offset2(followed, last);
        seen->outlined = true;
        seen->window_moving = reading.window_moving;
        seen->outline_slow = 2 * step >= moved.x2 && 2 * step >= moved.y2;
    }
    if (follows && near_size(followed.width, last.width, max_int(2, last.width / 8)) &&
        near_size(followed.height, last.height, max_int(2, last.height / 8)))
        box_may_be_part = false;  // a silhouette of the box's size
    box resized = found;
    if (follows) {
        resized = followed;
    } else if (motion.found) {
        resized = pull_box(motion, last, found, size_from_key);
    } else if (last.width != tracked.width || last.height != tracked.height) {
        resized = resized_about_centre(found, last.width, last.height);
    }
    resized = rounded_box(resized, width, height, config.rig);
    *cycles += cycles_of(cost::round_box_profile());
    if (motion.found) {  // a size kept, of an object going away: its depth kept with it
        if (same_size(last, tracked) && same_size(resized, tracked) &&
            size_still_stands(resized, motion.previous, sized_before, measured_disparity_q8))
            sized_disparity_q8 = sized_before;
        *cycles += cycles_of(cost::size_depth_profile());
    }
    if (status != track_status::tracking || !same_box(resized, found)) {
        tracker.start(history(0), resized);
        *cycles += cycles_of(
            cost::pattern_copy_profile(tracker.pattern_box().width, tracker.pattern_box().height));
    }
    return true;
}

// A still track gives way to a moving object elsewhere. Still: no
// difference around the box, which moved under key_frame::min_shift px,
// for still_track_pairs pairs. Then on each pair Dif(t-1,t) (the
// packed mask, just made) is read away from the box, outside the region
// its own differences are read in (size_rule_region): a block group of at
// least min_area set pixels there ends the track, and DETECT takes that
// object. An object that vanished away from every border (behind the
// background) leaves its box on a still patch of background, which the SAD
// pattern, re-taken each pair, matches in place for ever, as it does a
// ball that stopped; DETECT then never saw a second object (0 of 30 pairs).
// A stopped object with nothing else moving keeps its track. The mask is
// in L2; its unpacking is charged as a packed difference there (the same
// loads and bit operations per 8 pixels).
bool controller::impl::yields_to_mover(bool no_difference, uint64_t* cycles) {
    const box now = tracker.position();
    if (!no_difference) {
        still_pairs = 0;
        return false;
    }
    if (still_pairs == 0 || !moved_at_most(still_anchor, now, key_frame::min_shift - 1)) {
        still_anchor = now;  // a still run starts here
        still_pairs = 0;
    }
    if (++still_pairs < still_track_pairs) return false;
    const box own = size_rule_region(now, config.track.search_radius, width, height);
    later_blocks.begin(width, height);
    uint8_t* row = refit_rows;
    for (int y = 0; y < height; ++y) {
        const bool beside = y >= own.y && y < own.bottom();
        for (int x = 0; x < width; ++x)
            row[x] =
                !(beside && x >= own.x && x < own.right()) && packed_bit(motion_mask, width, x, y);
        later_blocks.add_row(row, y);
    }
    *cycles += cycles_of(cost::difference_packed_profile(width, height, cost::memory::l2)) +
               cycles_of(cost::motion_blocks_profile(width, height));
    return later_blocks.extent(box{}, config.detect.min_area).found;
}

// object(t-1)'s box is the box where both differences around it agree:
// Dif(t-2,t-1) spans object(t-2) and object(t-1), Dif(t-1,t) spans
// object(t-1) and object(t), so for a motion that does not reverse within
// the three frames the intersection of their extents is object(t-1)'s (the
// three-frame rule of eq. 4 applied to boxes). Each extent is the block group
// of that difference that is one object with the last box
// (dsp/motion_blocks.h: a large object's two crescents and its texture
// joined). The pixel AND of eq. 4 does not do here: on a mainly horizontal
// motion it holds almost nothing at the object's top and bottom (the lens
// there is v^2 / 2R high, 0.08 px for a 320 px ball at 5 px per frame), and
// measured the box's height jumped by up to 53 px from pair to pair.
// Both need enough set pixels: at least min_area, or an eighth of the last
// box's area if that is less (fewer: the object stopped).
// In DETECT object(t-1) is the detection's (`detected`) and the packed mask
// already holds Dif(t-1,t): only that difference is read.
// While the box may be a part of its object (box_may_be_part), the
// differences are read over the whole frame: the object may reach a ball's
// width past a part, and a region grown by the part's own size cut both
// differences short (around a 35 x 11 px part of a 160 px ball thrown up;
// the SAD's pull then grew its box by about 20 px a pair, four pairs to the
// ball's size).
controller::impl::motion_extents controller::impl::measure_motion(box last, const box* detected,
                                                                  uint64_t* cycles,
                                                                  sdram_traffic* traffic) {
    const box region = box_may_be_part && !detected
                           ? box{0, 0, width, height}
                           : size_rule_region(last, config.track.search_radius, width, height);
    const uint8_t threshold = config.detect.threshold;
    motion_blocks& earlier = detector.blocks();
    if (!detected) earlier.begin(region.width, region.height);
    later_blocks.begin(region.width, region.height);
    uint8_t* earlier_row = refit_rows;
    uint8_t* later_row = refit_rows + region.width;
    for (int y = 0; y < region.height; ++y) {
        const int frame_y = region.y + y;
        if (detected) {
            for (int x = 0; x < region.width; ++x)
                later_row[x] = packed_bit(motion_mask, width, region.x + x, frame_y) ? 1 : 0;
            later_blocks.add_row(later_row, y);
            continue;
        }
        const uint8_t* f_tm1 = history(1).row(frame_y) + region.x;
        const uint8_t* f_t = history(0).row(frame_y) + region.x;
        for (int x = 0; x < region.width; ++x) {
            const int diff = f_tm1[x] > f_t[x] ? f_tm1[x] - f_t[x] : f_t[x] - f_tm1[x];
            earlier_row[x] = packed_bit(motion_mask, width, region.x + x, frame_y) ? 1 : 0;
            later_row[x] = diff > threshold ? 1 : 0;
        }
        earlier.add_row(earlier_row, y);
        later_blocks.add_row(later_row, y);
    }
    const box seed = shifted(last, -region.x, -region.y);
    const int labellings = detected ? 1 : 2;  // the extents below
    *cycles += cycles_of(cost::three_frame_difference_packed_profile(region.width, region.height,
                                                                     config.frame_memory)) +
               labellings * cycles_of(cost::motion_blocks_profile(region.width, region.height));
    *traffic += cost::three_frame_difference_packed_traffic(region.width, region.height,
                                                            config.frame_memory);
    motion_extents m;
    const int enough = min_int(config.detect.min_area, last.width * last.height / 8);
    const block_group after = later_blocks.extent(seed, 0);
    if (!after.found || after.pixels < enough) return m;
    if (detected) {
        m.before = m.previous = shifted(*detected, -region.x, -region.y);
    } else {
        const block_group before = earlier.extent(seed, 0);
        if (!before.found || before.pixels < enough) return m;
        m.before = before.bbox;
        m.previous = intersection(before.bbox, after.bbox);
        if (m.previous.empty()) return m;  // the motion reversed: no common box
    }
    m.found = true;
    m.after = m.both = after.bbox;
    m.before = shifted(m.before, region.x, region.y);
    m.after = shifted(m.after, region.x, region.y);
    m.previous = shifted(m.previous, region.x, region.y);
    m.both = shifted(m.both, region.x, region.y);
    return m;
}

// object(t) from the extents, per axis: object(t-1) (previous_of) and
// where Dif(t-1,t) reaches past it (follow_axis), as wide as object(t-1)
// (the last box's size where the motion reversed). Not given when object(t-1)'s extent is not the
// size of the last box (within an eighth, at least 2 px: else the difference did not outline the
// object, which nearly stopped and only its texture changed, or it held more than the object), when
// Dif(t-1,t) reaches further than the object could have moved (twice the search radius: a change of
// the light, another mover joined), or when object(t) touches the image border (the SAD's rule then
// says whether it is leaving). On an axis where Dif(t-1,t) is a part of the object (is_part: a
// slow ball's leading crescent), object(t) is the last box's size from the part's outer edge.
// A box that may be a part of its object (`may_be_part`: a detection's, until a silhouette of its
// size confirms it) may take object(t-1)'s extent, the common part of both differences, as it is
// (dsp/part_growth.h).
// A fast object (read_speed: Dif(t-1,t) 2 min_shift px or more past object(t-1), or the extent
// window's step min_shift px a pair or more): a size measured short is a rim the differences
// missed, neither a reason to give up nor taken, and object(t) is fitted to the last pairs'
// extents (dsp/extent_window.h).
bool controller::impl::follow_object(const motion_extents& motion, box last, bool may_be_part,
                                     bool keyed, box* followed, follow_reading* reading) const {
    const track_params& p = config.track;
    const bool part_x = is_part(x_span(motion.both), x_span(last));
    const bool part_y = is_part(y_span(motion.both), y_span(last));
    if (part_x && part_y) return false;
    const int tolerance_x = max_int(2, last.width / 8), tolerance_y = max_int(2, last.height / 8);
    const span common_x = x_span(motion.previous), common_y = y_span(motion.previous);
    const part_growth grown = grow_part(motion, last, may_be_part, part_x, part_y,
                                        at_border(motion.previous), config.rig);
    if (reading) reading->round_read = grown.round_read;
    const bool grown_x = grown.x, grown_y = grown.y;
    const int slow = key_frame::min_shift;
    const int n = recent_extents.count;
    const span previous_x = grown_x ? common_x
                                    : previous_of(recent_extents.x, n, x_span(motion.before),
                                                  x_span(motion.after), x_span(last));
    const span previous_y = grown_y ? common_y
                                    : previous_of(recent_extents.y, n, y_span(motion.before),
                                                  y_span(motion.after), y_span(last));
    // How far Dif(t-1,t) reaches past object(t-1) on each axis.
    const int moved_x = motion.both.width - previous_x.size;
    const int moved_y = motion.both.height - previous_y.size;
    const axis_speed speed = read_speed(moved_x, moved_y, recent_extents, last);
    const bool fast_x = speed.fast_x, fast = speed.fast_x || speed.fast_y;
    // Its size measured short is a rim the differences missed, not a
    // difference that did not outline it.
    // So is a slower object's where its leading rim fades (dsp/extent_window.h).
    const fading_rims fading = read_fading_rims(fast, part_x, part_y, last);
    const bool rim_missed_x = fast || fading.x2 != 0, rim_missed_y = fast || fading.y2 != 0;
    const bool short_x = rim_missed_x && previous_x.size < last.width;
    const bool short_y = rim_missed_y && previous_y.size < last.height;
    if ((!part_x && !grown_x && !short_x && !near_size(previous_x.size, last.width, tolerance_x)) ||
        (!part_y && !grown_y && !short_y && !near_size(previous_y.size, last.height, tolerance_y)))
        return false;
    // object(t-1)'s measured size (within the tolerance above of the last):
    // its edges and object(t)'s leading edge are found alike, so their
    // rounding cancels in the centre. A part's axis keeps the last size.
    const int w = part_x || near_size(previous_x.size, last.width, 1)
                      ? last.width
                      : max_int(p.min_size, min_int(width, previous_x.size));
    const int h = part_y || near_size(previous_y.size, last.height, 1)
                      ? last.height
                      : max_int(p.min_size, min_int(height, previous_y.size));
    const int reach = 2 * p.search_radius;
    if (motion.both.width - w > reach || motion.both.height - h > reach) return false;
    // Across the motion a size the differences measured short is not taken.
    const bool unmoved = keyed && moved_x < slow && moved_y < slow;
    const int size_x =
        rim_missed_x || unmoved || across_motion(moved_x, moved_y) ? max_int(w, last.width) : w;
    const int size_y =
        rim_missed_y || unmoved || across_motion(moved_y, moved_x) ? max_int(h, last.height) : h;
    span object_x = part_x ? part_axis(x_span(motion.both), x_span(last))
                           : follow_axis(previous_x, x_span(motion.both), x_span(last), size_x);
    span object_y = part_y ? part_axis(y_span(motion.both), y_span(last))
                           : follow_axis(previous_y, y_span(motion.both), y_span(last), size_y);
    // A rim missed more from pair to pair: object(t) from the trailing edge.
    const bool edge_moved =
        on_trailing_edges(motion.both, fading.x2, fading.y2, size_x, size_y, &object_x, &object_y);
    // A fast object's box from the last pairs' extents (dsp/extent_window.h):
    // across the image at any time, down it only across a fast motion across
    // it: along a throw's fall gravity changes the speed every pair, its
    // bounce reverses it within a pair, and at its apex the window still
    // reads the rise.
    const int fitted = fit_to_window(fast && !part_x, fast_x && !part_y && moved_x > moved_y,
                                     size_x, size_y, last, &object_x, &object_y);
    if (reading) {
        reading->fitted_axes = fitted;
        reading->edge_axes = fading.read_axes;
        // A trailing edge that moved steadily is a motion the window read.
        reading->window_moving = speed.window_moving || edge_moved;
    }
    const box b = from_spans(object_x, object_y);
    if (at_border(b)) return false;
    *followed = b;
    return true;
}

// The trailing edge's step on each axis where a slower object's leading rim
// fades (fading_rim_step2): none for a fast object, nor on a part's axis.
controller::impl::fading_rims controller::impl::read_fading_rims(bool fast, bool part_x,
                                                                 bool part_y, box last) const {
    fading_rims f;
    const int n = recent_extents.count;
    if (fast) return f;
    if (!part_x)
        f.x2 = fading_rim_step2(recent_extents.x, recent_extents.depth_q8, n, x_span(last));
    if (!part_y)
        f.y2 = fading_rim_step2(recent_extents.y, recent_extents.depth_q8, n, y_span(last));
    f.read_axes = !part_x + !part_y;
    return f;
}

// object(t) on the axes asked from the extent window (dsp/extent_window.h),
// its extents first brought to the object's size now (dsp/size_at_depth.h).
// Returns how many axes were fitted.
int controller::impl::fit_to_window(bool fit_x, bool fit_y, int size_x, int size_y, box last,
                                    span* object_x, span* object_y) const {
    span now[extent_window::capacity];
    const int n = recent_extents.count;
    int fitted = 0;
    if (fit_x) {
        extents_at_depth(recent_extents.x, recent_extents.depth_q8, n, size_x,
                         measured_disparity_q8, now);
        fitted += window_axis(now, n, size_x, x_span(last), object_x);
    }
    if (fit_y) {
        extents_at_depth(recent_extents.y, recent_extents.depth_q8, n, size_y,
                         measured_disparity_q8, now);
        fitted += window_axis(now, n, size_y, y_span(last), object_y);
    }
    return fitted;
}

// The SAD box refitted towards object(t-1) per axis (pull_axis): its size
// follows the object's, and its centre is pulled towards the object's. The
// pull keeps the box on the object: re-taking the pattern at an integer
// position every frame makes the box drift by the rounding of the object's
// motion (0.3 px per frame at 0.7 px/frame, measured 9 px after 30 frames
// without it; 0.8 px per frame on a ball 160 px wide). A size a key
// outlined (`hold_size`) is held: not below the last box's, which is at the
// latest depth, and the box moved only to hold object(t-1)'s extent
// (hold_axis), which is then a slow ball's thin differences, short where a
// rim is under the threshold (a 40 px ball coming nearer lost 15 px of its
// height in three pairs after its key was dropped).
box controller::impl::pull_box(const motion_extents& motion, box last, box found,
                               bool hold_size) const {
    const track_params& p = config.track;
    const span mask_x = x_span(motion.previous), mask_y = y_span(motion.previous);
    if (hold_size) {
        const int w =
            step_size(found.width, mask_x.size, max_int(p.min_size, last.width), width, width);
        const int h =
            step_size(found.height, mask_y.size, max_int(p.min_size, last.height), height, height);
        return from_spans(hold_axis(x_span(found), mask_x, w, width),
                          hold_axis(y_span(found), mask_y, h, height));
    }
    return from_spans(pull_axis(x_span(found), x_span(last), mask_x, p.min_size, width, width),
                      pull_axis(y_span(found), y_span(last), mask_y, p.min_size, height, height));
}

}  // namespace dsp
