// What the platform tells a firmware behind the C ABI about the board a run
// configured (include/stereosim/firmware.h stereosim_board): the DSK, the
// card's bus timing and RETRY_LIMIT, the sensors' geometry and colour
// filter, the calibrated rig; and the firmware's key values.
#pragma once

#include <string>
#include <vector>

#include "stereosim/firmware.h"
#include "tb/platform/platform_config.h"

namespace platform {

stereosim_board board_of(const platform_config& config);

// A firmware's key values for a run: the run's setting of each key
// (config.firmware_settings, checked against the descriptor by the command
// line), its declared default where the run sets none.
std::vector<double> plugin_values(const stereosim_fw_descriptor& d, const platform_config& config);

// The name of the choice the run makes for the firmware's CHOICE key
// `name`, or empty if the firmware declares no such choice key.
std::string key_choice(const stereosim_fw_descriptor& d, const platform_config& config,
                       const char* name);
// Whether the firmware is asked to process a pair while the next one is
// captured: unless its CHOICE key `mode` is "sequential" (the convention of
// the reference and the example in C; docs/firmware-abi.md). The closed
// forms use it before a run; after one, the firmware's policy says.
bool asks_overlapped(const stereosim_fw_descriptor& d, const platform_config& config);

// The CECTL2/3 the board asks a firmware to program for the card: the DSK
// version's own (docs/c6416.md, [GEL]) with the run's card timing over it.
// The closed forms predict the card's bus time with it before a run; after
// one, the platform reads what the firmware did program from the EMIF.
uint32_t card_cectl_asked(const platform_config& config);

}  // namespace platform
