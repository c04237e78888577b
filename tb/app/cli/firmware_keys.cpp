#include "tb/app/cli/firmware_keys.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "tb/firmware/builtin.h"
#include "tb/firmware/plugin.h"

namespace cli {

namespace {

using nlohmann::json;

constexpr const char* prefix = "firmware.";

config_key key_of(const stereosim_fw_key& k) {
    config_key key;
    key.name = std::string(prefix) + k.name;
    key.min = k.min;
    key.max = k.max;
    key.doc = k.doc ? k.doc : "";
    switch (k.type) {
        case STEREOSIM_KEY_INT:
            key.type = key_type::integer;
            break;
        case STEREOSIM_KEY_FLOAT:
            key.type = key_type::real;
            break;
        case STEREOSIM_KEY_BOOL:
            key.type = key_type::boolean;
            break;
        default:
            key.type = key_type::choice;
            for (uint32_t c = 0; c < k.choice_count; ++c) key.choices.emplace_back(k.choices[c]);
    }
    return key;
}

// A value of key k as a config file holds it.
json value_of(const stereosim_fw_key& k, double v) {
    switch (k.type) {
        case STEREOSIM_KEY_INT:
            return json(static_cast<int64_t>(v));
        case STEREOSIM_KEY_FLOAT:
            return json(v);
        case STEREOSIM_KEY_BOOL:
            return json(v != 0.0);
        default:
            return json(k.choices[static_cast<size_t>(v)]);
    }
}

json default_of(const stereosim_fw_key& k) {
    return value_of(k, k.default_value);
}

// A setting as the key's value: text from --set, or a config file's JSON.
bool check_setting(const config_key& key, const json& given, double* value, std::string* error) {
    json checked;
    const bool ok = given.is_string() && key.type != key_type::choice
                        ? parse_value(key, given.get<std::string>(), &checked, error)
                        : check_value(key, given, &checked, error);
    if (!ok) return false;
    if (key.type == key_type::choice)
        *value = static_cast<double>(
            std::find(key.choices.begin(), key.choices.end(), checked.get<std::string>()) -
            key.choices.begin());
    else if (key.type == key_type::boolean)
        *value = checked.get<bool>() ? 1.0 : 0.0;
    else
        *value = checked.get<double>();
    return true;
}

// A typo of any key gets its suggestion; otherwise the firmware's own keys.
std::string unknown_setting_message(const std::string& name, const std::vector<config_key>& own,
                                    const char* firmware_name) {
    std::vector<std::string> names;
    for (const config_key& k : own) names.push_back(k.name);
    const std::string message = unknown_key_message(name, names);
    if (message.find("did you mean") != std::string::npos) return message;
    std::string listed;
    for (const std::string& n : names) listed += (listed.empty() ? "" : ", ") + n;
    return "unknown config key '" + name + "' (the firmware '" + firmware_name + "' declares " +
           (listed.empty() ? std::string("no keys of its own") : "of its own: " + listed) + ")";
}

}  // namespace

bool is_firmware_own_key(const std::string& name) {
    return name.rfind(prefix, 0) == 0 && name.size() > std::string(prefix).size() &&
           find_key(name) == nullptr;
}

std::vector<config_key> firmware_own_keys(const stereosim_fw_descriptor& descriptor) {
    std::vector<config_key> keys;
    for (uint32_t k = 0; k < descriptor.key_count; ++k) {
        config_key key = key_of(descriptor.keys[k]);
        if (!find_key(key.name)) keys.push_back(std::move(key));
    }
    return keys;
}

bool resolve_firmware_settings(const run_setup& setup,
                               std::vector<std::pair<std::string, double>>* values,
                               std::string* error) {
    values->clear();
    if (setup.firmware_settings.empty()) return true;
    std::unique_ptr<firmware::plugin> loaded;
    const stereosim_fw_descriptor* descriptor = &firmware::builtin();
    if (!setup.firmware.empty()) {
        loaded = firmware::plugin::load(setup.firmware, error);
        if (!loaded) return false;
        descriptor = &loaded->descriptor();
    }
    const std::vector<config_key> own = firmware_own_keys(*descriptor);
    for (const auto& [name, given] : setup.firmware_settings) {
        const auto key = std::find_if(own.begin(), own.end(),
                                      [&](const config_key& k) { return k.name == name; });
        if (key == own.end()) {
            *error = unknown_setting_message(name, own, descriptor->name);
            return false;
        }
        double value = 0.0;
        if (!check_setting(*key, given, &value, error)) return false;
        const std::string bare = name.substr(std::string(prefix).size());
        const auto same = std::find_if(values->begin(), values->end(),
                                       [&](const auto& v) { return v.first == bare; });
        if (same != values->end())
            same->second = value;
        else
            values->emplace_back(bare, value);
    }
    return true;
}

std::vector<std::string> settings_it_takes(const std::vector<std::string>& settings,
                                           const stereosim_fw_descriptor& d) {
    std::vector<std::string> taken;
    for (const std::string& setting : settings) {
        const size_t eq = setting.find('=');
        const std::string name = setting.substr(0, eq);
        bool takes = !is_firmware_own_key(name);
        for (uint32_t k = 0; k < d.key_count && !takes; ++k) {
            if (name != std::string(prefix) + d.keys[k].name) continue;
            // A key of the same name whose declaration refuses the value
            // (another firmware's `mode`) is not the setting the plan means.
            double value = 0.0;
            std::string why;
            takes = eq != std::string::npos &&
                    check_setting(key_of(d.keys[k]), json(setting.substr(eq + 1)), &value, &why);
        }
        if (takes) taken.push_back(setting);
    }
    return taken;
}

json firmware_values_json(const stereosim_fw_descriptor& d, const std::vector<double>& values) {
    json out = json::object();
    for (uint32_t k = 0; k < d.key_count && k < values.size(); ++k)
        out[d.keys[k].name] = value_of(d.keys[k], values[k]);
    return out;
}

json typed_setting(const json& given) {
    if (!given.is_string()) return given;
    const std::string text = given.get<std::string>();
    if (text == "true" || text == "false") return json(text == "true");
    char* end = nullptr;
    const long long integer = std::strtoll(text.c_str(), &end, 10);
    if (!text.empty() && *end == '\0') return json(static_cast<int64_t>(integer));
    const double real = std::strtod(text.c_str(), &end);
    if (!text.empty() && *end == '\0' && std::isfinite(real)) return json(real);
    return given;
}

bool print_firmware_keys(const std::string& path, std::string* error) {
    std::unique_ptr<firmware::plugin> loaded;
    if (!path.empty()) {
        loaded = firmware::plugin::load(path, error);
        if (!loaded) return false;
    }
    const stereosim_fw_descriptor& d = loaded ? loaded->descriptor() : firmware::builtin();
    const run_setup defaults;
    for (const config_key& k : config_keys())
        std::printf("%-30s %-34s default %-12s %s\n", k.name.c_str(), k.range_text().c_str(),
                    k.get(defaults).dump().c_str(), k.doc.c_str());
    std::printf("# the firmware '%s' %s declares:\n", d.name, d.version);
    for (uint32_t i = 0; i < d.key_count; ++i) {
        const config_key k = key_of(d.keys[i]);
        if (find_key(k.name)) continue;
        std::printf("%-30s %-34s default %-12s %s\n", k.name.c_str(), k.range_text().c_str(),
                    default_of(d.keys[i]).dump().c_str(), k.doc.c_str());
    }
    return true;
}

}  // namespace cli
