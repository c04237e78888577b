// A large object's depth from tiles (dsp/object_depth.h) on synthetic pairs
// whose disparities are known by construction: an object box whose left
// half lies at disparity 40 and right half at 44 over a background at 10,
// every layer its own random texture. The expected disparity is the one of
// the halves' mean depth, 2 / (1/40 + 1/44) (each half holds as many tiles),
// computed here, not by the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "dsp/object_depth.h"
#include "tests/support/layer_texture.h"

namespace {

constexpr int width = 320, height = 240;
constexpr int near_half = 40, far_half = 44, background = 10;  // disparities, px
const dsp::box object{100, 60, 128, 128};

struct pair_images {
    std::vector<uint8_t> right, left;
    dsp::gray_cplane right_view() const { return {right.data(), width, height, width}; }
    dsp::gray_cplane left_view() const { return {left.data(), width, height, width}; }
};

using test_support::layer_texture;

// Right (x, y) shows the layer there; left (x, y) shows the layer whose
// right-image point x - d lands on it (the object in front of the background).
pair_images make_pair() {
    pair_images p{std::vector<uint8_t>(width * height), std::vector<uint8_t>(width * height)};
    const int split = object.x + object.width / 2;
    auto on_object = [](int x, int y) {
        return x >= object.x && x < object.right() && y >= object.y && y < object.bottom();
    };
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            p.right[y * width + x] =
                on_object(x, y) ? layer_texture(1, x, y) : layer_texture(0, x, y);
            const int x_near = x - near_half, x_far = x - far_half;
            uint8_t v = layer_texture(0, x - background, y);
            if (on_object(x_near, y) && x_near < split) v = layer_texture(1, x_near, y);
            if (on_object(x_far, y) && x_far >= split) v = layer_texture(1, x_far, y);
            p.left[y * width + x] = v;
        }
    }
    return p;
}

dsp::stereo_params depth_range_search() {
    dsp::stereo_params s;
    s.min_disparity = 0;
    s.max_disparity = 100;
    return s;
}

// The core's match as the controller makes it (the box less an eighth of
// each side, over the whole depth range): the tiles' starting point.
int32_t core_disparity_q8(const pair_images& p, dsp::box b) {
    const dsp::box core{b.x + b.width / 8, b.y + b.height / 8, b.width - 2 * (b.width / 8),
                        b.height - 2 * (b.height / 8)};
    const dsp::stereo_result m =
        dsp::stereo_match_sad(p.right_view(), p.left_view(), core, depth_range_search());
    EXPECT_TRUE(m.valid);
    return m.disparity_q8;
}

double halves_mean_depth_disparity(double offset) {
    return offset + 2.0 / (1.0 / (near_half - offset) + 1.0 / (far_half - offset));
}

TEST(ObjectDepth, TheTilesGiveTheDisparityOfTheMeanDepth) {
    const pair_images p = make_pair();
    const dsp::camera_rig rig;
    const dsp::object_depth_result r = dsp::match_object_surface(
        p.right_view(), p.left_view(), object, core_disparity_q8(p, object), depth_range_search(),
        rig, dsp::object_depth_params{}, false);
    EXPECT_TRUE(r.tiled);
    ASSERT_TRUE(r.valid);
    EXPECT_EQ(r.tiles, 64);  // 128 / 16 px a side: 8 x 8
    EXPECT_EQ(r.matched, 64);
    EXPECT_EQ(r.tile_width, 16);
    EXPECT_NEAR(r.disparity_q8, 256 * halves_mean_depth_disparity(0), 1.0);
    // Not the core's disparity, nor the halves' mean disparity (42): the
    // mean depth is farther.
    EXPECT_GE(std::abs(r.disparity_q8 - core_disparity_q8(p, object)), 20);
    EXPECT_LT(r.disparity_q8, 42 * 256 - 20);
}

TEST(ObjectDepth, BackgroundTilesAreLeftOut) {
    const pair_images p = make_pair();
    // The box overreaches the object by two tile columns of background.
    dsp::box wide = object;
    wide.width += 32;
    const dsp::object_depth_result r =
        dsp::match_object_surface(p.right_view(), p.left_view(), wide, core_disparity_q8(p, object),
                                  depth_range_search(), dsp::camera_rig{}, {}, false);
    ASSERT_TRUE(r.valid);
    EXPECT_EQ(r.tiles, 80);
    EXPECT_EQ(r.matched, 64);
    EXPECT_NEAR(r.disparity_q8, 256 * halves_mean_depth_disparity(0), 1.0);
}

TEST(ObjectDepth, ThePrincipalOffsetIsOutsideTheMean) {
    // Principal points 20 px apart (cx_left - cx_right = -20): depth goes
    // with 1 / (d + 20), so the mean is taken over d + 20.
    const pair_images p = make_pair();
    dsp::camera_rig rig;
    rig.cx_right_q8 = rig.cx_left_q8 + 20 * 256;
    const dsp::object_depth_result r = dsp::match_object_surface(
        p.right_view(), p.left_view(), object, core_disparity_q8(p, object), depth_range_search(),
        rig, {}, false);
    ASSERT_TRUE(r.valid);
    EXPECT_NEAR(r.disparity_q8, 256 * halves_mean_depth_disparity(-20), 1.0);
    EXPECT_GT(
        std::fabs(256 * halves_mean_depth_disparity(-20) - 256 * halves_mean_depth_disparity(0)),
        4.0);  // the two differ by more than the tolerance
}

// Tiled from five tiles of 16 px a side (dsp/object_depth.h): a 79 px box
// stands on its core's match, an 80 px one is cut into 5 x 5 tiles.
TEST(ObjectDepth, ObjectsUnderFiveTilesASideAreNotTiled) {
    const pair_images p = make_pair();
    dsp::box small = object;
    small.width = small.height = 79;
    const dsp::object_depth_result r =
        dsp::match_object_surface(p.right_view(), p.left_view(), small, core_disparity_q8(p, small),
                                  depth_range_search(), {}, {}, false);
    EXPECT_FALSE(r.tiled);
    EXPECT_FALSE(r.valid);
    EXPECT_EQ(r.tiles, 0);
    dsp::box five_tiles = object;
    five_tiles.width = five_tiles.height = 80;
    const dsp::object_depth_result t = dsp::match_object_surface(
        p.right_view(), p.left_view(), five_tiles, core_disparity_q8(p, five_tiles),
        depth_range_search(), {}, {}, false);
    EXPECT_TRUE(t.tiled);
    EXPECT_TRUE(t.valid);
    EXPECT_EQ(t.columns, 5);
    EXPECT_EQ(t.rows, 5);
    EXPECT_EQ(t.tiles, 25);
}

// A disc (the box's inscribed circle) of faint texture at one disparity in
// front of a wall of full-contrast texture 3 px behind it (inside the
// object's narrow range): a tile on the outline is mostly wall by contrast,
// its minimum goes to the wall's disparity, and its SAD is low (the wall
// matches there), so the gate keeps it. With the outline (the box's ellipse
// less outline_inset a side) only the disc's pixels are matched, and each
// tile weighs by its pixels on it.
pair_images make_disc_pair(int disparity, int wall, int wall_contrast_shift = 0) {
    pair_images p{std::vector<uint8_t>(width * height), std::vector<uint8_t>(width * height)};
    const double cx = object.x + 0.5 * object.width, cy = object.y + 0.5 * object.height;
    const double radius = 0.5 * object.width;
    auto on_disc = [&](int x, int y) { return std::hypot(x + 0.5 - cx, y + 0.5 - cy) <= radius; };
    auto faint = [](int x, int y) {
        return static_cast<uint8_t>(120 + layer_texture(1, x, y) / 16);
    };
    // The wall's texture around mid-grey, its contrast divided by 2^shift.
    auto wall_at = [&](int x, int y) {
        return static_cast<uint8_t>(128 +
                                    (layer_texture(0, x, y) - 128) / (1 << wall_contrast_shift));
    };
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            p.right[y * width + x] = on_disc(x, y) ? faint(x, y) : wall_at(x, y);
            const int x_disc = x - disparity;
            p.left[y * width + x] = on_disc(x_disc, y) ? faint(x_disc, y) : wall_at(x - wall, y);
        }
    }
    return p;
}

TEST(ObjectDepth, TheOutlineKeepsTheBackgroundOutOfTheDiscsTiles) {
    constexpr int disc = 42, wall = 39;
    const pair_images p = make_disc_pair(disc, wall);
    const int32_t core = core_disparity_q8(p, object);
    const dsp::object_depth_result whole = dsp::match_object_surface(
        p.right_view(), p.left_view(), object, core, depth_range_search(), {}, {}, false);
    const dsp::object_depth_result outlined = dsp::match_object_surface(
        p.right_view(), p.left_view(), object, core, depth_range_search(), {}, {}, true);
    ASSERT_TRUE(whole.valid);
    ASSERT_TRUE(outlined.valid);
    std::printf("disc at %d px: whole tiles %.3f px (%d kept), outlined %.3f px (%d kept)\n", disc,
                whole.disparity_q8 / 256.0, whole.matched, outlined.disparity_q8 / 256.0,
                outlined.matched);
    // 8 x 8 tiles of 16 px: the 4 corner tiles hold no disc pixel, 8 more
    // hold under a quarter of a tile (the 128 px circle's corner slivers).
    EXPECT_EQ(outlined.tiles, 64 - 4 - 8);
    EXPECT_NEAR(outlined.disparity_q8, disc * 256, 8);  // within 1/32 px
    EXPECT_GT(std::abs(whole.disparity_q8 - disc * 256), 3 * 8);
}

// The outline's ellipse reaching past the disc (a box 16 px too large a
// side) over a faint wall (contrast / 8) whose true match lies outside the
// object's range: the ring of tiles partly on the wall find false minima
// inside the range, their SAD a few levels a pixel, far above the disc's
// tiles'. The gate compares each tile's SAD scaled to a whole tile's; a
// quarter-tile's raw SAD passed it (41.82 px, 5 more tiles kept).
TEST(ObjectDepth, AnOutlineTooLargeKeepsTheBackgroundTilesOut) {
    constexpr int disc = 42;
    const pair_images p = make_disc_pair(disc, background, 3);
    const dsp::box large{object.x - 16, object.y - 16, object.width + 32, object.height + 32};
    const dsp::object_depth_result r =
        dsp::match_object_surface(p.right_view(), p.left_view(), large,
                                  core_disparity_q8(p, object), depth_range_search(), {}, {}, true);
    ASSERT_TRUE(r.valid);
    std::printf("outline 16 px too large: %.3f px, %d of %d inside the range kept\n",
                r.disparity_q8 / 256.0, r.matched, r.inside);
    EXPECT_NEAR(r.disparity_q8, disc * 256, 8);
}

}  // namespace
