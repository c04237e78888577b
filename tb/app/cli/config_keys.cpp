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
#include "tb/app/cli/scenarios.h"

namespace cli {

namespace {

using nlohmann::json;

// ---- table builders: a key bound to one run_setup member -----------------------------------

template <typename T>
config_key integer_key(std::string name, T run_setup::*member, double min, double max,
                       std::string doc) {
    config_key k;
    k.name = std::move(name);
    k.type = key_type::integer;
    k.min = min;
    k.max = max;
    k.doc = std::move(doc);
    k.set = [member](run_setup& s, const json& v) { s.*member = v.get<T>(); };
    k.get = [member](const run_setup& s) { return json(s.*member); };
    return k;
}

config_key real_key(std::string name, double run_setup::*member, double min, double max,
                    std::string doc) {
    config_key k;
    k.name = std::move(name);
    k.type = key_type::real;
    k.min = min;
    k.max = max;
    k.doc = std::move(doc);
    k.set = [member](run_setup& s, const json& v) { s.*member = v.get<double>(); };
    k.get = [member](const run_setup& s) { return json(s.*member); };
    return k;
}

config_key bool_key(std::string name, bool run_setup::*member, std::string doc) {
    config_key k;
    k.name = std::move(name);
    k.type = key_type::boolean;
    k.doc = std::move(doc);
    k.set = [member](run_setup& s, const json& v) { s.*member = v.get<bool>(); };
    k.get = [member](const run_setup& s) { return json(s.*member); };
    return k;
}

config_key choice_key(std::string name, std::string run_setup::*member,
                      std::vector<std::string> choices, std::string doc) {
    config_key k;
    k.name = std::move(name);
    k.type = key_type::choice;
    k.choices = std::move(choices);
    k.doc = std::move(doc);
    k.set = [member](run_setup& s, const json& v) { s.*member = v.get<std::string>(); };
    k.get = [member](const run_setup& s) { return json(s.*member); };
    return k;
}

// The same for a member of run_setup::scenario.
template <typename T>
config_key scenario_key(config_key k, T scenario_params::*member) {
    k.set = [member](run_setup& s, const json& v) { s.scenario.*member = v.get<T>(); };
    k.get = [member](const run_setup& s) { return json(s.scenario.*member); };
    return k;
}

std::vector<std::string> profile_names() {
    return {"default", "ov7620", "mt9v011", "mt9v012", "pas302"};
}

std::vector<config_key> make_table() {
    std::vector<config_key> t;
    // ---- scenario -------------------------------------------------------------------------
    {
        config_key k;
        k.name = "scenario.name";
        k.type = key_type::text;
        k.doc = "built-in scenario (stereosim scenarios); its settings apply before any other key";
        k.set = [](run_setup& s, const json& v) { s.scenario.name = v.get<std::string>(); };
        k.get = [](const run_setup& s) { return json(s.scenario.name); };
        t.push_back(k);
    }
    config_key k;
    k.type = key_type::integer;
    k.name = "scenario.still_frames";
    k.min = 0;
    k.max = 1000;
    k.doc = "frames the ball rests before it moves";
    t.push_back(scenario_key(k, &scenario_params::still_frames));

    k = {};
    k.type = key_type::choice;
    k.name = "scenario.path";
    k.choices = {"bounce", "circle", "line", "still"};
    k.doc = "the ball's path: thrown and bouncing, circling, a straight line, at rest";
    t.push_back(scenario_key(k, &scenario_params::path));

    k = {};
    k.type = key_type::real;
    k.name = "scenario.depth_m";
    k.min = 0.5;
    k.max = 4.5;  // the background plane is at 5 m
    k.doc = "the ball's starting depth, m (circle: the depth of its plane)";
    t.push_back(scenario_key(k, &scenario_params::depth_m));

    k.name = "scenario.speed";
    k.min = 0.0;
    k.max = 8.0;
    k.doc = "time scale of the path: 1 nominal, 2 twice as fast, 0 at rest";
    t.push_back(scenario_key(k, &scenario_params::speed));

    k.name = "scenario.ball_radius_mm";
    k.min = 5.0;
    k.max = 300.0;
    k.doc = "ball radius, mm (DESIGN.md default 50)";
    t.push_back(scenario_key(k, &scenario_params::ball_radius_mm));

    k = {};
    k.type = key_type::choice;
    k.name = "scenario.light";
    k.choices = {"none", "step", "ramp"};
    k.doc = "a global lighting change: none, a step, or a linear ramp";
    t.push_back(scenario_key(k, &scenario_params::light));

    k = {};
    k.type = key_type::integer;
    k.name = "scenario.light_frame";
    k.min = 0;
    k.max = 100000;
    k.doc = "frame of the step, or the ramp's first frame";
    t.push_back(scenario_key(k, &scenario_params::light_frame));

    k = {};
    k.type = key_type::real;
    k.name = "scenario.light_gain";
    k.min = 0.05;
    k.max = 4.0;
    k.doc = "global light gain after the change (1 = unchanged)";
    t.push_back(scenario_key(k, &scenario_params::light_gain));

    k = {};
    k.type = key_type::integer;
    k.name = "scenario.light_ramp_frames";
    k.min = 1;
    k.max = 1000;
    k.doc = "length of the ramp, frame periods";
    t.push_back(scenario_key(k, &scenario_params::light_ramp_frames));

    k = {};
    k.type = key_type::text;
    k.name = "scenario.replay";
    k.doc =
        "replay manifest (model/scene/replay.h): PNG frames instead of the renderer; "
        "empty = render";
    t.push_back(scenario_key(k, &scenario_params::replay));

    // ---- rig --------------------------------------------------------------------------------
    t.push_back(real_key("rig.baseline_mm", &run_setup::baseline_mm, 10.0, 2000.0,
                         "stereo baseline s, mm (DESIGN.md default rig: 120)"));
    t.push_back(real_key("rig.focal_length_mm", &run_setup::focal_length_mm, 1.0, 100.0,
                         "lens focal length, mm (default 6)"));
    t.push_back(real_key("rig.pixel_pitch_um", &run_setup::pixel_pitch_um, 1.0, 50.0,
                         "sensor pixel pitch, um (OV7620: 7.6, hardware-facts.md section 6)"));

    // ---- sensor -----------------------------------------------------------------------------
    t.push_back(choice_key("sensor.profile", &run_setup::sensor_profile, profile_names(),
                           "sensor timing profile (docs/sensor.md)"));
    t.push_back(bool_key("sensor.noise", &run_setup::sensor_noise,
                         "shot and read noise on the sensors' pixels"));

    // ---- DSK --------------------------------------------------------------------------------
    t.push_back(integer_key("dsk.version", &run_setup::dsk_version, 1, 3,
                            "DSK version: 1 600/100 MHz, 2 720/120, 3 1000/125 (CPU/EMIF)"));
    // Stored as 0 = "the version's", shown as the clock in use.
    t.push_back(real_key("dsk.cpu_mhz", &run_setup::cpu_mhz, 50.0, 2000.0,
                         "CPU clock, MHz (default: the DSK version's)"));
    t.back().get = [](const run_setup& s) { return json(s.effective_cpu_mhz()); };
    t.push_back(real_key("dsk.eclk_mhz", &run_setup::eclk_mhz, 10.0, 200.0,
                         "EMIF clock ECLKOUT, MHz (default: the DSK version's)"));
    t.back().get = [](const run_setup& s) { return json(s.effective_eclk_mhz()); };

    // ---- firmware ---------------------------------------------------------------------------
    t.push_back(choice_key("firmware.mode", &run_setup::mode, {"sequential", "overlapped"},
                           "read the pair then process it, or process pair N while N+1 is read"));
    t.push_back(integer_key("firmware.search_radius", &run_setup::search_radius, 1, 1000,
                            "SAD tracking search radius, px each way (window 2r+1 must fit the "
                            "image)"));
    t.push_back(choice_key("firmware.stereo_method", &run_setup::stereo_method,
                           {"sad", "edge", "both"}, "which stereo match gives the 3D point"));
    t.push_back(integer_key("firmware.detect_threshold", &run_setup::detect_threshold, 1, 254,
                            "three-frame differencing: Binary(a) = a > threshold, gray levels"));
    t.push_back(choice_key("firmware.frame_memory", &run_setup::frame_memory, {"l2", "sdram"},
                           "where the firmware's gray frames and motion mask live (l2: the memory "
                           "plan of docs/firmware.md)"));
    t.push_back(bool_key("firmware.sdram_traffic_on_bus", &run_setup::sdram_traffic_on_bus,
                         "the firmware's SDRAM traffic goes out on EMIFA (competes with capture)"));
    t.push_back(integer_key("firmware.watchdog_ms", &run_setup::watchdog_ms, 0, 10000,
                            "period of the firmware's card watchdog, ms (0: off)"));
    t.push_back(integer_key("firmware.card_start_timeout", &run_setup::card_start_timeout, 1, 65535,
                            "START_TIMEOUT the firmware programs: lines the card waits for "
                            "the first VSYNC after OE rises"));

    // ---- run --------------------------------------------------------------------------------
    t.push_back(integer_key("run.frames", &run_setup::frames, 1, 100000,
                            "sync periods of 24.5 ms to simulate"));
    t.push_back(integer_key("run.seed", &run_setup::seed, 0, 2147483647.0,
                            "seed: sensor seeds 2 seed (left) and 2 seed + 1 (right)"));
    t.push_back(integer_key("run.quantum_ns", &run_setup::quantum_ns, 0, 24500000,
                            "the island's longest run-ahead before it syncs with SystemC, ns "
                            "(0: one sensor line); changes no result"));
    t.push_back(bool_key("run.hash_pins", &run_setup::hash_pins,
                         "fold every pin change into the pin hash"));
    return t;
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

std::string format_number(double v) {
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

std::string unknown_key_message(const std::string& name) {
    const config_key* nearest = nullptr;
    size_t best = std::string::npos;
    for (const config_key& k : config_keys()) {
        const size_t d = edit_distance(name, k.name);
        if (d < best) best = d, nearest = &k;
    }
    std::string message = "unknown config key '" + name + "'";
    // A suggestion only when it is plausibly a typo (a third of the name).
    if (nearest && best <= std::max<size_t>(3, nearest->name.size() / 3))
        message += " (did you mean '" + nearest->name + "'?)";
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
    for (const auto& [name, value] : leaves) {
        const config_key* key = find_key(name);
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
        json value;
        if (!key || !parse_value(*key, text, &value, error))
            throw std::logic_error("built-in scenario " + scenario + ": bad setting " + name);
        key->set(*setup, value);
    }
    for (const key_assignment& a : assignments) {
        if (a.key == "scenario.name") continue;
        const config_key* key = find_key(a.key);
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
    const int window = 2 * setup.search_radius + 1;
    if (window > std::min(profile.active_cols, profile.active_rows)) {
        *error = "config key 'firmware.search_radius': the search window " +
                 std::to_string(window) + " x " + std::to_string(window) +
                 " px is larger than the image (" + std::to_string(profile.active_cols) + " x " +
                 std::to_string(profile.active_rows) + ")";
        return false;
    }
    if (setup.effective_eclk_mhz() > setup.effective_cpu_mhz() / 2.0) {
        // The C64x EMIF clock is at most CPU/4 or CPU/6 on the DSKs (hardware-facts.md
        // section 2); half the CPU clock is the bound the model is sure to handle.
        *error = "dsk.eclk_mhz " + format_number(setup.effective_eclk_mhz()) +
                 " is more than half of dsk.cpu_mhz " + format_number(setup.effective_cpu_mhz());
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
    return out;
}

}  // namespace cli
