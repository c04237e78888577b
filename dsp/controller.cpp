// The controller (dsp/controller.h): each pair's flow through the stages,
// preprocessing, and the memory plan; the stages' own parts are in
// controller_detect.cpp, controller_track.cpp, controller_key.cpp and
// controller_stereo.cpp (dsp/controller_impl.h).
#include "dsp/controller_impl.h"

namespace dsp {

using namespace controller_parts;

namespace {

// Rows of the Sobel bands: the tracker never holds a pattern taller than
// track.max_size; one input row more on each side.
int band_capacity_rows(const controller_config& config) {
    return config.track.max_size < config.max_height ? config.track.max_size : config.max_height;
}

// The refit region is the last box grown by its own size each side, clipped
// to the frame: its mask row needs the frame's width (or height).
int size_rule_side(const controller_config& config) {
    return config.max_width > config.max_height ? config.max_width : config.max_height;
}

}  // namespace

const char* tracker_state_name(tracker_state s) {
    switch (s) {
        case tracker_state::detect:
            return "DETECT";
        case tracker_state::track:
            return "TRACK";
        case tracker_state::lost:
            return "LOST";
    }
    return "?";
}

const char* stereo_method_name(stereo_method m) {
    switch (m) {
        case stereo_method::sad:
            return "sad";
        case stereo_method::edge:
            return "edge";
        case stereo_method::both:
            return "both";
    }
    return "?";
}

memory_plan plan_memory(const controller_config& config) {
    memory_plan plan;
    const size_t w = static_cast<size_t>(config.max_width);
    const size_t frame = w * static_cast<size_t>(config.max_height);
    plan.right_gray = 2 * frame;
    plan.left_gray = frame;
    plan.motion_mask = packed_mask_bytes(config.max_width, config.max_height);
    plan.line_scratch = w * sizeof(rgb8);
    plan.detector = motion_detector::workspace_bytes(config.max_width, config.max_height,
                                                     config.max_motion_labels, false);
    const size_t side = static_cast<size_t>(max_int(config.track.max_size, 1));
    plan.tracker = side * side;
    const size_t region = static_cast<size_t>(size_rule_side(config));
    // Two mask rows; the block groups of Dif(t-2,t-1) in the detector's
    // workspace (not in DETECT), those of Dif(t-1,t) in their own.
    plan.refit = 2 * region + motion_blocks::workspace_bytes(config.max_width, config.max_height);
    const size_t bands = 2 * w * static_cast<size_t>(band_capacity_rows(config) + 2);
    // By stereo_edge f(t-1) is dead (the next pair's Dif is made), so the
    // bands borrow its buffer when they fit in it.
    if (bands <= frame) {
        plan.edge_bands_overlaid = bands;
    } else {
        plan.edge_bands = bands;
    }
    plan.raw_pair_sdram = 2 * frame;
    plan.key_sdram =
        key_frame::sdram_bytes(config.max_width, config.max_height, config.track.max_size);
    return plan;
}

controller::~controller() {
    delete m_impl;
}

void controller::init(const controller_config& config, hal& hardware) {
    delete m_impl;
    m_impl = new impl;
    impl& s = *m_impl;
    s.config = config;
    s.hardware = &hardware;
    m_state = tracker_state::detect;

    s.plan = plan_memory(config);
    const size_t frame_pixels = static_cast<size_t>(config.max_width) * config.max_height;
    s.line_scratch = new rgb8[config.max_width];
    for (auto& frame : s.right_gray) frame = new uint8_t[frame_pixels];
    s.left_gray = new uint8_t[frame_pixels];
    s.motion_mask = new uint8_t[s.plan.motion_mask]();
    const int region_side = size_rule_side(config);
    s.refit_rows = new uint8_t[2 * static_cast<size_t>(region_side)]();
    s.later_blocks.init(config.max_width, config.max_height);
    s.band_rows = band_capacity_rows(config);
    if (s.plan.edge_bands != 0) s.edge_band_storage = new uint8_t[s.plan.edge_bands]();

    s.detector.init(config.max_width, config.max_height, config.max_motion_labels, false);
    s.tracker.init(config.track);
    s.key.init(config.max_width, config.max_height, config.track.max_size);
    s.stride.init(s.left_gray, frame_pixels);

    if (config.disparity_from_rig) {
        const int64_t near_q8 =
            disparity_q8_at_depth(config.rig, int64_t{config.min_depth_mm} * 1000);
        const int64_t far_q8 =
            disparity_q8_at_depth(config.rig, int64_t{config.max_depth_mm} * 1000);
        const int max_d = static_cast<int>((near_q8 + 255) / 256) + config.disparity_margin_px;
        const int min_d = max_int(0, static_cast<int>(far_q8 / 256) - config.disparity_margin_px);
        s.config.stereo.min_disparity = min_d;
        s.config.stereo.max_disparity = max_d;
        s.config.edge.min_disparity = min_d;
        s.config.edge.max_disparity = max_d;
        s.far_disparity_q8 = far_q8;
        s.near_disparity_q8 = near_q8;
    } else {
        s.far_disparity_q8 = int64_t{256} * config.stereo.min_disparity;
        s.near_disparity_q8 = int64_t{256} * config.stereo.max_disparity;
    }
}

const controller_config& controller::config() const {
    return m_impl->config;
}

const uint8_t* controller::motion_mask() const {
    return m_impl ? m_impl->motion_mask : nullptr;
}

gray_cplane controller::gray_left() const {
    if (!m_impl || m_impl->frames_in_history == 0) return gray_cplane{};
    return m_impl->left();
}

gray_cplane controller::gray_right() const {
    if (!m_impl || m_impl->frames_in_history == 0) return gray_cplane{};
    return m_impl->history(0);
}

frame_output controller::process_pair(gray_cplane raw_left, gray_cplane raw_right) {
    frame_output out;
    out.state = m_state;
    if (!m_impl) {
        out.accepted = false;
        return out;
    }
    impl& s = *m_impl;
    const controller_config& cfg = s.config;
    out.frame_index = s.frame_index++;

    const int w = raw_right.width, h = raw_right.height;
    if (raw_left.width != w || raw_left.height != h || w > cfg.max_width || h > cfg.max_height ||
        w < 4 || h < 4 || (w & 1) || (h & 1)) {
        out.accepted = false;
        return out;
    }
    if (w != s.width || h != s.height) {  // a new image size starts a new history
        s.width = w;
        s.height = h;
        s.frames_in_history = 0;
        s.slow_candidate = false;
        s.stride.reset();
        m_state = tracker_state::detect;
    }

    s.preprocess(raw_left, raw_right, m_state, out);

    bool has_object = false;
    // TRACK's box is the object's outline (within a pixel or two: box_refit.h);
    // a detection's may be a part of it (one pair's thin differences).
    const bool outlined = m_state == tracker_state::track;
    switch (m_state) {
        case tracker_state::detect:
            has_object = s.detect(out);
            if (has_object) {  // a new track: its size stands for no depth yet, nor a key's
                m_state = tracker_state::track;
                s.measured_disparity_q8 = s.sized_disparity_q8 = s.key_sized_q8 = 0;
                s.reported_depth.clear();
                s.size_from_key = false;
                s.still_pairs = 0;
            }
            break;
        case tracker_state::track:
            has_object = s.track(out);
            if (!has_object) {
                s.lost_pairs = 0;
                m_state =
                    cfg.lost_frames_to_detect > 0 ? tracker_state::lost : tracker_state::detect;
            }
            break;
        case tracker_state::lost:
            if (++s.lost_pairs >= cfg.lost_frames_to_detect) m_state = tracker_state::detect;
            break;
    }
    out.state = m_state;
    if (!has_object) return out;

    out.has_object = true;
    if (!s.left_made) {  // a DETECT pair's left image, left for a detection
        stage_scope scope(*s.hardware, stage::preprocess, out);
        s.preprocess_left(raw_left, out.gain_q8);
        sdram_traffic traffic;
        scope.charge(s.preprocess_cost(&traffic), traffic);
        s.left_made = true;
    }
    out.box_right = s.tracker.position();
    s.stereo_sad(out.box_right, outlined, out);
    s.stereo_edge(out.box_right, out);
    if (!s.choose_disparity(out)) {
        s.reported_depth.clear();
        return out;
    }
    // For the next pair's size (dsp/size_at_depth.h): the part of the
    // disparity inversely proportional to depth.
    s.measured_disparity_q8 = out.disparity_q8 - cfg.rig.principal_offset_q8();
    s.xyz(out.box_right, out);
    // A key taken, and the window's extents read, before the track had a
    // disparity (at its detection) stand for the first one measured.
    if (s.key.valid() && s.key_sized_q8 <= 0) s.key_sized_q8 = s.measured_disparity_q8;
    s.recent_extents.give_depth(s.measured_disparity_q8);
    return out;
}

// Stage preprocess: both images to gray. The right one overwrites the last
// pair's f(t-1) (this pair's f(t-2), which lives on only as the packed mask);
// the last pair's f(t) becomes f(t-1). Brightness compensation is an L2 pass over
// the gray frame (exact, dsp/preprocess.h): no SDRAM traffic besides the raw
// read. Outside DETECT the packed mask is brought up to date here (LOST, and
// the second frame of a history); TRACK does it after its refit, DETECT in
// its three-frame pass.
void controller::impl::preprocess(gray_cplane raw_left, gray_cplane raw_right, tracker_state state,
                                  frame_output& out) {
    stage_scope scope(*hardware, stage::preprocess, out);
    newest = 1 - newest;
    out.gain_q8 = preprocess_raw_to_gray(raw_right, config.cfa, config.brightness, line_scratch,
                                         frame_plane(right_gray[newest]))
                      .gain_q8;
    if (frames_in_history < history_frames) ++frames_in_history;
    sdram_traffic traffic;
    const uint64_t per_image = preprocess_cost(&traffic);
    scope.charge(per_image, traffic);
    // The left image is for stereo: a DETECT pair whose left buffer holds
    // the strided history (dsp/stride_history.h) makes it only once it has
    // an object (process_pair).
    left_made = !(state == tracker_state::detect && stride.has_frame());
    if (left_made) {
        preprocess_left(raw_left, out.gain_q8);
        scope.charge(per_image, traffic);
    }

    const bool detect_makes_it = state == tracker_state::detect && frames_in_history >= 3;
    if (state != tracker_state::track && !detect_makes_it) {
        uint64_t cycles = 0;
        sdram_traffic mask_traffic;
        update_motion_mask(&cycles, &mask_traffic);
        scope.charge(cycles, mask_traffic);
    }
}

// One image's preprocess cost (demosaic, gray, gain), its SDRAM traffic
// into `traffic`.
uint64_t controller::impl::preprocess_cost(sdram_traffic* traffic) const {
    uint64_t cycles = cycles_of(
        cost::demosaic_gray_profile(width, height, config.frame_memory, config.raw_memory));
    *traffic = cost::demosaic_gray_traffic(width, height, config.frame_memory, config.raw_memory);
    if (config.brightness.enabled) {
        cycles += cycles_of(cost::brightness_profile(width, height, config.frame_memory));
        *traffic += cost::brightness_traffic(width, height, config.frame_memory);
    }
    return cycles;
}

// The left image takes the right one's gain. Each image's own mean differs
// with what the other view sees around the object (a 1 % gain step moved
// the matches of a smooth, shaded ball by 1-3 px); a light change reaches
// both sensors alike, so one gain still cancels it. Its buffer is the
// strided history's while DETECT finds nothing; a pair that makes it after
// its detection ended that history (detect), as every way out of DETECT does.
void controller::impl::preprocess_left(gray_cplane raw_left, uint16_t gain_q8) {
    brightness_params ungained = config.brightness;
    ungained.enabled = false;
    preprocess_raw_to_gray(raw_left, config.cfa, ungained, line_scratch, frame_plane(left_gray));
    if (config.brightness.enabled) apply_gain(frame_plane(left_gray), gain_q8);
}

void controller::impl::update_motion_mask(uint64_t* cycles, sdram_traffic* traffic) {
    if (frames_in_history < 2) return;
    difference_packed(history(1), history(0), config.detect.threshold, motion_mask);
    *cycles += cycles_of(cost::difference_packed_profile(width, height, config.frame_memory));
    *traffic += cost::difference_packed_traffic(width, height, config.frame_memory);
}

}  // namespace dsp
