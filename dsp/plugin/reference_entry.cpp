// The entry symbol of libstereosim_fw_reference.so, the only symbol it
// exports (the module is built with hidden visibility).
#include "dsp/plugin/reference_firmware.h"

extern "C" __attribute__((visibility("default"))) const stereosim_fw_descriptor* stereosim_firmware(
    void) {
    return &dsp::plugin::reference_firmware();
}
