#include "tb/app/cli/scenarios.h"

#include <cmath>

#include "model/scene/background.h"
#include "model/scene/ball_paths.h"
#include "model/scene/lighting.h"

namespace cli {

const std::vector<builtin_scenario>& builtin_scenarios() {
    // Each a few keys over the defaults; `stereosim scenarios` prints them in
    // this order. The over-budget ones are results, not failures (exit 1).
    static const std::vector<builtin_scenario> list = {
        {"default",
         "thrown ball bouncing towards the rig (2.6 -> 1.6 m), DSK v1 600 MHz, overlapped",
         {}},
        {"near",
         "ball circling at 1.0 m (disparity ~95 px)",
         {{"scenario.path", "circle"}, {"scenario.depth_m", "1.0"}}},
        {"far",
         "ball circling at 3.0 m (disparity ~32 px)",
         {{"scenario.path", "circle"}, {"scenario.depth_m", "3.0"}}},
        {"fast",
         "the default throw at twice the speed (up to ~48 px per frame)",
         {{"scenario.speed", "2.0"}}},
        {"line",
         "ball flying left to right at 2.6 m, 1 m/s (~7 px per frame)",
         {{"scenario.path", "line"}}},
        {"light-step",
         "default throw; the light drops to 60 % at frame 6",
         {{"scenario.light", "step"},
          {"scenario.light_frame", "6"},
          {"scenario.light_gain", "0.6"}}},
        {"light-ramp",
         "default throw; the light dims to 50 % over frames 5-9",
         {{"scenario.light", "ramp"},
          {"scenario.light_frame", "5"},
          {"scenario.light_gain", "0.5"},
          {"scenario.light_ramp_frames", "4"}}},
        {"gray-in-sdram",
         "default throw, gray frames in SDRAM (before the L2 memory plan): over budget",
         {{"firmware.frame_memory", "sdram"}}},
        {"sequential",
         "default throw in sequential mode: over budget (22.5 ms capture + processing)",
         {{"firmware.mode", "sequential"}}},
        // Objects of any size (docs/firmware.md): the same pass across the
        // view, the ball 2 f r / sqrt(Z^2 - r^2) wide (f = 789.47 px).
        {"small",
         "a ball 10 px wide (16.5 mm at 2.6 m) on a slow pass across the view",
         {{"scenario.path", "pass"},
          {"scenario.depth_m", "2.6"},
          {"scenario.ball_radius_mm", "16.5"}}},
        {"large",
         "a ball half the image wide (320 px: 278 mm at 1.4 m) on a slow pass across the view",
         {{"scenario.path", "pass"},
          {"scenario.depth_m", "1.4"},
          {"scenario.ball_radius_mm", "278"}}},
        // A thrown ball spins: 100 mm radius, 61 px wide at 2.6 m to 99 px at 1.6 m,
        // turning 5 times a second (44 degrees a frame) about the axis across
        // the view, so its texture moves against its outline.
        {"spinning",
         "the default throw, a ball of 100 mm radius (61-99 px) spinning at 5 rev/s (300 rpm)",
         {{"scenario.ball_radius_mm", "100"},
          {"scenario.spin_rpm", "300"},
          {"scenario.spin_axis", "x"}}},
        {"slow-cpu",
         "300 MHz CPU and a 96 px tracking search radius: over budget in track",
         {{"dsk.cpu_mhz", "300"}, {"firmware.search_radius", "96"}}},
        {"dsk-v3",
         "default throw on the C6416T DSK v3 (1 GHz CPU, 125 MHz EMIF)",
         {{"dsk.version", "3"}}},
        // The paper's own system (docs/paper.md): its firmware in compiled C.
        // The factor 7 is the middle of the 5-10x that TI publishes for natural
        // C against tuned code (SPRU198K Table 3-4: 10 cycles/iteration vs 1;
        // its tutor1-4: 414 vs 55 cycles, 7.5x; MCU+ SDK DSPLIB DSP_add32 on
        // C66x: 2168 vs 342 cycles at N = 256, 6.3x); no source gives it for
        // SAD, Sobel or demosaic on the C64x. Not fitted to the paper's times.
        {"paper",
         "the paper's system: the default throw, firmware as compiled C (cost x7, docs/paper.md)",
         {{"firmware.compiled_c_factor", "7"}}},
    };
    return list;
}

const builtin_scenario* find_scenario(const std::string& name) {
    for (const builtin_scenario& s : builtin_scenarios())
        if (name == s.name) return &s;
    return nullptr;
}

scene::scenario build_scenario(const scenario_params& p, const scene::stereo_rig& rig) {
    scene::scenario s;
    s.scene.rig = rig;
    s.scene.background =
        scene::background_desc::procedural_plane(scene::procedural_texture_params{}, 5.0);
    const double period = s.frame_period_s;
    const double start = scene::motion_start_s(p.still_frames, period);
    scene::ball_desc ball;
    ball.radius_m = p.ball_radius_mm / 1000.0;
    ball.spin_rad_s = p.spin_rpm * 2.0 * M_PI / 60.0;
    ball.spin_axis = p.spin_axis == "y"   ? scene::vec3{0.0, 1.0, 0.0}
                     : p.spin_axis == "z" ? scene::vec3{0.0, 0.0, 1.0}
                                          : scene::vec3{1.0, 0.0, 0.0};
    if (p.path == "circle")
        ball.path = scene::circling_path(p.depth_m, p.speed, start);
    else if (p.path == "line")
        ball.path = scene::line_path(p.depth_m, p.speed, start);
    else if (p.path == "pass")
        ball.path = scene::pass_path(p.depth_m, p.speed, start);
    else if (p.path == "still")
        ball.path = scene::resting_path(p.depth_m);
    else
        ball.path = scene::thrown_ball_path(p.depth_m, ball.radius_m, p.speed, start);
    s.scene.balls.push_back(ball);
    if (p.light == "step") {
        // Half a period early, so frame light_frame (rendered within its own
        // period) is the first to see it.
        s.scene.light = scene::lighting::with_step((p.light_frame - 0.5) * period, p.light_gain);
    } else if (p.light == "ramp") {
        s.scene.light = scene::lighting::with_ramp(
            (p.light_frame - 0.5) * period, (p.light_frame - 0.5 + p.light_ramp_frames) * period,
            p.light_gain);
    }
    s.frame_count = 100;
    return s;
}

}  // namespace cli
