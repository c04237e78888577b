// The firmware's reports as the platform keeps them: the ABI's events
// (include/stereosim/firmware.h, docs/firmware-abi.md "The reporting
// protocol"), each with the simulated tick it was reported at. Nothing of a
// firmware's own types: every observer of the platform reads these.
#pragma once

#include <cstdint>

#include "model/time/ticks.h"
#include "stereosim/firmware.h"

namespace platform {

// The name of an event kind in reports, timelines and violations.
constexpr const char* report_name(uint32_t kind) {
    switch (kind) {
        case STEREOSIM_EV_BOOT:
            return "boot";
        case STEREOSIM_EV_EMIF_PROGRAMMED:
            return "emif_programmed";
        case STEREOSIM_EV_CARD_FOUND:
            return "card_found";
        case STEREOSIM_EV_CARD_MISSING:
            return "card_missing";
        case STEREOSIM_EV_CARD_CONFIGURED:
            return "card_configured";
        case STEREOSIM_EV_OE_RAISED:
            return "oe_raised";
        case STEREOSIM_EV_IN_STEP:
            return "in_step";
        case STEREOSIM_EV_SYNC_ERROR:
            return "sync_error";
        case STEREOSIM_EV_OVERFLOW:
            return "overflow";
        case STEREOSIM_EV_CARD_REARMED:
            return "card_rearmed";
        case STEREOSIM_EV_WATCHDOG:
            return "watchdog";
        case STEREOSIM_EV_PAIR_CAPTURED:
            return "pair_captured";
        case STEREOSIM_EV_PAIR_REJECTED:
            return "pair_rejected";
        case STEREOSIM_EV_PAIR_DROPPED:
            return "pair_dropped";
        case STEREOSIM_EV_PAIR_PROCESSED:
            return "pair_processed";
        case STEREOSIM_EV_STOPPED:
            return "stopped";
        case STEREOSIM_EV_HARD_ERROR:
            return "hard_error";
        case STEREOSIM_EV_FRAMES_USED:
            return "frames_used";
        default:
            return "?";
    }
}

struct fw_event {
    simtime::ticks tick = 0;
    stereosim_event event{};  // left / right: the frames' addresses, where the kind has them
};

}  // namespace platform
