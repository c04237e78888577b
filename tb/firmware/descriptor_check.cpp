#include "tb/firmware/descriptor_check.h"

#include <cmath>
#include <cstring>
#include <set>

namespace firmware {

bool is_plain_name(const char* name, bool upper) {
    const auto letter = [upper](char c) {
        return (c >= 'a' && c <= 'z') || (upper && c >= 'A' && c <= 'Z');
    };
    if (name == nullptr || !letter(name[0])) return false;
    for (const char* c = name; *c != '\0'; ++c)
        if (!(letter(*c) || (*c >= '0' && *c <= '9') || *c == '_')) return false;
    return true;
}

namespace {

// Keys under firmware. that the platform itself owns (the cost model and the
// bus replay of the firmware's SDRAM traffic, docs/config.md).
const char* const platform_firmware_keys[] = {"compiled_c_factor", "sdram_traffic_on_bus"};

std::string names_problem(const char* what, uint32_t count, uint32_t max, const char* const* names,
                          bool upper) {
    if (count < 1 || count > max)
        return std::string(what) + " count " + std::to_string(count) + " outside 1.." +
               std::to_string(max);
    if (names == nullptr) return std::string(what) + " names missing";
    std::set<std::string> seen;
    for (uint32_t i = 0; i < count; ++i) {
        if (!is_plain_name(names[i], upper))
            return std::string(what) + " " + std::to_string(i) + " has no plain name (" +
                   (upper ? "[A-Za-z0-9_]+" : "[a-z0-9_]+") + ")";
        if (!seen.insert(names[i]).second)
            return std::string(what) + " name '" + names[i] + "' appears twice";
    }
    return "";
}

std::string key_problem(const stereosim_fw_key& k) {
    const std::string name = std::string("key '") + k.name + "'";
    if (k.doc == nullptr || k.doc[0] == '\0') return name + " has no doc line";
    switch (k.type) {
        case STEREOSIM_KEY_BOOL:
            if (k.default_value != 0 && k.default_value != 1) return name + ": default not 0 or 1";
            return "";
        case STEREOSIM_KEY_CHOICE: {
            if (k.choices == nullptr || k.choice_count < 1) return name + ": no choices";
            std::set<std::string> seen;
            for (uint32_t i = 0; i < k.choice_count; ++i)
                if (!is_plain_name(k.choices[i]) || !seen.insert(k.choices[i]).second)
                    return name + ": choice " + std::to_string(i) + " not a plain, unique name";
            const double d = k.default_value;
            if (d < 0 || d >= k.choice_count || d != std::floor(d))
                return name + ": default is no choice's index";
            return "";
        }
        case STEREOSIM_KEY_INT:
        case STEREOSIM_KEY_FLOAT:
            if (!(k.min <= k.max)) return name + ": range min > max";
            if (k.default_value < k.min || k.default_value > k.max)
                return name + ": default outside its range";
            if (k.type == STEREOSIM_KEY_INT &&
                (k.min != std::floor(k.min) || k.max != std::floor(k.max) ||
                 k.default_value != std::floor(k.default_value)))
                return name + ": an INT key with a fractional range or default";
            return "";
        default:
            return name + ": unknown type " + std::to_string(k.type);
    }
}

}  // namespace

std::string descriptor_problem(const stereosim_fw_descriptor& d) {
    if (d.abi_version != STEREOSIM_FIRMWARE_ABI_VERSION)
        return "built for ABI version " + std::to_string(d.abi_version) +
               ", this stereosim speaks " + std::to_string(STEREOSIM_FIRMWARE_ABI_VERSION);
    if (d.name == nullptr || d.name[0] == '\0') return "no name";
    if (d.version == nullptr || d.version[0] == '\0') return "no version";
    std::string problem =
        names_problem("stage", d.stage_count, STEREOSIM_FW_MAX_STAGES, d.stage_names, false);
    if (!problem.empty()) return problem;
    problem = names_problem("tracker state", d.tracker_state_count, STEREOSIM_FW_MAX_TRACKER_STATES,
                            d.tracker_state_names, true);
    if (!problem.empty()) return problem;
    if (d.key_count > 0 && d.keys == nullptr) return "config keys missing";
    std::set<std::string> keys;
    for (uint32_t i = 0; i < d.key_count; ++i) {
        if (!is_plain_name(d.keys[i].name))
            return "config key " + std::to_string(i) + " has no plain name ([a-z0-9_]+)";
        if (!keys.insert(d.keys[i].name).second)
            return std::string("config key '") + d.keys[i].name + "' appears twice";
        for (const char* platform_key : platform_firmware_keys)
            if (std::strcmp(d.keys[i].name, platform_key) == 0)
                return std::string("config key '") + d.keys[i].name +
                       "' clashes with the platform's firmware." + platform_key;
        problem = key_problem(d.keys[i]);
        if (!problem.empty()) return problem;
    }
    if (d.create == nullptr || d.run == nullptr || d.destroy == nullptr || d.policy == nullptr)
        return "an entry point (create, run, destroy, policy) is missing";
    return "";
}

std::string host_problem(const stereosim_fw_host& h) {
    if (h.abi_version != STEREOSIM_FIRMWARE_ABI_VERSION)
        return "host entry built for ABI version " + std::to_string(h.abi_version) +
               ", this stereosim speaks " + std::to_string(STEREOSIM_FIRMWARE_ABI_VERSION);
    if (h.create == nullptr || h.process_pair == nullptr || h.destroy == nullptr)
        return "a host entry point (create, process_pair, destroy) is missing";
    return "";
}

}  // namespace firmware
