// The shipped firmware of dsp/ (dsp::control_program and its controller)
// behind the C ABI (docs/firmware-abi.md): its descriptor, with the config
// keys it takes, and the configuration a board and those keys' values make.
// Built into libstereosim_fw_reference.so (which exports the entry) and
// linked into stereosim as the default firmware.
#pragma once

#include "dsp/control_program.h"
#include "stereosim/firmware.h"

namespace dsp::plugin {

// The reference firmware's key indices in its descriptor's `keys`.
enum reference_key : uint32_t {
    key_mode,
    key_search_radius,
    key_stereo_method,
    key_detect_threshold,
    key_frame_memory,
    key_watchdog_ms,
    key_card_start_timeout,
    key_card_frame_id_check,
    key_capture_cycles,
    key_hard_error_rearms,
    key_rearm_on_overflow,
    key_rearm_on_every_sync_error,
    reference_key_count
};

const stereosim_fw_descriptor& reference_firmware();
// Its optional host entry: the controller alone over raw pairs (the sweep's
// closed form).
const stereosim_fw_host& reference_host();

// The control program's configuration for `board` and the keys' `values`
// (reference_key_count of them, in range).
control_program_config reference_config(const stereosim_board& board, const double* values);

}  // namespace dsp::plugin
