// A fast object's box fitted to the last pairs' frame differences
// (dsp/extent_window.h), against extents worked out from a known motion:
// the object [s_t, s_t + size) at s_t = s_0 + v t, Dif(t-1,t)'s extent
// their union rounded to whole pixels, and rims missed by shortening an
// extent on one side (a difference reads inside the object, never outside).
// The oracle is that motion, not the fit. Within 1.5 px: the extents'
// rounding (half a pixel at each end) and the half-pixel velocity grid
// (a quarter pixel per pair of the window).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dsp/box_refit.h"
#include "dsp/extent_window.h"
#include "dsp/size_at_depth.h"

namespace {

using dsp::span;

struct motion {
    double s0, v;  // object(t) starts at s0 + v t + a t^2 / 2 (px)
    int size;
    double a = 0;
    double start(int t) const { return s0 + v * t + a * t * t / 2; }
    // Dif(t-1,t)'s extent: object(t-1) and object(t).
    span extent(int t) const {
        const double lo = std::fmin(start(t - 1), start(t));
        const double hi = std::fmax(start(t - 1), start(t)) + size;
        const int a = static_cast<int>(std::lround(lo)), b = static_cast<int>(std::lround(hi));
        return span{a, b - a};
    }
    span object(int t) const { return span{static_cast<int>(std::lround(start(t))), size}; }
};

// The window at pair t: extents t, t-1, ... newest first.
std::vector<span> window_at(const motion& m, int t, int count) {
    std::vector<span> w;
    for (int k = 0; k < count; ++k) w.push_back(m.extent(t - k));
    return w;
}

span shortened(span s, int at_start, int at_end) {
    return span{s.start + at_start, s.size - at_start - at_end};
}

span fit(const std::vector<span>& w, int size, span last) {
    span object{-1000, 0};
    EXPECT_TRUE(dsp::window_axis(w.data(), static_cast<int>(w.size()), size, last, &object));
    return object;
}

TEST(WindowAxis, EveryRimReadGivesTheObjectWhereverTheLastBoxStood) {
    for (const motion m : {motion{100.3, 25.2, 80}, motion{500.6, -30.3, 60},
                           motion{200.0, 2.3, 40}, motion{300.4, 0.0, 100}}) {
        const int t = 8;
        for (const int last_off : {0, 5, -5}) {
            span last = m.object(t - 1);
            last.start += last_off;
            const span got = fit(window_at(m, t, 4), m.size, last);
            EXPECT_NEAR(got.start, m.start(t), 1.5) << "v " << m.v << ", last off " << last_off;
            EXPECT_EQ(got.size, m.size);
        }
    }
}

// The 80 px ball over teddy: object(t)'s leading rim 7 px short now and
// 5 px short the pair before. The difference alone puts object(t) that far
// behind (follow_axis); the window holds it by the trailing rims.
TEST(WindowAxis, LeadingRimsReadShortDoNotLeaveTheBoxBehind) {
    const motion m{100.3, 25.2, 80};
    const int t = 8;
    std::vector<span> w = window_at(m, t, 4);
    w[0] = shortened(w[0], 0, 7);
    w[1] = shortened(w[1], 0, 5);
    const span alone =
        dsp::follow_axis(span{w[0].start, w[1].end() - w[0].start}, w[0], m.object(t - 1), m.size);
    EXPECT_LT(alone.start, m.start(t) - 5.0) << "the case must be one a single pair misses";
    EXPECT_NEAR(fit(w, m.size, m.object(t - 1)).start, m.start(t), 1.5);

    const motion left{600.2, -25.2, 80};  // the same leftwards
    std::vector<span> wl = window_at(left, t, 4);
    wl[0] = shortened(wl[0], 7, 0);
    wl[1] = shortened(wl[1], 5, 0);
    EXPECT_NEAR(fit(wl, left.size, left.object(t - 1)).start, left.start(t), 1.5);
}

// A trailing rim read 3 px inside (a 90 px ball over venus): a velocity
// taken from the trailing rims alone would put the box 6 px ahead.
TEST(WindowAxis, ATrailingRimReadInsideDoesNotPushTheBoxAhead) {
    const motion m{272.0, 30.0, 90};
    const int t = 6;
    std::vector<span> w = window_at(m, t, 3);
    w[0] = shortened(w[0], 3, 0);
    EXPECT_NEAR(fit(w, m.size, m.object(t - 1)).start, m.start(t), 1.5);
}

// Across a pass, 2.3 px per pair down, the ball's bottom missed by 9 px in
// every pair (its shaded side): the tops still place it.
TEST(WindowAxis, AnEdgeMissedInEveryPairAcrossTheMotion) {
    const motion m{208.3, 2.3, 40};
    const int t = 9;
    std::vector<span> w = window_at(m, t, 4);
    for (span& e : w) e = shortened(e, 0, 9);
    EXPECT_NEAR(fit(w, m.size, m.object(t - 1)).start, m.start(t), 1.5);
}

// The same with the bottom short by 3-7 px, a different amount each pair,
// and the last box 5 px behind: the tops agree over the window, the
// bottoms do not, so object(t) stands on the tops' bound. Moved by the
// velocity and held inside the bounds, the box would keep 3 px of its lag.
// Leftwards the same with the leading (left) rims short.
TEST(WindowAxis, ARimReadAlikeInEveryPairPlacesTheBox) {
    const int t = 9;
    const motion down{208.3, 2.3, 40};
    std::vector<span> w = window_at(down, t, 4);
    const int short_by[4] = {3, 5, 7, 4};
    for (int k = 0; k < 4; ++k) w[k] = shortened(w[k], 0, short_by[k]);
    span behind = down.object(t - 1);
    behind.start -= 5;
    EXPECT_NEAR(fit(w, down.size, behind).start, down.start(t), 1.0);

    const motion left{600.2, -25.2, 80};
    std::vector<span> wl = window_at(left, t, 4);
    for (int k = 0; k < 4; ++k) wl[k] = shortened(wl[k], short_by[k], 0);
    span behind_left = left.object(t - 1);
    behind_left.start += 5;
    EXPECT_NEAR(fit(wl, left.size, behind_left).start, left.start(t), 1.0);
}

// A ball on a circle slows on one axis as it turns, 2-4 px a pair every
// pair (a 44 px ball circling at 20 px a frame): one velocity over the
// window is its speed a pair or two ago, and the box is placed past the
// ball. Every rim read, the last box on object(t-1).
TEST(WindowAxis, ASpeedThatChangesEveryPairIsFollowed) {
    const int t = 8;
    for (const motion m : {motion{100.3, 30.2, 44, -3.0}, motion{700.6, -40.3, 44, 4.1},
                           motion{300.0, 5.0, 60, 2.2}, motion{400.4, 20.0, 80, -2.5}}) {
        const span got = fit(window_at(m, t, 4), m.size, m.object(t - 1));
        EXPECT_NEAR(got.start, m.start(t), 1.5) << "v " << m.v << ", a " << m.a;
    }
}

// Faster changes, 6-8 px a pair every pair (a ball circling at 30 px a
// frame on a 110-150 px radius, v^2 / R, where it turns on that axis): the
// steps' median is the velocity a pair before the last, over 6 px from the
// last pair's, so the velocity is searched around the median moved by the
// change. Every rim read, the last box on object(t-1); no reversal within
// the window.
TEST(WindowAxis, ASpeedThatChangesFastIsSearchedAroundTheLastPairs) {
    const int t = 8;
    for (const motion m : {motion{100.3, -20.0, 40, 6.0}, motion{700.6, 25.4, 40, -6.0},
                           motion{200.2, -30.0, 60, 8.0}, motion{900.7, 33.1, 60, -8.0}}) {
        const span got = fit(window_at(m, t, 4), m.size, m.object(t - 1));
        EXPECT_NEAR(got.start, m.start(t), 1.5) << "v " << m.v << ", a " << m.a;
    }
}

// Edges read 1 px off from pair to pair (each extent's rounding, or a rim
// read a pixel short) make every second difference 1 px the same way at a
// constant velocity: no change of speed, so the fit stays where the
// motion puts the ball.
TEST(WindowAxis, AChangeWithinTheRoundingIsNoChangeOfSpeed) {
    const int t = 8;
    for (const motion m : {motion{218.0, 8.0, 22}, motion{400.0, -10.0, 30}}) {
        std::vector<span> w = window_at(m, t, 4);
        w[0] = shortened(w[0], 1, 0);
        w[3] = shortened(w[3], 1, 0);
        w[1] = shortened(w[1], 0, 1);
        w[2] = shortened(w[2], 0, 1);
        const span got = fit(w, m.size, m.object(t - 1));
        EXPECT_NEAR(got.start, m.start(t), 1.0) << "v " << m.v;
    }
    // Three extents hold one second difference an edge: both 2 px the same
    // way here (the newest and oldest starts and the middle end a pixel
    // short), which two rims read short make as well as a change of speed.
    const motion m{218.0, 8.0, 22};
    std::vector<span> w = window_at(m, t, 3);
    w[0] = shortened(w[0], 1, 0);
    w[2] = shortened(w[2], 1, 0);
    w[1] = shortened(w[1], 0, 1);
    EXPECT_NEAR(fit(w, m.size, m.object(t - 1)).start, m.start(t), 1.0);
}

// Rims read 1-2 px short in some pairs, at a constant velocity, can make
// three second differences 2-3 px the same way and the fourth none: a
// change that not every edge shows is not read.
TEST(WindowAxis, AChangeNotEveryEdgeShowsIsNotRead) {
    const int t = 8;
    const motion m{218.0, 8.0, 22};
    std::vector<span> w = window_at(m, t, 4);
    const int start_short[4] = {2, 0, 0, 2}, end_short[4] = {0, 2, 1, 0};
    for (int k = 0; k < 4; ++k) w[k] = shortened(w[k], start_short[k], end_short[k]);
    EXPECT_NEAR(fit(w, m.size, m.object(t - 1)).start, m.start(t), 1.0);
}

TEST(WindowAxis, FewerThanThreeExtentsAreNotFitted) {
    const motion m{100.0, 20.0, 50};
    const std::vector<span> w = window_at(m, 5, 2);
    span object{7, 7};
    EXPECT_FALSE(dsp::window_axis(w.data(), 2, m.size, m.object(4), &object));
    EXPECT_EQ(object.start, 7);
    EXPECT_EQ(object.size, 7);
}

// Bounds that cross (the object smaller than its extents say: it grew, or
// the size kept is short): object(t) midway between them, not wherever the
// last box was.
TEST(WindowAxis, CrossingBoundsGiveTheirMiddle) {
    const motion m{100.0, 10.0, 50};
    const int t = 6;
    const std::vector<span> w = window_at(m, t, 4);
    // 10 px too small: its end's bound 10 px past its start's.
    const span got = fit(w, m.size - 10, span{0, m.size - 10});
    EXPECT_NEAR(got.start, m.start(t) + 5.0, 1.5);
}

// Extents read before the track had a disparity (its detection's) take the
// first one measured; those read with one keep it.
TEST(ExtentWindow, ExtentsReadWithoutADisparityTakeTheFirstMeasured) {
    dsp::extent_window w;
    w.push(span{100, 50}, span{80, 50});  // at the detection: none yet
    w.give_depth(9900);                   // the detection pair's, measured after
    w.push(span{104, 49}, span{80, 49}, 9900);
    w.push(span{108, 48}, span{81, 48}, 9800);
    w.give_depth(9700);  // none left without one
    ASSERT_EQ(w.count, 3);
    EXPECT_EQ(w.depth_q8[0], 9800);
    EXPECT_EQ(w.depth_q8[1], 9900);
    EXPECT_EQ(w.depth_q8[2], 9900);
    // Narrowed to the depth now as the others are (dsp/size_at_depth.h).
    span now[3];
    dsp::extents_at_depth(w.x, w.depth_q8, w.count, 48, 9700, now);
    EXPECT_LT(now[2].size, 50);
}

// The 140 px ball over teddy at 6.1 px per pair: its leading rim 12-29 px
// short in the last pairs. The reach of Dif(t-1,t) past object(t-1), the
// firmware's first measure of a motion, then reads none; the window's
// median step still reads the motion.
TEST(WindowStep, AShortLeadingRimDoesNotHideTheMotion) {
    const motion m{260.0, 6.1, 140};
    const int t = 16;
    std::vector<span> w = window_at(m, t, 4);
    const int short_by[4] = {29, 25, 12, 27};
    for (int k = 0; k < 4; ++k) w[k] = shortened(w[k], 0, short_by[k]);
    const span previous = dsp::previous_axis(w[1], w[0], m.size);
    EXPECT_LT(w[0].size - previous.size, 4) << "the case must be one the reach misses";
    const int step2 = dsp::window_step2(w.data(), 4, m.size);
    EXPECT_NEAR(step2 / 2.0, m.v, 1.0);
    // Leftwards the same, negative.
    const motion left{500.0, -6.1, 140};
    std::vector<span> wl = window_at(left, t, 4);
    for (int k = 0; k < 4; ++k) wl[k] = shortened(wl[k], short_by[k], 0);
    EXPECT_NEAR(dsp::window_step2(wl.data(), 4, left.size) / 2.0, left.v, 1.0);
}

// A slowly turning texture's differences: pieces of the object, their
// edges jumping from pair to pair. One extent under half the box: no
// motion is read from the window (the reach alone decides).
TEST(WindowStep, PiecesOfTheObjectReadNoMotion) {
    const motion m{220.0, 0.5, 90};
    std::vector<span> w = window_at(m, 24, 4);
    w[1] = span{221, 16};
    w[2] = span{285, 28};  // a piece 60 px away: a step of 30 px if read
    EXPECT_EQ(dsp::window_step2(w.data(), 4, m.size), 0);
    const std::vector<span> whole = window_at(m, 24, 4);
    EXPECT_EQ(dsp::window_step2(whole.data(), 2, m.size), 0) << "fewer than three extents";
    EXPECT_NEAR(dsp::window_step2(whole.data(), 4, m.size) / 2.0, m.v, 0.5);
}

// A leading rim missed more from pair to pair (a shaded side entering a dark
// background): extent t shortened at its leading side by `missed` px more
// each pair, so that side moves `missed` px a pair less than the object.
std::vector<span> fading_window(const motion& m, int t, int count, int missed) {
    std::vector<span> w = window_at(m, t, count);
    for (int k = 0; k < count; ++k) {
        const int cut = missed * (count - k);
        w[k] = m.v > 0 ? shortened(w[k], 0, cut) : shortened(w[k], cut, 0);
    }
    return w;
}

// object(t) where the window reads a fading rim (the test fails where it
// does not); `last` is object(t-1), where the box stood when it was right.
span from_fading(const std::vector<span>& w, const std::vector<int64_t>& depth_q8, int size,
                 span last) {
    const int step2 =
        dsp::fading_rim_step2(w.data(), depth_q8.data(), static_cast<int>(w.size()), last);
    EXPECT_NE(step2, 0) << "no fading rim read";
    return step2 ? dsp::from_trailing_edge(w[0], step2, size) : span{-1000, 0};
}

const std::vector<int64_t> no_depth(4, 0);

TEST(FadingRim, ALeadingRimMissedMoreEachPairLeavesTheTrailingEdgeToPlaceTheObject) {
    for (const motion m : {motion{297.3, 3.7, 82}, motion{400.6, -3.4, 60}, motion{120.0, 5.4, 140},
                           motion{250.2, -4.1, 40}}) {
        const int t = 10;
        const double speed = std::fabs(m.v);
        // From 1 px a pair (the leading edge moving on) to a quarter more
        // than the object's step (the leading edge going back).
        for (const int missed : {1, static_cast<int>(std::lround(speed)),
                                 static_cast<int>(std::floor(5 * speed / 4))}) {
            const std::vector<span> w = fading_window(m, t, 4, missed);
            const span got = from_fading(w, no_depth, m.size, m.object(t - 1));
            EXPECT_NEAR(got.start, m.start(t), 1.0)
                << "v " << m.v << " size " << m.size << " missed " << missed;
            EXPECT_EQ(got.size, m.size);
        }
    }
}

// A ball coming nearer, growing 2 px a pair about its centre while it moves
// 4 px a pair, its disparity growing with its size: its leading rim missed
// 2 px more each pair, so the extent read keeps its width.
TEST(FadingRim, AGrowingObjectsRimIsJudgedAgainstItsSizeAtTheDepth) {
    const double s0 = 250.3, v = 4.0, size0 = 100.0, growth = 2.0;
    const int t = 12, count = 4, missed = 2;
    auto start = [&](int n) { return s0 + v * n - growth * n / 2; };
    auto size = [&](int n) { return size0 + growth * n; };
    std::vector<span> w;
    std::vector<int64_t> depth_q8;
    for (int k = 0; k < count; ++k) {
        const int n = t - k;
        const int a = static_cast<int>(std::lround(start(n - 1)));
        const int b = static_cast<int>(std::lround(start(n) + size(n)));
        w.push_back(shortened(span{a, b - a}, 0, missed * (count - k)));
        depth_q8.push_back(static_cast<int64_t>(std::lround(256.0 * size(n) / 4.0)));
    }
    const span last{static_cast<int>(std::lround(start(t - 1))),
                    static_cast<int>(std::lround(size(t - 1)))};
    const int now = static_cast<int>(std::lround(size(t)));
    const span got = from_fading(w, depth_q8, now, last);
    EXPECT_NEAR(got.start, start(t), 1.0);
    // As read, the newest extent is as wide as the oldest: no rim missed.
    EXPECT_EQ(dsp::fading_rim_step2(w.data(), no_depth.data(), count, last), 0);
}

TEST(FadingRim, NotReadWhereTheRimsAreReadOrTheObjectDoesNotMoveSteadily) {
    const motion m{297.3, 3.7, 82};
    const span last = m.object(9);
    const std::vector<span> whole = window_at(m, 10, 4);
    EXPECT_EQ(dsp::fading_rim_step2(whole.data(), no_depth.data(), 4, last), 0) << "every rim read";
    const std::vector<span> w = fading_window(m, 10, 4, 4);
    EXPECT_EQ(dsp::fading_rim_step2(w.data(), no_depth.data(), 2, last), 0)
        << "fewer than three extents";
    // Both edges moving alike: the rim missed by as much in every pair.
    std::vector<span> alike = window_at(m, 10, 4);
    for (span& e : alike) e = shortened(e, 0, 10);
    EXPECT_EQ(dsp::fading_rim_step2(alike.data(), no_depth.data(), 4, last), 0) << "a steady miss";
    // A ball going away: its trailing edge 3 px a pair, its leading edge
    // 1-2 px, its extent shrinking 1.3 px a pair as its disparity does (2.45 %
    // a pair); read without the disparities, a rim missed.
    const std::vector<span> receding{{253, 51}, {250, 53}, {247, 54}, {244, 55}};
    const std::vector<int64_t> receding_q8{2560, 2624, 2690, 2757};
    EXPECT_EQ(dsp::fading_rim_step2(receding.data(), receding_q8.data(), 4, span{252, 52}), 0)
        << "shrinking with its disparity";
    EXPECT_NE(dsp::fading_rim_step2(receding.data(), no_depth.data(), 4, span{252, 52}), 0)
        << "the disparities not read";
    // A throw near its apex, rising 21, 15, then 9 px a pair (its top
    // turning): both edges slow down alike.
    const std::vector<span> apex{{164, 29}, {163, 39}, {170, 47}, {186, 52}};
    EXPECT_EQ(dsp::fading_rim_step2(apex.data(), no_depth.data(), 4, span{163, 31}), 0)
        << "a speed that changes";
    // A slow object: a step of 2 px in a pair (a 150 px ball passing at
    // 1.5 px a frame read 4, 2, 2 px, its extent 4 px short once).
    const std::vector<span> slow{{197, 148}, {193, 151}, {191, 152}, {189, 152}};
    EXPECT_EQ(dsp::fading_rim_step2(slow.data(), no_depth.data(), 4, span{194, 150}), 0)
        << "a step of 2 px";
    // A spinning ball's texture: a piece inside the box moving across it.
    const std::vector<span> piece{{197, 71}, {193, 75}, {190, 78}, {187, 81}};
    EXPECT_EQ(dsp::fading_rim_step2(piece.data(), no_depth.data(), 4, span{186, 82}), 0)
        << "the trailing edge 11 px inside the last box";
    // The leading edge moving, the trailing one standing: follow_axis's.
    const motion back{400.6, -3.6, 60};
    std::vector<span> lead = window_at(back, 10, 4);
    for (int k = 0; k < 4; ++k) lead[k] = shortened(lead[k], 0, 4 * k + 5);
    EXPECT_EQ(dsp::fading_rim_step2(lead.data(), no_depth.data(), 4, back.object(9)), 0)
        << "the leading edge moved";
}

}  // namespace
