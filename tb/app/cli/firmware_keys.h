// The firmware's own config keys (docs/firmware-abi.md "Config keys"): the
// keys a plugin declares in its descriptor beyond the platform's table
// (tb/app/cli/config_keys.h). `--set firmware.KEY=V` and a config file's
// "firmware" object reach them; they are checked against the descriptor of
// the firmware the run loads (run.firmware, or the built-in reference) with
// the same one-line messages as the table's keys, and handed to the
// firmware's create() by name (platform_config::firmware_settings).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "stereosim/firmware.h"
#include "tb/app/cli/config_keys.h"

namespace cli {

// "firmware.NAME" that is not a key of the platform's table: its check
// waits until the run's firmware is known.
bool is_firmware_own_key(const std::string& name);

// The descriptor's keys the table does not hold, as config keys (name with
// the "firmware." prefix, type, range, choices, doc; no setter).
std::vector<config_key> firmware_own_keys(const stereosim_fw_descriptor& descriptor);

// The setup's firmware settings checked against the firmware it loads:
// (name without the prefix, value; a choice as its index), in the order
// given, a later setting of a key replacing an earlier one. false + *error
// (one line: an unknown key with the nearest name, a wrong type, a value
// out of the declared range).
bool resolve_firmware_settings(const run_setup& setup,
                               std::vector<std::pair<std::string, double>>* values,
                               std::string* error);

// Of `settings` (KEY=VALUE), those the firmware `d` describes can take:
// every key of the platform's table, and the
// firmware's own keys it declares with a value its declaration accepts. A
// campaign's plan asks every firmware for the same settings; a firmware
// without the key (or whose key of that name means something else) runs
// the row without it.
std::vector<std::string> settings_it_takes(const std::vector<std::string>& settings,
                                           const stereosim_fw_descriptor& d);

// Every key value a firmware ran with (its descriptor's `values`, in order)
// as a config file's "firmware" object holds them: {"NAME": value, ...}.
nlohmann::json firmware_values_json(const stereosim_fw_descriptor& d,
                                    const std::vector<double>& values);

// A setting as a config file holds it: `--set` text that reads as a number
// or true / false becomes one (the checks accept either form).
nlohmann::json typed_setting(const nlohmann::json& given);

// `stereosim config --list [--firmware PATH]`: the table, then the own keys
// of the firmware (PATH, or the built-in reference if empty) with their
// declared defaults. false + *error if it cannot load.
bool print_firmware_keys(const std::string& path, std::string* error);

}  // namespace cli
