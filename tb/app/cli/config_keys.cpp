#include "tb/app/cli/config_keys.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "model/scene/replay.h"
#include "model/sensor/profile.h"
#include "tb/app/cli/firmware_keys.h"
#include "tb/app/cli/scenarios.h"
#include "tb/firmware/plugin.h"

namespace cli {

namespace {

using nlohmann::json;

// ---- the table: one declaration per key ----------------------------------------------------
//
// A declaration is the key's name, its type and range, its doc line and the
// field of run_setup it reads and writes (a `field`: where the value lives,
// and what `get` shows, which for the clocks is the clock in use).

template <typename T>
struct field {
    std::function<T&(run_setup&)> ref;
    std::function<T(const run_setup&)> shown;
};

template <typename T>
field<T> setup_field(T run_setup::*member) {
    return {[member](run_setup& s) -> T& { return s.*member; },
            [member](const run_setup& s) { return s.*member; }};
}

template <typename T>
field<T> scenario_field(T scenario_params::*member) {
    return {[member](run_setup& s) -> T& { return s.scenario.*member; },
            [member](const run_setup& s) { return s.scenario.*member; }};
}

// Stored as 0 = "the DSK version's clock", shown as the clock in use.
field<double> clock_field(double run_setup::*member, double (run_setup::*in_use)() const) {
    return {[member](run_setup& s) -> double& { return s.*member; },
            [in_use](const run_setup& s) { return (s.*in_use)(); }};
}

template <typename T>
config_key declare(const char* name, key_type type, double min, double max,
                   std::vector<std::string> choices, field<T> f, const char* doc) {
    config_key k;
    k.name = name;
    k.type = type;
    k.min = min;
    k.max = max;
    k.choices = std::move(choices);
    k.doc = doc;
    k.set = [ref = f.ref](run_setup& s, const json& v) { ref(s) = v.get<T>(); };
    k.get = [shown = f.shown](const run_setup& s) { return json(shown(s)); };
    return k;
}

template <typename T>
config_key integer(const char* name, field<T> f, double min, double max, const char* doc) {
    return declare(name, key_type::integer, min, max, {}, std::move(f), doc);
}
config_key number(const char* name, field<double> f, double min, double max, const char* doc) {
    return declare(name, key_type::real, min, max, {}, std::move(f), doc);
}
config_key boolean(const char* name, field<bool> f, const char* doc) {
    return declare(name, key_type::boolean, 0.0, 0.0, {}, std::move(f), doc);
}
config_key choice(const char* name, field<std::string> f, std::vector<std::string> choices,
                  const char* doc) {
    return declare(name, key_type::choice, 0.0, 0.0, std::move(choices), std::move(f), doc);
}
config_key text(const char* name, field<std::string> f, const char* doc) {
    return declare(name, key_type::text, 0.0, 0.0, {}, std::move(f), doc);
}

std::vector<config_key> scenario_keys() {
    return {
        text("scenario.name", scenario_field(&scenario_params::name),
             "built-in scenario (stereosim scenarios); its settings apply before any other key"),
        integer("scenario.still_frames", scenario_field(&scenario_params::still_frames), 0, 1000,
                "frames the ball rests before it moves"),
        choice("scenario.path", scenario_field(&scenario_params::path),
               {"bounce", "circle", "line", "pass", "still"},
               "the ball's path: thrown and bouncing, circling, a straight line, a slow pass "
               "across the middle of the view, at rest"),
        // At most 4.5 m: the background plane is at 5 m.
        number("scenario.depth_m", scenario_field(&scenario_params::depth_m), 0.5, 4.5,
               "the ball's starting depth, m (circle: the depth of its plane)"),
        number("scenario.speed", scenario_field(&scenario_params::speed), 0.0, 8.0,
               "time scale of the path: 1 nominal, 2 twice as fast, 0 at rest"),
        number("scenario.ball_radius_mm", scenario_field(&scenario_params::ball_radius_mm), 5.0,
               300.0, "ball radius, mm (docs/design-brief.md default 50)"),
        // A tossed or thrown ball turns 1-10 times a second. Frames are
        // rendered at an instant, so past half a turn per 24.5 ms frame
        // (1224 rpm) the texture's motion aliases.
        number("scenario.spin_rpm", scenario_field(&scenario_params::spin_rpm), 0.0, 1200.0,
               "the ball's spin once it moves, revolutions per minute (0: none)"),
        choice("scenario.spin_axis", scenario_field(&scenario_params::spin_axis), {"x", "y", "z"},
               "the spin's axis in the right camera's frame: x across the view, y vertical, z "
               "along the view (the texture turns in the image plane)"),
        choice("scenario.light", scenario_field(&scenario_params::light), {"none", "step", "ramp"},
               "a global lighting change: none, a step, or a linear ramp"),
        integer("scenario.light_frame", scenario_field(&scenario_params::light_frame), 0, 100000,
                "frame of the step, or the ramp's first frame"),
        number("scenario.light_gain", scenario_field(&scenario_params::light_gain), 0.05, 4.0,
               "global light gain after the change (1 = unchanged)"),
        integer("scenario.light_ramp_frames", scenario_field(&scenario_params::light_ramp_frames),
                1, 1000, "length of the ramp, frame periods"),
        text("scenario.replay", scenario_field(&scenario_params::replay),
             "replay manifest (model/scene/replay.h): PNG frames instead of the renderer; "
             "empty = render"),
    };
}

std::vector<config_key> hardware_keys() {
    return {
        number("rig.baseline_mm", setup_field(&run_setup::baseline_mm), 10.0, 2000.0,
               "stereo baseline s, mm (docs/design-brief.md default rig: 120)"),
        number("rig.focal_length_mm", setup_field(&run_setup::focal_length_mm), 1.0, 100.0,
               "lens focal length, mm (default 6)"),
        number("rig.pixel_pitch_um", setup_field(&run_setup::pixel_pitch_um), 1.0, 50.0,
               "sensor pixel pitch, um (OV7620: 7.6, docs/hardware-facts.md section 6)"),
        choice("sensor.profile", setup_field(&run_setup::sensor_profile),
               {"default", "ov7620", "mt9v011", "mt9v012", "pas302"},
               "sensor timing profile (docs/sensor.md)"),
        boolean("sensor.noise", setup_field(&run_setup::sensor_noise),
                "shot and read noise on the sensors' pixels"),
        integer("sensor.window_cols", setup_field(&run_setup::window_cols), 0, 4096,
                "centred readout window width, px (0: the profile's; e.g. 320 for QVGA)"),
        integer("sensor.window_rows", setup_field(&run_setup::window_rows), 0, 4096,
                "centred readout window height, px (0: the profile's; e.g. 240 for QVGA)"),
        integer("dsk.version", setup_field(&run_setup::dsk_version), 1, 3,
                "DSK version: 1 600/100 MHz, 2 720/120, 3 1000/125 (CPU/EMIF)"),
        number("dsk.cpu_mhz", clock_field(&run_setup::cpu_mhz, &run_setup::effective_cpu_mhz), 50.0,
               2000.0, "CPU clock, MHz (default: the DSK version's)"),
        number("dsk.eclk_mhz", clock_field(&run_setup::eclk_mhz, &run_setup::effective_eclk_mhz),
               10.0, 200.0, "EMIF clock ECLKOUT, MHz (default: the DSK version's)"),
        integer("dsk.card_setup", setup_field(&run_setup::card_setup), 0, 15,
                "the card's CE2/CE3 setup (RDSETUP, WRSETUP), ECLK (0: the DSK's, 2)"),
        integer("dsk.card_strobe", setup_field(&run_setup::card_strobe), 0, 63,
                "the card's CE2/CE3 strobe (RDSTRB, WRSTRB), ECLK (0: the DSK's, 10 v1 / 12 v2-3)"),
        integer("dsk.card_hold", setup_field(&run_setup::card_hold), 0, 3,
                "the card's CE2/CE3 hold (RDHLD, WRHLD), ECLK (0: the DSK's, 2)"),
    };
}

std::vector<config_key> firmware_keys() {
    return {
        boolean("firmware.sdram_traffic_on_bus", setup_field(&run_setup::sdram_traffic_on_bus),
                "the firmware's SDRAM traffic goes out on EMIFA (competes with capture)"),
        number("firmware.compiled_c_factor", setup_field(&run_setup::compiled_c_factor), 1.0, 100.0,
               "the cost model's compiled-C factor: 1 hand-scheduled kernels, more: compiled C "
               "(docs/paper.md)"),
    };
}

std::vector<config_key> run_keys() {
    return {
        integer("run.frames", setup_field(&run_setup::frames), 1, 100000,
                "sync periods of 24.5 ms to simulate"),
        integer("run.seed", setup_field(&run_setup::seed), 0, 2147483647.0,
                "seed: sensor seeds 2 seed (left) and 2 seed + 1 (right)"),
        integer("run.quantum_ns", setup_field(&run_setup::quantum_ns), 0, 24500000,
                "the island's longest run-ahead before it syncs with SystemC, ns (0: one sensor "
                "line); changes no result"),
        boolean("run.hash_pins", setup_field(&run_setup::hash_pins),
                "fold every pin change into the pin hash"),
        text("run.firmware", setup_field(&run_setup::firmware),
             "the firmware under test: a plugin built against include/stereosim/firmware.h "
             "(docs/firmware-abi.md); empty: the built-in reference firmware"),
    };
}

// The table, in the order of docs/config.md and config files.
std::vector<config_key> make_table() {
    std::vector<config_key> table;
    for (auto section : {scenario_keys, hardware_keys, firmware_keys, run_keys})
        for (config_key& key : section()) table.push_back(std::move(key));
    return table;
}

size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

// Whole numbers in full (a range 0..2147483647, not 0..2.14748e+09), others as
// a stream shows them.
std::string format_number(double v) {
    if (std::floor(v) == v && std::fabs(v) < 1e15) return std::to_string(static_cast<long long>(v));
    std::ostringstream out;
    out << v;
    return out.str();
}

// Flattens nested objects into dotted names; other values are leaves.
void flatten(const json& object, const std::string& prefix,
             std::vector<std::pair<std::string, json>>* out) {
    for (auto it = object.begin(); it != object.end(); ++it) {
        const std::string name = prefix.empty() ? it.key() : prefix + "." + it.key();
        if (it->is_object())
            flatten(*it, name, out);
        else
            out->emplace_back(name, *it);
    }
}

}  // namespace

const char* key_type_name(key_type t) {
    switch (t) {
        case key_type::integer:
            return "integer";
        case key_type::real:
            return "number";
        case key_type::boolean:
            return "boolean";
        case key_type::choice:
            return "choice";
        case key_type::text:
            return "string";
    }
    return "?";
}

std::string config_key::range_text() const {
    switch (type) {
        case key_type::integer:
        case key_type::real:
            return std::string(key_type_name(type)) + " " + format_number(min) + ".." +
                   format_number(max);
        case key_type::boolean:
            return "true|false";
        case key_type::choice: {
            std::string s = "one of ";
            for (size_t i = 0; i < choices.size(); ++i) s += (i ? "|" : "") + choices[i];
            return s;
        }
        case key_type::text:
            return "string";
    }
    return {};
}

const std::vector<config_key>& config_keys() {
    static const std::vector<config_key> table = make_table();
    return table;
}

const config_key* find_key(const std::string& name) {
    for (const config_key& k : config_keys())
        if (k.name == name) return &k;
    return nullptr;
}

std::string unknown_key_message(const std::string& name,
                                const std::vector<std::string>& more_names) {
    std::vector<std::string> names = more_names;
    for (const config_key& k : config_keys()) names.push_back(k.name);
    const std::string* nearest = nullptr;
    size_t best = std::string::npos;
    for (const std::string& candidate : names) {
        const size_t d = edit_distance(name, candidate);
        if (d < best) best = d, nearest = &candidate;
    }
    std::string message = "unknown config key '" + name + "'";
    // A suggestion only when it is plausibly a typo (a third of the name).
    if (nearest && best <= std::max<size_t>(3, nearest->size() / 3))
        message += " (did you mean '" + *nearest + "'?)";
    else
        message += " (stereosim config --list shows the keys)";
    return message;
}

bool check_value(const config_key& key, const json& value, json* checked, std::string* error) {
    const std::string what = "config key '" + key.name + "': ";
    switch (key.type) {
        case key_type::integer: {
            double v = 0.0;
            if (value.is_number_integer())
                v = static_cast<double>(value.get<int64_t>());
            else if (value.is_number_float() &&
                     std::floor(value.get<double>()) == value.get<double>())
                v = value.get<double>();
            else {
                *error = what + "expected an integer, got " + value.dump();
                return false;
            }
            if (v < key.min || v > key.max) {
                *error = what + format_number(v) + " is out of range " + format_number(key.min) +
                         ".." + format_number(key.max);
                return false;
            }
            *checked = static_cast<int64_t>(v);
            return true;
        }
        case key_type::real: {
            if (!value.is_number()) {
                *error = what + "expected a number, got " + value.dump();
                return false;
            }
            const double v = value.get<double>();
            if (!std::isfinite(v) || v < key.min || v > key.max) {
                *error = what + format_number(v) + " is out of range " + format_number(key.min) +
                         ".." + format_number(key.max);
                return false;
            }
            *checked = v;
            return true;
        }
        case key_type::boolean:
            if (!value.is_boolean()) {
                *error = what + "expected true or false, got " + value.dump();
                return false;
            }
            *checked = value;
            return true;
        case key_type::choice:
            if (!value.is_string() || std::find(key.choices.begin(), key.choices.end(),
                                                value.get<std::string>()) == key.choices.end()) {
                *error = what + value.dump() + " is not " + key.range_text();
                return false;
            }
            *checked = value;
            return true;
        case key_type::text:
            if (!value.is_string()) {
                *error = what + "expected a string, got " + value.dump();
                return false;
            }
            *checked = value;
            return true;
    }
    return false;
}

bool parse_value(const config_key& key, const std::string& text, json* value, std::string* error) {
    const std::string what = "config key '" + key.name + "': ";
    switch (key.type) {
        case key_type::integer: {
            char* end = nullptr;
            errno = 0;
            const long long v = std::strtoll(text.c_str(), &end, 10);
            if (text.empty() || *end != '\0' || errno == ERANGE) {
                *error = what + "expected an integer, got '" + text + "'";
                return false;
            }
            return check_value(key, json(static_cast<int64_t>(v)), value, error);
        }
        case key_type::real: {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0') {
                *error = what + "expected a number, got '" + text + "'";
                return false;
            }
            return check_value(key, json(v), value, error);
        }
        case key_type::boolean:
            if (text == "true" || text == "1" || text == "on" || text == "yes")
                return check_value(key, json(true), value, error);
            if (text == "false" || text == "0" || text == "off" || text == "no")
                return check_value(key, json(false), value, error);
            *error = what + "expected true or false, got '" + text + "'";
            return false;
        case key_type::choice:
        case key_type::text:
            return check_value(key, json(text), value, error);
    }
    return false;
}

bool read_config_file(const std::string& path, std::vector<key_assignment>* out,
                      std::string* error) {
    std::ifstream in(path);
    if (!in) {
        *error = "cannot read config file '" + path + "'";
        return false;
    }
    json document;
    try {
        document = json::parse(in);
    } catch (const json::parse_error& e) {
        // e.what() is "[json.exception.parse_error.101] parse error at line 3, column 5: ..."
        std::string what = e.what();
        const size_t at = what.find("parse error");
        *error = "config file '" + path +
                 "': malformed JSON: " + (at == std::string::npos ? what : what.substr(at));
        return false;
    }
    if (document.is_object() && document.contains("schema_version") && document.contains("config"))
        document = document["config"];  // a report.json: replay the run it describes
    if (!document.is_object()) {
        *error = "config file '" + path + "': expected a JSON object";
        return false;
    }
    if (!document.contains("version")) {
        *error = "config file '" + path + "': missing \"version\" (this stereosim reads version 1)";
        return false;
    }
    if (document["version"] != json(1)) {
        *error = "config file '" + path + "': unsupported version " + document["version"].dump() +
                 " (this stereosim reads version 1)";
        return false;
    }
    document.erase("version");
    std::vector<std::pair<std::string, json>> leaves;
    flatten(document, "", &leaves);
    std::map<std::string, json> by_name;
    std::vector<key_assignment> firmware_own;
    for (const auto& [name, value] : leaves) {
        const config_key* key = find_key(name);
        if (!key && is_firmware_own_key(name)) {
            firmware_own.push_back({name, value});  // checked once the firmware is known
            continue;
        }
        if (!key) {
            *error = "config file '" + path + "': " + unknown_key_message(name);
            return false;
        }
        json checked;
        if (!check_value(*key, value, &checked, error)) {
            *error = "config file '" + path + "': " + *error;
            return false;
        }
        by_name[name] = checked;
    }
    // Table order, not the file's (JSON objects have none).
    for (const config_key& key : config_keys()) {
        const auto it = by_name.find(key.name);
        if (it != by_name.end()) out->push_back({key.name, it->second});
    }
    out->insert(out->end(), firmware_own.begin(), firmware_own.end());
    return true;
}

bool apply_assignments(const std::vector<key_assignment>& assignments, run_setup* setup,
                       std::string* error) {
    std::string scenario = "default";
    for (const key_assignment& a : assignments)
        if (a.key == "scenario.name") scenario = a.value.get<std::string>();
    const builtin_scenario* preset = find_scenario(scenario);
    if (!preset) {
        *error = "unknown scenario '" + scenario + "' (stereosim scenarios lists them)";
        return false;
    }
    *setup = run_setup{};
    setup->scenario.name = scenario;
    for (const auto& [name, text] : preset->settings) {
        const config_key* key = find_key(name);
        if (!key && is_firmware_own_key(name)) {  // the reference firmware's keys
            setup->firmware_settings.emplace_back(name, json(text));
            continue;
        }
        json value;
        if (!key || !parse_value(*key, text, &value, error))
            throw std::logic_error("built-in scenario " + scenario + ": bad setting " + name);
        key->set(*setup, value);
    }
    for (const key_assignment& a : assignments) {
        if (a.key == "scenario.name") continue;
        const config_key* key = find_key(a.key);
        if (!key && is_firmware_own_key(a.key)) {
            setup->firmware_settings.emplace_back(a.key, a.value);
            continue;
        }
        if (!key) {
            *error = unknown_key_message(a.key);
            return false;
        }
        key->set(*setup, a.value);
    }
    return true;
}

bool validate_setup(const run_setup& setup, std::string* error) {
    sensor::sensor_profile profile;
    try {
        profile = sensor::profile_by_name(setup.sensor_profile);
    } catch (const std::exception&) {
        *error = "unknown sensor profile '" + setup.sensor_profile + "'";
        return false;
    }
    try {
        profile = sensor_profile_of(setup);
    } catch (const std::exception& e) {
        *error =
            std::string("config keys 'sensor.window_cols' / 'sensor.window_rows': ") + e.what();
        return false;
    }
    if (setup.effective_eclk_mhz() > setup.effective_cpu_mhz() / 2.0) {
        // The C64x EMIF clock is at most CPU/4 or CPU/6 on the DSKs (docs/hardware-facts.md
        // section 2); half the CPU clock is the bound the model is sure to handle.
        *error = "dsk.eclk_mhz " + format_number(setup.effective_eclk_mhz()) +
                 " is more than half of dsk.cpu_mhz " + format_number(setup.effective_cpu_mhz());
        return false;
    }
    // A plugin that cannot run is bad input now, not a failure after the
    // output folder exists.
    if (!setup.firmware.empty() && !firmware::plugin::load(setup.firmware, error)) return false;
    std::vector<std::pair<std::string, double>> firmware_values;
    if (!resolve_firmware_settings(setup, &firmware_values, error)) return false;
    // The built-in firmware's search window must fit the image.
    for (const auto& [name, value] : firmware_values) {
        const int window = 2 * static_cast<int>(value) + 1;
        if (!setup.firmware.empty() || name != "search_radius" ||
            window <= std::min(profile.active_cols, profile.active_rows))
            continue;
        *error = "config key 'firmware.search_radius': the search window " +
                 std::to_string(window) + " x " + std::to_string(window) +
                 " px is larger than the image (" + std::to_string(profile.active_cols) + " x " +
                 std::to_string(profile.active_rows) + ")";
        return false;
    }
    if (!setup.scenario.replay.empty()) {
        try {
            scene::replay replay(setup.scenario.replay, profile.active_cols, profile.active_rows);
            // The sensors ask for scene frames 0 .. frames (one per period).
            replay.path(scene::camera_id::left, static_cast<uint64_t>(setup.frames));
            // Decode every frame the run can show now, so a corrupt image is
            // bad input here and not a failure in the middle of the run.
            const int last = std::min(replay.frame_count() - 1, setup.frames);
            for (int n = 0; n <= last; ++n) {
                replay.frame(scene::camera_id::left, static_cast<uint64_t>(n));
                replay.frame(scene::camera_id::right, static_cast<uint64_t>(n));
            }
        } catch (const std::out_of_range& e) {
            *error = std::string(e.what()) + " (the run needs frames 0.." +
                     std::to_string(setup.frames) + ")";
            return false;
        } catch (const std::exception& e) {
            *error = e.what();
            return false;
        }
    }
    return true;
}

json config_json(const run_setup& setup) {
    json out;
    out["version"] = 1;
    for (const config_key& key : config_keys()) {
        const size_t dot = key.name.find('.');
        out[key.name.substr(0, dot)][key.name.substr(dot + 1)] = key.get(setup);
    }
    for (const auto& [name, value] : setup.firmware_settings)
        out["firmware"][name.substr(name.find('.') + 1)] = typed_setting(value);
    return out;
}

}  // namespace cli
