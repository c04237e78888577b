// DETECT: the detections (paper eq. 2-4), the strided pass for slow objects,
// and the slow candidate, keyed until its outline is known (dsp/key_frame.h).
#include "dsp/controller_impl.h"

namespace dsp {

using namespace controller_parts;

namespace {

// A detection's pattern matched in f(t) as a key's turned pattern does
// (key_frame::match_turned): its texture turned between the
// frames (a spinning ball), so where the SAD placed it says nothing of how
// far the object moved. Read on a detection a motion block across or more:
// a narrower one's pattern is mostly outline, which changes as the object
// enters the view (a 6 x 16 px sliver of a 20 px ball read 9.3 a pixel).
bool texture_turned(const sad_result& match, box pattern, box detected) {
    const uint64_t area = static_cast<uint64_t>(pattern.width) * pattern.height;
    return min_int(detected.width, detected.height) >= motion_blocks::block_side &&
           key_frame::match_turned(match.sad, area);
}

}  // namespace

// Stage detect: three-frame differencing gives object(t-1) in the middle
// frame; the tracker takes the pattern there and finds it in the newest
// frame, so the track starts at the current frame's position.
bool controller::impl::detect(frame_output& out) {
    if (frames_in_history < history_frames) return false;
    stage_scope scope(*hardware, stage::detect, out);
    const detection found =
        detector.detect_packed(history(1), history(0), motion_mask, config.detect);
    scope.charge(detection_pass_cycles(),
                 cost::three_frame_difference_packed_traffic(width, height, config.frame_memory));
    // A slow candidate waiting from an earlier pair (start_track) goes on
    // after this pair's detection, which may start a faster object instead.
    const bool waiting = slow_candidate;
    uint64_t cycles = 0;
    sdram_traffic traffic;
    if (found.object_found) {
        detection_edges.push(found.object_box, frame_index);
        cycles += cycles_of(cost::detection_steps_profile());
    }
    out.detected = found.object_found && start_detection(found, out, &cycles, &traffic);
    if (!out.detected && waiting && slow_candidate)
        out.detected = confirm_slow_object(&cycles, &traffic);
    else if (!out.detected && !slow_candidate)
        detect_over_stride(out, &cycles, &traffic);
    // A track or a candidate ends the strided history (it restarts after).
    if (out.detected || slow_candidate) stride.reset();
    scope.charge(cycles, traffic);
    return out.detected;
}

// The detector's last pass: the packed three-frame difference, the opening,
// closing and labelling, and the object's extent (the largest component
// joined with the raw mask's block group around it, dsp/motion_blocks.h, or
// that group alone when the opening left no component).
uint64_t controller::impl::detection_pass_cycles() const {
    const int passes = 2 * (config.detect.open_passes + config.detect.close_passes);
    return cycles_of(
               cost::three_frame_difference_packed_profile(width, height, config.frame_memory)) +
           cycles_of(cost::morphology_profile(width, height, passes)) +
           cycles_of(cost::connected_components_profile(width, height,
                                                        detector.last_foreground_pixels())) +
           cycles_of(cost::motion_blocks_profile(width, height));
}

// When one pair's differences found nothing: on the stride's due pairs the
// three-frame pass over frames a stride apart (dsp/stride_history.h),
// whose object(t-s) is keyed as a slow candidate (confirm_slow_object);
// the pair's frame is then kept. Both passes are charged as the packed
// three-frame kernel, whose operations per 8 pixels they repeat (2 loads,
// 2 SUBABS4, 2 CMPGTU4, the bit masks, 1 store).
void controller::impl::detect_over_stride(frame_output& out, uint64_t* cycles,
                                          sdram_traffic* traffic) {
    if (!stride.due()) return;
    const c64x::kernel_profile pass =
        cost::three_frame_difference_packed_profile(width, height, config.frame_memory);
    if (stride.ready()) {
        struct rows {
            const stride_history* history;
            gray_cplane f_t;
            uint8_t threshold;
        } source_rows{&stride, history(0), config.detect.threshold};
        auto source = [](void* context, int y, uint8_t* object_row) {
            const auto& r = *static_cast<const rows*>(context);
            r.history->three_frame_row(r.f_t.row(y), y, r.threshold, object_row);
        };
        const detection found =
            detector.detect_rows(width, height, config.detect, source, &source_rows);
        *cycles += detection_pass_cycles();
        *traffic += cost::sdram_traffic_of(pass);
        if (found.object_found && !out.motion_found) {
            out.motion_found = true;
            out.motion_box = found.object_box;
        }
        if (found.object_found && !at_border(found.object_box) &&
            start_slow_candidate(found.object_box, stride.kept(), cycles, traffic))
            return;
    }
    stride.keep(history(0), config.detect.threshold);
    *cycles += cycles_of(pass);
    *traffic += cost::sdram_traffic_of(pass);
}

// A strided detection's object(t-s) in `middle`: its pattern searched in
// f(t) (it moved a stride's worth), and keyed there as a slow candidate, its
// region grown as a one-pair slow detection's (start_track).
bool controller::impl::start_slow_candidate(box detected, gray_cplane middle, uint64_t* cycles,
                                            sdram_traffic* traffic) {
    tracker.start(middle, detected);
    const box pattern = tracker.pattern_box();
    *cycles += cycles_of(cost::pattern_copy_profile(pattern.width, pattern.height));
    traffic->bytes_read += static_cast<uint64_t>(pattern.width) * pattern.height;
    const track_status status = tracker.update(history(0));
    *cycles += cycles_of(
        cost::sad_search_profile(pattern.width, pattern.height, tracker.last_match().positions));
    if (status != track_status::tracking) return false;
    take_key(
        cycles, traffic,
        2 * max_int(detected.width, detected.height) + key_frame::max_shift + key_frame::margin);
    slow_candidate = key.valid();
    candidate_pairs = 0;
    return slow_candidate;
}

bool controller::impl::start_detection(const detection& found, frame_output& out, uint64_t* cycles,
                                       sdram_traffic* traffic) {
    out.motion_found = true;
    out.motion_box = found.object_box;
    // An object cut by the image border is not started: its box would hold
    // mostly background (a 5 px sliver of the ball grew to an 8 px box that
    // then "tracked" the static background for good), and stereo needs the
    // object whole. It is detected again once wholly inside. The closing
    // clears the outermost close_passes rows and columns, so the border
    // band is one wider than that.
    if (at_border(found.object_box)) {
        out.detection_at_border = true;
        return false;
    }
    return start_track(found.object_box, cycles, traffic);
}

// The track's first box from the detection (object(t-1)): the SAD pattern taken
// there is searched in f(t) around it (paper eq. 5), and object(t) placed where
// Dif(t-1,t) reaches past object(t-1), as in TRACK (track_object), with
// object(t-1)'s size; without such an extent, where the SAD found the pattern.
// Where the SAD moved at most key_frame::max_step px, the last detections'
// outline does not step on (a turning texture read still:
// dsp/detection_steps.h) and its texture did not turn (texture_turned: then the
// SAD's place is the background's in the box's corners, and a key's pattern
// would read no motion either), the object is slow, and its detection, made of
// one pair's thin differences, may hold a part of it only (a 110 px ball at 1
// px per frame over a cluttered photograph: a 23 x 86 px crescent, or a 22 x 39
// px piece); it is not started but keyed (confirm_slow_object), the key's
// region grown by twice the detection's longer side, where the rest of its
// object may lie (a crescent is as long as its ball is wide; a smaller piece's
// ball reached further). One candidate at a time: while one waits, a slow
// detection is left to it, and a faster one starts its track (a candidate must
// not hold a thrown ball back for its 10 pairs).
bool controller::impl::start_track(box detected, uint64_t* cycles, sdram_traffic* traffic) {
    tracker.start(history(1), detected);
    const box pattern = tracker.pattern_box();
    *cycles += cycles_of(cost::pattern_copy_profile(pattern.width, pattern.height));
    const track_status status = tracker.update(history(0));
    *cycles += cycles_of(
        cost::sad_search_profile(pattern.width, pattern.height, tracker.last_match().positions));
    if (status == track_status::tracking) {
        *cycles += cycles_of(
            cost::pattern_copy_profile(tracker.pattern_box().width, tracker.pattern_box().height));
        // Still by the SAD, but its outline stepping on (dsp/detection_steps.h):
        // a moving object whose texture or background corners matched in place.
        const bool outline_moves = detection_edges.edge_keeps_stepping(key_frame::max_step + 1);
        if (moved_at_most(detected, tracker.position(), key_frame::max_step) && !outline_moves &&
            !texture_turned(tracker.last_match(), pattern, detected)) {
            if (slow_candidate) return false;  // one at a time: the waiting one goes on
            take_key(cycles, traffic,
                     2 * max_int(detected.width, detected.height) + key_frame::max_shift +
                         key_frame::margin);
            slow_candidate = key.valid();
            candidate_pairs = 0;
            if (slow_candidate) return false;
        }
    }
    // Read only for an object that is started: not in a slow candidate's pairs.
    const motion_extents motion = measure_motion(detected, &detected, cycles, traffic);
    recent_extents.clear();  // a new track: the window starts at its detection
    box followed;
    const bool follows = motion.found && follow_object(motion, detected, false, false, &followed);
    if (!follows && status != track_status::tracking) return false;
    key.drop();
    slow_candidate = false;
    box_may_be_part = true;
    if (motion.found) recent_extents.push(x_span(motion.after), y_span(motion.after));
    if (follows) {
        tracker.start(history(0), followed);
        *cycles += cycles_of(
            cost::pattern_copy_profile(tracker.pattern_box().width, tracker.pattern_box().height));
    }
    return true;
}

// A slow object's detection confirmed from its key: each pair the key's
// pattern is searched as in TRACK (key_frame::displacement); once the
// object has moved min_shift px, Dif(key, t) holds its whole outline and
// the track starts on object(t) from it (keyed_axis), with a new key
// there. Not started when the pattern is lost (the object turned or sped
// up: detected again) or has not moved min_shift px within
// max_candidate_pairs (an object that stopped, or a flicker), unless the
// pattern turned and Dif(key, t)'s outline moved min_shift px as a slow
// object does (outline_shift): a ball spinning against its path was keyed
// again from each detection (125 px at 1.5 px a frame, 0.5 rev/s: not
// started for 27 pairs).
bool controller::impl::confirm_slow_object(uint64_t* cycles, sdram_traffic* traffic) {
    // After this pair's detection (its pass made Dif(t-1,t)): f(t-1)'s
    // buffer is the pattern's scratch.
    const bool still = search_key(cycles, traffic);
    const bool waits = still && key.shift() < key_frame::min_shift;
    if (waits && ++candidate_pairs < max_candidate_pairs) return false;
    slow_candidate = false;
    // Where its pattern drops it (lost, or still) and its texture turned,
    // Dif(key, t)'s outline reads the motion (outline_shift).
    const bool dropped = waits || !still;
    if (dropped && !key.turned()) {
        key.drop();
        return false;
    }
    const block_group moved = keyed_extent(cycles, traffic);
    int dx = key.dx(), dy = key.dy();
    if (dropped && !(outline_shift(moved, &dx, &dy) &&
                     max_int(abs_int(dx), abs_int(dy)) >= key_frame::min_shift)) {
        key.drop();
        return false;
    }
    box object;
    const bool outlined = keyed_object(moved, dx, dy, true, &object);
    key.drop();
    // object(t) lies within Dif(key, t)'s extent. Where that extent reaches
    // the border band, the image edge may cut the outline: a ball entering
    // the view has its trailing rim outside, and its box would be the part
    // inside, started as the whole object.
    if (!outlined || at_border(moved.bbox)) return false;
    tracker.start(history(0), object);
    *cycles += cycles_of(
        cost::pattern_copy_profile(tracker.pattern_box().width, tracker.pattern_box().height));
    take_key(cycles, traffic);
    box_may_be_part = false;  // the key's outline: the whole object
    return true;
}

// A candidate whose pattern turned (a ball spinning against its path: the
// pattern reads it nearly still, then loses it) moved as Dif(key, t)'s
// outline did past the key's box (difference_shift) on each axis where it
// reads a slow object's step: at most max_step px a pair since the key (a
// key taken on a part has the rest of its object past its box at once).
// Elsewhere the pattern's displacement stays. False when neither axis reads.
bool controller::impl::outline_shift(const block_group& moved, int* dx, int* dy) const {
    if (!moved.found) return false;
    const box k = key.object();
    const int reach = key_frame::max_step * key.pairs() + 1;
    auto read = [reach](span both, span key_box, int* shift) {
        int s = 0;
        if (!difference_shift(both, key_box, &s) || abs_int(s) > reach) return false;
        *shift = s;
        return true;
    };
    const bool read_x = read(x_span(moved.bbox), x_span(k), dx);
    const bool read_y = read(y_span(moved.bbox), y_span(k), dy);
    return read_x || read_y;
}

}  // namespace dsp
