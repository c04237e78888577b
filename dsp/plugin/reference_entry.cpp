// The entry symbols of libstereosim_fw_reference.so, the only symbols it
// exports (the module is built with hidden visibility).
#include "dsp/plugin/reference_firmware.h"

extern "C" __attribute__((visibility("default"))) const stereosim_fw_descriptor* stereosim_firmware(
    void) {
    return &dsp::plugin::reference_firmware();
}

extern "C" __attribute__((visibility("default"))) const stereosim_fw_host* stereosim_firmware_host(
    void) {
    return &dsp::plugin::reference_host();
}
