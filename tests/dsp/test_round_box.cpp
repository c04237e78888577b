// A tracked box brought back to a sphere's shape (dsp/round_box.h), against
// spheres projected here point by point: every point of a sphere's surface
// through a pinhole, the box the pixels of the projections span (the
// silhouette's extremes are points of the surface). The oracle is that
// brute-force projection in floating point, not the rule's square roots.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "dsp/round_box.h"

namespace {

using dsp::box;

constexpr int image_width = 640, image_height = 480;

dsp::camera_rig rig_with_lens_um(int focal_length_um) {
    dsp::camera_rig rig;
    rig.focal_length_um = focal_length_um;
    return rig;
}

// The pixel box of a sphere `diameter_px` across on the axis whose centre's
// ray meets the image at column `u`, row `v` (pixel-centre coordinates), one
// metre away, through rig's pinhole.
box sphere_box(const dsp::camera_rig& rig, double u, double v, double diameter_px) {
    const double f = static_cast<double>(rig.focal_length_um) * 1000.0 / rig.pixel_pitch_nm;
    const double cx = rig.cx_right_q8 / 256.0, cy = rig.cy_right_q8 / 256.0;
    const double x = (u - cx) / f, y = (v - cy) / f;  // the centre's ray at Z = 1
    const double radius = 0.5 * diameter_px / f;
    double min_u = 1e9, max_u = -1e9, min_v = 1e9, max_v = -1e9;
    constexpr int steps = 720;
    const double pi = std::acos(-1.0);
    for (int i = 0; i <= steps; ++i) {
        const double theta = pi * i / steps;
        for (int j = 0; j < 2 * steps; ++j) {
            const double phi = pi * j / steps;
            const double px = x + radius * std::sin(theta) * std::cos(phi);
            const double py = y + radius * std::sin(theta) * std::sin(phi);
            const double pz = 1.0 + radius * std::cos(theta);
            min_u = std::min(min_u, cx + f * px / pz);
            max_u = std::max(max_u, cx + f * px / pz);
            min_v = std::min(min_v, cy + f * py / pz);
            max_v = std::max(max_v, cy + f * py / pz);
        }
    }
    // Pixel i spans [i - 0.5, i + 0.5]: the pixels the silhouette enters.
    const int x0 = static_cast<int>(std::floor(min_u + 0.5));
    const int x1 = static_cast<int>(std::ceil(max_u - 0.5));
    const int y0 = static_cast<int>(std::floor(min_v + 0.5));
    const int y1 = static_cast<int>(std::ceil(max_v - 0.5));
    return box{x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

box cut_about_centre(box b, int width, int height) {
    return box{b.x + (b.width - width) / 2, b.y + (b.height - height) / 2, width, height};
}

::testing::AssertionResult same(box a, box b) {
    if (a.x == b.x && a.y == b.y && a.width == b.width && a.height == b.height)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << a.x << "," << a.y << " " << a.width << "x" << a.height << " vs " << b.x << "," << b.y
           << " " << b.width << "x" << b.height;
}

struct placement {
    double u, v, diameter_px;
};

// On the axis, at the ends of the middle row and column and near the
// corners: far off the axis a 2.8 mm lens draws a sphere out by 32 %.
const placement placements[] = {
    {319.5, 239.5, 100}, {70, 239.5, 100}, {580, 239.5, 100}, {319.5, 60, 100},
    {319.5, 420, 100},   {80, 70, 120},    {570, 420, 80},    {200, 300, 40},
    {40, 239.5, 60},     {600, 100, 60},   {450, 380, 160},   {160, 120, 200},
};

bool inside_image(box b) {
    return b.x > 0 && b.y > 0 && b.right() < image_width && b.bottom() < image_height;
}

// Calls check(rig, where, sphere's box) for each lens and placement whose
// box lies inside the image; returns how many it checked.
template <typename Check>
int for_each_sphere_in_image(Check check) {
    int checked = 0;
    for (const int lens_um : {2800, 6000, 12000}) {
        const dsp::camera_rig rig = rig_with_lens_um(lens_um);
        for (const placement& p : placements) {
            const box b = sphere_box(rig, p.u, p.v, p.diameter_px);
            if (!inside_image(b)) continue;
            ++checked;
            check(rig,
                  std::to_string(lens_um) + " um at " + std::to_string(p.u) + "," +
                      std::to_string(p.v),
                  b);
        }
    }
    return checked;
}

TEST(RoundBox, ASpheresOwnBoxIsKeptAtAnyLensAndPlace) {
    const int checked =
        for_each_sphere_in_image([](const dsp::camera_rig& rig, const std::string& at, box b) {
            EXPECT_TRUE(same(dsp::rounded_box(b, image_width, image_height, rig), b)) << at;
        });
    EXPECT_GE(checked, 30);
}

// Each side of a pixel box is within half a pixel of the silhouette's, so
// a size read from one side and the shape is within 2 px of the other's.
TEST(RoundBox, AShortSideGrowsBackToTheSpheres) {
    const int checked =
        for_each_sphere_in_image([](const dsp::camera_rig& rig, const std::string& at, box b) {
            const box low = cut_about_centre(b, b.width, b.height * 6 / 10);
            const box narrow = cut_about_centre(b, b.width * 6 / 10, b.height);
            for (const box& cut : {low, narrow}) {
                const box r = dsp::rounded_box(cut, image_width, image_height, rig);
                EXPECT_LE(std::abs(r.width - b.width), 2) << at;
                EXPECT_LE(std::abs(r.height - b.height), 2) << at;
                EXPECT_LE(std::abs(r.center_x2() - b.center_x2()), 2) << at;
                EXPECT_LE(std::abs(r.center_y2() - b.center_y2()), 2) << at;
            }
        });
    EXPECT_GE(checked, 30);
}

TEST(RoundBox, ASideShortByUpToAnEighthIsKept) {
    const dsp::camera_rig rig;
    const box b{272, 192, 96, 96};  // centred on the principal point (319.5, 239.5): square
    const box within = cut_about_centre(b, b.width, 84);  // short by 12 px, an eighth
    EXPECT_TRUE(same(dsp::rounded_box(within, image_width, image_height, rig), within));
    const box past = cut_about_centre(b, b.width, 83);
    EXPECT_EQ(dsp::rounded_box(past, image_width, image_height, rig).height, 96);
    const box small{314, 234, 12, 12};  // at least 2 px
    const box small_within = cut_about_centre(small, 12, 10);
    EXPECT_TRUE(same(dsp::rounded_box(small_within, image_width, image_height, rig), small_within));
    const box small_past = cut_about_centre(small, 12, 9);
    EXPECT_EQ(dsp::rounded_box(small_past, image_width, image_height, rig).height, 12);
}

TEST(RoundBox, NotWhereTheBorderCutsTheBoxNorWhereItWouldLeaveTheImage) {
    const dsp::camera_rig rig;
    const box at_left{0, 200, 90, 50};
    const box at_right{image_width - 90, 200, 90, 50};
    const box at_top{300, 0, 90, 50};
    const box at_bottom{300, image_height - 50, 90, 50};
    for (const box& b : {at_left, at_right, at_top, at_bottom})
        EXPECT_TRUE(same(dsp::rounded_box(b, image_width, image_height, rig), b));
    const box near_top{300, 10, 90, 50};  // grown to 90 high it starts 10 px above the image
    EXPECT_TRUE(same(dsp::rounded_box(near_top, image_width, image_height, rig), near_top));
    const box inside{300, 215, 90, 50};  // its centre on the principal point's row
    const box grown = dsp::rounded_box(inside, image_width, image_height, rig);
    EXPECT_EQ(grown.height, 90);
    EXPECT_EQ(grown.y, 195);
    EXPECT_TRUE(same(dsp::rounded_box(box{}, image_width, image_height, rig), box{}));
}

// is_round against the same projections: a sphere's own box is round at any
// lens and place, and one cut by over an eighth on either axis is not, up to
// the image's borders, which is_round does not look at.
TEST(RoundBox, IsRoundHoldsForASpheresBoxNotForOneCutShort) {
    const int checked =
        for_each_sphere_in_image([](const dsp::camera_rig& rig, const std::string& at, box b) {
            EXPECT_TRUE(dsp::is_round(b, rig)) << at;
            const box low = cut_about_centre(b, b.width, b.height * 8 / 10);
            const box narrow = cut_about_centre(b, b.width * 8 / 10, b.height);
            EXPECT_FALSE(dsp::is_round(low, rig)) << at;
            EXPECT_FALSE(dsp::is_round(narrow, rig)) << at;
        });
    EXPECT_GE(checked, 30);
    const dsp::camera_rig rig;
    const box on_axis{272, 192, 96, 96};
    EXPECT_TRUE(dsp::is_round(cut_about_centre(on_axis, 96, 84), rig));   // an eighth short
    EXPECT_FALSE(dsp::is_round(cut_about_centre(on_axis, 96, 83), rig));  // past it
    EXPECT_FALSE(dsp::is_round(cut_about_centre(on_axis, 83, 96), rig));
    EXPECT_TRUE(dsp::is_round(box{0, 200, 50, 50}, rig));  // at the border: its shape alone
    EXPECT_FALSE(dsp::is_round(box{}, rig));
}

// drawn_out against the same projections: a sphere's own box is drawn out
// on neither axis; widened by over an eighth on one side it is drawn out on
// that axis, on the other none.
TEST(RoundBox, DrawnOutNamesTheAxisAWideningLengthened) {
    const int checked =
        for_each_sphere_in_image([](const dsp::camera_rig& rig, const std::string& at, box b) {
            EXPECT_EQ(dsp::drawn_out(b, rig), dsp::drawn_out_axis::neither) << at;
            const box taller{b.x, b.y, b.width, b.height * 13 / 10};
            const box wider{b.x - b.width * 3 / 10, b.y, b.width * 13 / 10, b.height};
            EXPECT_EQ(dsp::drawn_out(taller, rig), dsp::drawn_out_axis::height) << at;
            EXPECT_EQ(dsp::drawn_out(wider, rig), dsp::drawn_out_axis::width) << at;
        });
    EXPECT_GE(checked, 30);
    const dsp::camera_rig rig;
    const box on_axis{272, 192, 84, 84};
    EXPECT_EQ(dsp::drawn_out(box{272, 192, 84, 96}, rig), dsp::drawn_out_axis::neither);
    EXPECT_EQ(dsp::drawn_out(box{272, 192, 84, 97}, rig), dsp::drawn_out_axis::height);
    EXPECT_EQ(dsp::drawn_out(box{272, 192, 97, 84}, rig), dsp::drawn_out_axis::width);
    EXPECT_EQ(dsp::drawn_out(on_axis, rig), dsp::drawn_out_axis::neither);
    EXPECT_EQ(dsp::drawn_out(box{}, rig), dsp::drawn_out_axis::neither);
}

}  // namespace
