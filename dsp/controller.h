// The firmware's controller (paper steps 2-6 per stereo pair):
//   DETECT -> TRACK -> LOST -> DETECT
// Each call of process_pair takes one raw Bayer stereo pair, pre-processes
// both images to gray, detects (three-frame differencing on the right image)
// or tracks (SAD), matches the pattern right -> left (SAD and edge
// methods), and triangulates. It charges the modelled cycles of every
// kernel it runs to the HAL, stage by stage.
//
// Per pair, by state at the start of the pair:
//   all states: preprocess both images (stage preprocess). The right gray
//     image goes straight into a ring of three history frames (no copy), so
//     the history stays consecutive whatever the state.
//   DETECT: with three frames in the history, three-frame differencing
//     gives object(t-1), the object in the MIDDLE frame (paper eq. 4). It is
//     turned into the current frame's pattern by starting the SAD tracker on
//     the middle frame at the detected box and letting it find that pattern
//     in the newest frame (a SAD search of track.search_radius around it).
//     Both are charged to stage detect. Success -> TRACK on this very pair.
//     A zone touching the image border (within close_passes + 1 px) is not
//     started: an object entering the view is taken once wholly inside.
//   TRACK: sad_tracker.update on the newest right frame (position only),
//     then the box's size and centre are refitted to object(t-1): the
//     three-frame mask around the LAST box (where the object was at t-1),
//     not around the new one as sad_tracker's own size rule would look;
//     size and centre move by at most max(1, larger of box and mask / 8) px
//     per frame; the centre pull stops the drift of re-taking the pattern at
//     integer positions (stage track). Lost -> LOST.
//   LOST: nothing but preprocess; after lost_frames_to_detect pairs in LOST
//     the state becomes DETECT (so the three-frame history no longer holds
//     the frames the track was lost in).
//   Whenever an object box is known after the above: stereo_match_sad of
//   the box's core (less 1/8 of each side: a round object's box corners are
//   background) into the left image (stage stereo_sad); Sobel on a band of
//   the box's rows of both images + stereo_match_edge of the whole box
//   (stage stereo_edge); a minimum on an end of the disparity range searched
//   is rejected; triangulation of the box centre with the chosen method's
//   disparity (stage xyz).
// Stage capture is not the controller's: the platform's capture path
// charges it.
//
// Costs: the sum of the modelled cycles of the kernels each stage runs
// (dsp/kernel_costs.h), charged once per stage and pair. With cost model
// c64x-op-model-v1 at 600 MHz on VGA pairs (tb/host demo, default scenario):
// preprocess 9.56 ms (two frames, SDRAM), detect up to 5.8 ms (full-frame
// differencing, morphology, labelling), track <= 1.9 ms, stereo_sad
// <= 0.15 ms, stereo_edge <= 0.64 ms, xyz ~300 cycles; largest pair 16 ms.
//
// Firmware rules: all buffers are allocated in init() from the maximum image
// size; process_pair allocates nothing and uses integer arithmetic per pixel.
// Memory: four gray frames (3 right history + left) of VGA are 1.2 MB, more
// than the C6416's 1 MB L2 (hardware-facts.md section 1), so frame-scale
// passes are charged as SDRAM passes by default (config.frame_memory).
#pragma once

#include <cstdint>

#include "dsp/bayer_demosaic.h"
#include "dsp/hal.h"
#include "dsp/image.h"
#include "dsp/kernel_costs.h"
#include "dsp/motion_detect.h"
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

    // Where the frame-scale buffers live, for the cost model (see above).
    cost::memory frame_memory = cost::memory::sdram;
};

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
    box box_right;  // object zone in the right image
    box box_left;   // matched zone in the left image (from the chosen disparity)
    stereo_result sad_match;
    stereo_result edge_match;
    // The minimum sat on an end of the disparity range searched (the range's
    // own ends, or where the left image's border cut it): not used.
    bool sad_at_range_end = false;
    bool edge_at_range_end = false;
    int32_t disparity_q8 = 0;  // the disparity the point was triangulated from
    bool has_point = false;
    point3_um point;              // right camera frame, micrometres
    uint16_t gain_q8_left = 256;  // brightness compensation gains
    uint16_t gain_q8_right = 256;
    uint64_t stage_cycles[stage_count] = {};  // modelled cycles charged per stage
};

class controller {
  public:
    controller() = default;
    ~controller();
    controller(const controller&) = delete;
    controller& operator=(const controller&) = delete;

    // Allocates every buffer (gray history, left gray, line scratch, Sobel
    // bands, detector, tracker). May be called again to re-initialise.
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

  private:
    struct impl;
    impl* m_impl = nullptr;
    tracker_state m_state = tracker_state::detect;
};

}  // namespace dsp
