// The config key table (tb/app/cli/config_keys.h) without a simulation: docs/config.md
// lists exactly its keys, values are type- and range-checked with one-line
// messages, a misspelled key gets the nearest name, a scenario's settings
// apply before other keys, and the default setup renders exactly the
// platform's default scene (scene::default_scenario(3)).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "dsp/plugin/reference_firmware.h"
#include "model/scene/renderer.h"
#include "model/scene/sequence.h"
#include "tb/app/cli/config_keys.h"
#include "tb/app/cli/firmware_keys.h"
#include "tb/app/cli/scenarios.h"

namespace {

using nlohmann::json;

std::set<std::string> doc_keys() {
    std::ifstream in(std::string(STEREOSIM_SOURCE_DIR) + "/docs/config.md");
    EXPECT_TRUE(in) << "docs/config.md";
    std::set<std::string> keys;
    const std::regex row(R"(^\| `([a-z_]+\.[a-z_0-9]+)` \|)");
    for (std::string line; std::getline(in, line);) {
        std::smatch m;
        if (std::regex_search(line, m, row)) keys.insert(m[1]);
    }
    return keys;
}

// The docs/config.md table starting with `header`.
std::string docs_table(const std::string& header) {
    std::ifstream in(std::string(STEREOSIM_SOURCE_DIR) + "/docs/config.md");
    std::string docs, line;
    bool in_table = false;
    while (std::getline(in, line)) {
        in_table = in_table || line.rfind(header, 0) == 0;
        if (in_table && line.rfind("|", 0) != 0) break;
        if (in_table) docs += line + "\n";
    }
    return docs;
}

// docs/config.md's tables are what `stereosim config --markdown` prints.
TEST(cli_config, docs_table_is_the_generated_one) {
    EXPECT_EQ(docs_table("| key | type / range |"), cli::config_table_markdown());
    EXPECT_EQ(docs_table("| firmware key | type / range |"), cli::firmware_table_markdown());
}

TEST(cli_config, docs_list_exactly_the_table_keys) {
    std::set<std::string> table;
    for (const cli::config_key& k : cli::config_keys()) {
        EXPECT_TRUE(table.insert(k.name).second) << "duplicate key " << k.name;
        EXPECT_FALSE(k.doc.empty()) << k.name;
    }
    // The built-in firmware's own keys, its descriptor's (the second table).
    for (const cli::config_key& k : cli::firmware_own_keys(dsp::plugin::reference_firmware()))
        EXPECT_TRUE(table.insert(k.name).second) << "duplicate key " << k.name;
    const std::set<std::string> docs = doc_keys();
    for (const std::string& k : table)
        EXPECT_TRUE(docs.count(k)) << k << " missing in docs/config.md";
    for (const std::string& k : docs)
        EXPECT_TRUE(table.count(k)) << k << " in docs/config.md is no key";
    std::printf("config keys: %zu in the table, %zu in docs/config.md\n", table.size(),
                docs.size());
}

TEST(cli_config, misspelled_key_names_the_nearest) {
    EXPECT_EQ(cli::unknown_key_message("rig.baselin_mm"),
              "unknown config key 'rig.baselin_mm' (did you mean 'rig.baseline_mm'?)");
    EXPECT_EQ(cli::unknown_key_message("run.frame"),
              "unknown config key 'run.frame' (did you mean 'run.frames'?)");
    // Nothing near: no guess.
    EXPECT_EQ(cli::unknown_key_message("colour.of.the.sky").find("did you mean"),
              std::string::npos);
}

TEST(cli_config, values_are_type_and_range_checked) {
    json v;
    std::string error;
    const cli::config_key* frames = cli::find_key("run.frames");
    ASSERT_NE(frames, nullptr);
    EXPECT_TRUE(cli::parse_value(*frames, "8", &v, &error));
    EXPECT_EQ(v, json(8));
    EXPECT_FALSE(cli::parse_value(*frames, "-3", &v, &error));
    EXPECT_EQ(error, "config key 'run.frames': -3 is out of range 1..100000");
    EXPECT_FALSE(cli::parse_value(*frames, "0", &v, &error));
    EXPECT_FALSE(cli::parse_value(*frames, "8x", &v, &error));
    EXPECT_EQ(error, "config key 'run.frames': expected an integer, got '8x'");
    EXPECT_FALSE(cli::check_value(*frames, json(2.5), &v, &error));

    const cli::config_key* cpu = cli::find_key("dsk.cpu_mhz");
    EXPECT_FALSE(cli::parse_value(*cpu, "0", &v, &error));
    EXPECT_EQ(error, "config key 'dsk.cpu_mhz': 0 is out of range 50..2000");
    EXPECT_TRUE(cli::parse_value(*cpu, "850.5", &v, &error));

    // The firmware's own keys are checked against its descriptor.
    cli::run_setup parallel;
    parallel.firmware_settings = {{"firmware.mode", json("parallel")}};
    EXPECT_FALSE(cli::validate_setup(parallel, &error));
    EXPECT_EQ(error,
              "config key 'firmware.mode': \"parallel\" is not one of sequential|overlapped");
    const cli::config_key* noise = cli::find_key("sensor.noise");
    EXPECT_TRUE(cli::parse_value(*noise, "off", &v, &error));
    EXPECT_EQ(v, json(false));
    EXPECT_FALSE(cli::check_value(*noise, json("yes"), &v, &error));
}

TEST(cli_config, search_window_must_fit_the_image) {
    cli::run_setup setup;
    std::string error;
    setup.firmware_settings = {{"firmware.search_radius", json(239)}};  // 479 x 479 fits
    EXPECT_TRUE(cli::validate_setup(setup, &error)) << error;
    setup.firmware_settings = {{"firmware.search_radius", json(240)}};  // 481 rows > 480
    EXPECT_FALSE(cli::validate_setup(setup, &error));
    EXPECT_EQ(error,
              "config key 'firmware.search_radius': the search window 481 x 481 px is larger than "
              "the image (640 x 480)");
}

TEST(cli_config, scenario_settings_apply_first_then_the_user_keys) {
    cli::run_setup setup;
    std::string error;
    // slow-cpu sets dsk.cpu_mhz 300 and firmware.search_radius 96; the user's
    // radius wins whatever the order it was given in.
    std::vector<cli::key_assignment> a = {{"firmware.search_radius", json(40)},
                                          {"scenario.name", json("slow-cpu")}};
    ASSERT_TRUE(cli::apply_assignments(a, &setup, &error)) << error;
    EXPECT_EQ(platform::firmware_key(cli::platform_config_of(setup), "search_radius", 0), 40);
    EXPECT_DOUBLE_EQ(setup.effective_cpu_mhz(), 300.0);
    a = {{"scenario.name", json("nosuch")}};
    EXPECT_FALSE(cli::apply_assignments(a, &setup, &error));
    EXPECT_EQ(error, "unknown scenario 'nosuch' (stereosim scenarios lists them)");
    // Every built-in scenario's settings are valid keys and values.
    for (const cli::builtin_scenario& s : cli::builtin_scenarios()) {
        a = {{"scenario.name", json(s.name)}};
        EXPECT_TRUE(cli::apply_assignments(a, &setup, &error)) << s.name << ": " << error;
        EXPECT_TRUE(cli::validate_setup(setup, &error)) << s.name << ": " << error;
    }
}

TEST(cli_config, config_json_round_trips_through_the_file_reader) {
    cli::run_setup setup;
    std::string error;
    std::vector<cli::key_assignment> a = {{"scenario.name", json("near")},
                                          {"dsk.version", json(2)},
                                          {"firmware.stereo_method", json("both")},
                                          {"run.frames", json(7)}};
    ASSERT_TRUE(cli::apply_assignments(a, &setup, &error));
    const std::string path = testing::TempDir() + "cli_config_round_trip.json";
    std::ofstream(path) << cli::config_json(setup).dump(2);
    std::vector<cli::key_assignment> read;
    ASSERT_TRUE(cli::read_config_file(path, &read, &error)) << error;
    EXPECT_EQ(read.size(), cli::config_keys().size() + setup.firmware_settings.size());
    cli::run_setup again;
    ASSERT_TRUE(cli::apply_assignments(read, &again, &error)) << error;
    EXPECT_EQ(cli::config_json(again), cli::config_json(setup));
    EXPECT_EQ(again.scenario.path, "circle");
    EXPECT_DOUBLE_EQ(again.effective_cpu_mhz(), 720.0);  // v2's CPU clock
}

// The default setup makes the platform's default scene: same ball path at
// every time (ground truth through the scene's closed form), same rig.
TEST(cli_config, default_setup_is_the_platform_default_scene) {
    const platform::platform_config config = cli::platform_config_of(cli::run_setup{});
    const scene::scenario reference = scene::default_scenario(3);
    ASSERT_EQ(config.scenario.scene.balls.size(), 1u);
    const scene::stereo_rig& rig = config.scenario.scene.rig;
    EXPECT_EQ(rig.focal_px(), reference.scene.rig.focal_px());
    EXPECT_EQ(rig.baseline_m, reference.scene.rig.baseline_m);
    int compared = 0;
    for (int n = 0; n < 40; ++n) {
        const double t = n * reference.frame_period_s;
        const scene::ball_truth a = scene::ball_truth_at(rig, config.scenario.scene.balls[0], t);
        const scene::ball_truth b =
            scene::ball_truth_at(reference.scene.rig, reference.scene.balls[0], t);
        EXPECT_EQ(a.centre_m.x, b.centre_m.x) << n;
        EXPECT_EQ(a.centre_m.y, b.centre_m.y) << n;
        EXPECT_EQ(a.centre_m.z, b.centre_m.z) << n;
        ++compared;
    }
    // Negative control: speed 2 moves the ball differently after the start.
    cli::run_setup fast;
    fast.scenario.speed = 2.0;
    const platform::platform_config f = cli::platform_config_of(fast);
    const double t = 10 * reference.frame_period_s;
    EXPECT_NE(scene::ball_truth_at(rig, f.scenario.scene.balls[0], t).centre_m.z,
              scene::ball_truth_at(rig, reference.scene.balls[0], t).centre_m.z);
    EXPECT_EQ(config.frames, 12);
    EXPECT_EQ(config.seed, 3u);
    EXPECT_EQ(config.quantum, platform::platform_config{}.quantum);
    std::printf("default setup: %d frame times compared with scene::default_scenario(3)\n",
                compared);
}

// The spin keys reach the renderer: `--scenario spinning` turns the ball's
// texture while its outline follows the path. Each axis name is its unit
// vector of the world frame. Rendered with and without the spin: before the
// throw (frame 1, no turn yet) the images are equal; at frame 5 (about a
// quarter turn on) the coverage (the outline) is equal and only pixels the
// ball covers differ.
TEST(cli_config, spin_turns_the_ball_texture_not_its_outline) {
    cli::run_setup spinning;
    std::string error;
    ASSERT_TRUE(cli::apply_assignments({{"scenario.name", json("spinning")}}, &spinning, &error))
        << error;
    EXPECT_EQ(spinning.scenario.spin_rpm, 300.0);
    EXPECT_EQ(spinning.scenario.spin_axis, "x");
    cli::run_setup still = spinning;
    still.scenario.spin_rpm = 0.0;
    const platform::platform_config a = cli::platform_config_of(spinning);
    const platform::platform_config b = cli::platform_config_of(still);
    ASSERT_EQ(a.scenario.scene.balls.size(), 1u);
    EXPECT_DOUBLE_EQ(a.scenario.scene.balls[0].spin_rad_s, 10.0 * M_PI);  // 300 rpm
    const std::pair<const char*, scene::vec3> axes[] = {
        {"x", {1.0, 0.0, 0.0}}, {"y", {0.0, 1.0, 0.0}}, {"z", {0.0, 0.0, 1.0}}};
    for (const auto& [name, unit] : axes) {
        cli::run_setup s = spinning;
        s.scenario.spin_axis = name;
        const scene::vec3 axis = cli::platform_config_of(s).scenario.scene.balls[0].spin_axis;
        EXPECT_EQ(axis.x, unit.x) << name;
        EXPECT_EQ(axis.y, unit.y) << name;
        EXPECT_EQ(axis.z, unit.z) << name;
    }
    const scene::renderer with_spin(a.scenario.scene), without(b.scenario.scene);
    const double period = a.scenario.frame_period_s;
    for (int frame : {1, 5}) {
        scene::rgb_image ia, ib;
        scene::gray_image ca, cb;
        with_spin.render(scene::camera_id::right, frame * period, &ia, &ca);
        without.render(scene::camera_id::right, frame * period, &ib, &cb);
        int ball_pixels = 0, differ_on_ball = 0, differ_off_ball = 0, outline_differs = 0;
        for (int y = 0; y < ia.height; ++y) {
            for (int x = 0; x < ia.width; ++x) {
                if (ca.at(x, y) != cb.at(x, y)) ++outline_differs;
                const bool on_ball = ca.at(x, y) > 0;
                const dsp::rgb8 p = ia.at(x, y), q = ib.at(x, y);
                const bool differ = p.r != q.r || p.g != q.g || p.b != q.b;
                ball_pixels += on_ball ? 1 : 0;
                differ_on_ball += on_ball && differ ? 1 : 0;
                differ_off_ball += !on_ball && differ ? 1 : 0;
            }
        }
        EXPECT_EQ(outline_differs, 0) << frame;
        EXPECT_EQ(differ_off_ball, 0) << frame;
        EXPECT_GT(ball_pixels, 2000) << frame;  // 61 px wide or more: ~2900 px
        if (frame == 1) {
            EXPECT_EQ(differ_on_ball, 0);  // the throw starts at frame 3
        } else {
            EXPECT_GT(differ_on_ball, ball_pixels / 2);
        }
        std::printf("frame %d: %d ball pixels, %d differ with the spin\n", frame, ball_pixels,
                    differ_on_ball);
    }
}

}  // namespace
