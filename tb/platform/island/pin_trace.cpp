#include "tb/platform/island/pin_trace.h"

namespace platform {

namespace {

using f = trace_format;

// Widths: sensor DATA[7:0] (docs/sensor.md); FIFO levels AW + 1 = 18 bits
// (card_top FIFO_AW = 17, docs/card.md); EA = AEA[21:2], 20 bits, BE 4, ED 32
// (docs/hardware-facts.md section 3); the card's registers are word indices
// EA[7:2] on CE2 (docs/card-registers.md).
const trace_signal table[trace_pin_count] = {
    {"sensor_L", "PCLK", 1, f::bits},
    {"sensor_L", "VSYNC", 1, f::bits},
    {"sensor_L", "HREF", 1, f::bits},
    {"sensor_L", "VALID", 1, f::bits},
    {"sensor_L", "DATA", 8, f::bits},
    {"sensor_L", "OE", 1, f::bits},
    {"sensor_L", "FODD", 1, f::bits},
    {"sensor_R", "PCLK", 1, f::bits},
    {"sensor_R", "VSYNC", 1, f::bits},
    {"sensor_R", "HREF", 1, f::bits},
    {"sensor_R", "VALID", 1, f::bits},
    {"sensor_R", "DATA", 8, f::bits},
    {"sensor_R", "OE", 1, f::bits},
    {"sensor_R", "FODD", 1, f::bits},
    {"card", "MCLK", 1, f::bits},
    {"card", "EXT_INT4", 1, f::bits},
    {"card", "EXT_INT5", 1, f::bits},
    {"card", "EXT_INT6", 1, f::bits},
    {"card.emif_slave", "ARDY", 1, f::bits},
    {"card.emif_slave", "ED_OE", 1, f::bits},
    {"card.emif_slave", "ED", 32, f::bits},
    {"card.emif_slave", "register", 6, f::card_register},
    {"card.sync_check", "oe_state", 3, f::oe_state},
    {"card.sync_check", "causes", 10, f::verdict},
    {"card.sync_check", "verdict", 10, f::verdict},
    {"card.fifo", "level_L", 18, f::decimal},
    {"card.fifo", "level_R", 18, f::decimal},
    {"card.fifo", "overflow_L", 1, f::bits},
    {"card.fifo", "overflow_R", 1, f::bits},
    {"emif", "ECLKOUT", 1, f::bits},
    {"emif", "CE0_n", 1, f::bits},
    {"emif", "CE2_n", 1, f::bits},
    {"emif", "CE3_n", 1, f::bits},
    {"emif", "EA", 20, f::bits},
    {"emif", "ED", 32, f::bits},
    {"emif", "BE_n", 4, f::bits},
    {"emif", "AOE_n", 1, f::bits},
    {"emif", "ARE_n", 1, f::bits},
    {"emif", "AWE_n", 1, f::bits},
    {"emif", "ARDY", 1, f::bits},
    {"interrupts", "taken", 8, f::interrupt},
    {"interrupts", "cpu_asleep", 1, f::bits},
    // Wide enough for every stage and tracker state the firmware ABI allows.
    {"firmware", "stage", 4, f::firmware_stage},
    {"firmware", "state", 3, f::tracker_state},
};

}  // namespace

const trace_signal& trace_pin_signal(trace_pin pin) {
    return table[static_cast<int>(pin)];
}

trace_group trace_pin_group(trace_pin pin) {
    const std::string& scope = table[static_cast<int>(pin)].scope;
    if (scope.rfind("sensor", 0) == 0) return trace_group::sensors;
    if (scope.rfind("card", 0) == 0) return trace_group::card;
    if (scope == "emif") return trace_group::emif;
    return trace_group::firmware;
}

}  // namespace platform
