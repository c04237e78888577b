#include "tb/app/cli/scenarios.h"

#include <cmath>

#include "model/scene/background.h"
#include "model/scene/lighting.h"
#include "model/scene/trajectory.h"

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
        {"slow-cpu",
         "300 MHz CPU and a 96 px tracking search radius: over budget in track",
         {{"dsk.cpu_mhz", "300"}, {"firmware.search_radius", "96"}}},
        {"dsk-v3",
         "default throw on the C6416T DSK v3 (1 GHz CPU, 125 MHz EMIF)",
         {{"dsk.version", "3"}}},
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
    // Frames 0 .. still_frames-1 all see the start position (as default_scenario).
    const double start = (p.still_frames > 0 ? p.still_frames - 1 : 0) * period;
    const double pi = std::acos(-1.0);
    const double v = p.speed;
    scene::ball_desc ball;
    ball.radius_m = p.ball_radius_mm / 1000.0;
    if (p.path == "circle") {
        const double radius = 0.15 * p.depth_m, speed = 0.41 * p.depth_m * v;
        ball.path = scene::trajectory::circle({0.0, 0.0, p.depth_m}, radius, {1.0, 0.0, 0.0},
                                              {0.0, 1.0, 0.0}, speed / radius, pi, start);
    } else if (p.path == "line") {
        ball.path =
            scene::trajectory::line({-0.25, -0.05, p.depth_m}, {1.0 * v, 0.1 * v, 0.0}, start);
    } else if (p.path == "still") {
        ball.path = scene::trajectory::still({-0.30, 0.0, p.depth_m});
    } else {
        // The floor 0.35 m below the optical axis: the centre touches it at
        // 0.35 - r (written so that r = 5 cm gives default_scenario's 0.30 exactly).
        const double bounce_y = 0.30 + (0.05 - ball.radius_m);
        ball.path = scene::trajectory::ballistic({-0.30, 0.0, p.depth_m},
                                                 {0.14 * v, -2.0 * v, -0.45 * v}, start,
                                                 /*has_floor=*/true, bounce_y, 0.8);
        ball.path.gravity_m_s2 *= v * v;  // time scale: p_v(t) = p(v t)
    }
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
