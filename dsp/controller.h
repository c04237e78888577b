// The firmware's controller (paper steps 2-6 per stereo pair):
//   DETECT -> TRACK -> LOST -> DETECT
// Each call of process_pair takes one raw Bayer stereo pair, pre-processes
// both images to gray, detects (three-frame differencing on the right image)
// or tracks (SAD), matches the pattern right -> left (SAD and edge
// methods), and triangulates. It charges the modelled cycles of every
// kernel it runs to the HAL, stage by stage.
//
// Per pair, by state at the start of the pair:
//   all states: preprocess both images (stage preprocess; in a DETECT pair
//     while the strided history below holds the left buffer, the left image
//     only once the pair has an object, in a second preprocess entry after
//     stage detect: it is needed only for stereo). The right gray
//     image goes into the older of the two right gray buffers (f(t-2)'s
//     place: the buffers swap roles, no copy). f(t-2) itself is not kept:
//     eq. 4 needs it only through Dif(t-2,t-1), which the previous pair left
//     as a bit-packed mask. Every pair, whatever the state, replaces that
//     mask by Dif(t-1,t) for the next pair (DETECT fuses it into its
//     three-frame pass, TRACK runs it after the refit, LOST and the second
//     pair of a history in stage preprocess), so the history stays
//     consecutive.
//   DETECT: with three frames in the history, three-frame differencing
//     (f(t-1), f(t) and the packed Dif(t-2,t-1); identical to the formula on
//     three full frames, tests/dsp/test_memory_plan.cpp)
//     gives object(t-1), the object in the MIDDLE frame (paper eq. 4). It is
//     turned into the current frame's pattern by starting the SAD tracker on
//     the middle frame at the detected box and letting it find that pattern
//     in the newest frame (a SAD search of track.search_radius around it,
//     centred where Dif(t-1,t) reaches past object(t-1), as in TRACK).
//     Both are charged to stage detect. Success -> TRACK on this very pair.
//     A zone touching the image border (within close_passes + 1 px) is not
//     started: an object entering the view is taken once wholly inside.
//     When one pair's differences find nothing, the same three-frame pass
//     runs every 4 pairs on frames 4 pairs apart (dsp/stride_history.h: an
//     object at 0.5-1 px per frame that one pair's miss), kept in the left
//     gray buffer; what it finds is keyed as a slow candidate.
//   TRACK: the two differences around the LAST box (where the object was
//     at t-1) give object(t-1) and, where Dif(t-1,t) reaches past it,
//     object(t) (dsp/box_refit.h); the SAD search (paper eq. 5) on the
//     newest right frame is centred there and the box is object(t)'s. When
//     the differences give no object (it nearly stopped, a light change),
//     the SAD box is kept, its size and centre pulled towards object(t-1)
//     by at most max(1, larger of box and mask / 8) px per frame (stage
//     track). Lost (SAD's rule, without a silhouette) -> LOST. A slow
//     object's box (the SAD moved at most 2 px and a silhouette confirmed
//     it) is then taken from a key frame (dsp/key_frame.h): the key's
//     pattern's displacement since, and once it is 4 px, Dif(key, t)'s
//     extent, which one pair's thin differences miss across the motion.
//     A still track (no difference around its box, which moved under 4 px,
//     for 20 pairs) ends -> LOST on a pair whose Dif(t-1,t) holds a moving
//     object away from it: an object that vanished mid-view, or stopped,
//     gives way to one that moves.
//   LOST: nothing but preprocess; after lost_frames_to_detect pairs in LOST
//     the state becomes DETECT (so the three-frame history no longer holds
//     the frames the track was lost in).
//   Whenever an object box is known after the above: stereo_match_sad of
//   the box's core (less 1/7 of each side: a round object's box corners are
//   background) into the left image, and for a box wider or taller than
//   96 px its tiles' mean depth around the core's disparity
//   (dsp/object_depth.h) (stage stereo_sad); Sobel on a band of
//   the box's rows of both images + stereo_match_edge of the whole box
//   (stage stereo_edge); a minimum on an end of the disparity range searched
//   is rejected; triangulation of the box centre with the chosen method's
//   disparity (stage xyz).
// Stage capture is not the controller's: the platform's capture path
// charges it.
//
// Costs: the sum of the modelled cycles of the kernels each stage runs
// (dsp/kernel_costs.h), charged once per stage and pair, with the SDRAM
// bytes of their streams (hal::charge_with_traffic). Figures: docs/firmware.md.
//
// Firmware rules: all buffers are allocated in init() from the maximum image
// size; process_pair allocates nothing and uses integer arithmetic per pixel.
//
// Memory plan (docs/design-brief.md "DSP memory"; L2 = 1 MB, docs/hardware-facts.md section
// 1). The raw Bayer pairs stay in SDRAM where the EDMA writes them; the
// preprocess reads each raw byte once (line by line: three raw rows -> one
// RGB row -> one gray row, the rows stay in L1D). Everything else is in L2:
//
//   buffer                                  bytes              VGA (640 x 480)
//   right gray f(t), f(t-1)                 2 W H                  614,400
//   left gray (DETECT: the strided history) W H                    307,200
//   packed Dif(t-2,t-1)                     W H / 8                 38,400
//   demosaic line (one RGB row)             3 W                      1,920
//   detector: 8 pass rings + 1 row, 2 label motion_detector::       37,880
//     rows, 256-label tables, block stats     workspace_bytes
//   tracker pattern                         max_size^2               9,216
//   refit: 2 mask rows, Dif(t-1,t) blocks   2 max(W, H) + 5,496      6,776
//   Sobel bands 2 W (max_size + 2)          inside f(t-1)'s buffer       0
//                                           (dead by stereo_edge)  (125,440)
//   total                                                        1,015,792
// of 1,048,576: 32,784 bytes (3.1 %) left for code, stack and the control
// program's few words; 16 if 32 KB of the L2 is configured as cache for
// the raw reads (plan_memory computes it; tests/dsp/test_memory_plan.cpp
// checks it). SDRAM per pair: the raw pair, 2 W H = 614,400 bytes read =
// 4,800 L2 lines of 128 bytes, nothing else frame-scale. A slow object's
// key (dsp/key_frame.h: its region less a hole inside the object, then its
// pattern; at most W H + max_size^2 bytes) is in SDRAM too: written when a
// key is taken, read (the ring and the pattern) each pair while it is used.
#pragma once

#include <cstdint>

#include "dsp/bayer_demosaic.h"
#include "dsp/hal.h"
#include "dsp/image.h"
#include "dsp/kernel_costs.h"
#include "dsp/motion_detect.h"
#include "dsp/object_depth.h"
#include "dsp/preprocess.h"
#include "dsp/stage.h"
#include "dsp/stereo_edge.h"
#include "dsp/stereo_sad.h"
#include "dsp/tracker.h"
#include "dsp/triangulate.h"

namespace dsp {

enum class tracker_state : uint8_t { detect, track, lost };
const char* tracker_state_name(tracker_state s);

// Which disparity gives the 3D point. Both matchers always run (the paper
// compares them); `both` uses the mean of the two when both are valid, else
// whichever is valid.
enum class stereo_method : uint8_t { sad, edge, both };
const char* stereo_method_name(stereo_method m);

struct controller_config {
    int max_width = 640;
    int max_height = 480;
    cfa_order cfa = cfa_order::bggr;
    brightness_params brightness;
    detect_params detect;
    track_params track;
    stereo_params stereo;
    object_depth_params surface;  // a large object's depth from tiles (dsp/object_depth.h)
    edge_params edge;
    stereo_method method = stereo_method::sad;  // which result gives the 3D point
    camera_rig rig;
    int lost_frames_to_detect = 1;  // frames in LOST before detection restarts

    // Disparity search range. When disparity_from_rig is set, init() replaces
    // the min/max disparity of `stereo` and `edge` by the disparities of the
    // depth range [min_depth_mm, max_depth_mm] on `rig`, widened by
    // disparity_margin_px each way (room for the sub-pixel parabola).
    bool disparity_from_rig = true;
    int32_t min_depth_mm = 800;
    int32_t max_depth_mm = 6000;
    int disparity_margin_px = 2;

    // Labels the motion detector can hand out per mask (its union-find
    // tables are part of the L2 plan).
    int max_motion_labels = 256;

    // For the cost model: where the gray frames and the packed mask live
    // (frame_memory: L2 in the plan above; sdram charges every gray-frame
    // pass as SDRAM traffic, what the plan would cost if they did not fit)
    // and where the raw pairs are (the EDMA writes them to SDRAM).
    cost::memory frame_memory = cost::memory::l2;
    cost::memory raw_memory = cost::memory::sdram;
};

// The buffers of the memory plan above for a configuration, in bytes (what
// init() allocates; the raw pair is the control program's, in SDRAM).
struct memory_plan {
    size_t right_gray = 0;           // f(t) and f(t-1)
    size_t left_gray = 0;            // the current left frame
    size_t motion_mask = 0;          // packed Dif(t-2,t-1)
    size_t line_scratch = 0;         // one demosaiced RGB row
    size_t detector = 0;             // motion_detector::workspace_bytes (no kept mask)
    size_t tracker = 0;              // the SAD pattern
    size_t refit = 0;                // object(t-1) row + projections of the refit region
    size_t edge_bands = 0;           // own Sobel bands (0 when they overlay f(t-1))
    size_t edge_bands_overlaid = 0;  // band bytes placed inside f(t-1)'s buffer
    size_t raw_pair_sdram = 0;       // one raw Bayer pair, in SDRAM: 2 W H
    size_t key_sdram = 0;            // a slow object's key (dsp/key_frame.h), SDRAM

    size_t l2_bytes() const {
        return right_gray + left_gray + motion_mask + line_scratch + detector + tracker + refit +
               edge_bands;
    }
};
memory_plan plan_memory(const controller_config& config);
constexpr size_t c6416_l2_bytes = 1'048'576;  // docs/hardware-facts.md section 1

struct frame_output {
    uint32_t frame_index = 0;
    bool accepted = true;  // false: the pair's size was not usable; nothing ran
    tracker_state state = tracker_state::detect;  // state after this pair
    // Stage detect found a moving zone (the detector's largest component) ...
    bool motion_found = false;
    box motion_box;
    // ... and it started the track on this pair, or it was not started
    // because it touched the image border.
    bool detected = false;
    bool detection_at_border = false;
    bool has_object = false;
    box box_right;            // object zone in the right image
    box box_left;             // matched zone in the left image (from the chosen disparity)
    stereo_result sad_match;  // the core's match; its disparity the tiles' when they matched
    object_depth_result surface;
    stereo_result edge_match;
    // The minimum sat on an end of the disparity range searched (the range's
    // own ends, or where the left image's border cut it): not used.
    bool sad_at_range_end = false;
    bool edge_at_range_end = false;
    int32_t disparity_q8 = 0;  // the disparity the point was triangulated from
    // ... the line of the track's last depths, not the match's: no motion of
    // the ball reaches the match's (a wrong match, dsp/depth_line.h).
    bool depth_from_line = false;
    bool has_point = false;
    point3_um point;         // right camera frame, micrometres
    uint16_t gain_q8 = 256;  // brightness compensation, both images (the right one's mean)
    uint64_t stage_cycles[stage_count] = {};  // modelled cycles charged per stage
};

class controller {
  public:
    controller() = default;
    ~controller();
    controller(const controller&) = delete;
    controller& operator=(const controller&) = delete;

    // Allocates every buffer of the memory plan (plan_memory). May be called
    // again to re-initialise.
    void init(const controller_config& config, hal& hardware);

    // One raw Bayer stereo pair (both images the same size, <= the maximum,
    // even width and height >= 4; otherwise the pair is not accepted).
    frame_output process_pair(gray_cplane raw_left, gray_cplane raw_right);

    tracker_state state() const { return m_state; }
    // Gray images of the last pair (after brightness compensation).
    gray_cplane gray_left() const;
    gray_cplane gray_right() const;
    // The configuration in use (with the disparity range init() derived).
    const controller_config& config() const;
    // The packed difference mask after the last pair: Dif(t-1,t) of the two
    // newest right frames once two are in the history (dsp/motion_detect.h
    // layout, width of the pairs); for tests.
    const uint8_t* motion_mask() const;

  private:
    struct impl;
    impl* m_impl = nullptr;
    tracker_state m_state = tracker_state::detect;
};

}  // namespace dsp
