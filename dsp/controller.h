// The firmware's controller (paper steps 2-6 per stereo pair):
//   DETECT -> TRACK -> LOST -> DETECT
// Each call of process_pair takes one raw Bayer stereo pair, pre-processes
// both images to gray, detects (three-frame differencing on the right image)
// or tracks (SAD), matches the pattern right -> left (SAD and edge
// methods), and triangulates. It charges the modelled cycles of every
// kernel it runs to the HAL, stage by stage.
//
// Firmware rules: all buffers are allocated in init() from the maximum image
// size; process_pair allocates nothing and uses integer arithmetic per pixel.
#pragma once

#include <cstdint>

#include "dsp/bayer_demosaic.h"
#include "dsp/hal.h"
#include "dsp/image.h"
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

enum class stereo_method : uint8_t { sad, edge, both };

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
};

struct frame_output {
    uint32_t frame_index = 0;
    tracker_state state = tracker_state::detect;  // state after this pair
    bool has_object = false;
    box box_right;  // object zone in the right image
    box box_left;   // matched zone in the left image
    stereo_result sad_match;
    stereo_result edge_match;
    bool has_point = false;
    point3_um point;                         // right camera frame, micrometres
    uint64_t stage_cycles[stage_count] = {}; // modelled cycles charged per stage
};

class controller {
public:
    controller() = default;
    ~controller();
    controller(const controller&) = delete;
    controller& operator=(const controller&) = delete;

    void init(const controller_config& config, hal& hardware);

    // One raw Bayer stereo pair (both images the same size, <= the maximum).
    frame_output process_pair(gray_cplane raw_left, gray_cplane raw_right);

    tracker_state state() const { return m_state; }
    // Gray images of the last pair (after brightness compensation).
    gray_cplane gray_left() const;
    gray_cplane gray_right() const;

private:
    struct impl;
    impl* m_impl = nullptr;
    tracker_state m_state = tracker_state::detect;
};

}  // namespace dsp
