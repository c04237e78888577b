// SAD tracking (dsp/tracker.h) on synthetic scenes whose truth is known
// exactly: a textured object moving by known integer shifts over a textured
// background is found at its true position with SAD 0 in every frame; the
// track is reported lost when the object leaves the image or is replaced by
// unrelated texture; with a motion mask the pattern size converges to the
// object's size by the documented step rule; no allocation per update.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "dsp/tracker.h"
#include "tests/support/heap_counter.h"

namespace {

struct gray_image {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;
    gray_image(int w, int h, uint8_t fill = 0)
        : width(w), height(h), pixels(static_cast<size_t>(w) * h, fill) {}
    uint8_t& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
    dsp::gray_cplane view() const { return dsp::gray_cplane{pixels.data(), width, height, width}; }
};

gray_image random_texture(int w, int h, int lo, int hi, std::mt19937& rng) {
    gray_image t(w, h);
    for (uint8_t& v : t.pixels)
        v = static_cast<uint8_t>(lo + static_cast<int>(rng() % (hi - lo + 1)));
    return t;
}

// The background with the object pasted at (x, y), clipped to the frame.
gray_image compose(const gray_image& background, const gray_image& object, int x, int y) {
    gray_image frame = background;
    for (int j = 0; j < object.height; ++j) {
        for (int i = 0; i < object.width; ++i) {
            const int fx = x + i, fy = y + j;
            if (fx >= 0 && fy >= 0 && fx < frame.width && fy < frame.height)
                frame.at(fx, fy) = object.pixels[static_cast<size_t>(j) * object.width + i];
        }
    }
    return frame;
}

gray_image silhouette(int w, int h, int x, int y, int ow, int oh) {
    gray_image mask(w, h);
    for (int j = std::max(y, 0); j < std::min(y + oh, h); ++j)
        for (int i = std::max(x, 0); i < std::min(x + ow, w); ++i) mask.at(i, j) = 255;
    return mask;
}

dsp::track_params params_with_radius(int radius) {
    dsp::track_params p;
    p.search_radius = radius;
    return p;
}

TEST(sad_tracker, follows_known_shifts_exactly) {
    std::mt19937 rng(17);
    const gray_image background = random_texture(200, 150, 0, 255, rng);
    const gray_image object = random_texture(24, 20, 0, 255, rng);
    // Shifts up to the radius (8) in both directions, a pause, diagonal moves.
    const int shifts[][2] = {{3, 1},  {-2, 4}, {5, -3}, {0, 0},   {8, 8},   {-8, -8},
                             {7, 2},  {-6, 5}, {1, -7}, {4, 4},   {-3, -1}, {2, 6},
                             {-8, 3}, {6, -2}, {0, 8},  {-5, -5}, {8, -8},  {1, 1}};
    int x = 80, y = 60;
    dsp::sad_tracker tracker;
    tracker.init(params_with_radius(8));
    tracker.start(compose(background, object, x, y).view(), dsp::box{x, y, 24, 20});
    int frames = 0;
    long allocations = 0;
    for (const auto& s : shifts) {
        x += s[0];
        y += s[1];
        const gray_image frame = compose(background, object, x, y);
        const test_support::heap_counter heap;
        const dsp::track_status status = tracker.update(frame.view());
        allocations += heap.allocations();
        ASSERT_EQ(status, dsp::track_status::tracking) << "frame " << frames;
        EXPECT_EQ(tracker.position().x, x) << "frame " << frames;
        EXPECT_EQ(tracker.position().y, y) << "frame " << frames;
        EXPECT_EQ(tracker.last_match().sad, 0u) << "frame " << frames;
        EXPECT_EQ(tracker.last_match().positions, 17 * 17);
        EXPECT_EQ(tracker.position().width, 24);  // no mask: size kept
        EXPECT_EQ(tracker.position().height, 20);
        ++frames;
    }
    std::printf(
        "tracked %d frames exactly (SAD 0 at the true shift), final (%d,%d); "
        "allocations in update(): %ld\n",
        frames, tracker.position().x, tracker.position().y, allocations);
    EXPECT_EQ(allocations, 0);
}

TEST(sad_tracker, lost_when_the_object_leaves_the_image) {
    std::mt19937 rng(23);
    const gray_image background = random_texture(160, 100, 0, 255, rng);
    const gray_image object = random_texture(24, 20, 0, 255, rng);
    const int w = 24, right_limit = 160 - w;  // last top-left x fully inside
    dsp::sad_tracker tracker;
    tracker.init(params_with_radius(6));
    int x = 100;
    tracker.start(compose(background, object, x, 40).view(), dsp::box{x, 40, w, 20});
    int tracked = 0, lost_at_x = -1;
    for (int t = 1; t <= 20 && lost_at_x < 0; ++t) {
        x += 4;
        const dsp::track_status status = tracker.update(compose(background, object, x, 40).view());
        if (status == dsp::track_status::lost) {
            lost_at_x = x;
            break;
        }
        ++tracked;
        EXPECT_EQ(tracker.position().x, x);
        EXPECT_EQ(tracker.position().y, 40);
    }
    std::printf(
        "object leaving to the right: tracked %d frames exactly, lost when its left edge "
        "reached x = %d (fully inside up to x = %d)\n",
        tracked, lost_at_x, right_limit);
    // Lost exactly when the best match sits on the clipped window edge:
    // the object touches the border (x = 136) and may go on beyond it.
    EXPECT_EQ(lost_at_x, right_limit);
    EXPECT_EQ(tracked, (right_limit - 100) / 4 - 1);
    // Lost is sticky: further frames do not revive the track.
    EXPECT_EQ(tracker.update(compose(background, object, 100, 40).view()), dsp::track_status::lost);
    EXPECT_EQ(tracker.status(), dsp::track_status::lost);
}

TEST(sad_tracker, lost_when_the_object_is_replaced_by_unrelated_texture) {
    std::mt19937 rng(29);
    const gray_image background = random_texture(160, 120, 0, 255, rng);
    const gray_image object = random_texture(24, 24, 0, 255, rng);
    const gray_image stranger = random_texture(24, 24, 0, 255, rng);
    dsp::sad_tracker tracker;
    tracker.init(params_with_radius(8));  // lost_mean_sad = 28 (default)
    tracker.start(compose(background, object, 60, 50).view(), dsp::box{60, 50, 24, 24});
    ASSERT_EQ(tracker.update(compose(background, object, 63, 52).view()),
              dsp::track_status::tracking);
    EXPECT_EQ(tracker.last_match().sad, 0u);
    const dsp::track_status status = tracker.update(compose(background, stranger, 65, 53).view());
    const double mean = tracker.last_match().sad / (24.0 * 24.0);
    std::printf(
        "object replaced by unrelated texture: best mean |diff| %.1f per pixel "
        "(limit %u) -> %s\n",
        mean, tracker.params().lost_mean_sad,
        status == dsp::track_status::lost ? "lost" : "tracking");
    EXPECT_EQ(status, dsp::track_status::lost);
    EXPECT_GT(mean, 28.0);
    // Lost keeps the last good box; start() resumes tracking.
    EXPECT_EQ(tracker.position().x, 63);
    EXPECT_EQ(tracker.position().y, 52);
    tracker.start(compose(background, stranger, 65, 53).view(), dsp::box{65, 53, 24, 24});
    EXPECT_EQ(tracker.update(compose(background, stranger, 66, 53).view()),
              dsp::track_status::tracking);
    EXPECT_EQ(tracker.position().x, 66);
}

// The size rule with an exact motion mask (the object's silhouette): the
// size moves towards the object's by max(1, size / 8) px per frame.
void expect_size_converges(int start_size, const std::vector<int>& expected_sizes,
                           int background_lo, int background_hi) {
    std::mt19937 rng(31);
    const int fw = 200, fh = 160, side = 24;
    const gray_image background = random_texture(fw, fh, background_lo, background_hi, rng);
    const gray_image object = random_texture(side, side, 0, 255, rng);
    int x = 60, y = 50;
    dsp::sad_tracker tracker;
    dsp::track_params p = params_with_radius(6);
    p.min_size = 8;
    p.max_size = 64;
    tracker.init(p);
    const int offset = (side - start_size) / 2;
    tracker.start(compose(background, object, x, y).view(),
                  dsp::box{x + offset, y + offset, start_size, start_size});
    std::vector<int> sizes;
    for (int t = 0; t < static_cast<int>(expected_sizes.size()); ++t) {
        x += 3;
        y += (t % 2) ? 2 : -1;
        const gray_image frame = compose(background, object, x, y);
        const gray_image mask = silhouette(fw, fh, x, y, side, side);
        ASSERT_EQ(tracker.update(frame.view(), mask.view()), dsp::track_status::tracking);
        const dsp::box b = tracker.position();
        sizes.push_back(b.width);
        EXPECT_EQ(b.width, b.height);
        // The box stays on the object: its centre within 2 px of the object's.
        EXPECT_LE(std::abs(b.center_x2() - (2 * x + side - 1)), 4) << "frame " << t;
        EXPECT_LE(std::abs(b.center_y2() - (2 * y + side - 1)), 4) << "frame " << t;
    }
    std::printf("size rule from %d: ", start_size);
    for (int s : sizes) std::printf("%d ", s);
    std::printf("(object %d)\n", side);
    EXPECT_EQ(sizes, expected_sizes);
}

TEST(sad_tracker, size_grows_to_the_object_with_a_motion_mask) {
    // 16 -> steps of 2 -> 24, then stays.
    expect_size_converges(16, {18, 20, 22, 24, 24, 24}, 0, 255);
}

TEST(sad_tracker, size_shrinks_to_the_object_with_a_motion_mask) {
    // 40 -> steps of max(1, size / 8) = 5, 4, 3, 3, 1 -> 24. The box starts with an 8 px ring of
    // background, which does not move with the object: a low-contrast
    // background keeps that ring from outweighing the object in the SAD.
    expect_size_converges(40, {35, 31, 28, 25, 24, 24}, 120, 127);
}

TEST(sad_tracker, size_kept_when_the_mask_is_empty) {
    std::mt19937 rng(37);
    const gray_image background = random_texture(120, 100, 0, 255, rng);
    const gray_image object = random_texture(20, 20, 0, 255, rng);
    const gray_image empty_mask(120, 100, 0);
    dsp::sad_tracker tracker;
    tracker.init(params_with_radius(4));
    tracker.start(compose(background, object, 40, 40).view(), dsp::box{40, 40, 20, 20});
    for (int t = 1; t <= 4; ++t) {
        ASSERT_EQ(tracker.update(compose(background, object, 40 + t, 40).view(), empty_mask.view()),
                  dsp::track_status::tracking);
        EXPECT_EQ(tracker.position().x, 40 + t);
        EXPECT_EQ(tracker.position().width, 20);
    }
}

TEST(sad_tracker, start_clamps_the_box_to_the_limits_and_the_frame) {
    std::mt19937 rng(41);
    const gray_image frame = random_texture(100, 80, 0, 255, rng);
    dsp::sad_tracker tracker;
    dsp::track_params p;
    p.min_size = 8;
    p.max_size = 32;
    tracker.init(p);
    // 60 x 4 around centre (49.5, 41.5): the object box keeps its width and
    // grows to min_size in height (60 x 8, centre kept); the pattern is its
    // centred crop of at most max_size: 32 x 8 at (34, 38).
    tracker.start(frame.view(), dsp::box{20, 40, 60, 4});
    EXPECT_EQ(tracker.position().x, 20);
    EXPECT_EQ(tracker.position().y, 38);
    EXPECT_EQ(tracker.position().width, 60);
    EXPECT_EQ(tracker.position().height, 8);
    EXPECT_EQ(tracker.pattern_box().x, 34);
    EXPECT_EQ(tracker.pattern_box().y, 38);
    EXPECT_EQ(tracker.pattern_box().width, 32);
    EXPECT_EQ(tracker.pattern_box().height, 8);
    EXPECT_EQ(tracker.pattern().at(0, 0), frame.view().at(34, 38));
    // Wider than the frame: the frame's width.
    tracker.start(frame.view(), dsp::box{-10, 10, 130, 20});
    EXPECT_EQ(tracker.position().x, 0);
    EXPECT_EQ(tracker.position().width, 100);
    EXPECT_EQ(tracker.pattern_box().x, 34);
    // Partly outside -> moved inside.
    tracker.start(frame.view(), dsp::box{90, -5, 20, 20});
    EXPECT_EQ(tracker.position().x, 80);
    EXPECT_EQ(tracker.position().y, 0);
    const dsp::gray_cplane pattern = tracker.pattern();
    EXPECT_EQ(pattern.at(0, 0), frame.view().at(80, 0));
    EXPECT_EQ(pattern.at(19, 19), frame.view().at(99, 19));
}

// An object wider than max_size is tracked by its centred pattern and the
// box moves with it: a 60 x 40 box on a texture shifted by (+5, -3).
TEST(sad_tracker, large_box_moves_with_its_centred_pattern) {
    std::mt19937 rng(43);
    const gray_image first = random_texture(160, 120, 0, 255, rng);
    gray_image second = first;
    for (int y = 0; y < 120; ++y)
        for (int x = 0; x < 160; ++x) {
            const int sx = x - 5, sy = y + 3;
            second.at(x, y) =
                (sx >= 0 && sy < 120) ? first.view().at(sx, sy) : static_cast<uint8_t>(0);
        }
    dsp::sad_tracker tracker;
    dsp::track_params p;
    p.max_size = 24;
    p.search_radius = 8;
    tracker.init(p);
    tracker.start(first.view(), dsp::box{50, 40, 60, 40});
    ASSERT_EQ(tracker.pattern_box().width, 24);
    ASSERT_EQ(tracker.update(second.view()), dsp::track_status::tracking);
    EXPECT_EQ(tracker.position().x, 55);
    EXPECT_EQ(tracker.position().y, 37);
    EXPECT_EQ(tracker.position().width, 60);
    EXPECT_EQ(tracker.position().height, 40);
    EXPECT_EQ(tracker.pattern_box().x, 55 + 18);
    EXPECT_EQ(tracker.pattern_box().y, 37 + 8);
}

TEST(sad_tracker, update_near_finds_an_object_beyond_the_radius_where_it_is_expected) {
    std::mt19937 rng(5);
    const gray_image background = random_texture(200, 150, 0, 255, rng);
    const gray_image object = random_texture(24, 20, 0, 255, rng);
    dsp::sad_tracker tracker;
    tracker.init(params_with_radius(8));
    tracker.start(compose(background, object, 40, 60).view(), dsp::box{40, 60, 24, 20});
    // 30 px to the right: three radii away from the window around (40, 60).
    const gray_image moved = compose(background, object, 70, 61);
    dsp::sad_tracker around_last;
    around_last.init(params_with_radius(8));
    around_last.start(compose(background, object, 40, 60).view(), dsp::box{40, 60, 24, 20});
    around_last.update(moved.view());
    EXPECT_FALSE(around_last.position().x == 70 && around_last.position().y == 61);
    // Expected 3 px off the truth: found exactly, the window centred there.
    ASSERT_EQ(tracker.update_near(moved.view(), dsp::box{67, 63, 24, 20}),
              dsp::track_status::tracking);
    EXPECT_EQ(tracker.position().x, 70);
    EXPECT_EQ(tracker.position().y, 61);
    EXPECT_EQ(tracker.last_match().sad, 0u);
    EXPECT_EQ(tracker.last_search_window().x, 67 - 8);
    EXPECT_EQ(tracker.last_search_window().y, 63 - 8);
}

}  // namespace
