// The reference firmware's entry points under the names the platform links
// it by when it is built in (tb/firmware/builtin.h); the plugin module
// exports the same tables as stereosim_firmware / stereosim_firmware_host
// (reference_entry.cpp).
#include "dsp/plugin/reference_firmware.h"

extern "C" const stereosim_fw_descriptor* stereosim_builtin_firmware(void) {
    return &dsp::plugin::reference_firmware();
}

extern "C" const stereosim_fw_host* stereosim_builtin_firmware_host(void) {
    return &dsp::plugin::reference_host();
}
