#include "dsp/plugin/reference_firmware.h"

#include <cstdio>
#include <new>

#include "dsp/plugin/services_hal.h"

namespace dsp::plugin {

// The ABI's numbers are the firmware's own: events and causes pass through.
static_assert(static_cast<int>(firmware_event::hard_error) == STEREOSIM_EV_HARD_ERROR);
static_assert(static_cast<int>(firmware_event::pair_captured) == STEREOSIM_EV_PAIR_CAPTURED);
static_assert(static_cast<int>(rearm_cause::watchdog) == STEREOSIM_REARM_WATCHDOG);
static_assert(static_cast<int>(cfa_order::gbrg) == STEREOSIM_CFA_GBRG);
static_assert(stage_count <= static_cast<int>(STEREOSIM_FW_MAX_STAGES));

namespace {

const char* const stage_names[] = {"capture",    "preprocess",  "detect", "track",
                                   "stereo_sad", "stereo_edge", "xyz"};
static_assert(sizeof stage_names / sizeof stage_names[0] == stage_count);
const char* const state_names[] = {"DETECT", "TRACK", "LOST"};
const char* const modes[] = {"sequential", "overlapped"};
const char* const methods[] = {"sad", "edge", "both"};
const char* const memories[] = {"l2", "sdram"};

stereosim_fw_key integer(const char* name, double lo, double hi, double def, const char* doc) {
    return stereosim_fw_key{name, STEREOSIM_KEY_INT, lo, hi, def, nullptr, 0, doc};
}

stereosim_fw_key choice(const char* name, const char* const* names, uint32_t count, double def,
                        const char* doc) {
    return stereosim_fw_key{name, STEREOSIM_KEY_CHOICE, 0, 0, def, names, count, doc};
}

stereosim_fw_key flag(const char* name, bool def, const char* doc) {
    return stereosim_fw_key{name, STEREOSIM_KEY_BOOL, 0, 1, def ? 1.0 : 0.0, nullptr, 0, doc};
}

// The keys with the firmware's own defaults (docs/config.md).
struct reference_keys {
    stereosim_fw_key keys[reference_key_count];

    reference_keys() {
        const control_program_config program;
        const controller_config pipeline;
        keys[key_mode] = choice("mode", modes, 2, static_cast<double>(program.mode),
                                "read the pair then process it, or process pair N while N+1 is "
                                "read");
        keys[key_search_radius] =
            integer("search_radius", 1, 1000, pipeline.track.search_radius,
                    "SAD tracking search radius, px each way (window 2r+1 must fit the image)");
        keys[key_stereo_method] =
            choice("stereo_method", methods, 3, static_cast<double>(pipeline.method),
                   "which stereo match gives the 3D point");
        keys[key_detect_threshold] =
            integer("detect_threshold", 1, 254, pipeline.detect.threshold,
                    "three-frame differencing: Binary(a) = a > threshold, gray levels");
        keys[key_frame_memory] =
            choice("frame_memory", memories, 2, static_cast<double>(pipeline.frame_memory),
                   "where the gray frames and motion mask live (l2: the memory plan of "
                   "docs/firmware.md)");
        keys[key_watchdog_ms] = integer("watchdog_ms", 0, 10000, program.watchdog_ms,
                                        "period of the card watchdog, ms (0: off)");
        keys[key_card_start_timeout] =
            integer("card_start_timeout", 1, 65535, card_regs::start_timeout_reset,
                    "START_TIMEOUT programmed: lines the card waits for the first VSYNC after OE "
                    "rises");
        keys[key_card_frame_id_check] =
            flag("card_frame_id_check", true,
                 "CHECKS.FRAME_ID programmed: the card compares the sensors' frame identity "
                 "(0: the paper's card, which forwards a repeated frame)");
        keys[key_capture_cycles] =
            integer("capture_cycles", 0, 1000000, static_cast<double>(program.capture_cycles),
                    "CPU cycles per pair charged to stage capture (interrupts, header, re-arm)");
        keys[key_hard_error_rearms] =
            integer("hard_error_rearms", 0, 16, program.hard_error_rearms,
                    "re-arms after a card HARD_ERROR, no good pair between, before giving up");
        keys[key_rearm_on_overflow] = flag("rearm_on_overflow", program.rearm_on_overflow,
                                           "re-arm the card (ENABLE 0 -> 1) after an overflow");
        keys[key_rearm_on_every_sync_error] =
            flag("rearm_on_every_sync_error", program.rearm_on_every_sync_error,
                 "re-arm after every sync error, not only the card's HARD_ERROR");
    }
};

const reference_keys& keys() {
    static const reference_keys k;
    return k;
}

struct instance {
    services_hal hal;
    control_program program;
    explicit instance(const stereosim_services& services) : hal(services) {}
};

void* create(const stereosim_services* services, const stereosim_board* board, const double* values,
             char* error, size_t error_size) {
    auto* fw = new (std::nothrow) instance(*services);
    if (fw == nullptr) {
        std::snprintf(error, error_size, "out of memory");
        return nullptr;
    }
    if (!fw->program.init(reference_config(*board, values), fw->hal)) {
        std::snprintf(error, error_size,
                      "the image size (%ux%u) or the buffer placement is not usable",
                      board->active_cols, board->active_rows);
        delete fw;
        return nullptr;
    }
    fw->hal.set_program(&fw->program);
    return fw;
}

void run(void* fw) {
    static_cast<instance*>(fw)->program.run();
}

void destroy(void* fw) {
    delete static_cast<instance*>(fw);
}

void policy(const void* fw, stereosim_fw_policy* out) {
    const control_program_config& c = static_cast<const instance*>(fw)->program.config();
    out->hard_error_rearms = c.hard_error_rearms;
    out->rearm_on_overflow = c.rearm_on_overflow ? 1u : 0u;
    out->rearm_on_every_sync_error = c.rearm_on_every_sync_error ? 1u : 0u;
    out->watchdog_ms = c.watchdog_ms;
    out->overlapped = c.mode == pipeline_mode::overlapped ? 1u : 0u;
    // The stereo method not asked for never runs.
    const stereo_method m = c.pipeline.method;
    out->optional_stages = m == stereo_method::sad    ? 1u << static_cast<int>(stage::stereo_edge)
                           : m == stereo_method::edge ? 1u << static_cast<int>(stage::stereo_sad)
                                                      : 0u;
}

camera_rig rig_of(const stereosim_board& b) {
    camera_rig rig;
    rig.baseline_um = b.baseline_um;
    rig.focal_length_um = b.focal_length_um;
    rig.pixel_pitch_nm = b.pixel_pitch_nm;
    rig.cx_left_q8 = b.cx_left_q8;
    rig.cy_left_q8 = b.cy_left_q8;
    rig.cx_right_q8 = b.cx_right_q8;
    rig.cy_right_q8 = b.cy_right_q8;
    return rig;
}

card_setup card_of(const stereosim_board& b) {
    card_setup c;
    c.h_start = b.h_start;
    c.dark_cols_left = b.dark_cols_left;
    c.border_cols_left = b.border_cols_left;
    c.active_cols = b.active_cols;
    c.border_cols_right = b.border_cols_right;
    c.dark_cols_right = b.dark_cols_right;
    c.line_total = b.line_total;
    c.v_start = b.v_start;
    c.dark_rows_top = b.dark_rows_top;
    c.border_rows_top = b.border_rows_top;
    c.active_rows = b.active_rows;
    c.border_rows_bottom = b.border_rows_bottom;
    c.dark_rows_bottom = b.dark_rows_bottom;
    c.frame_lines = b.frame_lines;
    c.retry_limit = b.card_retry_limit;
    return c;
}

}  // namespace

control_program_config reference_config(const stereosim_board& board, const double* values) {
    control_program_config c;
    c.pipeline.max_width = static_cast<int>(board.active_cols);
    c.pipeline.max_height = static_cast<int>(board.active_rows);
    c.pipeline.rig = rig_of(board);
    c.pipeline.cfa = static_cast<cfa_order>(board.cfa);
    c.pipeline.track.search_radius = static_cast<int>(values[key_search_radius]);
    c.pipeline.detect.threshold = static_cast<uint8_t>(values[key_detect_threshold]);
    c.pipeline.method = static_cast<stereo_method>(values[key_stereo_method]);
    c.pipeline.frame_memory = static_cast<cost::memory>(values[key_frame_memory]);
    c.card = card_of(board);
    c.card.start_timeout = static_cast<uint32_t>(values[key_card_start_timeout]);
    c.card.checks = values[key_card_frame_id_check] != 0 ? card_regs::checks_frame_id_mask : 0u;
    c.dsk = static_cast<dsk_version>(board.dsk_version);
    c.cpu_mhz = static_cast<uint32_t>(board.cpu_hz / 1000000);
    c.card_timing = card_bus_timing{board.card_setup, board.card_strobe, board.card_hold};
    c.mode = static_cast<pipeline_mode>(values[key_mode]);
    c.watchdog_ms = static_cast<uint32_t>(values[key_watchdog_ms]);
    c.capture_cycles = static_cast<uint64_t>(values[key_capture_cycles]);
    c.hard_error_rearms = static_cast<uint32_t>(values[key_hard_error_rearms]);
    c.rearm_on_overflow = values[key_rearm_on_overflow] != 0;
    c.rearm_on_every_sync_error = values[key_rearm_on_every_sync_error] != 0;
    return c;
}

const stereosim_fw_descriptor& reference_firmware() {
    static const stereosim_fw_descriptor d{STEREOSIM_FIRMWARE_ABI_VERSION,
                                           "stereosim-reference",
                                           "1.0",
                                           stage_count,
                                           stage_names,
                                           3,
                                           state_names,
                                           reference_key_count,
                                           keys().keys,
                                           create,
                                           run,
                                           destroy,
                                           policy};
    return d;
}

}  // namespace dsp::plugin
