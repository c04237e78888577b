// The ONE table of config keys (docs/config.md): dotted name, type, range,
// a doc line, a setter into run_setup and a getter. The config file reader,
// `--set key=value`, `stereosim config --list` and docs/config.md (a test
// compares them) all use it. A misspelled key or an out-of-range value is a
// one-line error naming it.
//
// Config file (JSON, versioned):
//   {"version": 1,
//    "scenario": {"name": "default", "still_frames": 3, ...},
//    "rig": {...}, "sensor": {...}, "dsk": {...}, "firmware": {...}, "run": {...}}
// Nested objects are the dotted names' parts; "scenario.name" picks a
// built-in scenario whose settings apply first, then every other key. A
// report.json is accepted too: its "config" object is a config file.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "tb/app/cli/run_setup.h"

namespace cli {

enum class key_type { integer, real, boolean, choice, text };
const char* key_type_name(key_type t);

struct config_key {
    std::string name;  // dotted, e.g. "rig.baseline_mm"
    key_type type = key_type::integer;
    double min = 0.0, max = 0.0;                                 // integer, real: inclusive range
    std::vector<std::string> choices;                            // choice
    std::string doc;                                             // one line
    std::function<void(run_setup&, const nlohmann::json&)> set;  // value already checked
    std::function<nlohmann::json(const run_setup&)> get;

    // "integer 1..10000", "one of sad|edge|both", ...
    std::string range_text() const;
};

const std::vector<config_key>& config_keys();

// The keys as docs/config.md's table (`stereosim config --markdown`): key,
// type / range, default, what; a `|` inside a cell escaped.
std::string config_table_markdown();
// The built-in firmware's own keys the same way (docs/config.md's second
// table): they are its descriptor's, checked against it like a plugin's.
std::string firmware_table_markdown();
const config_key* find_key(const std::string& name);

// The one-line error for an unknown key, with the nearest key name:
// "unknown config key 'rig.baselin' (did you mean 'rig.baseline_mm'?)".
// more_names: further keys to suggest (a firmware's own).
std::string unknown_key_message(const std::string& name,
                                const std::vector<std::string>& more_names = {});

// A value for a key from text (--set) or JSON (a file), type- and range-
// checked. Returns false and sets *error (one line) if it does not fit.
bool parse_value(const config_key& key, const std::string& text, nlohmann::json* value,
                 std::string* error);
bool check_value(const config_key& key, const nlohmann::json& value, nlohmann::json* checked,
                 std::string* error);

// One assignment, in the order the user gave them.
struct key_assignment {
    std::string key;
    nlohmann::json value;  // checked
};

// Reads a config file into assignments (table order). false + *error on an
// unreadable file, malformed JSON, a missing or wrong "version", an unknown
// key, a value of the wrong type or out of range.
bool read_config_file(const std::string& path, std::vector<key_assignment>* out,
                      std::string* error);

// Applies assignments to a default run_setup: the last "scenario.name" picks
// the built-in scenario (applied first), then every other assignment in
// order. false + *error for an unknown scenario.
bool apply_assignments(const std::vector<key_assignment>& assignments, run_setup* setup,
                       std::string* error);

// Checks across keys (search window against the image, the sensor profile
// name, the replay manifest is readable and long enough for the run, ...).
bool validate_setup(const run_setup& setup, std::string* error);

// The setup as a version-1 config file (every key, nested by its dotted parts).
nlohmann::json config_json(const run_setup& setup);

}  // namespace cli
