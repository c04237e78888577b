// The key frame of a slow object (dsp/key_frame.h) on drawn frames: a
// textured disc moving 1 px per frame over a textured background. The
// expected extents are the drawn discs' own pixels (the test's geometry,
// not the firmware's), the expected displacement the drawn motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "dsp/box_refit.h"
#include "dsp/key_frame.h"
#include "dsp/motion_blocks.h"

namespace {

constexpr int frame_w = 200, frame_h = 150;
constexpr int radius = 20;
constexpr int large_radius = 50;  // larger than twice key_frame::hole_inset

struct drawn {
    std::vector<uint8_t> pixels = std::vector<uint8_t>(frame_w * frame_h);
    dsp::box disc;  // the disc's pixels' bounding box
    dsp::gray_cplane plane() const {
        return dsp::gray_cplane{pixels.data(), frame_w, frame_h, frame_w};
    }
};

bool in_disc(int x, int y, int cx, int cy, int r = radius) {
    return (x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r;
}

// Background: a smooth ramp (40..100); the disc: a checker of 160 / 220
// whose squares move with it (`texture_shift` turns it instead).
drawn draw(int cx, int cy, int texture_shift = 0, int r = radius) {
    drawn d;
    int x0 = frame_w, y0 = frame_h, x1 = -1, y1 = -1;
    for (int y = 0; y < frame_h; ++y) {
        for (int x = 0; x < frame_w; ++x) {
            uint8_t v = static_cast<uint8_t>(40 + (x + 2 * y) % 61);
            if (in_disc(x, y, cx, cy, r)) {
                const int u = x - cx + 64 + texture_shift, w = y - cy + 64;
                v = ((u / 5 + w / 5) % 2) ? 220 : 160;
                x0 = std::min(x0, x), x1 = std::max(x1, x);
                y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
            d.pixels[static_cast<size_t>(y) * frame_w + x] = v;
        }
    }
    d.disc = dsp::box{x0, y0, x1 - x0 + 1, y1 - y0 + 1};
    return d;
}

dsp::box union_of(dsp::box a, dsp::box b) {
    return dsp::bounding_union(a, b);
}

void expect_same_box(dsp::box got, dsp::box expected) {
    EXPECT_EQ(got.x, expected.x);
    EXPECT_EQ(got.y, expected.y);
    EXPECT_EQ(got.width, expected.width);
    EXPECT_EQ(got.height, expected.height);
}

struct key_fixture : ::testing::Test {
    dsp::key_frame key;
    dsp::motion_blocks blocks;
    std::vector<uint8_t> scratch = std::vector<uint8_t>(96 * 96);
    std::vector<uint8_t> row = std::vector<uint8_t>(frame_w);
    int positions = 0;

    void SetUp() override {
        key.init(frame_w, frame_h, 96);
        blocks.init(frame_w, frame_h);
    }
    bool displace(const drawn& d) {
        return key.displacement(d.plane(), scratch.data(), 28, &positions);
    }
    // A key of a 100 px disc at (90, 75), its pattern 40 px inside it.
    drawn take_large_key() {
        const drawn start = draw(90, 75, 0, large_radius);
        key.take(start.plane(), start.disc, dsp::box{start.disc.x + 30, start.disc.y + 30, 40, 40});
        return start;
    }
};

TEST(KeyedAxis, TheExtentLessTheDisplacementOnTheSideMovedTo) {
    // object(key) [100, 160), 6 px on: Dif(key, t) [100, 166) -> [106, 166).
    const dsp::span ahead = dsp::keyed_axis(dsp::span{100, 66}, 6);
    EXPECT_EQ(ahead.start, 106);
    EXPECT_EQ(ahead.size, 60);
    const dsp::span back = dsp::keyed_axis(dsp::span{94, 66}, -6);
    EXPECT_EQ(back.start, 94);
    EXPECT_EQ(back.size, 60);
    const dsp::span still = dsp::keyed_axis(dsp::span{94, 66}, 0);
    EXPECT_EQ(still.start, 94);
    EXPECT_EQ(still.size, 66);
}

TEST_F(key_fixture, DisplacementIsTheDrawnMotionWithNoRoundingCarried) {
    const drawn start = draw(80, 70);
    key.take(start.plane(), start.disc, start.disc);
    ASSERT_TRUE(key.valid());
    for (int t = 1; t <= 8; ++t) {
        ASSERT_TRUE(displace(draw(80 + t, 70 - t / 2))) << "frame " << t;
        EXPECT_EQ(key.dx(), t);
        EXPECT_EQ(key.dy(), -(t / 2));
        EXPECT_EQ(positions, 7 * 7);  // within max_step + 1 of the last
    }
}

TEST_F(key_fixture, AMoveOverMaxStepOrATurnedTextureIsNoDisplacement) {
    const drawn start = draw(80, 70);
    key.take(start.plane(), start.disc, start.disc);
    // max_step + 1 px in one pair: the best match is on the window's edge.
    EXPECT_FALSE(displace(draw(80 + dsp::key_frame::max_step + 1, 70)));
    key.take(start.plane(), start.disc, start.disc);
    EXPECT_TRUE(displace(draw(80 + dsp::key_frame::max_step, 70)));
    // The same disc with its checker turned by half a square: no match.
    key.take(start.plane(), start.disc, start.disc);
    EXPECT_FALSE(displace(draw(81, 70, 5)));
}

TEST_F(key_fixture, ATextureThatTurnedALittleMatchesButCountsAsTurned) {
    const drawn start = draw(80, 70);
    key.take(start.plane(), start.disc, start.disc);
    ASSERT_TRUE(displace(draw(81, 70)));
    EXPECT_FALSE(key.turned()) << "a texture moving with its disc";
    // The checker turned 3 px of its 5 px squares while the disc moved 1 px
    // (a shift of 1 would leave it where it was: a texture still in the
    // image matches at 0 with only the rim differing): within the lost
    // rule's 28 per pixel, over turned_mean_sad.
    key.take(start.plane(), start.disc, start.disc);
    ASSERT_TRUE(displace(draw(81, 70, 3)));
    EXPECT_TRUE(key.turned());
    key.take(start.plane(), start.disc, start.disc);
    EXPECT_FALSE(key.turned()) << "a new key has not turned";
}

TEST_F(key_fixture, MovedExtentSpansTheKeysAndTheCurrentDisc) {
    const drawn start = draw(80, 70);
    key.take(start.plane(), start.disc, start.disc);
    for (int t = 1; t <= 5; ++t) {
        const drawn now = draw(80 + t, 70 + t);
        ASSERT_TRUE(displace(now));
        if (t < 5) continue;
        const dsp::block_group g = key.moved_extent(now.plane(), 20, blocks, row.data());
        ASSERT_TRUE(g.found);
        expect_same_box(g.bbox, union_of(start.disc, now.disc));
        // object(t) from it: the current disc's box.
        const dsp::span x = dsp::keyed_axis(dsp::span{g.bbox.x, g.bbox.width}, key.dx());
        const dsp::span y = dsp::keyed_axis(dsp::span{g.bbox.y, g.bbox.height}, key.dy());
        EXPECT_EQ(x.start, now.disc.x);
        EXPECT_EQ(x.size, now.disc.width);
        EXPECT_EQ(y.start, now.disc.y);
        EXPECT_EQ(y.size, now.disc.height);
    }
}

TEST_F(key_fixture, AnExtentReachingTheRegionsEdgeIsNotTheObjects) {
    // A key box on the disc's left part only: the difference runs on past
    // the key region (object box + max_shift + margin each side, x < 112).
    const drawn start = draw(100, 75);
    const dsp::box small{78, 65, 10, 10};
    key.take(start.plane(), small, small);
    const drawn now = draw(101, 75);
    ASSERT_TRUE(displace(now));
    const dsp::block_group g = key.moved_extent(now.plane(), 20, blocks, row.data());
    EXPECT_FALSE(g.found);
}

TEST_F(key_fixture, APatternOutsideTheRegionGivesNoKey) {
    const drawn start = draw(80, 70);
    const dsp::box far_pattern{150, 10, 20, 20};
    key.take(start.plane(), start.disc, far_pattern);
    EXPECT_FALSE(key.valid());
}

}  // namespace

// A disc of 100 px, larger than twice the hole's inset: the key holds the
// region less the hole (the disc's box shrunk by hole_inset each side) and
// the pattern; its extent is still the union of the two discs, and its
// displacement the drawn motion.
TEST_F(key_fixture, ALargeKeyHoldsARingAndItsPatternAndMeasuresAlike) {
    const drawn start = take_large_key();
    ASSERT_TRUE(key.valid());
    const int inset = dsp::key_frame::hole_inset;
    const dsp::box hole = key.hole();
    EXPECT_EQ(hole.x, start.disc.x + inset);
    EXPECT_EQ(hole.y, start.disc.y + inset);
    EXPECT_EQ(hole.width, start.disc.width - 2 * inset);
    EXPECT_EQ(hole.height, start.disc.height - 2 * inset);
    const dsp::box r = key.region();
    EXPECT_EQ(key.ring_bytes(), static_cast<size_t>(r.width * r.height - hole.width * hole.height));
    EXPECT_EQ(key.stored_bytes(), key.ring_bytes() + 40 * 40);
    for (int t = 1; t <= 6; ++t) {
        const drawn now = draw(90 + t, 75 - t / 3, 0, large_radius);
        ASSERT_TRUE(displace(now)) << "frame " << t;
        EXPECT_EQ(key.dx(), t);
        EXPECT_EQ(key.dy(), -(t / 3));
        if (t < 6) continue;
        const dsp::block_group g = key.moved_extent(now.plane(), 20, blocks, row.data());
        ASSERT_TRUE(g.found);
        expect_same_box(g.bbox, union_of(start.disc, now.disc));
    }
}

// What changes inside the hole is not read: the same disc, still, its
// texture turned (every pixel of its interior changed) gives no extent,
// while the turned rim, within hole_inset of the box, does.
TEST_F(key_fixture, ALargeKeysHoleIsNotRead) {
    const drawn start = take_large_key();
    ASSERT_TRUE(key.valid());
    drawn inside = start;
    const dsp::box hole = key.hole();
    for (int y = hole.y; y < hole.bottom(); ++y)
        for (int x = hole.x; x < hole.right(); ++x)
            inside.pixels[static_cast<size_t>(y) * frame_w + x] ^= 0x80;
    EXPECT_FALSE(key.moved_extent(inside.plane(), 20, blocks, row.data()).found);
    const drawn turned = draw(90, 75, 5, large_radius);
    const dsp::block_group g = key.moved_extent(turned.plane(), 20, blocks, row.data());
    ASSERT_TRUE(g.found);
    EXPECT_EQ(g.bbox.x, start.disc.x);
    EXPECT_EQ(g.bbox.width, start.disc.width);
}

// A large disc whose rim differs from the background only in a band 30 px
// high across its middle (above and below it the disc is the background's
// gray): its two crescents, 100 px apart, face each other along 30 px only,
// so they are two groups; the hole (the disc's, counted as changed) joins
// them, and the extent spans both discs along the motion.
TEST_F(key_fixture, TheHoleJoinsALargeDiscsCrescents) {
    constexpr int large = large_radius, band = 15, cy = 75;
    auto banded = [&](int cx) {
        drawn d;
        for (int y = 0; y < frame_h; ++y)
            for (int x = 0; x < frame_w; ++x) {
                const bool lit = in_disc(x, y, cx, cy, large) && y > cy - band && y < cy + band;
                d.pixels[static_cast<size_t>(y) * frame_w + x] = lit ? 200 : 100;
            }
        d.disc = dsp::box{cx - large, cy - large, 2 * large + 1, 2 * large + 1};
        return d;
    };
    const drawn start = banded(90);
    const dsp::box pattern{70, cy - 10, 40, 20};
    key.take(start.plane(), start.disc, pattern);
    ASSERT_TRUE(key.valid());
    ASSERT_FALSE(key.hole().empty());
    const drawn now = banded(95);
    const dsp::block_group g = key.moved_extent(now.plane(), 20, blocks, row.data());
    ASSERT_TRUE(g.found);
    EXPECT_EQ(g.bbox.x, start.disc.x);
    EXPECT_EQ(g.bbox.right(), now.disc.right());
}
