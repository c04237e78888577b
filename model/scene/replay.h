// Scene replay: left/right image sequences from PNG files, described by a
// small manifest, fed to the sensors instead of the renderer
// (model/sensor/scene_sources.h adapts it to sensor::frame_source).
//
// Manifest: plain text, one "key value..." per line, '#' starts a comment.
// Paths are relative to the manifest's folder (or absolute).
//
//   stereosim_replay 1                # format and version: first line, required
//   size 640 480                      # image size, required
//   frames 12                         # number of frames, required
//   left  left/frame_%04d.png         # file pattern per camera, required: one
//   right right/frame_%04d.png        #   %d or %0Nd, replaced by the number, or
//                                     #   none: that one file for every frame
//   first_number 0                    # number of frame 0's files (default 0)
//   focal_px 789.5                    # calibration, required
//   baseline_m 0.12
//   principal_left 319.5 239.5        # principal points, pixel-index coordinates
//   principal_right 319.5 239.5
//   after_last error                  # frame index >= frames: error | hold | loop
//   truth truth.csv                   # optional ground truth
//
// Ground-truth CSV: a header row of column names, one of them "frame" (the
// frame index 0 .. frames-1), then one row of numbers per frame listed.
// The moving object's truth, every column optional (docs/replay.md):
//   x_mm,y_mm,z_mm        the object's reference point (e.g. a ball's centre)
//                         in the RIGHT camera's frame, mm: X right, Y down, Z
//                         forward (model/scene/camera.h); the three together
//   u_right_px,v_right_px that point's pixel in the right image (pixel-index
//                         coordinates); the two together; without them the
//                         point is projected with the right camera
//   z_visible_mm          depth of the visible surface, mm: scored instead of
//                         z_mm where present (a stereo match sees the surface)
// A frame is scored in 3D with x/y/z, by its box centre with u/v or x/y/z.
// Unknown columns are kept and ignored. A frame with no row has no truth.
//
// Errors (std::runtime_error, naming the file and line): unreadable or
// malformed manifest (unknown or repeated key, missing key, bad number, bad
// pattern), a missing image file, an image whose size is not the manifest's,
// a manifest size that is not the one expected (the sensor profile's active
// size), a malformed CSV. Every image's header is checked at load; pixels are
// decoded on demand, one frame per camera cached.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "model/scene/camera.h"
#include "model/scene/images.h"
#include "model/scene/sequence.h"

namespace scene {

struct replay_calibration {
    double focal_px = 0.0;
    double baseline_m = 0.0;
    double cx_left = 0.0, cy_left = 0.0;
    double cx_right = 0.0, cy_right = 0.0;
};

struct replay_truth {
    std::vector<std::string> columns;         // as in the header, "frame" included
    std::map<int, std::vector<double>> rows;  // frame -> values, in column order

    // Value of a column for a frame; throws std::out_of_range if either is absent.
    double value(int frame, const std::string& column) const;
};

// A frame's object truth from the CSV, as the scoring of a rendered ball
// wants it (ball.centre_m, visible_mean_depth_m, right.ellipse_centre,
// disparity_visible_px); has_point: x/y/z given (3D scored), has_pixel: the
// right image point known (box centre scored).
struct replay_object_truth {
    bool has_point = false;
    bool has_pixel = false;
    ball_truth ball;
};

class replay {
  public:
    enum class after_last_policy { error, hold, loop };

    // expected_width/height: the size the consumer needs (e.g. the sensor
    // profile's active size); 0 = accept the manifest's.
    explicit replay(const std::string& manifest_path, int expected_width = 0,
                    int expected_height = 0);

    int width() const { return m_width; }
    int height() const { return m_height; }
    int frame_count() const { return m_frames; }
    const replay_calibration& calibration() const { return m_calibration; }
    // A pinhole camera per side from the calibration; the world frame is the
    // right camera's (model/scene/camera.h), the left camera at X = -baseline.
    pinhole_camera camera(camera_id id) const;
    bool has_truth() const { return !m_truth.columns.empty(); }
    const replay_truth& truth() const { return m_truth; }
    // The object's truth at `frame`; false if the frame has no row or the
    // CSV names neither x/y/z nor u/v.
    bool object_truth(int frame, replay_object_truth* out) const;

    // File of a camera's frame (after the after_last policy).
    std::string path(camera_id id, uint64_t index) const;
    // The frame's pixels, exactly the file's (gray files replicated to RGB).
    // The reference stays valid until the next call for the same camera.
    const rgb_image& frame(camera_id id, uint64_t index);

  private:
    int resolve_index(uint64_t index) const;

    std::string m_manifest_path;
    int m_width = 0;
    int m_height = 0;
    int m_frames = 0;
    int m_first_number = 0;
    // A file pattern split at its %d / %0Nd, resolved against the manifest folder.
    struct name_pattern {
        std::string prefix, suffix;
        int zero_pad = 0;    // digits, 0 = none
        bool fixed = false;  // no %d: the same file for every frame
        std::string format(int number) const;
    };

    name_pattern m_pattern[2];  // [camera_id]
    friend bool replay_file_name(const std::string&, int, std::string*);
    replay_calibration m_calibration;
    after_last_policy m_after_last = after_last_policy::error;
    replay_truth m_truth;

    rgb_image m_cache[2];
    int m_cached_index[2] = {-1, -1};
};

// The file a manifest's pattern names for `number` (the pattern itself when
// it has no %), as a replay reads it; false if the pattern is no valid one.
bool replay_file_name(const std::string& pattern, int number, std::string* name);

}  // namespace scene
