// The firmware ABI's loader (tb/firmware, docs/firmware-abi.md) on real
// shared objects: a small firmware written in C (plugins/minimal_firmware.c)
// built as it should be and once per defect, each refused with one line
// naming the file and the problem; the good one created, run and destroyed
// through the services table, its SHA-256 against coreutils' sha256sum.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "tb/firmware/descriptor_check.h"
#include "tb/firmware/plugin.h"

namespace {

// A platform that counts: a fixed number of interrupts, then a stop.
struct test_platform {
    int interrupts_left = 3;
    uint32_t ier = 0;
    std::vector<stereosim_event> events;
    uint64_t cycles[STEREOSIM_FW_MAX_STAGES] = {};
};

test_platform& of(void* ctx) {
    return *static_cast<test_platform*>(ctx);
}

stereosim_services services_of(test_platform* p) {
    stereosim_services s{};
    s.abi_version = STEREOSIM_FIRMWARE_ABI_VERSION;
    s.ctx = p;
    s.charge = [](void* ctx, uint32_t stage, uint64_t cycles, const stereosim_sdram_traffic*) {
        of(ctx).cycles[stage] += cycles;
    };
    s.set_interrupt_enable = [](void* ctx, uint32_t ier) { of(ctx).ier = ier; };
    s.stage_begin = [](void*, uint32_t) {};
    s.stage_end = [](void*, uint32_t) {};
    s.wait_for_interrupt = [](void* ctx) -> int32_t {
        return of(ctx).interrupts_left-- > 0 ? 4 : STEREOSIM_FW_NO_INTERRUPT;
    };
    s.stop_requested = [](void*) -> int32_t { return 0; };
    s.report = [](void* ctx, const stereosim_event* e) { of(ctx).events.push_back(*e); };
    return s;
}

std::string output_of(const std::string& command) {
    std::string text;
    if (std::FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[256];
        while (std::fgets(buffer, sizeof buffer, pipe)) text += buffer;
        pclose(pipe);
    }
    return text;
}

std::string refusal(const std::string& path) {
    std::string error;
    EXPECT_EQ(firmware::plugin::load(path, &error), nullptr) << path;
    return error;
}

TEST(FirmwarePlugin, AGoodPluginLoadsRunsAndIsIdentified) {
    std::string error;
    const auto p = firmware::plugin::load(MINIMAL_FIRMWARE, &error);
    ASSERT_NE(p, nullptr) << error;
    const stereosim_fw_descriptor& d = p->descriptor();
    EXPECT_STREQ(d.name, "minimal");
    EXPECT_STREQ(d.version, "0.1");
    EXPECT_EQ(d.stage_count, 2u);
    EXPECT_STREQ(d.stage_names[1], "think");
    EXPECT_EQ(p->host(), nullptr);  // it exports no host entry (optional)
    // The digest of an independent implementation (coreutils).
    const std::string expected = output_of("sha256sum '" + std::string(MINIMAL_FIRMWARE) + "'");
    ASSERT_GE(expected.size(), 64u);
    EXPECT_EQ(p->sha256(), expected.substr(0, 64));

    test_platform platform;
    const stereosim_services services = services_of(&platform);
    stereosim_board board{};
    board.active_cols = 640;
    const double values[] = {600, 1};  // cycles_per_wait, mode chatty
    char why[128] = "";
    void* instance = d.create(&services, &board, values, why, sizeof why);
    ASSERT_NE(instance, nullptr) << why;
    d.run(instance);
    d.destroy(instance);
    EXPECT_EQ(platform.ier, 1u << 4);
    EXPECT_EQ(platform.cycles[1], 3u * 600u);
    ASSERT_EQ(platform.events.size(), 5u);
    EXPECT_EQ(platform.events.front().kind, static_cast<uint32_t>(STEREOSIM_EV_BOOT));
    EXPECT_EQ(platform.events[1].kind, static_cast<uint32_t>(STEREOSIM_EV_WATCHDOG));
    EXPECT_EQ(platform.events.back().kind, static_cast<uint32_t>(STEREOSIM_EV_STOPPED));
    EXPECT_EQ(platform.events.back().value, 3u);

    board.active_cols = 0;  // the plugin's own refusal comes back as its line
    EXPECT_EQ(d.create(&services, &board, values, why, sizeof why), nullptr);
    EXPECT_STREQ(why, "the board has no active columns");
}

TEST(FirmwarePlugin, EveryDefectIsOneLineNamingTheFile) {
    const std::string bad_abi = MINIMAL_FIRMWARE_BAD_ABI;
    EXPECT_EQ(refusal(bad_abi),
              "firmware '" + bad_abi + "': built for ABI version 99, this stereosim speaks 1");
    const std::string no_entry = MINIMAL_FIRMWARE_NO_ENTRY;
    EXPECT_EQ(refusal(no_entry), "firmware '" + no_entry + "': no symbol stereosim_firmware");
    const std::string no_descriptor = MINIMAL_FIRMWARE_NO_DESCRIPTOR;
    EXPECT_EQ(refusal(no_descriptor),
              "firmware '" + no_descriptor + "': its entry returned no descriptor");
    const std::string stages = MINIMAL_FIRMWARE_TOO_MANY_STAGES;
    EXPECT_EQ(refusal(stages), "firmware '" + stages + "': stage count 16 outside 1..15");
    const std::string key = MINIMAL_FIRMWARE_BAD_KEY_DEFAULT;
    EXPECT_EQ(refusal(key),
              "firmware '" + key + "': key 'cycles_per_wait': default outside its range");
    const std::string host = MINIMAL_FIRMWARE_BAD_HOST_ABI;
    EXPECT_EQ(refusal(host), "firmware '" + host +
                                 "': host entry built for ABI version 7, this stereosim speaks 1");
    const std::string missing = "/nonexistent/firmware.so";
    EXPECT_EQ(refusal(missing), "firmware '" + missing + "': cannot load: " + missing +
                                    ": cannot open shared object file: No such file or directory");
    // Not a shared object at all.
    const std::string text = testing::TempDir() + "not_a_plugin.so";
    std::ofstream(text) << "not ELF\n";
    const std::string said = refusal(text);
    EXPECT_EQ(said.rfind("firmware '" + text + "': cannot load: ", 0), 0u) << said;
    EXPECT_EQ(said.find('\n'), std::string::npos) << said;
}

TEST(FirmwarePlugin, Sha256OfAKnownMessage) {
    // FIPS 180-2, appendix B.1: "abc".
    const std::string path = testing::TempDir() + "abc.txt";
    std::ofstream(path, std::ios::binary) << "abc";
    EXPECT_EQ(firmware::file_sha256(path),
              "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    EXPECT_EQ(firmware::file_sha256("/nonexistent"), "");
}

// ---- the descriptor's rules, one defect at a time, on descriptors in memory ------------------

const char* const two_stages[] = {"capture", "think"};
const char* const one_state[] = {"idle"};
const char* const choices[] = {"a", "b"};

void* no_create(const stereosim_services*, const stereosim_board*, const double*, char*, size_t) {
    return nullptr;
}
void no_run(void*) {}
void no_policy(const void*, stereosim_fw_policy*) {}

struct descriptor_under_test {
    stereosim_fw_key keys[2] = {
        {"gain", STEREOSIM_KEY_INT, 0, 10, 5, nullptr, 0, "a gain"},
        {"pick", STEREOSIM_KEY_CHOICE, 0, 0, 1, choices, 2, "a choice"},
    };
    stereosim_fw_descriptor d{STEREOSIM_FIRMWARE_ABI_VERSION,
                              "t",
                              "1",
                              2,
                              two_stages,
                              1,
                              one_state,
                              2,
                              keys,
                              no_create,
                              no_run,
                              no_run,
                              no_policy};
    std::string problem() const { return firmware::descriptor_problem(d); }
};

TEST(FirmwareDescriptor, EachRuleRefusesItsDefect) {
    descriptor_under_test t;
    EXPECT_EQ(t.problem(), "");
    const char* const bad_names[] = {"capture", "Think"};
    t.d.stage_names = bad_names;
    EXPECT_EQ(t.problem(), "stage 1 has no plain name ([a-z0-9_]+)");
    const char* const twice[] = {"capture", "capture"};
    t.d.stage_names = twice;
    EXPECT_EQ(t.problem(), "stage name 'capture' appears twice");
    t.d.stage_names = two_stages;
    const char* const spaced[] = {"NOT IDLE"};
    t.d.tracker_state_names = spaced;
    EXPECT_EQ(t.problem(), "tracker state 0 has no plain name ([A-Za-z0-9_]+)");
    t.d.tracker_state_names = one_state;
    t.d.tracker_state_count = 0;
    EXPECT_EQ(t.problem(), "tracker state count 0 outside 1..8");
    t.d.tracker_state_count = 1;
    t.keys[0].default_value = 5.5;
    EXPECT_EQ(t.problem(), "key 'gain': an INT key with a fractional range or default");
    t.keys[0].default_value = 5;
    t.keys[0].min = 11;
    EXPECT_EQ(t.problem(), "key 'gain': range min > max");
    t.keys[0].min = 0;
    t.keys[1].default_value = 2;
    EXPECT_EQ(t.problem(), "key 'pick': default is no choice's index");
    t.keys[1].default_value = 1;
    t.keys[1].name = "gain";
    EXPECT_EQ(t.problem(), "config key 'gain' appears twice");
    t.keys[1].name = "compiled_c_factor";
    EXPECT_EQ(t.problem(),
              "config key 'compiled_c_factor' clashes with the platform's "
              "firmware.compiled_c_factor");
    t.keys[1].name = "pick";
    t.keys[1].doc = "";
    EXPECT_EQ(t.problem(), "key 'pick' has no doc line");
    t.keys[1].doc = "a choice";
    t.d.policy = nullptr;
    EXPECT_EQ(t.problem(), "an entry point (create, run, destroy, policy) is missing");
    t.d.policy = no_policy;
    t.d.name = "";
    EXPECT_EQ(t.problem(), "no name");
}

}  // namespace
