// The reference firmware's configuration for a platform run's config, as
// the shipped firmware makes it from the board and its key values
// (dsp/plugin/reference_firmware.h), for the tests that drive its control
// program or controller directly beside a run.
#pragma once

#include <vector>

#include "dsp/control_program.h"
#include "dsp/controller.h"
#include "dsp/plugin/reference_firmware.h"
#include "tb/platform/firmware_board.h"
#include "tb/platform/platform_config.h"

namespace host {

// The control program's configuration the shipped firmware makes for a run.
inline dsp::control_program_config program_config(const platform::platform_config& config) {
    const std::vector<double> values =
        platform::plugin_values(dsp::plugin::reference_firmware(), config);
    return dsp::plugin::reference_config(platform::board_of(config), values.data());
}

// Its controller's configuration.
inline dsp::controller_config pipeline_config(const platform::platform_config& config) {
    return program_config(config).pipeline;
}

}  // namespace host
