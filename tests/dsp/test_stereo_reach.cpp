// How far an object reaches past its box's sides in the stereo pair
// (dsp/stereo_reach.h), on synthetic pairs whose layout is known by
// construction: an object at disparity 40 over columns [object_x0,
// object_x1) in front of a background at disparity 10, each its own random
// texture (the background also flat, faint or repeating). The expected
// reach is the distance from the given box's side to the object's,
// computed here.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "dsp/stereo_reach.h"
#include "tests/support/layer_texture.h"

namespace {

constexpr int width = 320, height = 120;
constexpr int object_disparity = 40, background_disparity = 10;
constexpr int object_x0 = 100, object_x1 = 220, object_y0 = 20, object_y1 = 100;

using test_support::layer_texture;

struct pair_images {
    std::vector<uint8_t> right, left;
    dsp::gray_cplane right_view() const { return {right.data(), width, height, width}; }
    dsp::gray_cplane left_view() const { return {left.data(), width, height, width}; }
};

bool on_object(int x, int y) {
    return x >= object_x0 && x < object_x1 && y >= object_y0 && y < object_y1;
}

enum class backdrop { textured, flat, faint, periodic, noisy, flat_patch, wide_flat_patch };

// The flat_patch backdrop's flat columns (in the right image): 12 px, so
// that exactly one tile of the reach's past the left side lies wholly on
// them (tiles of 8 px every 4 px).
constexpr int patch_x0 = 68, patch_x1 = 80;
// The wide_flat_patch backdrop's: 20 px, two tiles wholly on them in a row.
constexpr int wide_patch_x0 = 60, wide_patch_x1 = 80;

// The period of the periodic backdrop: the object's disparity less the
// background's, so that right of the object, where the left camera sees
// no background, the right image's background matches the left image's at
// the object's disparity.
constexpr int period = object_disparity - background_disparity;

// flat: the background one grey level (it matches everywhere); faint: a
// texture of 6 grey levels (any two of its pixels within the gate's floor);
// noisy: one grey level under each camera's own noise of 8 levels (a flat
// wall as a sensor sees it: it matches about equally badly everywhere).
// The object's first `noisy_rim` columns are such a wall too (a shaded rim
// with no texture left); its columns [flat_from, flat_to) one grey level (a
// plain band on its surface). The background stands at `back_disparity`.
pair_images make_pair(backdrop kind, int noisy_rim = 0, int flat_from = 0, int flat_to = 0,
                      int back_disparity = background_disparity) {
    pair_images p{std::vector<uint8_t>(width * height), std::vector<uint8_t>(width * height)};
    auto back = [&](int x, int y) {
        if (kind == backdrop::periodic)
            return layer_texture(0, ((x % period) + period) % period, y);
        if (kind == backdrop::flat_patch)
            return x >= patch_x0 && x < patch_x1 ? uint8_t{90} : layer_texture(0, x, y);
        if (kind == backdrop::wide_flat_patch)
            return x >= wide_patch_x0 && x < wide_patch_x1 ? uint8_t{90} : layer_texture(0, x, y);
        return kind == backdrop::flat    ? uint8_t{90}
               : kind == backdrop::faint ? static_cast<uint8_t>(88 + layer_texture(0, x, y) % 6)
                                         : layer_texture(0, x, y);
    };
    auto noise = [](int camera, int x, int y) {
        return static_cast<uint8_t>(86 + layer_texture(2 + camera, x, y) % 8);
    };
    const bool noisy = kind == backdrop::noisy;
    // The object's pixel at its column x_object, seen by `camera` at x.
    auto object = [&](int camera, int x_object, int x, int y) {
        if (x_object >= flat_from && x_object < flat_to) return uint8_t{120};
        return x_object < object_x0 + noisy_rim ? noise(camera, x, y)
                                                : layer_texture(1, x_object, y);
    };
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            p.right[y * width + x] = on_object(x, y) ? object(0, x, x, y)
                                     : noisy         ? noise(0, x, y)
                                                     : back(x, y);
            const int x_object = x - object_disparity;
            p.left[y * width + x] = on_object(x_object, y) ? object(1, x_object, x, y)
                                    : noisy                ? noise(1, x, y)
                                                           : back(x - back_disparity, y);
        }
    }
    return p;
}

dsp::stereo_params depth_range_search() {
    dsp::stereo_params s;
    s.min_disparity = 0;
    s.max_disparity = 80;
    return s;
}

// The object's match as the controller gives it: a spread of 3 px, a SAD
// of 0 a pixel (the synthetic pair is noise-free: the gate is its floor).
dsp::object_match at_disparity(int d) {
    dsp::object_match m;
    m.disparity = d;
    m.spread = 3;
    return m;
}

dsp::stereo_reach reach(const pair_images& p, dsp::box b, int max_reach = 60,
                        int d = object_disparity) {
    return dsp::reach_past_sides(p.right_view(), p.left_view(), b, at_disparity(d), max_reach,
                                 depth_range_search(), dsp::stereo_reach_params{});
}

TEST(StereoReach, ABoxShortAtBothSidesReachesTheObjectsSides) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::box narrow{object_x0 + 24, object_y0, 120 - 24 - 13, 80};  // 24 and 13 px short
    const dsp::stereo_reach r = reach(p, narrow);
    EXPECT_NEAR(r.left, 24, 2);
    EXPECT_NEAR(r.right, 13, 2);
    // The tiles wholly on the object (5 left, 2 right), a part-object one
    // either way, the first two not the object's a side (an end is taken
    // where the next tile is not the object's either) and the tile past
    // the bound a side, each over the depth range (81 disparities); both
    // ends split.
    EXPECT_GE(r.tiles, 13);
    EXPECT_LE(r.tiles, 15);
    EXPECT_EQ(r.positions, 81 * r.tiles);
    EXPECT_EQ(r.split_columns, 2 * 12);
}

TEST(StereoReach, ABoxOnTheObjectsSidesReachesNoFurther) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r = reach(p, dsp::box{object_x0, object_y0, 120, 80});
    EXPECT_LE(r.left, 2);
    EXPECT_LE(r.right, 2);
    EXPECT_EQ(r.tiles, 2);  // the first tile past each side is background
}

TEST(StereoReach, AFlatBackgroundIsNotTheObject) {
    const pair_images p = make_pair(backdrop::flat);
    const dsp::box narrow{object_x0 + 20, object_y0, 80, 80};
    const dsp::stereo_reach r = reach(p, narrow);
    EXPECT_NEAR(r.left, 20, 2);
    EXPECT_NEAR(r.right, 20, 2);  // not on into the flat background
}

// Right of the object the background is hidden from the left camera for
// 40 - 10 px: in the right image's tiles it matches nowhere, and a faint one
// matches within the gate at the object's disparity too. Read from the left
// image, which shows what lies past that side, it matches at its own.
TEST(StereoReach, ABackgroundHiddenFromOneCameraIsReadFromTheOther) {
    const pair_images p = make_pair(backdrop::faint);
    const dsp::box narrow{object_x0 + 9, object_y0, 120 - 9 - 13, 80};
    const dsp::stereo_reach r = reach(p, narrow);
    EXPECT_NEAR(r.left, 9, 2);
    EXPECT_NEAR(r.right, 13, 2);
}

// A background repeating every `period` px: right of the object the right
// image's tiles match it at the object's disparity (40) and, within a
// search up to 60 px, at no other but 10, where the left image shows the
// object: they would read as the object's for the 30 px the left camera
// cannot see. The left image's, past the object there, match at 10 and at
// 40 alike, and are not taken.
TEST(StereoReach, ARepeatingBackgroundHiddenFromOneCameraIsNotTheObject) {
    const pair_images p = make_pair(backdrop::periodic);
    dsp::stereo_params search = depth_range_search();
    search.max_disparity = 60;
    const dsp::box narrow{object_x0 + 9, object_y0, 120 - 9 - 13, 80};
    const dsp::stereo_reach r =
        dsp::reach_past_sides(p.right_view(), p.left_view(), narrow, at_disparity(object_disparity),
                              60, search, dsp::stereo_reach_params{});
    EXPECT_NEAR(r.left, 9, 2);
    EXPECT_NEAR(r.right, 13, 2);
}

// The object's sides met within the tiles read (to a tile and the spread
// past the bound), 14 px past each side: widened by the bound.
TEST(StereoReach, AtMostMaxReach) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::box narrow{object_x0 + 14, object_y0, 92, 80};
    const dsp::stereo_reach r = reach(p, narrow, 10);
    EXPECT_EQ(r.left, 10);
    EXPECT_EQ(r.right, 10);
}

// The object's sides 21 px past the box's, the bound 10: the last tile
// read (20-27 px out from the probe's start, 3 px inside the side) is the
// first not the object's. No tile past it is read (it would be past the
// bound), so the end is taken there, not waited for, and the box is
// widened by the bound.
TEST(StereoReach, ASideMetAtTheLastTileReadIsTaken) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r = reach(p, dsp::box{object_x0 + 21, object_y0, 120 - 42, 80}, 10);
    EXPECT_EQ(r.left, 10);
    EXPECT_EQ(r.right, 10);
}

// The object's sides farther out than the tiles read (40 px, the bound
// 10): its end not met, the box is not widened.
TEST(StereoReach, AnObjectWhoseSidesAreNotMetIsNotWidened) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r = reach(p, dsp::box{object_x0 + 40, object_y0, 40, 80}, 10);
    EXPECT_EQ(r.left, 0);
    EXPECT_EQ(r.right, 0);
}

// The object's sides 26 px past the box's, the bound 10: every tile read
// (to 27 px out from the probe's start, 3 px inside the side) is the
// object's, its end is not met, and the box is not widened. The tile past
// the bound (24-31 px out) holds 3 columns of background and 5 of the
// object, is not read as the object's and refuses nothing: the guard of an
// end not met stands alone here (40 px past, the tile past the bound is
// the object's and refuses the reach too).
TEST(StereoReach, AnObjectWhoseSidesAreNotMetIsNotWidenedToTheBound) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r = reach(p, dsp::box{object_x0 + 26, object_y0, 68, 80}, 10);
    EXPECT_EQ(r.left, 0);
    EXPECT_EQ(r.right, 0);
}

// A bound that puts the tile past it beyond the image's left edge (120 px
// from a box at x = 124): the background beside the object is not read
// there, and the side is reached.
TEST(StereoReach, AFarTileBeyondTheImageRefusesNothing) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::box narrow{object_x0 + 24, object_y0, 120 - 24 - 13, 80};
    EXPECT_NEAR(reach(p, narrow, 120).left, 24, 2);
}

// A box 8 px wider than the object each side, asked at the background's
// disparity (a core that matched what is behind): the background's tiles
// match there all the way to the bound. Unguarded the box was widened by
// its whole bound, half its size a side.
TEST(StereoReach, ABoxAskedAtTheBackgroundsDisparityIsNotWidenedToTheBound) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r =
        reach(p, dsp::box{object_x0 - 8, object_y0, 136, 80}, 30, background_disparity);
    EXPECT_EQ(r.left, 0);
    EXPECT_EQ(r.right, 0);
}

// A plain band 12 px wide on the object, 5-17 px left of a box 24 px short
// of its side, asked at 43 px (its core 3 px nearer than its rim): the
// band's one tile wholly on it matches as well at 36-39 px, outside the
// span, and is not the object's; the next one is. The reach goes on past
// the band to the object's side. Taken for the end, the side was moved out
// by 5 px.
TEST(StereoReach, APlainBandOnTheObjectIsNotItsEnd) {
    const pair_images p = make_pair(backdrop::textured, 0, 107, 119);
    const dsp::box narrow{object_x0 + 24, object_y0, 120 - 24 - 13, 80};
    EXPECT_NEAR(reach(p, narrow, 60, 43).left, 24, 2);
}

// Asked at 13 px, the background's 10 within the spread (3 px): it matches
// as the object does, as the background 0.5 m behind a ball going away did.
// A flat patch 12 px wide in it, 14-26 px left of the box, breaks the run
// of its tiles for one tile; the next is the object's again, so the
// patch is not the object's end and the reach runs on to its bound. Taken
// for the end, the box was widened 12-20 px to the patch.
TEST(StereoReach, AFlatPatchInABackgroundWithinTheSpanIsNotTheObjectsEnd) {
    const pair_images p = make_pair(backdrop::flat_patch);
    const dsp::stereo_reach r =
        reach(p, dsp::box{object_x0 - 8, object_y0, 136, 80}, 30, background_disparity + 3);
    EXPECT_EQ(r.left, 0);
    EXPECT_EQ(r.right, 0);
}

// A ball at the wall it was thrown at: the background 1 px behind the
// object's 40, within the spread (3 px), matches as the object does, and
// a flat patch two tiles wide, 44-64 px left of the box, ends the run of
// its tiles: read as the object's end, the box went about 44 px out to
// it (the object's side is 24 px out). The tile past the bound is the
// object's, the background beside it at the object's depth: no reach.
TEST(StereoReach, ABackgroundAtTheObjectsDepthBesideItIsNoReach) {
    const dsp::box narrow{object_x0 + 24, object_y0, 60, 80};
    const pair_images wall = make_pair(backdrop::wide_flat_patch, 0, 0, 0, object_disparity - 1);
    EXPECT_EQ(reach(wall, narrow).left, 0);
    // The same patch 30 px behind the object: its side is reached.
    const pair_images behind = make_pair(backdrop::wide_flat_patch);
    EXPECT_NEAR(reach(behind, narrow).left, 24, 2);
}

TEST(StereoReach, AnObjectAtTheBackgroundsDisparityIsNotWidened) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::box narrow{object_x0 + 24, object_y0, 60, 80};
    // Asked at the background's disparity: the object's tiles match elsewhere.
    const dsp::stereo_reach r = reach(p, narrow, 60, background_disparity);
    EXPECT_EQ(r.left, 0);
    EXPECT_EQ(r.right, 0);
}

// A ball's core stands nearer than its rim: asked at 43 px (within the
// spread of the object's 40), the right side's end is read in the left
// image at the rim's 40 and brought back to the right image at 40, not 43
// (3 px short).
TEST(StereoReach, TheRightEndIsBroughtBackAtTheRimsDisparity) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::box narrow{object_x0 + 24, object_y0, 120 - 24 - 13, 80};
    EXPECT_NEAR(reach(p, narrow, 60, 43).right, 13, 1);
}

dsp::stereo_reach reach_ends(const pair_images& p, dsp::box b, int max_reach = 40,
                             int d = object_disparity) {
    return dsp::reach_past_ends(p.right_view(), p.left_view(), b, at_disparity(d), max_reach,
                                depth_range_search(), dsp::stereo_reach_params{});
}

TEST(StereoReachEnds, ABoxShortAtTopAndBottomReachesTheObjectsEnds) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::box low{object_x0, object_y0 + 12, 120, 80 - 12 - 9};  // 12 and 9 px short
    const dsp::stereo_reach r = reach_ends(p, low);
    EXPECT_NEAR(r.up, 12, 2);
    EXPECT_NEAR(r.down, 9, 2);
    EXPECT_EQ(r.left, 0);
    EXPECT_EQ(r.right, 0);
    // 16 columns x 8 rows a tile: over the rows from 3 px inside (the
    // spread) to the object's end, a part-object one and the first two of
    // background each way; over the depth range (81 disparities); both split.
    EXPECT_GE(r.tiles, 8);
    EXPECT_LE(r.tiles, 11);
    EXPECT_EQ(r.positions, 81 * r.tiles);
    EXPECT_EQ(r.split_columns, 2 * 12);
}

TEST(StereoReachEnds, ABoxOnTheObjectsEndsReachesNoFurther) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r = reach_ends(p, dsp::box{object_x0, object_y0, 120, 80});
    EXPECT_LE(r.up, 2);
    EXPECT_LE(r.down, 2);
    EXPECT_EQ(r.tiles, 2);
}

TEST(StereoReachEnds, AFlatBackgroundIsNotTheObject) {
    const pair_images p = make_pair(backdrop::flat);
    const dsp::stereo_reach r = reach_ends(p, dsp::box{object_x0, object_y0 + 10, 120, 60});
    EXPECT_NEAR(r.up, 10, 2);
    EXPECT_NEAR(r.down, 10, 2);
}

// Read on the box's centre columns, not at its sides: a box whose left half
// hangs off the object still reads the object's ends under its middle.
TEST(StereoReachEnds, ReadOnTheBoxsCentreColumns) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r = reach_ends(p, dsp::box{object_x0 - 50, object_y0 + 8, 120, 64});
    EXPECT_NEAR(r.up, 8, 2);
    EXPECT_NEAR(r.down, 8, 2);
}

TEST(StereoReachEnds, AtMostMaxReach) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r = reach_ends(p, dsp::box{object_x0, object_y0 + 20, 120, 40}, 10);
    EXPECT_LE(r.up, 10);
    EXPECT_GE(r.up, 6);
    EXPECT_LE(r.down, 10);
    EXPECT_GE(r.down, 6);
}

TEST(StereoReachEnds, AnObjectAtTheBackgroundsDisparityIsNotWidened) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r =
        reach_ends(p, dsp::box{object_x0, object_y0 + 12, 120, 50}, 40, background_disparity);
    EXPECT_EQ(r.up, 0);
    EXPECT_EQ(r.down, 0);
}

// A flat wall under each camera's own noise matches about equally badly at
// the object's disparity and elsewhere, row by row: charged as the
// object's as readily as background, its noise carried the split 0-2 px
// past an end (and 1-10 px past a side, where the charges stay equal:
// docs/firmware.md, "Open").
TEST(StereoReachEnds, ANoisyFlatBackgroundIsNotTheObject) {
    const pair_images p = make_pair(backdrop::noisy);
    for (const int short_by : {8, 12}) {
        const dsp::stereo_reach r =
            reach_ends(p, dsp::box{object_x0, object_y0 + short_by, 120, 80 - 2 * short_by});
        EXPECT_NEAR(r.up, short_by, 1) << short_by;
        EXPECT_NEAR(r.down, short_by, 1) << short_by;
    }
}

// How far the object stops short of a box too large for it
// (short_of_sides, short_of_ends): the same tiles read inwards.
dsp::stereo_reach short_of(const pair_images& p, dsp::box b, int max_trim = 30,
                           int d = object_disparity) {
    return dsp::short_of_sides(p.right_view(), p.left_view(), b, at_disparity(d), max_trim,
                               depth_range_search(), dsp::stereo_reach_params{});
}

dsp::stereo_reach short_of_ends(const pair_images& p, dsp::box b, int max_trim = 30,
                                int d = object_disparity) {
    return dsp::short_of_ends(p.right_view(), p.left_view(), b, at_disparity(d), max_trim,
                              depth_range_search(), dsp::stereo_reach_params{});
}

// Right of the object the left image is read (at x - d in the right): in
// the right image the background there is hidden from the left camera by
// the object, and matches nowhere.
TEST(StereoShortOf, ABoxWideAtBothSidesStopsAtTheObjectsSides) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::box wide{object_x0 - 14, object_y0, 120 + 14 + 9, 80};  // 14 and 9 px wide
    const dsp::stereo_reach r = short_of(p, wide);
    EXPECT_NEAR(r.left, 14, 1);
    EXPECT_NEAR(r.right, 9, 1);
    EXPECT_EQ(r.up, 0);
    EXPECT_EQ(r.down, 0);
    // From 4 px outside each side in: the tiles wholly on background (4
    // left, 3 right) and the first not (a part-object tile is over the
    // gate), then the right rim's tile, over the depth range; both split.
    EXPECT_EQ(r.tiles, 8);
    EXPECT_EQ(r.positions, 81 * r.tiles);
    EXPECT_EQ(r.split_columns, 2 * 12);
}

TEST(StereoShortOf, ABoxOnTheObjectsSidesIsNotMovedIn) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r = short_of(p, dsp::box{object_x0, object_y0, 120, 80});
    EXPECT_EQ(r.left, 0);
    EXPECT_EQ(r.right, 0);
    EXPECT_EQ(r.tiles, 2);  // the first tile inside each side is the object's
}

// A rim with no texture before a flat wall, each under its camera's own
// noise, matches about as badly at the object's disparity as anywhere:
// not clearly background, it is kept.
TEST(StereoShortOf, AnUntexturedRimIsNotBackground) {
    const pair_images p = make_pair(backdrop::noisy, 16);
    const dsp::stereo_reach r = short_of(p, dsp::box{object_x0, object_y0, 120, 80});
    EXPECT_EQ(r.left, 0);
}

// A round object's rim stands farther than its core: the right side's
// start, found in the left image, is brought back at the disparity read on
// the rim (here the object's 40 where the core read 43, within its spread).
TEST(StereoShortOf, TheRightSideIsBroughtBackAtTheRimsDisparity) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r = dsp::short_of_sides(
        p.right_view(), p.left_view(), dsp::box{object_x0 - 14, object_y0, 143, 80},
        at_disparity(object_disparity + 3), 30, depth_range_search(), dsp::stereo_reach_params{});
    EXPECT_NEAR(r.left, 14, 1);
    EXPECT_NEAR(r.right, 9, 1);
}

// A band of 16 rows on the centre rows of an object under 48 px may run off
// it: such a box is not trimmed.
TEST(StereoShortOf, ABoxUnderThreeBandsIsNotTrimmed) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r = short_of(p, dsp::box{object_x0 - 14, object_y0 + 20, 143, 40});
    EXPECT_EQ(r.left, 0);
    EXPECT_EQ(r.right, 0);
    EXPECT_EQ(r.tiles, 0);
}

// The object met within the tiles read (to a tile past the bound), 14 px
// inside each side: moved in by the bound.
TEST(StereoShortOf, AtMostMaxTrim) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r = short_of(p, dsp::box{object_x0 - 14, object_y0, 148, 80}, 10);
    EXPECT_EQ(r.left, 10);
    EXPECT_EQ(r.right, 10);
}

// Asked at a wrong disparity (here the background's) every tile of the
// object matches clearly elsewhere: read inwards, a box inside the object
// sees background all the way, meets no object, and is not moved in (it
// would be by its whole bound, a quarter of the box).
TEST(StereoShortOf, AnObjectAtAWrongDisparityIsNotMovedIn) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::box inside{object_x0 + 10, object_y0 + 10, 100, 60};
    for (const int d : {background_disparity, object_disparity + 20}) {
        const dsp::stereo_reach r = short_of(p, inside, 25, d);
        EXPECT_EQ(r.left, 0) << d;
        EXPECT_EQ(r.right, 0) << d;
        const dsp::stereo_reach v = short_of_ends(p, inside, 15, d);
        EXPECT_EQ(v.up, 0) << d;
        EXPECT_EQ(v.down, 0) << d;
    }
}

// The object farther in than the tiles read (30 px, the bound 10): not met,
// not moved in either.
TEST(StereoShortOf, AnObjectNotMetWithinTheBoundIsNotMovedIn) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r = short_of(p, dsp::box{object_x0 - 30, object_y0, 180, 80}, 10);
    EXPECT_EQ(r.left, 0);
    EXPECT_EQ(r.right, 0);
}

TEST(StereoShortOfEnds, ABoxTallAtTopAndBottomStopsAtTheObjectsEnds) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::box tall{object_x0, object_y0 - 11, 120, 80 + 11 + 6};  // 11 and 6 px tall
    const dsp::stereo_reach r = short_of_ends(p, tall);
    EXPECT_NEAR(r.up, 11, 1);
    EXPECT_NEAR(r.down, 6, 1);
    EXPECT_EQ(r.left, 0);
    EXPECT_EQ(r.right, 0);
}

TEST(StereoShortOfEnds, ABoxOnTheObjectsEndsIsNotMovedIn) {
    const pair_images p = make_pair(backdrop::textured);
    const dsp::stereo_reach r = short_of_ends(p, dsp::box{object_x0, object_y0, 120, 80});
    EXPECT_EQ(r.up, 0);
    EXPECT_EQ(r.down, 0);
    EXPECT_EQ(r.tiles, 2);
}

}  // namespace
