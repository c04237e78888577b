// The shipped firmware behind the C ABI (dsp/plugin, docs/firmware-abi.md):
// libstereosim_fw_reference.so loads, describes the firmware of dsp/ (its
// stages, tracker states and config keys with the platform's defaults), makes
// from a board and key values exactly the configuration the platform gives
// the built-in firmware, and runs: with no card on the bus it reports the
// missing card and returns. Its host entry charges per pair what its
// controller charges.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dsp/controller.h"
#include "dsp/plugin/reference_firmware.h"
#include "tb/firmware/plugin.h"
#include "tb/platform/firmware_board.h"
#include "tb/platform/host/firmware_host.h"
#include "tb/platform/platform_config.h"
#include "tests/support/host/stereo_runner.h"

namespace {

std::unique_ptr<firmware::plugin> load_reference() {
    std::string error;
    auto p = firmware::plugin::load(REFERENCE_FIRMWARE, &error);
    EXPECT_NE(p, nullptr) << error;
    return p;
}

TEST(ReferencePlugin, DescribesTheFirmwareOfDsp) {
    const auto p = load_reference();
    ASSERT_NE(p, nullptr);
    const stereosim_fw_descriptor& d = p->descriptor();
    EXPECT_STREQ(d.name, "stereosim-reference");
    ASSERT_EQ(d.stage_count, static_cast<uint32_t>(dsp::stage_count));
    for (int s = 0; s < dsp::stage_count; ++s)
        EXPECT_STREQ(d.stage_names[s], dsp::stage_name(static_cast<dsp::stage>(s)));
    ASSERT_EQ(d.tracker_state_count, 3u);
    for (uint32_t s = 0; s < 3; ++s)
        EXPECT_STREQ(d.tracker_state_names[s],
                     dsp::tracker_state_name(static_cast<dsp::tracker_state>(s)));
    // Its defaults are the platform's: a run that sets nothing runs the same.
    const std::vector<double> platform_defaults =
        platform::reference_values(platform::platform_config{});
    ASSERT_EQ(d.key_count, platform_defaults.size());
    for (uint32_t k = 0; k < d.key_count; ++k)
        EXPECT_EQ(d.keys[k].default_value, platform_defaults[k]) << d.keys[k].name;
}

void expect_same(const dsp::control_program_config& a, const dsp::control_program_config& b) {
    EXPECT_EQ(a.pipeline.max_width, b.pipeline.max_width);
    EXPECT_EQ(a.pipeline.max_height, b.pipeline.max_height);
    EXPECT_EQ(a.pipeline.cfa, b.pipeline.cfa);
    EXPECT_EQ(a.pipeline.track.search_radius, b.pipeline.track.search_radius);
    EXPECT_EQ(a.pipeline.detect.threshold, b.pipeline.detect.threshold);
    EXPECT_EQ(a.pipeline.method, b.pipeline.method);
    EXPECT_EQ(a.pipeline.frame_memory, b.pipeline.frame_memory);
    EXPECT_EQ(a.pipeline.rig.baseline_um, b.pipeline.rig.baseline_um);
    EXPECT_EQ(a.pipeline.rig.focal_length_um, b.pipeline.rig.focal_length_um);
    EXPECT_EQ(a.pipeline.rig.pixel_pitch_nm, b.pipeline.rig.pixel_pitch_nm);
    EXPECT_EQ(a.pipeline.rig.cx_left_q8, b.pipeline.rig.cx_left_q8);
    EXPECT_EQ(a.pipeline.rig.cy_left_q8, b.pipeline.rig.cy_left_q8);
    EXPECT_EQ(a.pipeline.rig.cx_right_q8, b.pipeline.rig.cx_right_q8);
    EXPECT_EQ(a.pipeline.rig.cy_right_q8, b.pipeline.rig.cy_right_q8);
    const uint32_t* ca = &a.card.dark_threshold;
    const uint32_t* cb = &b.card.dark_threshold;
    constexpr size_t card_words = sizeof(dsp::card_setup) / sizeof(uint32_t);
    for (size_t i = 0; i < card_words; ++i) EXPECT_EQ(ca[i], cb[i]) << "card_setup word " << i;
    EXPECT_EQ(a.dsk, b.dsk);
    EXPECT_EQ(a.card_timing.setup, b.card_timing.setup);
    EXPECT_EQ(a.card_timing.strobe, b.card_timing.strobe);
    EXPECT_EQ(a.card_timing.hold, b.card_timing.hold);
    EXPECT_EQ(a.cpu_mhz, b.cpu_mhz);
    EXPECT_EQ(a.mode, b.mode);
    EXPECT_EQ(a.buffer_base, b.buffer_base);
    EXPECT_EQ(a.control_base, b.control_base);
    EXPECT_EQ(a.max_pairs, b.max_pairs);
    EXPECT_EQ(a.rearm_on_overflow, b.rearm_on_overflow);
    EXPECT_EQ(a.rearm_on_every_sync_error, b.rearm_on_every_sync_error);
    EXPECT_EQ(a.watchdog_ms, b.watchdog_ms);
    EXPECT_EQ(a.capture_cycles, b.capture_cycles);
    EXPECT_EQ(a.rearm_idle_polls, b.rearm_idle_polls);
    EXPECT_EQ(a.hard_error_rearms, b.hard_error_rearms);
}

// The configuration the plugin makes equals the one the platform gives the
// built-in firmware, over the settings a run can change.
TEST(ReferencePlugin, MakesThePlatformsConfiguration) {
    std::vector<platform::platform_config> configs(8);
    configs[1].dsk = c6416::dsk_v3();
    configs[2].mode = dsp::pipeline_mode::sequential;
    configs[3].card_timing = dsp::card_bus_timing{3, 20, 1};
    configs[3].card_retry_limit = 2;
    configs[4].watchdog_ms = 50;
    configs[4].card_start_timeout = 65535;
    configs[4].hard_error_rearms = 3;
    configs[5].stereo_method = dsp::stereo_method::both;
    configs[5].frame_memory = dsp::cost::memory::sdram;
    configs[5].track_search_radius = 40;
    configs[5].detect_threshold = 33;
    configs[6].dsk = c6416::dsk_custom(800000000, 100000000);
    configs[7].capture_cycles = 1200;
    configs[7].profile.cfa = dsp::cfa_order::grbg;
    for (size_t i = 0; i < configs.size(); ++i) {
        SCOPED_TRACE("config " + std::to_string(i));
        const std::vector<double> values = platform::reference_values(configs[i]);
        expect_same(dsp::plugin::reference_config(platform::board_of(configs[i]), values.data()),
                    platform::program_config(configs[i]));
        // Loaded as a plugin it gets the same values.
        EXPECT_EQ(platform::plugin_values(dsp::plugin::reference_firmware(), configs[i]), values);
    }
}

// Another firmware's keys: one named like a reference setting takes the run's
// value when it fits the key (a choice by name), the others their defaults.
TEST(ReferencePlugin, AnotherFirmwaresKeysTakeTheRunsSettingsByName) {
    const char* const modes[] = {"overlapped", "turbo"};
    const stereosim_fw_key keys[] = {
        {"watchdog_ms", STEREOSIM_KEY_INT, 0, 100, 7, nullptr, 0, "a watchdog"},
        {"mode", STEREOSIM_KEY_CHOICE, 0, 0, 1, modes, 2, "a mode"},
        {"gain", STEREOSIM_KEY_FLOAT, 0, 2, 1.5, nullptr, 0, "its own"},
    };
    stereosim_fw_descriptor d = dsp::plugin::reference_firmware();
    d.keys = keys;
    d.key_count = 3;
    platform::platform_config config;  // watchdog 500 ms: outside 0..100, overlapped
    EXPECT_EQ(platform::plugin_values(d, config), (std::vector<double>{7, 0, 1.5}));
    config.watchdog_ms = 50;
    config.mode = dsp::pipeline_mode::sequential;  // no such choice: the default
    EXPECT_EQ(platform::plugin_values(d, config), (std::vector<double>{50, 1, 1.5}));
}

// A bus with nothing on it (every read 0, so no card ID) and the DSK's
// memories: L2 from 0, SDRAM from 0x80000000 (16 MB).
struct empty_bus {
    std::vector<stereosim_event> events;
    std::vector<uint8_t> l2 = std::vector<uint8_t>(1u << 20);
    std::vector<uint8_t> sdram = std::vector<uint8_t>(16u << 20);

    uint8_t* memory(uint32_t address, uint32_t bytes) {
        const uint64_t end = uint64_t{address} + bytes;
        if (end <= l2.size()) return l2.data() + address;
        if (address >= 0x80000000u && end - 0x80000000u <= sdram.size())
            return sdram.data() + (address - 0x80000000u);
        return nullptr;
    }
};

TEST(ReferencePlugin, RunsAndReportsAMissingCard) {
    const auto p = load_reference();
    ASSERT_NE(p, nullptr);
    empty_bus bus;
    stereosim_services s{};
    s.abi_version = STEREOSIM_FIRMWARE_ABI_VERSION;
    s.ctx = &bus;
    s.charge = [](void*, uint32_t, uint64_t, const stereosim_sdram_traffic*) {};
    s.kernel_cycles = [](void*, const stereosim_kernel_profile*, stereosim_sdram_traffic*) {
        return uint64_t{0};
    };
    s.stage_begin = [](void*, uint32_t) {};
    s.stage_end = [](void*, uint32_t) {};
    s.read32 = [](void*, uint32_t) { return 0u; };
    s.write32 = [](void*, uint32_t, uint32_t) {};
    s.memory = [](void* ctx, uint32_t address, uint32_t bytes) {
        return static_cast<empty_bus*>(ctx)->memory(address, bytes);
    };
    s.set_interrupt_enable = [](void*, uint32_t) {};
    s.interrupt_flags = [](void*) { return 0u; };
    s.clear_interrupt_flags = [](void*, uint32_t) {};
    s.wait_for_interrupt = [](void*) -> int32_t { return STEREOSIM_FW_NO_INTERRUPT; };
    s.stop_requested = [](void*) -> int32_t { return 1; };
    s.report = [](void* ctx, const stereosim_event* e) {
        static_cast<empty_bus*>(ctx)->events.push_back(*e);
    };
    s.report_result = [](void*, const stereosim_result*) {};

    const platform::platform_config config;
    const stereosim_board board = platform::board_of(config);
    const std::vector<double> values = platform::reference_values(config);
    char error[160] = "";
    const stereosim_fw_descriptor& d = p->descriptor();
    void* fw = d.create(&s, &board, values.data(), error, sizeof error);
    ASSERT_NE(fw, nullptr) << error;
    stereosim_fw_policy policy{};
    d.policy(fw, &policy);
    EXPECT_EQ(policy.hard_error_rearms, 1u);
    EXPECT_EQ(policy.watchdog_ms, 500u);
    EXPECT_EQ(policy.overlapped, 1u);
    d.run(fw);
    d.destroy(fw);
    ASSERT_FALSE(bus.events.empty());
    EXPECT_EQ(bus.events.back().kind, static_cast<uint32_t>(STEREOSIM_EV_CARD_MISSING));
    EXPECT_EQ(bus.events.back().value, 0u);

    stereosim_board tiny = board;
    tiny.active_cols = 2;  // smaller than any usable image: refused with its line
    EXPECT_EQ(d.create(&s, &tiny, values.data(), error, sizeof error), nullptr);
    EXPECT_STREQ(error, "the image size (2x480) or the buffer placement is not usable");
}

// The .so's host entry over the default scenario (tb/platform/host/
// firmware_host) against the test harness driving the reference's
// controller directly through a counting HAL: per pair, per stage, the
// result's cycles are what the controller charged, the capture stage's plus
// the control program's capture work; the same boxes, state and point.
TEST(ReferencePlugin, TheHostEntryChargesWhatTheControllerCharges) {
    const auto p = load_reference();
    ASSERT_NE(p, nullptr);
    ASSERT_NE(p->host(), nullptr);
    platform::platform_config config;
    config.scenario = scene::default_scenario(2);
    std::string error;
    const auto fw = host::firmware_host::create(
        *p->host(), p->descriptor().stage_count, config.scenario, platform::board_of(config),
        platform::plugin_values(p->descriptor(), config), platform::cost_model_of(config), &error);
    ASSERT_NE(fw, nullptr) << error;
    host::stereo_runner runner(config.scenario, platform::pipeline_config(config),
                               platform::cost_model_of(config));
    int tracked = 0;
    for (int n = 0; n < 10; ++n) {
        stereosim_result r{};
        ASSERT_TRUE(fw->step(n, &r, &error)) << error;
        const host::host_record h = runner.step(n);
        for (int s = 0; s < dsp::stage_count; ++s) {
            const uint64_t capture = s == 0 ? config.capture_cycles : 0;
            EXPECT_EQ(r.stage_cycles[s],
                      runner.hal().frame_cycles(static_cast<dsp::stage>(s)) + capture)
                << "pair " << n << " stage " << s;
        }
        EXPECT_EQ(r.state, h.out.state) << n;
        EXPECT_EQ(r.has_object, h.out.has_object) << n;
        EXPECT_EQ(r.box_left.x, h.out.box_left.x) << n;
        EXPECT_EQ(r.box_right.y, h.out.box_right.y) << n;
        EXPECT_EQ(r.has_point, h.out.has_point) << n;
        EXPECT_EQ(r.z_um, h.out.z_um) << n;
        tracked += r.has_point;
    }
    EXPECT_GE(tracked, 5);  // the ball is found and followed: the chain ran
    // A scenario whose images are not the sensors' active area is refused.
    platform::platform_config small = config;
    small.scenario.scene.rig.width = 320;
    EXPECT_EQ(
        host::firmware_host::create(*p->host(), p->descriptor().stage_count, small.scenario,
                                    platform::board_of(config), platform::reference_values(config),
                                    platform::cost_model_of(config), &error),
        nullptr);
    EXPECT_EQ(error, "the scenario's images are not the sensors' active area");
}

}  // namespace
