// The box refit's axis rules (dsp/box_refit.h), each against extents worked
// out by hand: object(t) ends where Dif(t-1,t) reaches past object(t-1),
// object(t-1) is the common part of the two differences unless they share
// one edge only (the motion reversed), the SAD box's pull keeps its
// documented step, and Dif(key, t) reads a displacement only where one side
// reaches past the key's box and the other does not. A box placed past
// Dif(t-1,t)'s extent is held at its end where the SAD box read that end.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "dsp/box_refit.h"

namespace {

using dsp::span;

::testing::AssertionResult is_span(span got, int start, int size) {
    if (got.start == start && got.size == size) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "got [" << got.start << ", +" << got.size
                                         << "), expected [" << start << ", +" << size << ")";
}

TEST(FollowAxis, ObjectTEndsWhereTheDifferenceReachesPastObjectTMinus1) {
    // object(t-1) [100, 160); Dif(t-1,t) [100, 180): moved 20 px towards the end.
    EXPECT_TRUE(
        is_span(dsp::follow_axis(span{100, 60}, span{100, 80}, span{100, 60}, 60), 120, 60));
    // Dif(t-1,t) [75, 160): moved 25 px towards the start.
    EXPECT_TRUE(is_span(dsp::follow_axis(span{100, 60}, span{75, 85}, span{100, 60}, 60), 75, 60));
    // A 10 px object 30 px further on, apart from where it was: [100, 110)
    // and [130, 140) joined as [100, 140).
    EXPECT_TRUE(
        is_span(dsp::follow_axis(span{100, 10}, span{100, 40}, span{100, 10}, 10), 130, 10));
}

TEST(FollowAxis, NoSideFurtherIsTheCentreOfTheDifference) {
    EXPECT_TRUE(
        is_span(dsp::follow_axis(span{100, 60}, span{100, 60}, span{100, 60}, 60), 100, 60));
    // An odd excess: centre2 = 100 + 161 = 261 -> start floor((261 - 60) / 2) = 100.
    EXPECT_TRUE(
        is_span(dsp::follow_axis(span{100, 61}, span{100, 61}, span{100, 60}, 60), 100, 60));
}

// The extents traced on a 130 px ball at 1 px per frame spinning about x
// over "cones" (docs/firmware.md): last box [199, 328), Dif(t-1,t) [286, 329)
// only, its leading crescent; the ball was at [197.8, 328.1).
TEST(PartAxis, APartUnderHalfTheBoxGivesItsOuterEdge) {
    EXPECT_TRUE(dsp::is_part(span{286, 43}, span{199, 129}));
    EXPECT_FALSE(dsp::is_part(span{286, 65}, span{199, 129}));  // 130 >= 129: not a part
    EXPECT_TRUE(dsp::is_part(span{286, 64}, span{199, 129}));   // 128 < 129
    EXPECT_TRUE(is_span(dsp::part_axis(span{286, 43}, span{199, 129}), 200, 129));
    // Its mirror: a crescent in the box's first half leads towards the start.
    EXPECT_TRUE(is_span(dsp::part_axis(span{199, 43}, span{199, 129}), 199, 129));
    EXPECT_TRUE(is_span(dsp::part_axis(span{190, 43}, span{199, 129}), 190, 129));
}

TEST(DifferenceShift, TheSideReachedPastWithTheOtherWithinTwoPixels) {
    int shift = 99;
    // The key's box [230, 311); Dif(key, t) [230, 317): moved 6 px towards the end.
    ASSERT_TRUE(dsp::difference_shift(span{230, 87}, span{230, 81}, &shift));
    EXPECT_EQ(shift, 6);
    // A box 8 px wider than the object on the trailing side ([198, 330), the
    // object [206, 331)) does not matter: [206, 340) is 10 px on.
    ASSERT_TRUE(dsp::difference_shift(span{206, 134}, span{198, 132}, &shift));
    EXPECT_EQ(shift, 10);
    // Towards the start, the box 2 px short at the end: [186, 267) vs [191, 265).
    ASSERT_TRUE(dsp::difference_shift(span{186, 81}, span{191, 74}, &shift));
    EXPECT_EQ(shift, -5);
    // Equally far on both sides, within 2 px: no motion on this axis.
    ASSERT_TRUE(dsp::difference_shift(span{144, 114}, span{145, 112}, &shift));
    EXPECT_EQ(shift, 0);
}

TEST(DifferenceShift, PastTheBoxOnBothSidesReadsNothing) {
    int shift = 99;
    // [162, 289) around the key's box [166, 288): 4 px past at the start, 1 at
    // the end is a reading; 4 and 3 px is not (the box did not outline it).
    EXPECT_TRUE(dsp::difference_shift(span{162, 127}, span{166, 122}, &shift));
    EXPECT_EQ(shift, -4);
    EXPECT_FALSE(dsp::difference_shift(span{162, 129}, span{166, 122}, &shift));
    EXPECT_FALSE(dsp::difference_shift(span{160, 130}, span{166, 118}, &shift));
}

TEST(KeyReach, TheFurtherSidePastTheKeysBox) {
    EXPECT_EQ(dsp::key_reach(span{186, 81}, span{201, 66}), 15);
    EXPECT_EQ(dsp::key_reach(span{230, 94}, span{230, 81}), 13);
    EXPECT_EQ(dsp::key_reach(span{206, 128}, span{198, 132}), 4);
}

// A key of the outline: the hull of Dif(key, t)'s extent and the key's box.
TEST(FollowAxis, NarrowerThanTheObjectTheLastBoxMovedOnlyToHoldIt) {
    // The trace of a 140 px ball about z: the last box y 156..294, Dif(t-1,t)
    // 172..291 inside it (object(t-1) 181..291): the last box stands.
    EXPECT_TRUE(
        is_span(dsp::follow_axis(span{181, 110}, span{172, 119}, span{156, 138}, 138), 156, 138));
    // The difference 4 px past its end: moved 4 px towards it.
    EXPECT_TRUE(
        is_span(dsp::follow_axis(span{181, 110}, span{180, 118}, span{156, 138}, 138), 160, 138));
    // 3 px past its start: moved 3 px towards it.
    EXPECT_TRUE(
        is_span(dsp::follow_axis(span{160, 90}, span{153, 100}, span{156, 138}, 138), 153, 138));
    // Dif(t-1,t) [101, 159) inside the last box [100, 160): no motion.
    EXPECT_TRUE(
        is_span(dsp::follow_axis(span{100, 60}, span{101, 58}, span{100, 60}, 60), 100, 60));
}

TEST(BoundedShift, AtMostTheDifferenceLessTheKeysBoxPlusOne) {
    // The trace of a 140 px ball about x: the pattern read 7 px down, Dif(key,
    // t) 139 px high for the key's 137: at most 3.
    bool bounded = false;
    EXPECT_EQ(dsp::bounded_shift(span{155, 139}, span{163, 137}, 7, &bounded), 3);
    EXPECT_TRUE(bounded);
    EXPECT_EQ(dsp::bounded_shift(span{155, 139}, span{163, 137}, -7, &bounded), -3);
    EXPECT_TRUE(bounded);
    // Within it: as read.
    EXPECT_EQ(dsp::bounded_shift(span{100, 150}, span{100, 140}, 10, &bounded), 10);
    EXPECT_FALSE(bounded);
    // A difference smaller than the key's box leaves 1 px; being a part of
    // the outline (the trace's first pair after a key: 116 px high for the
    // key's 128), it does not stand for the object.
    EXPECT_EQ(dsp::bounded_shift(span{176, 116}, span{164, 128}, 2, &bounded), 1);
    EXPECT_FALSE(bounded);
    // The key's box at most 2 px wider than the extent: still the outline.
    EXPECT_EQ(dsp::bounded_shift(span{100, 138}, span{100, 140}, 3, &bounded), 1);
    EXPECT_TRUE(bounded);
    EXPECT_EQ(dsp::bounded_shift(span{100, 137}, span{100, 140}, 3, &bounded), 1);
    EXPECT_FALSE(bounded);
}

TEST(AcrossMotion, AnAxisTheDifferenceReachedAQuarterAsFarOnAtLeastMinShift) {
    // The trace of the 155 px ball after its bounce: Dif(t-1,t) 147 x 166 px
    // past object(t-1)'s 145 x 154: 2 px across (x), 12 px along (y).
    EXPECT_TRUE(dsp::across_motion(2, 12));
    EXPECT_FALSE(dsp::across_motion(12, 2));
    EXPECT_TRUE(dsp::across_motion(1, 4));
    EXPECT_FALSE(dsp::across_motion(2, 7));  // under four times as far
    EXPECT_FALSE(dsp::across_motion(0, 3));  // under min_shift: no motion to be across
}

TEST(ContradictedShift, TheDifferenceWhereItReadsMoreThanAStepOtherwise) {
    // The trace of a 125 px ball about y (x axis, key's box 230..356): the
    // pattern read -1, -3, -4 while Dif(key, t) reached 2, 4, 7 px past the
    // key's box on the right, none on the left.
    int shift = -1;
    EXPECT_TRUE(dsp::contradicted_shift(span{230, 128}, span{230, 126}, 3, &shift));
    EXPECT_EQ(shift, 2);
    shift = -3;
    EXPECT_TRUE(dsp::contradicted_shift(span{230, 130}, span{230, 126}, 5, &shift));
    EXPECT_EQ(shift, 4);
    shift = -4;
    EXPECT_TRUE(dsp::contradicted_shift(span{230, 133}, span{230, 126}, 7, &shift));
    EXPECT_EQ(shift, 7);
    // Within a step of the pattern's: the pattern's stands.
    shift = 5;
    EXPECT_FALSE(dsp::contradicted_shift(span{230, 133}, span{230, 126}, 7, &shift));
    EXPECT_EQ(shift, 5);
    // More than a slow object could have moved by then: not read.
    shift = 0;
    EXPECT_FALSE(dsp::contradicted_shift(span{230, 133}, span{230, 126}, 5, &shift));
    EXPECT_EQ(shift, 0);
    // A part of the outline (the 80 px ball's first pair: 66 px high for the
    // key's 76, 5 px past its end) or an extent past the key's box on both
    // sides: not read, however far a slow object could have moved.
    EXPECT_FALSE(dsp::contradicted_shift(span{200, 66}, span{185, 76}, 15, &shift));
    EXPECT_FALSE(dsp::contradicted_shift(span{180, 90}, span{185, 76}, 15, &shift));
    EXPECT_EQ(shift, 0);
    // The key's box 2 px wider than the extent is still its outline.
    shift = -3;
    EXPECT_TRUE(dsp::contradicted_shift(span{189, 74}, span{185, 76}, 15, &shift));
    EXPECT_EQ(shift, 2);
}

TEST(FirstExtentShift, AgainstTheFirstReadingWithinASlowObjectsReach) {
    // The trace of a 140 px ball circling upwards over aloe (y axis): the
    // first extent 162..305, eight pairs later 156..305: 6 px up.
    bool usable = true;
    int shift = 3;  // the pattern's, following the texture down
    EXPECT_TRUE(dsp::first_extent_shift(span{156, 149}, span{162, 143}, 17, &usable, &shift));
    EXPECT_EQ(shift, -6);
    EXPECT_TRUE(usable);
    // The co-simulated ball moving 2 px a pair: 11 px at its sixth pair.
    EXPECT_TRUE(dsp::first_extent_shift(span{171, 74}, span{182, 63}, 13, &usable, &shift));
    EXPECT_EQ(shift, -11);
    // Not usable: nothing read.
    usable = false;
    shift = 0;
    EXPECT_FALSE(dsp::first_extent_shift(span{156, 149}, span{162, 143}, 17, &usable, &shift));
    EXPECT_EQ(shift, 0);
}

TEST(FirstExtentShift, APartIsOfNoMoreUse) {
    // The trace of a 110 px ball passing along x (y axis): the first extent
    // 183..281 was a part; a pair later 170..281, 13 px, further than a slow
    // object moves in two pairs: not read, and not read against again, even
    // once a slow object could have moved that far (the sixth pair).
    bool usable = true;
    int shift = 0;
    EXPECT_FALSE(dsp::first_extent_shift(span{170, 111}, span{183, 98}, 5, &usable, &shift));
    EXPECT_FALSE(usable);
    EXPECT_FALSE(dsp::first_extent_shift(span{170, 112}, span{183, 98}, 13, &usable, &shift));
    EXPECT_EQ(shift, 0);
    // Past it on both sides: a part too.
    usable = true;
    EXPECT_FALSE(dsp::first_extent_shift(span{160, 130}, span{170, 111}, 15, &usable, &shift));
    EXPECT_FALSE(usable);
    EXPECT_EQ(shift, 0);
}

TEST(OutlineKeyAxis, AcrossTheMotionTheHull) {
    // The trace of a 140 px ball about y: the key's box missed 6 px at the
    // top, Dif(key, t) 1 (y 156..293 against the key's 161..292).
    EXPECT_TRUE(
        is_span(dsp::outline_key_axis(span{156, 137}, span{161, 131}, 131, true, span{156, 137}, 0),
                156, 137));
    // At most a quarter more than the key's box, + 1.
    EXPECT_TRUE(
        is_span(dsp::outline_key_axis(span{100, 200}, span{120, 100}, 100, true, span{100, 200}, 0),
                100, 126));
}

// The traced 73 px ball circling at 3 px a pair, spinning 1 rev/s about y:
// keyed at x 166..241, Dif(key, t) first 167..242, later 167..245: grown
// 3 px at its end and none at its start, and its silhouette's centre moved
// right (toward +1): it drifted 3 px right. The hull [166, 245) less 3 px
// at its start.
TEST(OutlineKeyAxis, AcrossTheMotionTheHullLessADrift) {
    EXPECT_TRUE(is_span(
        dsp::outline_key_axis(span{167, 78}, span{166, 75}, 75, true, span{167, 75}, 1), 169, 76));
    // One pixel of growth is one pixel of drift: [166, 244) less 1 px.
    EXPECT_TRUE(is_span(
        dsp::outline_key_axis(span{167, 77}, span{166, 75}, 75, true, span{167, 76}, 1), 167, 77));
    // Towards the start: [160, 241) less 4 px at its end.
    EXPECT_TRUE(is_span(
        dsp::outline_key_axis(span{160, 80}, span{166, 75}, 75, true, span{164, 76}, -1), 160, 77));
    // A drift never takes the box under the key's: grown 21 px at the end of
    // [166, 251), the key's box 75 px wide at that end.
    EXPECT_TRUE(is_span(
        dsp::outline_key_axis(span{166, 85}, span{166, 75}, 75, true, span{166, 64}, 1), 176, 75));
}

TEST(OutlineKeyAxis, AcrossTheMotionNoDriftTheHull) {
    // Grown 3 px at the end, but the silhouette did not move that way (a
    // 185 px ball whose texture turned into one pole first): the hull.
    EXPECT_TRUE(is_span(
        dsp::outline_key_axis(span{167, 78}, span{166, 75}, 75, true, span{167, 75}, 0), 166, 79));
    EXPECT_TRUE(is_span(
        dsp::outline_key_axis(span{167, 78}, span{166, 75}, 75, true, span{167, 75}, -1), 166, 79));
    // The traced 120 px ball keyed 109 px wide (141..250), its silhouette
    // 109-122 px: Dif(key, t) reads 13 px past the key's box from the first
    // reading on, and grows no further. The hull.
    EXPECT_TRUE(
        is_span(dsp::outline_key_axis(span{141, 122}, span{141, 109}, 109, true, span{141, 122}, 1),
                141, 122));
    // Grown alike at both ends (the texture turned into the poles): the hull.
    EXPECT_TRUE(is_span(
        dsp::outline_key_axis(span{160, 90}, span{166, 75}, 75, true, span{165, 80}, 1), 160, 90));
}

TEST(OutlineKeyAxis, AlongTheMotionTheSizeAtTheLeadingEnd) {
    // Moved 10 px towards the end: [193, 344) less the size from its end,
    // never under the key's box (141).
    EXPECT_TRUE(is_span(
        dsp::outline_key_axis(span{194, 150}, span{193, 141}, 140, false, span{}, 0), 203, 141));
    EXPECT_TRUE(is_span(
        dsp::outline_key_axis(span{194, 150}, span{193, 141}, 145, false, span{}, 0), 199, 145));
    // Towards the start.
    EXPECT_TRUE(is_span(
        dsp::outline_key_axis(span{180, 150}, span{190, 140}, 140, false, span{}, 0), 180, 140));
    // Equally far on both sides: the key's box was 2 px short on each; the
    // hull [100, 164).
    EXPECT_TRUE(is_span(dsp::outline_key_axis(span{100, 64}, span{102, 60}, 60, false, span{}, 0),
                        100, 64));
    // Past it by 6 px ahead and 2 behind: 4 px more than the key's box, at the
    // leading end of the hull [98, 166).
    EXPECT_TRUE(
        is_span(dsp::outline_key_axis(span{98, 68}, span{100, 60}, 60, false, span{}, 0), 102, 64));
    // A part inside the key's box (a leading crescent 41 px of 129): the key's box.
    EXPECT_TRUE(is_span(dsp::outline_key_axis(span{289, 41}, span{201, 129}, 129, false, span{}, 0),
                        201, 129));
}

TEST(PreviousAxis, TheCommonPartOfBothDifferences) {
    // Moving towards the end: Dif(t-2,t-1) [90, 160), Dif(t-1,t) [100, 180).
    EXPECT_TRUE(is_span(dsp::previous_axis(span{90, 70}, span{100, 80}, 60), 100, 60));
    // No motion along the axis: both edges shared.
    EXPECT_TRUE(is_span(dsp::previous_axis(span{100, 60}, span{100, 60}, 60), 100, 60));
    // Edges 1 px apart on both sides count as both shared: the common part.
    EXPECT_TRUE(is_span(dsp::previous_axis(span{100, 60}, span{101, 60}, 60), 101, 59));
}

TEST(PreviousAxis, OneSharedEdgeIsAReversalAndObjectTMinus1IsSizeFromIt) {
    // A bounce at the bottom: object(t-2) at [90, 150), object(t-1) [100, 160),
    // object(t) [75, 135). Dif(t-2,t-1) [90, 160), Dif(t-1,t) [75, 160): their
    // common part [90, 160) holds object(t-2)'s top; object(t-1) is 60 px up
    // from the shared end.
    EXPECT_TRUE(is_span(dsp::previous_axis(span{90, 70}, span{75, 85}, 60), 100, 60));
    // The same at the start: Dif(t-2,t-1) [100, 170), Dif(t-1,t) [100, 185).
    EXPECT_TRUE(is_span(dsp::previous_axis(span{100, 70}, span{100, 85}, 60), 100, 60));
    // Then object(t) follows from it: Dif(t-1,t) reaches 25 px past its start.
    EXPECT_TRUE(is_span(dsp::follow_axis(dsp::previous_axis(span{90, 70}, span{75, 85}, 60),
                                         span{75, 85}, span{100, 60}, 60),
                        75, 60));
}

// A bounce at the bottom that brings object(t) back where object(t-2) was:
// object(t-3) at [240, 275), object(t-2) and object(t) at [261, 296),
// object(t-1) at [280, 315). Dif(t-3,t-2) spans [240, 296); both later
// differences [261, 315).
TEST(ReturnedAxis, ObjectTMinus1IsTheEndTheLastBoxHolds) {
    const span earlier{240, 56}, extent{261, 54}, last{280, 35};
    span previous;
    ASSERT_TRUE(dsp::returned_axis(earlier, extent, extent, last, &previous));
    EXPECT_TRUE(is_span(previous, 280, 35));
    // object(t) then follows at the other end, where object(t-2) was.
    EXPECT_TRUE(is_span(dsp::follow_axis(previous, extent, last, 35), 261, 35));
    // Edges 1 px apart still shared; a last box 4 px off its end (an eighth
    // of 35 px) still holds it.
    ASSERT_TRUE(dsp::returned_axis(earlier, span{262, 53}, extent, span{276, 35}, &previous));
    EXPECT_TRUE(is_span(previous, 280, 35));
    // The same at the start, mirrored: object(t-1) at [100, 135), object(t-2)
    // and object(t) at [119, 154), object(t-3) at [140, 175).
    ASSERT_TRUE(
        dsp::returned_axis(span{119, 56}, span{100, 54}, span{100, 54}, span{100, 35}, &previous));
    EXPECT_TRUE(is_span(previous, 100, 35));
}

TEST(ReturnedAxis, NotWhereTheExtentsSayNothingOfAReturn) {
    const span earlier{240, 56}, extent{261, 54};
    span previous{1, 1};
    // A last box 5 px off both ends holds neither.
    EXPECT_FALSE(dsp::returned_axis(earlier, extent, extent, span{275, 35}, &previous));
    // Extents within an eighth of the object (a ball the differences hold
    // whole, with its rim): no motion to read.
    EXPECT_FALSE(
        dsp::returned_axis(earlier, span{261, 39}, span{261, 39}, span{265, 35}, &previous));
    // One edge shared is previous_axis's reversal, not this.
    EXPECT_FALSE(
        dsp::returned_axis(earlier, span{261, 54}, span{255, 60}, span{280, 35}, &previous));
    // The extent of the pair before already reached the end the last box
    // holds: the object did not come to it (a slow 160 px ball near its
    // apex, differences holding it whole around a box too small).
    EXPECT_FALSE(
        dsp::returned_axis(span{166, 94}, span{93, 169}, span{94, 169}, span{123, 145}, &previous));
    EXPECT_FALSE(dsp::returned_axis(span{255, 56}, extent, extent, span{280, 35}, &previous));
    EXPECT_TRUE(is_span(previous, 1, 1)) << "nothing written";
}

TEST(StepSize, AtMostAnEighthOfTheLargerSizePerFrame) {
    EXPECT_EQ(dsp::step_size(80, 100, 8, 640, 640), 92);    // step 100 / 8 = 12
    EXPECT_EQ(dsp::step_size(80, 70, 8, 640, 640), 70);     // within the step
    EXPECT_EQ(dsp::step_size(5, 4, 8, 640, 640), 8);        // at least min_size
    EXPECT_EQ(dsp::step_size(630, 700, 8, 640, 640), 640);  // at most the limit
}

TEST(PullAxis, SizeStepsAndTheCentreIsPulledHalfTheOffsetAtMostAStep) {
    // found [200, 260), last [190, 250), object(t-1) [180, 240): step 7, the
    // offset between last and object(t-1) 10 px (20 in Q1), half of it 5 px.
    EXPECT_TRUE(
        is_span(dsp::pull_axis(span{200, 60}, span{190, 60}, span{180, 60}, 8, 640, 640), 195, 60));
    // An offset of 40 px is pulled by the step, 7 px.
    EXPECT_TRUE(
        is_span(dsp::pull_axis(span{200, 60}, span{220, 60}, span{180, 60}, 8, 640, 640), 193, 60));
    // Kept inside [0, limit).
    EXPECT_TRUE(
        is_span(dsp::pull_axis(span{0, 60}, span{10, 60}, span{0, 60}, 8, 640, 640), 0, 60));
}

// hold_axis against a search of every start: within a step of the box's
// centred start, the one leaving least of the mask outside, the nearest to
// the centred start among those.
span held_by_search(span found, span mask, int size, int limit) {
    const int step = std::max(1, std::max(size, mask.size) / 8);
    const int centred = static_cast<int>(std::floor((found.start + found.size / 2.0) - size / 2.0));
    int best = centred, best_out = -1;
    for (int s = centred - step; s <= centred + step; ++s) {
        const int out = std::max(0, s - mask.start) + std::max(0, mask.end() - (s + size));
        if (best_out < 0 || out < best_out ||
            (out == best_out && std::abs(s - centred) < std::abs(best - centred))) {
            best = s;
            best_out = out;
        }
    }
    return span{std::clamp(best, 0, limit - size), size};
}

TEST(HoldAxis, MovedOnlyToHoldTheMaskAtMostAStep) {
    // A mask inside the box: not moved (pull_axis would move it towards the
    // mask's centre). found [200, 248) held at 49 px, object(t-1) [208, 248).
    EXPECT_TRUE(is_span(dsp::hold_axis(span{200, 48}, span{208, 40}, 49, 480), 199, 49));
    // The mask past the box's end by 3 px: moved 3 px.
    EXPECT_TRUE(is_span(dsp::hold_axis(span{200, 50}, span{210, 43}, 50, 480), 203, 50));
    // 20 px past: moved a step, 50 / 8 = 6 px.
    EXPECT_TRUE(is_span(dsp::hold_axis(span{200, 50}, span{230, 40}, 50, 480), 206, 50));
    // A mask larger than the box on both sides: not moved.
    EXPECT_TRUE(is_span(dsp::hold_axis(span{120, 50}, span{100, 100}, 50, 480), 120, 50));
    // Kept inside [0, limit).
    EXPECT_TRUE(is_span(dsp::hold_axis(span{0, 40}, span{0, 30}, 44, 480), 0, 44));
    int compared = 0;
    for (int found_start = 0; found_start < 120; found_start += 7)
        for (int found_size = 10; found_size < 90; found_size += 9)
            for (int mask_start = 0; mask_start < 160; mask_start += 5)
                for (int mask_size = 4; mask_size < 120; mask_size += 11)
                    for (int size = found_size; size < found_size + 20; size += 3) {
                        const span found{found_start, found_size}, mask{mask_start, mask_size};
                        const span want = held_by_search(found, mask, size, 200);
                        ASSERT_TRUE(
                            is_span(dsp::hold_axis(found, mask, size, 200), want.start, want.size))
                            << "found [" << found_start << ", +" << found_size << "), mask ["
                            << mask_start << ", +" << mask_size << "), size " << size;
                        ++compared;
                    }
    EXPECT_GT(compared, 10000);
}

// held_at_extent_end(placed, found, both) against the start expected.
struct extent_end_case {
    span placed, found, both;
    int start;
};

void expect_held(const std::vector<extent_end_case>& cases) {
    for (const extent_end_case& c : cases)
        EXPECT_TRUE(
            is_span(dsp::held_at_extent_end(c.placed, c.found, c.both), c.start, c.placed.size))
            << "placed " << c.placed.start << ", SAD box " << c.found.start << " +" << c.found.size
            << ", extent " << c.both.start << " +" << c.both.size;
}

// Round 99's 22 px ball circling (traced): the window placed it at 335
// (to 359) past Dif(t-1,t)'s 313..351, the SAD box at 327..351; the ball's
// top stood at 327.3. Moving up (round 100's 23 px ball): 119 against the
// extent's 128 and the SAD box's 128, the ball's top at 127.2.
TEST(HeldAtExtentEnd, PastTheExtentWhereTheSadBoxReadItsEnd) {
    expect_held({{{335, 24}, {327, 24}, {313, 38}, 327}, {{119, 24}, {128, 24}, {128, 37}, 128}});
}

TEST(HeldAtExtentEnd, TwoPixelsPastOrTheSadBoxElsewhereIsKept) {
    expect_held({
        // 2 px past the end: kept; 3 px: held.
        {{329, 24}, {327, 24}, {313, 38}, 329},
        {{330, 24}, {327, 24}, {313, 38}, 327},
        {{126, 24}, {128, 24}, {128, 37}, 126},
        {{125, 24}, {128, 24}, {128, 37}, 128},
        // The SAD box's side 2 px off the end still reads it; 3 px off (a
        // rim the differences missed, the texture past it) does not.
        {{119, 24}, {130, 24}, {128, 37}, 128},
        {{119, 24}, {126, 24}, {128, 37}, 128},
        {{335, 24}, {329, 24}, {313, 38}, 327},
        {{335, 24}, {325, 24}, {313, 38}, 327},
        {{335, 24}, {330, 24}, {313, 38}, 335},
        {{335, 24}, {324, 24}, {313, 38}, 335},
        {{119, 24}, {131, 24}, {128, 37}, 119},
        {{119, 24}, {125, 24}, {128, 37}, 119},
    });
}

TEST(HeldAtExtentEnd, ASadBoxOfAnotherSizeOrABoxInsideTheExtentIsKept) {
    expect_held({
        // A SAD box of another size (a pattern taken at another depth)
        // reads no end of this box's.
        {{335, 24}, {325, 26}, {313, 38}, 335},
        {{119, 24}, {128, 23}, {128, 37}, 119},
        // Inside the extent, whatever the SAD box reads.
        {{320, 24}, {327, 24}, {313, 38}, 320},
        {{313, 24}, {313, 24}, {313, 38}, 313},
    });
}

}  // namespace
