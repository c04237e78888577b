// Which axes a detection's box (a part of its object, maybe) takes both
// frame differences' common part on (dsp/part_growth.h). The extents are
// laid out here by hand for a 110 px ball in the default 640 x 480 view:
// where it was at t-2, t-1 and t, what Dif(t-2,t-1) and Dif(t-1,t) span,
// and a detection that holds a part of it. The oracle is the rule as
// docs/firmware.md states it per axis, not the code's output.
#include <gtest/gtest.h>

#include "dsp/part_growth.h"

namespace {

using dsp::box;

constexpr int ball = 110;

// A ball at rest on x at column 245 (clear of the side borders) rising `step`
// px a frame, object(t-1) at row `top`: Dif(t-2,t-1) spans object(t-2)
// and object(t-1), Dif(t-1,t) object(t-1) and object(t), cut at the image's
// bottom (row 480) when `bottom_cut`.
dsp::difference_extents rising(int top, int step, bool bottom_cut) {
    auto span_y = [&](int from, int to) {
        const int end = bottom_cut && to > 480 ? 480 : to;
        return box{245, from, ball, end - from};
    };
    const box before = span_y(top, top + step + ball);
    const box after = span_y(top - step, top + ball);
    const int end = bottom_cut && top + ball > 480 ? 480 : top + ball;
    return {before, after, box{245, top, ball, end - top}};
}

// The same ball at rest on y at row 185, moving right `step` px a frame.
dsp::difference_extents moving_right(int left, int step) {
    return {box{left - step, 185, ball + step, ball}, box{left, 185, ball + step, ball},
            box{left, 185, ball, ball}};
}

dsp::part_growth grow(const dsp::difference_extents& e, box last, bool may_be_part = true,
                      bool at_border = false) {
    return dsp::grow_part(e, last, may_be_part, false, false, at_border, dsp::camera_rig{});
}

TEST(PartGrowth, ARiseGrowsTheDetectionAcrossIt) {
    // Thrown up through the image's bottom, 8 px a frame: x's edges stand,
    // y's move by 8 (over min_shift). A 60 px wide detection inside the
    // ball is grown on x only; the common part is cut by the border, so
    // the sphere's shape is not read.
    const dsp::difference_extents e = rising(376, 8, true);
    const box detection{270, 380, 60, 96};
    const dsp::part_growth g = grow(e, detection, true, true);
    EXPECT_TRUE(g.x);
    EXPECT_FALSE(g.y);
    EXPECT_FALSE(g.round_read);
}

TEST(PartGrowth, AMotionAlongXGrowsTheDetectionOnY) {
    // Moving right at 8 px a frame near the left border (its common part
    // taken as touching it, so only the per-axis rule decides): y's edges
    // stand.
    const dsp::difference_extents e = moving_right(10, 8);
    const box detection{10, 200, 100, 50};
    const dsp::part_growth g = grow(e, detection, true, true);
    EXPECT_FALSE(g.x);
    EXPECT_TRUE(g.y);
}

TEST(PartGrowth, OnlyWhereTheCommonPartHoldsTheBox) {
    // The detection reaches 5 px past the ball's right (past the 1 px the
    // hold allows): not grown on x, though the ball is slow on x.
    const dsp::difference_extents e = rising(376, 8, true);
    const dsp::part_growth g = grow(e, box{300, 380, 60, 96}, true, true);
    EXPECT_FALSE(g.x);
    EXPECT_FALSE(g.y);
}

TEST(PartGrowth, ARoundCommonPartGrowsBothAxesAtAnySpeed) {
    // 20 px a frame to the right, clear of the borders: the common part is
    // the ball, 110 px square, holding a 60 x 104 px detection and over an
    // eighth wider: both axes (y is within its eighth: by the slow rule
    // alone it would not grow).
    const dsp::difference_extents e = moving_right(265, 20);
    const box detection{290, 188, 60, 104};
    const dsp::part_growth g = grow(e, detection);
    EXPECT_TRUE(g.round_read);
    EXPECT_TRUE(g.x);
    EXPECT_TRUE(g.y);
    // Not once the box is no part (later in a track), nor where the
    // common part is cut by the border.
    const dsp::part_growth tracked = grow(e, detection, false);
    EXPECT_FALSE(tracked.x || tracked.y || tracked.round_read);
    const dsp::part_growth cut = grow(e, detection, true, true);
    EXPECT_FALSE(cut.x || cut.y || cut.round_read);
}

TEST(PartGrowth, ACommonPartOfNoSpheresShapeOrNotHoldingTheBoxIsNotTaken) {
    // A 110 x 60 px common part (the differences missed the ball's top and
    // bottom): read, not round, so nothing grows (x moves fast, y is
    // within its eighth).
    dsp::difference_extents flat = moving_right(265, 20);
    flat.before.y = flat.after.y = flat.previous.y = 210;
    flat.before.height = flat.after.height = flat.previous.height = 60;
    const dsp::part_growth g = grow(flat, box{290, 212, 60, 56});
    EXPECT_TRUE(g.round_read);
    EXPECT_FALSE(g.x);
    EXPECT_FALSE(g.y);
    // The round ball's common part with a detection 10 px above it.
    const dsp::part_growth above = grow(moving_right(265, 20), box{290, 175, 60, 60});
    EXPECT_FALSE(above.round_read);
    EXPECT_FALSE(above.x || above.y);
}

}  // namespace
