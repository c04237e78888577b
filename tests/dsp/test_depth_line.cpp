// A wrong match's depth reported at the line of the track's last depths
// (dsp/depth_line.h), on depths worked out here in closed form: a ball at
// constant velocity in depth, one bouncing off a wall, one swung round;
// each pair's depth measured through its disparity on the pinhole model
// (f B / Z, Q8 disparity, micrometre depth), with a fixed +-0.1 % pattern
// of noise (the box cases' per-pair depth noise). The oracle is the true
// depth, not the code's line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "dsp/depth_line.h"

namespace {

constexpr double pair_s = 0.0245;     // the frame period
constexpr double focal_base = 94.74;  // f B, px m: 789.5 px, 0.12 m (the default rig)

int64_t disparity_q8(double depth_m) {
    return std::llround(256.0 * focal_base / depth_m);
}

// The depth triangulation gives, micrometres, for the Q8 disparity of
// depth_m with `factor` on it (noise, or a wrong match).
int32_t measured_um(double depth_m, double factor = 1.0) {
    const double q8 = static_cast<double>(std::llround(disparity_q8(depth_m) * factor));
    return static_cast<int32_t>(std::llround(1e6 * 256.0 * focal_base / q8));
}

// +-0.1 %, no two pairs alike in a row.
double noise(int pair) {
    static const double pattern[] = {0.0006, -0.0009, 0.0003, 0.001, -0.0004, -0.001, 0.0008};
    return pattern[pair % 7];
}

struct reading {
    double depth_m;
    bool replaced;
};

// Each pair's true depth measured with the noise, and `wrong` (a factor on
// the disparity) at pair `at`; the depths reported.
std::vector<reading> run(const std::vector<double>& truth, int at = -1, double wrong = 1.0) {
    dsp::depth_line line;
    std::vector<reading> out;
    for (int i = 0; i < static_cast<int>(truth.size()); ++i) {
        const double factor = (1.0 + noise(i)) * (i == at ? wrong : 1.0);
        bool replaced = false;
        const int32_t um = line.reported(measured_um(truth[i], factor), &replaced);
        out.push_back({um * 1e-6, replaced});
    }
    return out;
}

// z0 + v t, pair by pair.
std::vector<double> straight(double z0, double v, int pairs) {
    std::vector<double> z;
    for (int i = 0; i < pairs; ++i) z.push_back(z0 + v * i * pair_s);
    return z;
}

// Thrown at `v` m/s from z0 towards a wall (the ball's centre stops at
// wall_m), back at 0.75 of it; the bounce `phase` of a pair after pair 6.
std::vector<double> rebound(double z0, double v, double phase, double* wall_m) {
    const double t_wall = (6.0 + phase) * pair_s;
    *wall_m = z0 + v * t_wall;
    std::vector<double> z;
    for (int i = 0; i < 16; ++i) {
        const double t = i * pair_s;
        z.push_back(t <= t_wall ? z0 + v * t : *wall_m - 0.75 * v * (t - t_wall));
    }
    return z;
}

TEST(DepthLine, AWrongMatchIsReportedAtTheLine) {
    // Going away at 1 depth a second, coming nearer at 0.6, still; wrong
    // matches 7-40 % off in disparity, either way.
    const std::vector<std::vector<double>> paths = {
        straight(2.5, 2.5, 14), straight(3.9, -0.6 * 3.9, 14), straight(2.7, 0.0, 14)};
    for (const auto& truth : paths) {
        for (double wrong : {1.07, 1.16, 1.4, 0.93, 0.84, 0.6}) {
            const std::vector<reading> r = run(truth, 9, wrong);
            EXPECT_TRUE(r[9].replaced) << "x" << wrong;
            EXPECT_LE(std::fabs(r[9].depth_m / truth[9] - 1.0), 0.005) << "x" << wrong;
            for (int i = 0; i < static_cast<int>(r.size()); ++i) {
                if (i == 9) continue;
                EXPECT_FALSE(r[i].replaced) << "pair " << i << " x" << wrong;
                EXPECT_LE(std::fabs(r[i].depth_m / truth[i] - 1.0), 0.0015)
                    << "pair " << i;  // as measured
            }
        }
    }
}

TEST(DepthLine, ADepthAMotionReachesIsReportedAsMeasured) {
    // A bounce at 1-4 m/s from 3.5-4 m, at every phase of its pair: its
    // depth leaves the line by up to (1 + 0.75) v T, 3.8 % at 4 m/s.
    for (double v : {1.0, 2.0, 3.0, 4.0}) {
        for (double z0 : {3.5, 4.0}) {
            for (double phase = 0.0; phase < 1.0; phase += 0.125) {
                double wall = 0.0;
                const std::vector<double> truth = rebound(z0, v, phase, &wall);
                for (const reading& r : run(truth)) EXPECT_FALSE(r.replaced) << v << " m/s";
            }
        }
    }
    // A ball swung round at 3.9 rad/s on a circle 0.4 m in radius, 2 m away.
    std::vector<double> swung;
    for (int i = 0; i < 40; ++i) swung.push_back(2.0 + 0.4 * std::cos(3.9 * i * pair_s));
    for (const reading& r : run(swung)) EXPECT_FALSE(r.replaced);
}

TEST(DepthLine, OfTwoInARowTheSecondIsTakenAndTheLineStartsAgain) {
    const std::vector<double> truth = straight(2.5, 2.5, 16);
    dsp::depth_line line;
    bool replaced = false;
    for (int i = 0; i < 6; ++i) line.reported(measured_um(truth[i]), &replaced);
    line.reported(measured_um(truth[6], 1.2), &replaced);
    EXPECT_TRUE(replaced);
    const int32_t second = measured_um(truth[7], 1.2);
    EXPECT_EQ(line.reported(second, &replaced), second);
    EXPECT_FALSE(replaced);
    // The line from the second on: the true depths after it are no line
    // with it, so none is replaced until three lie on one.
    for (int i = 8; i < 16; ++i) {
        const int32_t um = measured_um(truth[i]);
        EXPECT_EQ(line.reported(um, &replaced), um) << "pair " << i;
        EXPECT_FALSE(replaced);
    }
}

TEST(DepthLine, DepthsOffTheirLineGateNothing) {
    // The detection's depth read on a part of the ball, 7.7 % near: the
    // three are no line, so a pair 10 % off after them is taken.
    const std::vector<double> truth = straight(3.0, 0.0, 5);
    dsp::depth_line line;
    bool replaced = false;
    line.reported(measured_um(truth[0], 1.077), &replaced);
    line.reported(measured_um(truth[1]), &replaced);
    line.reported(measured_um(truth[2]), &replaced);
    const int32_t off = measured_um(truth[3], 1.1);
    EXPECT_EQ(line.reported(off, &replaced), off);
    EXPECT_FALSE(replaced);
}

TEST(DepthLine, AWrongMatchThatDriftsIsNoLine) {
    // A wrong match 3 % off, then 10 % (round 103's 36 px ball thrown at the
    // wall over teddy): each off the line before it by under the gate, and
    // the three since are no line, so the good depth after them is taken.
    const std::vector<double> truth = straight(3.6, 1.4, 8);
    dsp::depth_line line;
    bool replaced = false;
    for (int i = 0; i < 4; ++i) line.reported(measured_um(truth[i]), &replaced);
    const double drift[] = {1.0 / 1.03, 1.0 / 1.1};
    for (int i = 4; i < 6; ++i) {
        const int32_t off = measured_um(truth[i], drift[i - 4]);
        EXPECT_EQ(line.reported(off, &replaced), off) << "pair " << i;
        EXPECT_FALSE(replaced) << "pair " << i;
    }
    for (int i = 6; i < 8; ++i) {
        const int32_t um = measured_um(truth[i]);
        EXPECT_EQ(line.reported(um, &replaced), um) << "pair " << i;
        EXPECT_FALSE(replaced) << "pair " << i;
    }
}

TEST(DepthLine, ClearedOrWithoutADisparityItStartsAgain) {
    const std::vector<double> truth = straight(2.5, 2.5, 8);
    dsp::depth_line line;
    bool replaced = false;
    for (int i = 0; i < 4; ++i) line.reported(measured_um(truth[i]), &replaced);
    line.clear();
    line.reported(measured_um(truth[4]), &replaced);
    line.reported(measured_um(truth[5]), &replaced);
    const int32_t off = measured_um(truth[6], 1.3);  // two pairs since: no line yet
    EXPECT_EQ(line.reported(off, &replaced), off);
    EXPECT_FALSE(replaced);
    // A pair without a disparity restarts it as clear() does.
    for (int i = 0; i < 3; ++i) line.reported(measured_um(truth[i]), &replaced);
    EXPECT_EQ(line.reported(0, &replaced), 0);
    line.reported(measured_um(truth[4]), &replaced);
    line.reported(measured_um(truth[5]), &replaced);
    const int32_t off2 = measured_um(truth[6], 1.3);
    EXPECT_EQ(line.reported(off2, &replaced), off2);
    EXPECT_FALSE(replaced);
}

}  // namespace
