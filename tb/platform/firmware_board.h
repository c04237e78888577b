// What the platform tells a firmware behind the C ABI about the board a run
// configured (include/stereosim/firmware.h stereosim_board): the DSK, the
// card's bus timing and RETRY_LIMIT, the sensors' geometry and colour
// filter, the calibrated rig. And, while the run's config still carries the
// reference firmware's settings, those settings as its key values.
#pragma once

#include <vector>

#include "stereosim/firmware.h"
#include "tb/platform/platform_config.h"

namespace platform {

stereosim_board board_of(const platform_config& config);

// The reference firmware's key values (dsp/plugin/reference_firmware.h
// reference_key order) for a run's config.
std::vector<double> reference_values(const platform_config& config);

// A plugin's key values for a run: a key named and typed like one of the
// reference firmware's takes the run's value of that setting (a choice by
// its name, if the plugin has it), every other key its default; a key the
// user set (config.firmware_settings) takes that value. The shipped
// firmware loaded as a plugin thus runs as the built-in one.
std::vector<double> plugin_values(const stereosim_fw_descriptor& d, const platform_config& config);

}  // namespace platform
