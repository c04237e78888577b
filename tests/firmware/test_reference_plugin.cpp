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
#include "dsp/kernel_costs.h"
#include "dsp/plugin/reference_firmware.h"
#include "dsp/plugin/services_hal.h"
#include "tb/firmware/plugin.h"
#include "tb/platform/firmware_board.h"
#include "tb/platform/host/cost_service.h"
#include "tb/platform/host/firmware_host.h"
#include "tb/platform/platform_config.h"
#include "tests/support/host/reference_config.h"
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
}

// The configuration the plugin makes from a run's board and key settings:
// every board fact and every key where the control program reads it.
TEST(ReferencePlugin, MakesTheConfigurationARunAsksFor) {
    platform::platform_config config;
    config.dsk = c6416::dsk_v3();
    config.card_timing = platform::card_bus_timing{3, 20, 1};
    config.card_retry_limit = 2;
    config.profile.cfa = dsp::cfa_order::grbg;
    const std::pair<const char*, double> settings[] = {{"mode", 0},
                                                       {"search_radius", 40},
                                                       {"stereo_method", 2},
                                                       {"detect_threshold", 33},
                                                       {"frame_memory", 1},
                                                       {"watchdog_ms", 50},
                                                       {"card_start_timeout", 65535},
                                                       {"capture_cycles", 1200},
                                                       {"hard_error_rearms", 3},
                                                       {"rearm_on_overflow", 0},
                                                       {"rearm_on_every_sync_error", 1}};
    for (const auto& [name, value] : settings) platform::set_firmware_key(&config, name, value);
    const std::vector<double> values =
        platform::plugin_values(dsp::plugin::reference_firmware(), config);
    const dsp::control_program_config c =
        dsp::plugin::reference_config(platform::board_of(config), values.data());
    EXPECT_EQ(c.dsk, dsp::dsk_version::v3);
    EXPECT_EQ(c.cpu_mhz, 1000u);
    EXPECT_EQ(c.card_timing.setup, 3u);
    EXPECT_EQ(c.card_timing.strobe, 20u);
    EXPECT_EQ(c.card_timing.hold, 1u);
    EXPECT_EQ(c.card.retry_limit, 2u);
    EXPECT_EQ(c.card.active_cols, 640u);
    EXPECT_EQ(c.card.frame_lines, 525u);
    EXPECT_EQ(c.pipeline.cfa, dsp::cfa_order::grbg);
    EXPECT_EQ(c.pipeline.max_width, 640);
    EXPECT_EQ(c.pipeline.rig.baseline_um, 120000);
    EXPECT_EQ(c.mode, dsp::pipeline_mode::sequential);
    EXPECT_EQ(c.pipeline.track.search_radius, 40);
    EXPECT_EQ(c.pipeline.method, dsp::stereo_method::both);
    EXPECT_EQ(c.pipeline.detect.threshold, 33);
    EXPECT_EQ(c.pipeline.frame_memory, dsp::cost::memory::sdram);
    EXPECT_EQ(c.watchdog_ms, 50u);
    EXPECT_EQ(c.card.start_timeout, 65535u);
    EXPECT_EQ(c.capture_cycles, 1200u);
    EXPECT_EQ(c.hard_error_rearms, 3u);
    EXPECT_FALSE(c.rearm_on_overflow);
    EXPECT_TRUE(c.rearm_on_every_sync_error);
    // A run that sets nothing: the firmware's own defaults.
    const platform::platform_config plain;
    const std::vector<double> defaults =
        platform::plugin_values(dsp::plugin::reference_firmware(), plain);
    const dsp::control_program_config d =
        dsp::plugin::reference_config(platform::board_of(plain), defaults.data());
    const dsp::control_program_config own;
    EXPECT_EQ(d.mode, own.mode);
    EXPECT_EQ(d.pipeline.track.search_radius, own.pipeline.track.search_radius);
    EXPECT_EQ(d.pipeline.method, own.pipeline.method);
    EXPECT_EQ(d.pipeline.detect.threshold, own.pipeline.detect.threshold);
    EXPECT_EQ(d.pipeline.frame_memory, own.pipeline.frame_memory);
    EXPECT_EQ(d.watchdog_ms, own.watchdog_ms);
    EXPECT_EQ(d.card.start_timeout, own.card.start_timeout);
    EXPECT_EQ(d.capture_cycles, own.capture_cycles);
    EXPECT_EQ(d.hard_error_rearms, own.hard_error_rearms);
    EXPECT_EQ(d.rearm_on_overflow, own.rearm_on_overflow);
    EXPECT_EQ(d.rearm_on_every_sync_error, own.rearm_on_every_sync_error);
}

// The CECTL the closed forms predict is what the reference firmware
// programs for the same board (its own computation, dsp::card_cectl).
TEST(ReferencePlugin, TheBoardAsksTheCectlTheFirmwarePrograms) {
    const platform::card_bus_timing timings[] = {{0, 0, 0}, {3, 20, 1}, {15, 63, 3}, {0, 7, 0}};
    for (int version = 1; version <= 3; ++version)
        for (const platform::card_bus_timing& t : timings) {
            platform::platform_config config;
            config.dsk = c6416::dsk_version(version);
            config.card_timing = t;
            const std::vector<double> values =
                platform::plugin_values(dsp::plugin::reference_firmware(), config);
            const uint32_t programmed = dsp::card_cectl(
                dsp::plugin::reference_config(platform::board_of(config), values.data()));
            EXPECT_EQ(platform::card_cectl_asked(config), programmed)
                << "v" << version << " " << t.setup << "/" << t.strobe << "/" << t.hold;
        }
}

// Another firmware's keys: each takes the run's setting by its name, or the
// default it declares (never the reference's default of a key of the same
// name).
TEST(ReferencePlugin, AnotherFirmwaresKeysTakeItsOwnDefaults) {
    const char* const modes[] = {"overlapped", "turbo"};
    const stereosim_fw_key keys[] = {
        {"watchdog_ms", STEREOSIM_KEY_INT, 0, 100, 7, nullptr, 0, "a watchdog"},
        {"mode", STEREOSIM_KEY_CHOICE, 0, 0, 1, modes, 2, "a mode"},
        {"gain", STEREOSIM_KEY_FLOAT, 0, 2, 1.5, nullptr, 0, "its own"},
    };
    stereosim_fw_descriptor d = dsp::plugin::reference_firmware();
    d.keys = keys;
    d.key_count = 3;
    platform::platform_config config;
    EXPECT_EQ(platform::plugin_values(d, config), (std::vector<double>{7, 1, 1.5}));
    EXPECT_TRUE(platform::asks_overlapped(d, config));  // "turbo" is not "sequential"
    platform::set_firmware_key(&config, "watchdog_ms", 50);
    platform::set_firmware_key(&config, "mode", 0);
    EXPECT_EQ(platform::plugin_values(d, config), (std::vector<double>{50, 0, 1.5}));
    EXPECT_EQ(platform::key_choice(d, config, "mode"), "overlapped");
    EXPECT_EQ(platform::key_choice(d, config, "gain"), "");  // not a choice
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
    const std::vector<double> values =
        platform::plugin_values(dsp::plugin::reference_firmware(), config);
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

// A kernel whose profile holds a block entered 0 times (the window fit's
// second differences over a window of three) costs through the ABI's cost
// service what it costs in the controller's own model: the ABI takes 0
// entries as 1, so such a block must not cross it.
TEST(ReferencePlugin, AKernelCostsThroughTheAbiWhatItCostsInProcess) {
    const c64x::cost_model model;
    for (const int extents : {3, 4}) {
        const c64x::kernel_profile k = dsp::cost::window_fit_profile(extents);
        c64x::kernel_profile with_empty = k;
        with_empty.add(c64x::block("never", c64x::op_mix{1, 0, 0, 0, 0, 0}, 5, 0));
        for (const c64x::kernel_profile& profile : {k, with_empty}) {
            const stereosim_kernel_profile abi = dsp::plugin::abi_profile(profile);
            EXPECT_EQ(host::kernel_cycles(model, abi, nullptr), model.cycles(profile))
                << extents << " extents, " << profile.section_count << " sections";
        }
    }
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
    const dsp::control_program_config program = host::program_config(config);
    host::stereo_runner runner(config.scenario, program.pipeline, platform::cost_model_of(config));
    int tracked = 0;
    for (int n = 0; n < 10; ++n) {
        stereosim_result r{};
        ASSERT_TRUE(fw->step(n, &r, &error)) << error;
        const host::host_record h = runner.step(n);
        for (int s = 0; s < dsp::stage_count; ++s) {
            const uint64_t capture = s == 0 ? program.capture_cycles : 0;
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
    EXPECT_EQ(host::firmware_host::create(*p->host(), p->descriptor().stage_count, small.scenario,
                                          platform::board_of(config),
                                          platform::plugin_values(p->descriptor(), config),
                                          platform::cost_model_of(config), &error),
              nullptr);
    EXPECT_EQ(error, "the scenario's images are not the sensors' active area");
}

}  // namespace
