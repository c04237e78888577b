#include "dsp/controller.h"

#include <cstring>

#include "dsp/box_refit.h"
#include "dsp/kernel_costs.h"
#include "dsp/key_frame.h"
#include "dsp/sobel.h"
#include "dsp/stride_history.h"

namespace dsp {

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

namespace {

constexpr int history_frames = 3;  // paper eq. 2-4 needs f(t-2), f(t-1), f(t)
// Pairs a slow detection waits for its object to move key_frame::min_shift
// px: slower than 0.4 px per frame it is taken as still.
constexpr int max_candidate_pairs = 10;

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

int max_int(int a, int b) {
    return a > b ? a : b;
}
int min_int(int a, int b) {
    return a < b ? a : b;
}

// Disparity (Q8 px) of a point at depth_mm on the rig: d = s f / D + dcx
// (the inverse of dsp/triangulate.h). Integer, once at init.
int64_t disparity_q8_at_depth(const camera_rig& rig, int32_t depth_mm) {
    const int64_t depth_um = static_cast<int64_t>(depth_mm) * 1000;
    return static_cast<int64_t>(rig.baseline_um) * rig.focal_px_q8() / depth_um +
           rig.principal_offset_q8();
}

// Where the differences are read when the object's box at t-1 was `last`:
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

// `b` within `step` px of `a` on both axes.
bool moved_at_most(box a, box b, int step) {
    return b.x - a.x <= step && a.x - b.x <= step && b.y - a.y <= step && a.y - b.y <= step;
}

// How far apart two boxes' centres are on each axis, in half pixels.
struct centre_gap {
    int x2, y2;
};
centre_gap centre_offset2(box a, box b) {
    const int x2 = a.center_x2() - b.center_x2(), y2 = a.center_y2() - b.center_y2();
    return centre_gap{max_int(x2, -x2), max_int(y2, -y2)};
}

bool same_box(box a, box b) {
    return a.x == b.x && a.y == b.y && a.width == b.width && a.height == b.height;
}

box from_spans(span x, span y) {
    return box{x.start, y.start, x.size, y.size};
}
span x_span(box b) {
    return span{b.x, b.width};
}
span y_span(box b) {
    return span{b.y, b.height};
}

box intersection(box a, box b) {
    const int x0 = max_int(a.x, b.x), y0 = max_int(a.y, b.y);
    const int x1 = min_int(a.right(), b.right()), y1 = min_int(a.bottom(), b.bottom());
    if (x1 <= x0 || y1 <= y0) return box{};
    return box{x0, y0, x1 - x0, y1 - y0};
}

bool near_size(int measured, int size, int tolerance) {
    return measured >= size - tolerance && measured <= size + tolerance;
}

bool covers(span outer, span inner) {
    return outer.start <= inner.start + 1 && outer.end() >= inner.end() - 1;
}

box shifted(box b, int dx, int dy) {
    return box{b.x + dx, b.y + dy, b.width, b.height};
}

// The part of an object box SAD stereo matches: the box less one seventh of
// its width and height on each side (same centre). A round object fills only
// pi/4 of its bounding box; the corners are background at another depth and
// pulled the disparity towards it (measured +1.5 % to +2 % depth at 2.2 m,
// background at 5 m). A core of side c is inside a disc of diameter w when
// c <= w / sqrt(2): at a seventh c = 0.714 w, its corners on the rim (0.02 %
// of it background; at an eighth 0.67 %, and a 62 px ball spinning about x
// was 1.17 % far in one pair, 0.60 % at a seventh), its mean surface 0.13 r
// nearer than the whole visible surface's (0.11 r at an eighth; at a sixth
// 0.16 r, which took four 90 px balls past 1 % near).
// Below 16 px a seventh rounds down to 1 px, which leaves the corners of a
// small disc's core on the background: 2 px. The 10 px ball's depth error
// was 1.02 % in one pair with 1 px, 0.37 % with 2 px.
int core_trim(int side) {
    return side < 16 ? 2 : side / 7;
}

box object_core(box object) {
    const int trim_x = core_trim(object.width), trim_y = core_trim(object.height);
    return box{object.x + trim_x, object.y + trim_y, object.width - 2 * trim_x,
               object.height - 2 * trim_y};
}

// stage_begin / stage_end around a scope; the cycles charged inside go to
// the HAL (once, at the end, with the SDRAM traffic of its kernels) and to
// the frame's record.
class stage_scope {
  public:
    stage_scope(hal& hardware, stage s, frame_output& out)
        : m_hal(hardware), m_stage(s), m_out(out) {
        m_hal.stage_begin(m_stage);
    }
    ~stage_scope() {
        m_hal.charge_with_traffic(m_stage, m_cycles, m_traffic);
        m_out.stage_cycles[static_cast<int>(m_stage)] += m_cycles;
        m_hal.stage_end(m_stage);
    }
    stage_scope(const stage_scope&) = delete;
    stage_scope& operator=(const stage_scope&) = delete;

    void charge(uint64_t cycles) { m_cycles += cycles; }
    void charge(uint64_t cycles, const sdram_traffic& traffic) {
        m_cycles += cycles;
        m_traffic += traffic;
    }

  private:
    hal& m_hal;
    stage m_stage;
    frame_output& m_out;
    uint64_t m_cycles = 0;
    sdram_traffic m_traffic;
};

}  // namespace

struct controller::impl {
    controller_config config;
    hal* hardware = nullptr;
    // A kernel call's cycles under the platform's cost model (hal::kernel_cycles).
    uint64_t cycles_of(const c64x::kernel_profile& kernel) const {
        return hardware->kernel_cycles(kernel);
    }
    memory_plan plan;

    rgb8* line_scratch = nullptr;    // one demosaiced row
    uint8_t* right_gray[2] = {};     // f(t) and f(t-1); roles swap every pair
    uint8_t* left_gray = nullptr;    // the current left gray frame
    uint8_t* motion_mask = nullptr;  // packed Dif(t-2,t-1), then Dif(t-1,t)
    uint8_t* refit_rows = nullptr;  // one row of Dif(t-2,t-1) and of Dif(t-1,t) around the last box
    motion_blocks later_blocks;     // block groups of Dif(t-1,t); Dif(t-2,t-1)'s: the detector's
    uint8_t* edge_band_storage = nullptr;  // own Sobel bands, or null: inside f(t-1)
    int band_rows = 0;

    motion_detector detector;
    sad_tracker tracker;
    key_frame key;          // a slow object's older frame (dsp/key_frame.h), SDRAM
    stride_history stride;  // DETECT: frames a stride apart (dsp/stride_history.h), in left_gray
    bool slow_candidate = false;  // DETECT: a slow object's key, waiting for its outline
    int candidate_pairs = 0;      // pairs the candidate has waited
    // What Dif(key, t) has said of the key's box on one axis (key_axis_shift).
    struct key_axis {
        bool unfit = false;      // the key's box did not outline the object there
        bool has_first = false;  // `first` holds the object's outline there
        span first;              // Dif(key, t)'s extent at the key's first pair
    };
    key_axis key_x, key_y;
    bool key_first_seen = false;   // Dif(key, t) found since the key was taken
    char outline_key_across = 0;   // a key of the outline: 'x' or 'y' across the motion, 0 unknown
    bool box_may_be_part = false;  // a detection's box no silhouette of its size has confirmed

    // Disparities (Q8) of the depth range's ends, without the search margin.
    int64_t far_disparity_q8 = 0, near_disparity_q8 = 0;
    int width = 0, height = 0;  // size of the pairs in the history
    int newest = 1;             // right_gray[newest] = f(t)
    int frames_in_history = 0;  // right frames seen, at most 3
    int lost_pairs = 0;
    uint32_t frame_index = 0;
    bool left_made = false;  // left_gray holds this pair's left image

    ~impl() {
        delete[] line_scratch;
        for (auto* frame : right_gray) delete[] frame;
        delete[] left_gray;
        delete[] motion_mask;
        delete[] refit_rows;
        delete[] edge_band_storage;
    }

    gray_plane frame_plane(uint8_t* data) const { return gray_plane{data, width, height, width}; }
    gray_cplane history(int age) const {  // age 0 = f(t), 1 = f(t-1)
        return frame_plane(right_gray[age == 0 ? newest : 1 - newest]).as_const();
    }
    gray_cplane left() const { return frame_plane(left_gray).as_const(); }

    void preprocess(gray_cplane raw_left, gray_cplane raw_right, tracker_state state,
                    frame_output& out);
    uint64_t preprocess_cost(sdram_traffic* traffic) const;
    void preprocess_left(gray_cplane raw_left, uint16_t gain_q8);
    // Dif(t-1,t) into the packed mask for the next pair (not in DETECT,
    // whose three-frame pass makes it).
    void update_motion_mask(uint64_t* cycles, sdram_traffic* traffic);
    // Each returns whether an object box is known after it.
    bool detect(frame_output& out);
    bool track(frame_output& out);
    // What track_object saw of the object's speed, for the key.
    struct track_motion {
        bool sad_slow = false;      // the SAD pattern moved at most key_frame::max_step px
        bool confirmed = false;     // a silhouette within an eighth of the SAD box
        bool outlined = false;      // the box followed a silhouette (follow_object)
        bool outline_slow = false;  // whose centre moved at most key_frame::max_step px
    };
    bool track_object(uint64_t* cycles, sdram_traffic* traffic, track_motion* seen);
    void follow_slow_object(track_motion seen, uint64_t* cycles, sdram_traffic* traffic);
    void follow_outline_key(track_motion seen, uint64_t* cycles, sdram_traffic* traffic);
    void judge_across(track_motion seen, box silhouette);
    void take_outline_key(uint64_t* cycles, sdram_traffic* traffic);
    void take_key(uint64_t* cycles, sdram_traffic* traffic,
                  int grow = key_frame::max_shift + key_frame::margin);
    bool start_detection(const detection& found, frame_output& out, uint64_t* cycles,
                         sdram_traffic* traffic);
    bool start_track(box detected, uint64_t* cycles, sdram_traffic* traffic);
    uint64_t detection_pass_cycles() const;
    void detect_over_stride(frame_output& out, uint64_t* cycles, sdram_traffic* traffic);
    bool start_slow_candidate(box detected, gray_cplane middle, uint64_t* cycles,
                              sdram_traffic* traffic);
    bool confirm_slow_object(uint64_t* cycles, sdram_traffic* traffic);
    bool search_key(uint64_t* cycles, sdram_traffic* traffic);
    block_group keyed_extent(uint64_t* cycles, sdram_traffic* traffic);
    bool keyed_object(const block_group& u, int dx, int dy, bool of_part, box* object) const;
    // The displacement since the key, and the axes to take from Dif(key, t) now.
    struct key_reading {
        int dx = 0, dy = 0;
        bool outline_x = false, outline_y = false;
    };
    bool key_displacement(const block_group& u, bool matched, key_reading* r);
    bool key_axis_shift(key_axis& axis, span both, span key_box, bool first_pair, int* shift,
                        bool* outline);
    bool at_border(box b) const {
        const int border = config.detect.close_passes + 1;
        return b.x <= border || b.y <= border || b.right() >= width - border ||
               b.bottom() >= height - border;
    }
    // What the two frame differences say around the last box (dsp/box_refit.h).
    struct motion_extents {
        bool found = false;  // both differences hold enough pixels and share a box
        box before;          // Dif(t-2,t-1)'s extent (DETECT: object(t-1))
        box after;           // Dif(t-1,t)'s extent around the last box
        box previous;        // object(t-1): the two extents' common box
        box both;            // Dif(t-1,t)'s extent: object(t-1) and object(t)
    };
    motion_extents measure_motion(box last, const box* detected, uint64_t* cycles,
                                  sdram_traffic* traffic);
    bool follow_object(const motion_extents& motion, box last, bool may_be_part, bool keyed,
                       box* followed) const;
    box pull_box(const motion_extents& motion, box last, box found) const;
    void stereo_sad(box object, bool outlined, frame_output& out);
    void stereo_edge(box object, frame_output& out);
    bool choose_disparity(frame_output& out) const;
    void xyz(box object, frame_output& out);
};

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
        const int64_t near_q8 = disparity_q8_at_depth(config.rig, config.min_depth_mm);
        const int64_t far_q8 = disparity_q8_at_depth(config.rig, config.max_depth_mm);
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
            if (has_object) m_state = tracker_state::track;
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
    if (s.choose_disparity(out)) s.xyz(out.box_right, out);
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

// The track's first box from the detection (object(t-1)): the SAD pattern
// taken there is searched in f(t) around it (paper eq. 5), and object(t)
// placed where Dif(t-1,t) reaches past object(t-1), as in TRACK
// (track_object), with object(t-1)'s size; without such an extent, where
// the SAD found the pattern. Where the SAD moved at most key_frame::max_step
// px the object is slow, and its detection, made of one pair's thin
// differences, may hold a part of it only (a 110 px ball at 1 px per frame
// over a cluttered photograph: a 23 x 86 px crescent, or a 22 x 39 px
// piece); it is not started but keyed (confirm_slow_object), the key's
// region grown by twice the detection's longer side, where the rest of its
// object may lie (a crescent is as long as its ball is wide; a smaller
// piece's ball reached further). One candidate at a time: while one waits,
// a slow detection is left to it, and a faster one starts its track (a
// candidate must not hold a thrown ball back for its 10 pairs).
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
        if (moved_at_most(detected, tracker.position(), key_frame::max_step)) {
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
    box followed;
    const bool follows = motion.found && follow_object(motion, detected, false, false, &followed);
    if (!follows && status != track_status::tracking) return false;
    key.drop();
    slow_candidate = false;
    box_may_be_part = true;
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
// max_candidate_pairs (an object that stopped, or a flicker).
bool controller::impl::confirm_slow_object(uint64_t* cycles, sdram_traffic* traffic) {
    // After this pair's detection (its pass made Dif(t-1,t)): f(t-1)'s
    // buffer is the pattern's scratch.
    const bool still = search_key(cycles, traffic);
    const bool waits = still && key.shift() < key_frame::min_shift;
    if (waits && ++candidate_pairs < max_candidate_pairs) return false;
    slow_candidate = false;
    if (waits || !still) {
        key.drop();
        return false;
    }
    const block_group moved = keyed_extent(cycles, traffic);
    box object;
    const bool outlined = keyed_object(moved, key.dx(), key.dy(), true, &object);
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
    return true;
}

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
    const bool tracking = track_object(&cycles, &traffic, &seen);
    // The refit has used Dif(t-2,t-1); now Dif(t-1,t) for the next pair.
    update_motion_mask(&cycles, &traffic);
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
    const box last = tracker.position();
    const box pattern = tracker.pattern_box();
    const motion_extents motion = measure_motion(last, nullptr, cycles, traffic);
    box followed;
    const bool keyed = key.valid() && !key.outline_only();
    const bool follows =
        motion.found && follow_object(motion, last, box_may_be_part, keyed, &followed);
    const track_status status =
        follows ? tracker.update_near(history(0), followed) : tracker.update(history(0));
    *cycles += cycles_of(
        cost::sad_search_profile(pattern.width, pattern.height, tracker.last_match().positions));
    if (status != track_status::tracking && !follows) return false;
    if (status == track_status::tracking)
        *cycles += cycles_of(
            cost::pattern_copy_profile(tracker.pattern_box().width, tracker.pattern_box().height));

    const box found = tracker.position();
    const int step = key_frame::max_step;
    seen->sad_slow = status == track_status::tracking && moved_at_most(last, found, step);
    if (follows) {
        const centre_gap off = centre_offset2(followed, found);
        seen->confirmed = 2 * max_int(step, found.width / 8) >= off.x2 &&
                          2 * max_int(step, found.height / 8) >= off.y2;
        const centre_gap moved = centre_offset2(followed, last);
        seen->outlined = true;
        seen->outline_slow = 2 * step >= moved.x2 && 2 * step >= moved.y2;
    }
    if (follows && near_size(followed.width, last.width, max_int(2, last.width / 8)) &&
        near_size(followed.height, last.height, max_int(2, last.height / 8)))
        box_may_be_part = false;  // a silhouette of the box's size
    box resized = found;
    if (follows) {
        resized = followed;
    } else if (motion.found) {
        resized = pull_box(motion, last, found);
    }
    if (status != track_status::tracking || !same_box(resized, found)) {
        tracker.start(history(0), resized);
        *cycles += cycles_of(
            cost::pattern_copy_profile(tracker.pattern_box().width, tracker.pattern_box().height));
    }
    return true;
}

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
    if (!key_displacement(u, matched, &r)) {
        key.drop();
        return;
    }
    const int dx = r.dx, dy = r.dy;
    box b = shifted(k, dx, dy);
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
        if (outline_x) b = from_spans(x_span(outlined), y_span(b));
        if (outline_y) b = from_spans(x_span(b), y_span(outlined));
    }
    b.x = max_int(0, min_int(b.x, width - b.width));
    b.y = max_int(0, min_int(b.y, height - b.height));
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
    const block_group u = keyed_extent(cycles, traffic);
    if (!u.found) {
        key.drop();
        return;
    }
    judge_across(seen, s);
    // Under half the key's box: a part of the object changed, not its outline.
    if (2 * u.bbox.width < k.width || 2 * u.bbox.height < k.height) return;
    const int size_x = max_int(s.width, k.width), size_y = max_int(s.height, k.height);
    box b =
        from_spans(outline_key_axis(x_span(u.bbox), x_span(k), size_x, outline_key_across == 'x'),
                   outline_key_axis(y_span(u.bbox), y_span(k), size_y, outline_key_across == 'y'));
    b.x = max_int(0, min_int(b.x, width - b.width));
    b.y = max_int(0, min_int(b.y, height - b.height));
    if (!same_box(b, s)) {
        tracker.start(history(0), b);
        *cycles += cycles_of(
            cost::pattern_copy_profile(tracker.pattern_box().width, tracker.pattern_box().height));
    }
    if (max_int(key_reach(x_span(u.bbox), x_span(k)), key_reach(y_span(u.bbox), y_span(k))) >=
        key_frame::max_shift)
        take_outline_key(cycles, traffic);
}

// The axis across the motion for a key of the outline: the one along which
// the silhouette's centre moved at most half as far since the key as along
// the other, that one at least min_shift px; none before (both axes then
// take the object's size at the hull's leading end, or centred).
void controller::impl::judge_across(track_motion seen, box silhouette) {
    if (!seen.outlined) return;
    const centre_gap moved = centre_offset2(silhouette, key.object());
    const int move_x = moved.x2 / 2, move_y = moved.y2 / 2;
    if (2 * move_y <= move_x && move_x >= key_frame::min_shift) outline_key_across = 'y';
    if (2 * move_x <= move_y && move_y >= key_frame::min_shift) outline_key_across = 'x';
}

void controller::impl::take_outline_key(uint64_t* cycles, sdram_traffic* traffic) {
    take_key(cycles, traffic);
    key.set_outline_only();
    outline_key_across = 0;
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
controller::impl::motion_extents controller::impl::measure_motion(box last, const box* detected,
                                                                  uint64_t* cycles,
                                                                  sdram_traffic* traffic) {
    const box region = size_rule_region(last, config.track.search_radius, width, height);
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

// object(t) from the extents, per axis: object(t-1) (previous_axis) and
// where Dif(t-1,t) reaches past it (follow_axis), as wide as object(t-1)
// (the last box's size where the motion reversed). Not given when object(t-1)'s extent is not the
// size of the last box (within an eighth, at least 2 px: else the difference did not outline the
// object, which nearly stopped and only its texture changed, or it held more than the object), when
// Dif(t-1,t) reaches further than the object could have moved (twice the search radius: a change of
// the light, another mover joined), or when object(t) touches the image border (the SAD's rule then
// says whether it is leaving). On an axis where Dif(t-1,t) is a part of the object (is_part: a
// slow ball's leading crescent), object(t) is the last box's size from the part's outer edge.
// A box that may be a part of its object (`may_be_part`: a detection's, until a silhouette of its
// size confirms it) of a slow object takes object(t-1)'s extent, the common part of both
// differences, on an axis where that extent holds the box and is larger than the tolerance
// allows: the three-frame AND of a slow spinning ball holds where its texture changed most (a
// detection 67 x 34 px of a 110 px ball, 88 px wide of 140), both differences the whole ball. Not
// later in a track (at a bounce the common part holds the ball and where it was and will be), nor
// for a fast object (a throw's first common part is over an eighth larger than its detection).
bool controller::impl::follow_object(const motion_extents& motion, box last, bool may_be_part,
                                     bool keyed, box* followed) const {
    const track_params& p = config.track;
    const bool part_x = is_part(x_span(motion.both), x_span(last));
    const bool part_y = is_part(y_span(motion.both), y_span(last));
    if (part_x && part_y) return false;
    const int tolerance_x = max_int(2, last.width / 8), tolerance_y = max_int(2, last.height / 8);
    const span common_x = x_span(motion.previous), common_y = y_span(motion.previous);
    // A slow object's: both differences' extents within min_shift px of each other.
    const int slow = key_frame::min_shift;
    const bool grows = may_be_part && near_size(motion.before.x, motion.after.x, slow) &&
                       near_size(motion.before.right(), motion.after.right(), slow) &&
                       near_size(motion.before.y, motion.after.y, slow) &&
                       near_size(motion.before.bottom(), motion.after.bottom(), slow);
    const bool grown_x = grows && !part_x && covers(common_x, x_span(last)) &&
                         common_x.size > last.width + tolerance_x;
    const bool grown_y = grows && !part_y && covers(common_y, y_span(last)) &&
                         common_y.size > last.height + tolerance_y;
    const span previous_x =
        grown_x ? common_x : previous_axis(x_span(motion.before), x_span(motion.after), last.width);
    const span previous_y =
        grown_y ? common_y
                : previous_axis(y_span(motion.before), y_span(motion.after), last.height);
    if ((!part_x && !grown_x && !near_size(previous_x.size, last.width, tolerance_x)) ||
        (!part_y && !grown_y && !near_size(previous_y.size, last.height, tolerance_y)))
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
    const int moved_x = motion.both.width - previous_x.size;
    const int moved_y = motion.both.height - previous_y.size;
    const bool unmoved = keyed && moved_x < slow && moved_y < slow;
    const int size_x = unmoved || across_motion(moved_x, moved_y) ? max_int(w, last.width) : w;
    const int size_y = unmoved || across_motion(moved_y, moved_x) ? max_int(h, last.height) : h;
    const box b =
        from_spans(part_x ? part_axis(x_span(motion.both), x_span(last))
                          : follow_axis(previous_x, x_span(motion.both), x_span(last), size_x),
                   part_y ? part_axis(y_span(motion.both), y_span(last))
                          : follow_axis(previous_y, y_span(motion.both), y_span(last), size_y));
    if (at_border(b)) return false;
    *followed = b;
    return true;
}

// The SAD box refitted towards object(t-1) per axis (pull_axis): its size
// follows the object's, and its centre is pulled towards the object's. The
// pull keeps the box on the object: re-taking the pattern at an integer
// position every frame makes the box drift by the rounding of the object's
// motion (0.3 px per frame at 0.7 px/frame, measured 9 px after 30 frames
// without it; 0.8 px per frame on a ball 160 px wide).
box controller::impl::pull_box(const motion_extents& motion, box last, box found) const {
    const track_params& p = config.track;
    return from_spans(
        pull_axis(x_span(found), x_span(last), x_span(motion.previous), p.min_size, width, width),
        pull_axis(y_span(found), y_span(last), y_span(motion.previous), p.min_size, height,
                  height));
}

// Stage stereo_sad: the object's core (the right pattern) along the same rows
// (+-row_slack) of the left image over the depth range; a large
// object's disparity is then its tiles' mean depth around the core's
// (dsp/object_depth.h), the core's when too few tiles matched.
void controller::impl::stereo_sad(box object, bool outlined, frame_output& out) {
    stage_scope scope(*hardware, stage::stereo_sad, out);
    const box core = object_core(object);
    out.sad_match = stereo_match_sad(history(0), left(), core, config.stereo);
    out.sad_at_range_end = at_range_end(out.sad_match, core, config.stereo.min_disparity,
                                        config.stereo.max_disparity, width);
    scope.charge(
        cycles_of(cost::sad_search_profile(core.width, core.height, out.sad_match.positions)));
    if (config.stereo.subpixel && out.sad_match.valid)
        scope.charge(cycles_of(cost::subpixel_profile()));
    if (!out.sad_match.valid || out.sad_at_range_end) return;
    if (!object_is_tiled(object, config.surface)) return;
    const object_depth_result& r = out.surface =
        match_object_surface(history(0), left(), object, out.sad_match.disparity_q8, config.stereo,
                             config.rig, config.surface, outlined);
    // Each tile a search of its own (the mean of their positions: they
    // differ only where the left image's border clips one).
    if (r.tiles > 0)
        scope.charge(r.tiles * cycles_of(cost::sad_search_profile(r.tile_width, r.tile_height,
                                                                  r.positions / r.tiles)));
    if (config.stereo.subpixel) scope.charge(r.tiles * cycles_of(cost::subpixel_profile()));
    if (outlined)
        scope.charge(
            cycles_of(cost::surface_outline_profile(r.rows * r.tile_height, r.columns, r.inside)));
    scope.charge(cycles_of(cost::surface_mean_profile(r.inside, r.matched)));
    if (r.valid) out.sad_match.disparity_q8 = r.disparity_q8;
}

// Stage stereo_edge: Sobel on a band of the pattern's rows of both images
// (one extra input row each side for the 3x3), then segment matching. The
// band planes have their own row numbering, so the pattern's rows are shifted
// by the band's first row; columns, and so disparities, are unchanged.
void controller::impl::stereo_edge(box object, frame_output& out) {
    stage_scope scope(*hardware, stage::stereo_edge, out);
    box pattern = object;
    if (pattern.height > band_rows) {  // keep the central rows
        pattern.y += (pattern.height - band_rows) / 2;
        pattern.height = band_rows;
    }
    const int in_y0 = max_int(0, pattern.y - 1);
    const int in_rows = min_int(height, pattern.bottom() + 1) - in_y0;
    // The bands live in f(t-1)'s buffer (memory plan), dead by now: the next
    // pair's Dif(t-1,t) is already in the packed mask.
    uint8_t* band_base = edge_band_storage ? edge_band_storage : right_gray[1 - newest];
    const size_t band_bytes = static_cast<size_t>(width) * static_cast<size_t>(in_rows);
    const gray_plane right_band{band_base, width, in_rows, width};
    const gray_plane left_band{band_base + band_bytes, width, in_rows, width};
    const int out_y0 = pattern.y - in_y0, out_y1 = out_y0 + pattern.height;
    // At the image's top or bottom row the band's edge is the image's edge,
    // where sobel_3x3 also writes 0: the band equals the whole-image Sobel.
    sobel_3x3_rows(history(0).sub(0, in_y0, width, in_rows), out_y0, out_y1, right_band);
    sobel_3x3_rows(left().sub(0, in_y0, width, in_rows), out_y0, out_y1, left_band);
    box band_pattern = pattern;
    band_pattern.y = out_y0;
    out.edge_match =
        stereo_match_edge(right_band.as_const(), left_band.as_const(), band_pattern, config.edge);
    out.edge_at_range_end = at_range_end(out.edge_match, object, config.edge.min_disparity,
                                         config.edge.max_disparity, width);
    scope.charge(
        2 * cycles_of(cost::sobel_profile(width, pattern.height)) +
        cycles_of(cost::edge_match_profile(width, config.edge.lines, config.edge.max_disparity,
                                           config.edge.min_disparity)));
}

bool controller::impl::choose_disparity(frame_output& out) const {
    const bool sad_ok = out.sad_match.valid && !out.sad_at_range_end;
    const bool edge_ok = out.edge_match.valid && !out.edge_at_range_end;
    bool ok = false;
    switch (config.method) {
        case stereo_method::sad:
            ok = sad_ok;
            out.disparity_q8 = out.sad_match.disparity_q8;
            break;
        case stereo_method::edge:
            ok = edge_ok;
            out.disparity_q8 = out.edge_match.disparity_q8;
            break;
        case stereo_method::both:
            ok = sad_ok || edge_ok;
            if (sad_ok && edge_ok) {
                out.disparity_q8 = (out.sad_match.disparity_q8 + out.edge_match.disparity_q8) / 2;
            } else {
                out.disparity_q8 =
                    sad_ok ? out.sad_match.disparity_q8 : out.edge_match.disparity_q8;
            }
            break;
    }
    // A disparity outside the depth range's (in the search margin) is no
    // measurement of an object inside it: withheld. Measured: a ball that
    // the left image's border still cut matched the background at 13.8 px
    // (6.9 m, beyond the 6 m range) against its true 38 px.
    if (!ok || out.disparity_q8 < far_disparity_q8 || out.disparity_q8 > near_disparity_q8)
        return false;
    out.box_left = out.box_right;
    out.box_left.x += (out.disparity_q8 + 128) >> 8;
    if (config.method == stereo_method::sad) out.box_left.y += out.sad_match.dy;
    return true;
}

// Stage xyz: the box centre (Q8, from the exact Q1 centre) and the chosen
// disparity.
void controller::impl::xyz(box object, frame_output& out) {
    stage_scope scope(*hardware, stage::xyz, out);
    out.has_point = triangulate(config.rig, object.center_x2() * 128, object.center_y2() * 128,
                                out.disparity_q8, &out.point);
    scope.charge(cycles_of(cost::triangulate_profile()));
}

}  // namespace dsp
