// Triangulation (dsp/triangulate.h) against the closed-form pinhole model in
// double: points are projected into both cameras of the rig, quantised to Q8
// as the matcher reports them, and back-projected.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "dsp/triangulate.h"

namespace {

int32_t to_q8(double px) {
    return static_cast<int32_t>(std::lround(px * 256.0));
}

struct errors {
    double worst_depth_rel = 0.0;    // |Z - Z_true| / Z_true
    double worst_lateral_rel = 0.0;  // max(|X - X_true|, |Y - Y_true|) / Z_true
    double worst_arith_um = 0.0;     // vs the closed form evaluated on the Q8 inputs
    int points = 0;
};

// Points at depths 1..3 m spread over the right image (and visible in the
// left one), projected with the true focal length f / pitch in double.
errors sweep(const dsp::camera_rig& rig, int width, int height) {
    errors e;
    const double f_px = static_cast<double>(rig.focal_length_um) * 1000.0 / rig.pixel_pitch_nm;
    const double s = rig.baseline_um;
    const double cxl = rig.cx_left_q8 / 256.0, cxr = rig.cx_right_q8 / 256.0;
    const double cyr = rig.cy_right_q8 / 256.0;
    const double f_q8 = static_cast<double>(rig.focal_px_q8());
    for (double z_m = 1.0; z_m <= 3.0001; z_m += 0.125) {
        const double z = z_m * 1e6;  // um
        const double disparity_true = f_px * s / z + (cxl - cxr);
        for (double u = 4.0; u < width - 4.0 - disparity_true; u += 37.3) {
            for (double v = 4.0; v < height - 4.0; v += 29.1) {
                const double x = (u - cxr) * z / f_px;
                const double y = (v - cyr) * z / f_px;
                // Projection: right camera at the origin, left camera at X = -s.
                const double u_right = cxr + f_px * x / z;
                const double v_right = cyr + f_px * y / z;
                const double u_left = cxl + f_px * (x + s) / z;
                const int32_t xq = to_q8(u_right), yq = to_q8(v_right);
                const int32_t dq = to_q8(u_left - u_right);

                dsp::point3_um p;
                EXPECT_TRUE(dsp::triangulate(rig, xq, yq, dq, &p));
                e.worst_depth_rel = std::fmax(e.worst_depth_rel, std::fabs(p.z - z) / z);
                e.worst_lateral_rel = std::fmax(
                    e.worst_lateral_rel, std::fmax(std::fabs(p.x - x), std::fabs(p.y - y)) / z);

                // The same formula on the same quantised inputs, in double.
                const double den = dq - (rig.cx_left_q8 - rig.cx_right_q8);
                const double zc = s * f_q8 / den;
                const double xc = s * (xq - rig.cx_right_q8) / den;
                const double yc = s * (yq - rig.cy_right_q8) / den;
                e.worst_arith_um =
                    std::fmax(e.worst_arith_um,
                              std::fmax(std::fabs(p.z - zc),
                                        std::fmax(std::fabs(p.x - xc), std::fabs(p.y - yc))));
                ++e.points;
            }
        }
    }
    return e;
}

TEST(triangulate, default_rig_focal_length_in_pixels) {
    const dsp::camera_rig rig;
    // 6 mm / 7.6 um = 789.4737 px; * 256 = 202105.26 -> 202105.
    EXPECT_EQ(rig.focal_px_q8(), 202105);
}

TEST(triangulate, default_rig_matches_the_pinhole_model_from_1_to_3_m) {
    const dsp::camera_rig rig;  // f 789.47 px, s 120 mm, principal points (319.5, 239.5)
    const errors e = sweep(rig, 640, 480);
    std::printf(
        "default rig: %d points, worst depth error %.5f%% of depth, worst X/Y error "
        "%.5f%% of depth, worst deviation from the closed form on Q8 inputs %.2f um\n",
        e.points, 100.0 * e.worst_depth_rel, 100.0 * e.worst_lateral_rel, e.worst_arith_um);
    EXPECT_GT(e.points, 500);
    EXPECT_LT(e.worst_depth_rel, 1e-3);
    EXPECT_LT(e.worst_lateral_rel, 1e-3);
    EXPECT_LE(e.worst_arith_um, 0.5 + 1e-6);  // one rounding to nearest um
}

// A rig unlike the default one: 95 mm, 4.8 mm lenses, 5.6 um pixels,
// principal points off centre (dcx = 21.5 px).
dsp::camera_rig offset_rig() {
    dsp::camera_rig rig;
    rig.baseline_um = 95000;
    rig.focal_length_um = 4800;
    rig.pixel_pitch_nm = 5600;
    rig.cx_left_q8 = to_q8(331.25);
    rig.cx_right_q8 = to_q8(309.75);
    rig.cy_left_q8 = to_q8(244.0);
    rig.cy_right_q8 = to_q8(236.5);
    return rig;
}

TEST(triangulate, rig_with_offset_principal_points) {
    const dsp::camera_rig rig = offset_rig();
    const errors e = sweep(rig, 640, 480);
    std::printf(
        "offset rig (dcx 21.5 px): %d points, worst depth error %.5f%%, worst X/Y "
        "%.5f%% of depth, worst vs closed form %.2f um\n",
        e.points, 100.0 * e.worst_depth_rel, 100.0 * e.worst_lateral_rel, e.worst_arith_um);
    EXPECT_LT(e.worst_depth_rel, 1e-3);
    EXPECT_LT(e.worst_lateral_rel, 1e-3);
    EXPECT_LE(e.worst_arith_um, 0.5 + 1e-6);
}

TEST(triangulate, disparity_at_or_below_the_principal_point_offset_gives_false) {
    dsp::camera_rig rig;
    rig.cx_left_q8 = to_q8(325.0);
    rig.cx_right_q8 = to_q8(315.0);  // dcx = 10 px
    dsp::point3_um p{1, 2, 3};
    EXPECT_FALSE(dsp::triangulate(rig, to_q8(320), to_q8(240), to_q8(10.0), &p));
    EXPECT_FALSE(dsp::triangulate(rig, to_q8(320), to_q8(240), to_q8(9.5), &p));
    EXPECT_FALSE(dsp::triangulate(rig, to_q8(320), to_q8(240), -to_q8(4.0), &p));
    EXPECT_EQ(p.x, 1);  // untouched on failure
    EXPECT_EQ(p.y, 2);
    EXPECT_EQ(p.z, 3);
    // 1/256 px past dcx is ~24 km away: does not fit 32-bit micrometres.
    EXPECT_FALSE(dsp::triangulate(rig, to_q8(320), to_q8(240), to_q8(10.0) + 1, &p));
    // Half a pixel past dcx: 120 mm * 789.47 / 0.5 = 189.47 m.
    ASSERT_TRUE(dsp::triangulate(rig, to_q8(320), to_q8(240), to_q8(10.5), &p));
    EXPECT_NEAR(p.z, 120000.0 * 202105 / 128.0, 0.5);
    const dsp::camera_rig default_rig;  // dcx = 0
    EXPECT_FALSE(dsp::triangulate(default_rig, to_q8(320), to_q8(240), 0, &p));
    // 120 mm * 789.47 px / 31.5789 px = 3 m; Q8 gives 8084/256 px: 120000 * 202105 / 8084.
    EXPECT_TRUE(dsp::triangulate(default_rig, to_q8(320), to_q8(240), to_q8(31.5789), &p));
    EXPECT_EQ(p.z, 3000074);
    EXPECT_NEAR(p.z, 3.0e6, 300.0);  // 0.01 % of depth
}

TEST(triangulate, disparity_at_a_depth_is_the_pinhole_models) {
    // The inverse of the depth: s f / D + dcx from the rig's true focal
    // length in double, within the Q8 step and f_px's rounding to 1/256 px;
    // triangulated back, the depth within the Q8 disparity's error.
    for (const dsp::camera_rig& rig : {dsp::camera_rig{}, offset_rig()}) {
        const double f_px = static_cast<double>(rig.focal_length_um) * 1000.0 / rig.pixel_pitch_nm;
        const double dcx = (rig.cx_left_q8 - rig.cx_right_q8) / 256.0;
        for (double z_m = 0.5; z_m <= 8.0001; z_m += 0.25) {
            const int64_t z_um = std::llround(z_m * 1e6);
            const int64_t q8 = dsp::disparity_q8_at_depth(rig, z_um);
            const double d = rig.baseline_um * f_px / (z_m * 1e6) + dcx;
            EXPECT_NEAR(q8 / 256.0, d, 1.0 / 256) << z_m << " m";
            dsp::point3_um p;
            ASSERT_TRUE(dsp::triangulate(rig, rig.cx_right_q8, rig.cy_right_q8,
                                         static_cast<int32_t>(q8), &p));
            EXPECT_NEAR(p.z, z_um, z_um / (256.0 * (d - dcx))) << z_m << " m";
        }
    }
}

}  // namespace
