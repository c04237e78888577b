#include "model/sensor/fault.h"

namespace sensor {

const char* fault_kind_name(fault_kind kind) {
    switch (kind) {
        case fault_kind::start_skew:
            return "start_skew";
        case fault_kind::dropped_line:
            return "dropped_line";
        case fault_kind::dropped_frame:
            return "dropped_frame";
        case fault_kind::extra_frame:
            return "extra_frame";
        case fault_kind::vsync_glitch:
            return "vsync_glitch";
        case fault_kind::href_glitch:
            return "href_glitch";
        case fault_kind::pclk_drift:
            return "pclk_drift";
        case fault_kind::dark_leak:
            return "dark_leak";
        case fault_kind::stuck_data_bit:
            return "stuck_data_bit";
        case fault_kind::never_start:
            return "never_start";
        case fault_kind::ignore_oe:
            return "ignore_oe";
    }
    return "?";
}

}  // namespace sensor
