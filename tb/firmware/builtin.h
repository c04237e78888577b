// The built-in firmware: the shipped reference (dsp/plugin), linked into
// stereosim as the default and reached, as a plugin is, only through the
// ABI's entry points (defined by dsp/plugin/builtin_entry.cpp).
#pragma once

#include "stereosim/firmware.h"

extern "C" {
const stereosim_fw_descriptor* stereosim_builtin_firmware(void);
const stereosim_fw_host* stereosim_builtin_firmware_host(void);
}

namespace firmware {

inline const stereosim_fw_descriptor& builtin() {
    return *stereosim_builtin_firmware();
}

inline const stereosim_fw_host& builtin_host() {
    return *stereosim_builtin_firmware_host();
}

}  // namespace firmware
