#include "tb/app/cli/firmware_command.h"

#include <cstdio>
#include <filesystem>

#include "tb/firmware/builtin.h"
#include "tb/app/cli/firmware_check.h"
#include "tb/app/cli/run_command.h"
#include "tb/firmware/plugin.h"

namespace cli {

namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.15g", v);
    return text;
}

std::string joined(const char* const* names, uint32_t count, const char* separator) {
    std::string text;
    for (uint32_t i = 0; i < count; ++i) text += (i ? separator : "") + std::string(names[i]);
    return text;
}

}  // namespace

std::string key_range_text(const stereosim_fw_key& k) {
    switch (k.type) {
        case STEREOSIM_KEY_BOOL:
            return "true|false";
        case STEREOSIM_KEY_CHOICE:
            return joined(k.choices, k.choice_count, "|");
        case STEREOSIM_KEY_FLOAT:
            return "float " + number(k.min) + ".." + number(k.max);
        default:
            return number(k.min) + ".." + number(k.max);
    }
}

std::string key_default_text(const stereosim_fw_key& k) {
    if (k.type == STEREOSIM_KEY_BOOL) return k.default_value != 0 ? "true" : "false";
    if (k.type == STEREOSIM_KEY_CHOICE) return k.choices[static_cast<size_t>(k.default_value)];
    return number(k.default_value);
}

firmware_command::firmware_command(CLI::App& app) {
    m_app = app.add_subcommand("firmware", "the firmware under test (docs/firmware-abi.md)");
    m_app->require_subcommand(1);
    m_info = m_app->add_subcommand(
        "info", "what a firmware plugin declares (without PATH: the built-in firmware)");
    m_info->add_option("path", m_path, "the plugin (.so)");
    m_check = m_app->add_subcommand(
        "check",
        "whether a firmware is deterministic: the default scenario twice, and fault runs forked "
        "from a snapshot against their runs from the start (without PATH: the built-in one)");
    m_check->add_option("path", m_path, "the plugin (.so)");
}

int firmware_command::execute() {
    if (*m_check) {
        std::error_code ec;
        const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
        return check_firmware(ec ? std::string("stereosim") : self.string(), m_path);
    }
    std::unique_ptr<firmware::plugin> plugin;
    if (!m_path.empty()) {
        std::string error;
        plugin = firmware::plugin::load(m_path, &error);
        if (!plugin) {
            print_error(error);
            return exit_bad_input;
        }
    }
    const stereosim_fw_descriptor& d =
        plugin ? plugin->descriptor() : firmware::builtin();
    std::printf("firmware  %s %s (ABI version %u)\n", d.name, d.version, d.abi_version);
    std::printf("file      %s\n", plugin ? plugin->path().c_str() : "built in");
    if (plugin) std::printf("sha256    %s\n", plugin->sha256().c_str());
    std::printf("stages    %s\n", joined(d.stage_names, d.stage_count, " ").c_str());
    std::printf("states    %s\n",
                joined(d.tracker_state_names, d.tracker_state_count, " ").c_str());
    const bool host = plugin ? plugin->host() != nullptr : true;
    std::printf("host      %s\n", host ? "yes (the sweep's closed form prices its pairs)"
                                       : "no (no closed-form processing estimate)");
    std::printf("keys      %u\n", d.key_count);
    for (uint32_t i = 0; i < d.key_count; ++i) {
        const stereosim_fw_key& k = d.keys[i];
        std::printf("  firmware.%-26s %-24s default %-10s %s\n", k.name, key_range_text(k).c_str(),
                    key_default_text(k).c_str(), k.doc);
    }
    return 0;
}

}  // namespace cli
