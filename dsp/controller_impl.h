// The controller's private parts, shared by the files that implement it:
// controller.cpp (the pair's flow, preprocessing, the memory plan),
// controller_detect.cpp (DETECT: the detections, the strided pass, the slow
// candidate), controller_track.cpp (TRACK: the SAD box and its refit from
// the frame differences), controller_key.cpp (a slow object's key frame) and
// controller_stereo.cpp (stereo and the 3D point). Not part of the API.
#pragma once

#include "dsp/box_refit.h"
#include "dsp/controller.h"
#include "dsp/depth_line.h"
#include "dsp/detection_steps.h"
#include "dsp/extent_window.h"
#include "dsp/int_bounds.h"
#include "dsp/kernel_costs.h"
#include "dsp/key_frame.h"
#include "dsp/part_growth.h"
#include "dsp/size_at_depth.h"
#include "dsp/sobel.h"
#include "dsp/stereo_reach.h"
#include "dsp/stride_history.h"

namespace dsp {
namespace controller_parts {

constexpr int history_frames = 3;  // paper eq. 2-4 needs f(t-2), f(t-1), f(t)
// Pairs a slow detection waits for its object to move key_frame::min_shift
// px: slower than 0.4 px per frame it is taken as still.
constexpr int max_candidate_pairs = 10;
// Pairs a track's box stays within min_shift px, with no difference
// around it, before it is still (yields_to_mover): under 0.2 px a pair,
// half the slowest object DETECT starts. With max_candidate_pairs a ball
// at 0.45 px a frame, its box lagging it, was taken as still.
constexpr int still_track_pairs = 2 * max_candidate_pairs;

// `b` within `step` px of `a` on both axes.
inline bool moved_at_most(box a, box b, int step) {
    return b.x - a.x <= step && a.x - b.x <= step && b.y - a.y <= step && a.y - b.y <= step;
}

// How far apart two boxes' centres are on each axis, in half pixels.
struct centre_gap {
    int x2, y2;
};
inline centre_gap centre_offset2(box a, box b) {
    const int x2 = a.center_x2() - b.center_x2(), y2 = a.center_y2() - b.center_y2();
    return centre_gap{max_int(x2, -x2), max_int(y2, -y2)};
}

inline bool same_box(box a, box b) {
    return a.x == b.x && a.y == b.y && a.width == b.width && a.height == b.height;
}

inline bool same_size(box a, box b) {
    return a.width == b.width && a.height == b.height;
}

inline box from_spans(span x, span y) {
    return box{x.start, y.start, x.size, y.size};
}
inline span x_span(box b) {
    return span{b.x, b.width};
}
inline span y_span(box b) {
    return span{b.y, b.height};
}

inline box intersection(box a, box b) {
    const int x0 = max_int(a.x, b.x), y0 = max_int(a.y, b.y);
    const int x1 = min_int(a.right(), b.right()), y1 = min_int(a.bottom(), b.bottom());
    if (x1 <= x0 || y1 <= y0) return box{};
    return box{x0, y0, x1 - x0, y1 - y0};
}

inline bool near_size(int measured, int size, int tolerance) {
    return measured >= size - tolerance && measured <= size + tolerance;
}

inline bool covers(span outer, span inner) {
    return outer.start <= inner.start + 1 && outer.end() >= inner.end() - 1;
}

inline box shifted(box b, int dx, int dy) {
    return box{b.x + dx, b.y + dy, b.width, b.height};
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

}  // namespace controller_parts

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
    uint8_t* refit_rows = nullptr;   // a row of Dif(t-2,t-1) and of Dif(t-1,t): TRACK's region
    motion_blocks later_blocks;      // block groups of Dif(t-1,t); Dif(t-2,t-1)'s: the detector's
    uint8_t* edge_band_storage = nullptr;  // own Sobel bands, or null: inside f(t-1)
    int band_rows = 0;

    motion_detector detector;
    sad_tracker tracker;
    key_frame key;          // a slow object's older frame (dsp/key_frame.h), SDRAM
    stride_history stride;  // DETECT: frames a stride apart (dsp/stride_history.h), in left_gray
    bool slow_candidate = false;      // DETECT: a slow object's key, waiting for its outline
    detection_steps detection_edges;  // DETECT: the last pairs' detections (moving, SAD still)
    int candidate_pairs = 0;          // pairs the candidate has waited
    // What Dif(key, t) has said of the key's box on one axis (key_axis_shift).
    struct key_axis {
        bool unfit = false;      // the key's box did not outline the object there
        bool has_first = false;  // `first` holds the object's outline there
        // Dif(key, t)'s extent at the key's first pair (a key of the outline's:
        // at its first pair that held the key's box there, first_outline)
        span first;
        int last = 0;  // the displacement read on the last pair
    };
    key_axis key_x, key_y;
    bool key_first_seen = false;   // Dif(key, t) found since the key was taken
    char outline_key_across = 0;   // a key of the outline: 'x' or 'y' across the motion, 0 unknown
    int outline_key_drift = 0;     // which way its silhouette drifted across (judge_across)
    bool box_may_be_part = false;  // a detection's box no silhouette of its size has confirmed
    // The box's size is a key's outline (follow_slow_object) and the object
    // has not moved fast since in this track: where the differences do not
    // give object(t), a size their extent reads shorter is a rim they missed
    // (pull_box).
    bool size_from_key = false;
    extent_window recent_extents;  // Dif(t-1,t)'s extents of this track's last pairs
    // The object's size carried with its depth (dsp/size_at_depth.h): the
    // latest pair's disparity (Q8, 0 none yet in this track), the one the
    // tracker's box stands for, and the one the key's box stood for when taken.
    int64_t measured_disparity_q8 = 0, sized_disparity_q8 = 0;
    int64_t key_sized_q8 = 0;
    depth_line reported_depth;  // the track's last depths: a wrong match reported at their line

    // Disparities (Q8) of the depth range's ends, without the search margin.
    int64_t far_disparity_q8 = 0, near_disparity_q8 = 0;
    int width = 0, height = 0;  // size of the pairs in the history
    int newest = 1;             // right_gray[newest] = f(t)
    int frames_in_history = 0;  // right frames seen, at most 3
    int lost_pairs = 0;
    // TRACK: pairs the box has been still, and where it was on the first (yields_to_mover)
    int still_pairs = 0;
    box still_anchor;
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
        bool sad_slow = false;       // the SAD pattern moved at most key_frame::max_step px
        bool confirmed = false;      // a silhouette within an eighth of the SAD box
        bool outlined = false;       // the box followed a silhouette (follow_object)
        bool outline_slow = false;   // whose centre moved at most key_frame::max_step px
        bool window_moving = false;  // the extent window read a motion (follow_reading)
        bool no_difference = false;  // neither difference held the object around the box
        bool depth_resized = false;  // the depth moved a side of the box more than max_step px
    };
    bool track_object(uint64_t* cycles, sdram_traffic* traffic, track_motion* seen);
    bool yields_to_mover(bool no_difference, uint64_t* cycles);
    void follow_slow_object(track_motion seen, uint64_t* cycles, sdram_traffic* traffic);
    void follow_outline_key(track_motion seen, uint64_t* cycles, sdram_traffic* traffic);
    span first_outline(key_axis& axis, span both, span key_box);
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
    bool outline_shift(const block_group& moved, int* dx, int* dy) const;
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
    // What the two frame differences say around the last box (dsp/box_refit.h):
    // before (in DETECT object(t-1)), after and previous as difference_extents
    // (dsp/part_growth.h) has them.
    struct motion_extents : difference_extents {
        bool found = false;  // both differences hold enough pixels and share a box
        box both;            // Dif(t-1,t)'s extent: object(t-1) and object(t)
    };
    motion_extents measure_motion(box last, const box* detected, uint64_t* cycles,
                                  sdram_traffic* traffic);
    // What follow_object read beside the box: the axes fitted to the extent
    // window (each charged), and whether the window's median step reads a
    // motion of min_shift px a pair or more on an axis.
    struct follow_reading {
        int fitted_axes = 0;
        int edge_axes = 0;  // axes whose fading rim was read (fading_rim_step2)
        bool window_moving = false;
        bool round_read = false;  // a part's common part tested for a sphere's shape (is_round)
    };
    // The trailing edge's step per axis where a leading rim fades, in half
    // pixels (0: none), and how many axes were read.
    struct fading_rims {
        int x2 = 0, y2 = 0, read_axes = 0;
    };
    fading_rims read_fading_rims(bool fast, bool part_x, bool part_y, box last) const;
    bool follow_object(const motion_extents& motion, box last, bool may_be_part, bool keyed,
                       box* followed, follow_reading* reading = nullptr) const;
    int fit_to_window(bool fit_x, bool fit_y, int size_x, int size_y, box last, span* object_x,
                      span* object_y) const;
    box pull_box(const motion_extents& motion, box last, box found, bool hold_size) const;
    void stereo_sad(box object, bool outlined, frame_output& out);
    uint64_t match_core(box object, frame_output& out, int* core_pixels);
    uint64_t rematch_core(box moved_in, frame_output& out, int* core_pixels);
    uint64_t match_surface(box object, bool outlined, frame_output& out);
    // core_pixels: the pixels of the box's core, whose SAD match `out` holds.
    uint64_t read_short_of(int core_pixels, const frame_output& out, stereo_reach* short_sides,
                           stereo_reach* short_ends);
    uint64_t widen_to_stereo_reach(int core_pixels, const stereo_reach& short_sides,
                                   const stereo_reach& short_ends, frame_output& out);
    uint64_t reach_cycles(const stereo_reach& reach, bool rows) const;
    box moved_box(box b, const stereo_reach& sides, const stereo_reach& ends,
                  const stereo_reach& short_sides, const stereo_reach& short_ends) const;
    void stereo_edge(box object, frame_output& out);
    bool choose_disparity(frame_output& out) const;
    void xyz(box object, frame_output& out);
};

}  // namespace dsp
