// The detections' outline stepping on (dsp/detection_steps.h), on boxes
// the firmware detected (traced from the box cases named, then written
// here) and on boxes made to step by a known amount.
#include <gtest/gtest.h>

#include <vector>

#include "dsp/detection_steps.h"
#include "dsp/key_frame.h"

namespace {

using dsp::box;
using dsp::detection_steps;

constexpr int step = dsp::key_frame::max_step + 1;

// Pushes boxes at consecutive pairs from `first`; whether the edge kept
// stepping after each.
std::vector<bool> push_all(detection_steps& steps, const std::vector<box>& boxes,
                           uint32_t first = 10) {
    std::vector<bool> read;
    for (const box& b : boxes) {
        steps.push(b, first++);
        read.push_back(steps.edge_keeps_stepping(step));
    }
    return read;
}

// heldout25_recede110px_2pxpf_1rps_y_tsukuba, pairs 4-7: the ball going
// away at 2-3.5 px a frame, its SAD pattern moved 1 px a pair. The left
// edge stepped 4, 5 and 3 px.
TEST(DetectionSteps, AMovingBallsOutlineStepsOn) {
    detection_steps steps;
    const std::vector<bool> read = push_all(
        steps,
        {{206, 170, 109, 108}, {210, 172, 107, 106}, {215, 174, 104, 103}, {218, 176, 103, 100}});
    EXPECT_EQ(read, (std::vector<bool>{false, false, false, true}));
}

// heldout4_pass90px_1pxpf_2rps_y, pairs 4-8: a 90 px ball at 1 px a frame
// spinning 2 rev/s. Its detections' edges move 0-6 px, none the same way
// 3 px or more in three pairs running.
TEST(DetectionSteps, ASlowBallsDetectionsDoNot) {
    detection_steps steps;
    const std::vector<bool> read = push_all(steps, {{212, 189, 91, 78},
                                                    {213, 190, 91, 78},
                                                    {214, 185, 91, 83},
                                                    {216, 184, 90, 84},
                                                    {222, 183, 85, 85}});
    EXPECT_EQ(read, std::vector<bool>(5, false));
}

// Slow balls' detections growing or cut to a piece: heldout10_spin75px_1pxpf_1_2rps_y_photo4,
// pairs 8-11 (the top edge 6, 6 and 5 px up, the bottom down: a piece
// growing), and heldout16_circle100px_halfpxpf_tsukuba, pairs 5-9 (the top
// edge 60, 3 and 4 px down, the bottom edge 2 px up: the ball's bottom
// alone detected, then less of it).
TEST(DetectionSteps, ASlowBallsGrowingOrShrinkingPieceDoesNot) {
    detection_steps growing;
    EXPECT_EQ(
        push_all(growing,
                 {{292, 216, 8, 30}, {293, 210, 8, 37}, {293, 204, 9, 44}, {231, 199, 72, 54}}),
        std::vector<bool>(4, false));
    detection_steps cut;
    EXPECT_EQ(push_all(cut, {{170, 190, 80, 100},
                             {178, 189, 72, 100},
                             {178, 249, 73, 40},
                             {176, 252, 74, 36},
                             {179, 256, 69, 32}}),
              std::vector<bool>(5, false));
}

// A box moved on either axis, either way, by `step` px a pair; one edge
// alone, a step of max_step px, a step back, or a pair without a detection
// between breaks the run.
TEST(DetectionSteps, TheBoxMovingTheSameWayInEveryPair) {
    const box b{100, 100, 50, 50};
    auto shifted = [&](int axis, int by, int opposite_by) {
        box m = b;  // the near edge by `by`, the far one by `opposite_by`
        if (axis == 0) m.x += by, m.width += opposite_by - by;
        if (axis == 1) m.y += by, m.height += opposite_by - by;
        return m;
    };
    for (int axis = 0; axis < 2; ++axis) {
        for (int sign : {1, -1}) {
            auto run = [&](int near, int far, std::vector<int> pattern = {1, 2, 3}) -> bool {
                detection_steps steps;
                std::vector<box> boxes{b};
                for (int k : pattern)
                    boxes.push_back(shifted(axis, sign * k * near, sign * k * far));
                return push_all(steps, boxes).back();
            };
            const char* where = axis == 0 ? "x" : "y";
            EXPECT_TRUE(run(step, step)) << where << sign;
            EXPECT_TRUE(run(step, 1)) << where << sign << ": the far edge 1 px a pair";
            EXPECT_FALSE(run(step, 0)) << where << sign << ": one edge alone";
            EXPECT_FALSE(run(0, step)) << where << sign << ": the other edge alone";
            EXPECT_FALSE(run(step - 1, step - 1)) << where << sign;
            EXPECT_FALSE(run(step, step, {1, 0, 1})) << where << sign << ": a step back";
        }
    }
    // Three edges, each stepping in one pair only.
    detection_steps apart;
    const box left{b.x + step, b.y, b.width - step, b.height};
    const box right{left.x, left.y, left.width + step, left.height};
    const box top{right.x, right.y + step, right.width, right.height - step};
    EXPECT_FALSE(push_all(apart, {b, left, right, top}).back());
    auto moved = [&](int by) { return box{b.x + by, b.y, b.width, b.height}; };
    detection_steps gap;
    gap.push(b, 1);
    gap.push(moved(step), 2);
    gap.push(moved(2 * step), 4);  // pair 3 had no detection
    gap.push(moved(3 * step), 5);
    EXPECT_FALSE(gap.edge_keeps_stepping(step));
    gap.push(moved(4 * step), 6);
    gap.push(moved(5 * step), 7);
    EXPECT_TRUE(gap.edge_keeps_stepping(step));
    gap.clear();
    EXPECT_FALSE(gap.edge_keeps_stepping(step));
}

}  // namespace
