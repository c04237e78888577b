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
    double s0, v;  // object(t) starts at s0 + v t (px)
    int size;
    double start(int t) const { return s0 + v * t; }
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
// each pair, so that side stands while the object moves.
std::vector<span> fading_window(const motion& m, int t, int count, int missed) {
    std::vector<span> w = window_at(m, t, count);
    for (int k = 0; k < count; ++k) {
        const int cut = missed * (count - k);
        w[k] = m.v > 0 ? shortened(w[k], 0, cut) : shortened(w[k], cut, 0);
    }
    return w;
}

// The last box: object(t-1), where the box stood when it was right.
span trailing(const std::vector<span>& w, int size, span last) {
    span object{-1000, 0};
    EXPECT_TRUE(dsp::trailing_edge_axis(w.data(), static_cast<int>(w.size()), size, last, &object));
    return object;
}

TEST(TrailingEdge, ALeadingRimMissedMoreEachPairLeavesTheTrailingEdgeToPlaceTheObject) {
    for (const motion m : {motion{297.3, 3.7, 82}, motion{400.6, -2.6, 60}, motion{120.0, 5.4, 140},
                           motion{250.2, -3.1, 40}}) {
        const int t = 10;
        // The leading edge standing, or moving up to a quarter of the
        // object's step either way.
        const double speed = std::fabs(m.v);
        for (const int missed :
             {static_cast<int>(std::ceil(3 * speed / 4)), static_cast<int>(std::lround(speed)),
              static_cast<int>(std::floor(5 * speed / 4))}) {
            const std::vector<span> w = fading_window(m, t, 4, missed);
            const span got = trailing(w, m.size, m.object(t - 1));
            EXPECT_NEAR(got.start, m.start(t), 1.0)
                << "v " << m.v << " size " << m.size << " missed " << missed;
            EXPECT_EQ(got.size, m.size);
        }
    }
}

TEST(TrailingEdge, NotReadWhereTheRimsAreReadOrTheObjectDoesNotMoveSteadily) {
    span object{-1000, 0};
    const motion m{297.3, 3.7, 82};
    const span last = m.object(9);
    const std::vector<span> whole = window_at(m, 10, 4);
    EXPECT_FALSE(dsp::trailing_edge_axis(whole.data(), 4, m.size, last, &object))
        << "every rim read: the extent spans the object";
    const std::vector<span> w = fading_window(m, 10, 4, 4);
    EXPECT_FALSE(dsp::trailing_edge_axis(w.data(), 2, m.size, last, &object))
        << "fewer than three extents";
    // Both edges moving alike: the rim missed by as much in every pair.
    std::vector<span> alike = window_at(m, 10, 4);
    for (span& e : alike) e = shortened(e, 0, 10);
    EXPECT_FALSE(dsp::trailing_edge_axis(alike.data(), 4, m.size, last, &object))
        << "a steady miss";
    // A slow ball going away: its trailing edge 2-3 px a pair, its leading
    // edge 1 px (a third of that or more: it moves, and shrinks).
    const std::vector<span> receding{{251, 51}, {248, 53}, {246, 54}, {244, 55}};
    EXPECT_FALSE(dsp::trailing_edge_axis(receding.data(), 4, 60, span{250, 60}, &object))
        << "the leading edge moved a third as far";
    // A slow object's texture: pieces stepping under 2 px in a pair.
    const std::vector<span> slow{{223, 70}, {222, 71}, {219, 74}, {217, 76}};
    EXPECT_FALSE(dsp::trailing_edge_axis(slow.data(), 4, 90, span{222, 90}, &object))
        << "a step of 1 px";
    // A spinning ball's texture: a piece inside the box moving across it.
    const std::vector<span> piece{{195, 71}, {191, 75}, {189, 77}, {187, 79}};
    EXPECT_FALSE(dsp::trailing_edge_axis(piece.data(), 4, 81, span{186, 81}, &object))
        << "the trailing edge 9 px inside the last box";
    // The leading edge moving, the trailing one standing: follow_axis's.
    const motion back{400.6, -3.6, 60};
    std::vector<span> lead = window_at(back, 10, 4);
    for (int k = 0; k < 4; ++k) lead[k] = shortened(lead[k], 0, 4 * k + 5);
    EXPECT_FALSE(dsp::trailing_edge_axis(lead.data(), 4, back.size, back.object(9), &object))
        << "the leading edge moved";
    EXPECT_EQ(object.start, -1000) << "nothing written";
}

}  // namespace
