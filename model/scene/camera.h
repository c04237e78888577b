// Pinhole cameras and the parallel-axis stereo rig of the daughter card.
//
// Conventions used by the whole scene library (and by dsp/triangulate.h):
// - World frame = the RIGHT camera's frame: X right, Y down, Z forward, in
//   METRES. The right camera's projection centre is the origin; the LEFT
//   camera sits at X = -baseline, axes parallel.
// - Pixel-index coordinates: pixel (i, j) (column i, row j) has its centre
//   at (x, y) = (i, j) and covers [i - 0.5, i + 0.5) x [j - 0.5, j + 0.5).
//   So the centre of a W x H image is ((W - 1) / 2, (H - 1) / 2), e.g.
//   (319.5, 239.5) for VGA, and an intensity centroid computed with pixel
//   indices as coordinates (cv::moments) is in this frame.
// - Projection: x = cx + f (X - Xc) / (Z - Zc), y = cy + f (Y - Yc) / (Z - Zc)
//   with (Xc, Yc, Zc) the camera's centre and f in pixels. A point at depth Z
//   appears in the left image f * baseline / Z columns further RIGHT than in
//   the right image (plus cx_left - cx_right): disparity d = x_left - x_right.
#pragma once

#include <cstdint>

#include "dsp/triangulate.h"
#include "model/scene/geometry.h"

namespace scene {

enum class camera_id : uint8_t { left, right };

struct pinhole_camera {
    double focal_px = 0.0;  // f / pixel pitch
    double cx = 0.0;        // principal point, pixel-index coordinates
    double cy = 0.0;
    int width = 0;
    int height = 0;
    vec3 centre;  // projection centre in the world frame, metres

    // Image point of a world point (which must be in front: Z > centre.z).
    vec2 project(vec3 p) const {
        const double inv_z = 1.0 / (p.z - centre.z);
        return {cx + focal_px * (p.x - centre.x) * inv_z, cy + focal_px * (p.y - centre.y) * inv_z};
    }
    // Direction of the ray through image point (x, y), scaled so its Z is 1.
    vec3 ray_direction(double x, double y) const {
        return {(x - cx) / focal_px, (y - cy) / focal_px, 1.0};
    }
};

struct stereo_rig {
    double baseline_m = 0.120;      // s (docs/design-brief.md default rig)
    double focal_length_m = 0.006;  // 6 mm lenses (docs/design-brief.md default rig)
    double pixel_pitch_m = 7.6e-6;  // OV7620 pixel, 7.6 um (docs/hardware-facts.md section 6)
    int width = 640;                // OV7620 default valid window 640 x 480 (section 6)
    int height = 480;
    // Principal points as offsets from the image centre ((W-1)/2, (H-1)/2),
    // so changing the image size keeps them centred.
    double principal_dx_left = 0.0, principal_dy_left = 0.0;
    double principal_dx_right = 0.0, principal_dy_right = 0.0;

    double focal_px() const { return focal_length_m / pixel_pitch_m; }  // 789.47 px by default
    double cx_left() const { return 0.5 * (width - 1) + principal_dx_left; }
    double cy_left() const { return 0.5 * (height - 1) + principal_dy_left; }
    double cx_right() const { return 0.5 * (width - 1) + principal_dx_right; }
    double cy_right() const { return 0.5 * (height - 1) + principal_dy_right; }

    pinhole_camera left() const;
    pinhole_camera right() const;
    pinhole_camera camera(camera_id id) const { return id == camera_id::left ? left() : right(); }

    // Disparity x_left - x_right of a point at depth z (metres).
    double disparity_px(double z) const {
        return focal_px() * baseline_m / z + (cx_left() - cx_right());
    }
    // Depth of a disparity, the inverse of disparity_px.
    double depth_m(double disparity) const {
        return focal_px() * baseline_m / (disparity - (cx_left() - cx_right()));
    }
};

// The firmware's integer description of the same rig (micrometres, Q8 px).
dsp::camera_rig to_dsp_rig(const stereo_rig& rig);
// A world point in the firmware's units (micrometres, rounded).
dsp::point3_um to_point3_um(vec3 p_m);
// Pixels to Q8 (1/256 px), rounded to nearest.
int32_t to_q8(double px);

}  // namespace scene
