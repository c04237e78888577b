// Fault hooks of the sensor model. Each fault's exact pin-level outcome is in
// docs/sensor-faults.md; tests/model/test_sensor_faults.cpp checks each one.
//
// A fault starts at a trigger point: a position (frame, line, column) of the
// sensor's own frame timing, or a time (the first pixel clock whose rising
// edge is at or after the tick). Frame numbers count the frames the sensor
// starts (truth index, model/sensor/truth.h). Each kind acts at its own
// granularity from the first unit at or after the point:
//   frame faults   start_skew, dropped_frame, extra_frame
//   line faults    dropped_line (the first readout row line)
//   pixel faults   vsync_glitch, href_glitch, stuck_data_bit, dark_leak,
//                  pclk_drift, never_start, ignore_oe (from that clock on)
#pragma once

#include <cstdint>

#include "model/time/ticks.h"

namespace sensor {

enum class fault_kind : uint8_t {
    start_skew,
    dropped_line,
    dropped_frame,
    extra_frame,
    vsync_glitch,
    href_glitch,
    pclk_drift,
    dark_leak,
    stuck_data_bit,
    never_start,
    ignore_oe,
};
inline constexpr int fault_kind_count = 11;

const char* fault_kind_name(fault_kind kind);

// Bit of a fault kind in frame_truth::faults.
constexpr uint32_t fault_bit(fault_kind kind) {
    return 1u << static_cast<unsigned>(kind);
}

struct fault_trigger {
    bool by_time = false;
    uint64_t frame = 0;  // by position
    int line = 0;
    int col = 0;
    simtime::ticks tick = 0;  // by time

    static fault_trigger at_frame(uint64_t frame, int line = 0, int col = 0) {
        return {false, frame, line, col, 0};
    }
    static fault_trigger at_time(simtime::ticks t) { return {true, 0, 0, 0, t}; }
};

struct fault {
    fault_kind kind = fault_kind::start_skew;
    fault_trigger when;
    int skew_pclks = 0;       // start_skew: idle clocks inserted before the frame
    int width_pclks = 1;      // glitches: clocks the pin is inverted
    int32_t drift_ppm = 0;    // pclk_drift: period error, + = slower oscillator
    int leak_level = 255;     // dark_leak: what dark pixels read instead of black
    int bit = 0;              // stuck_data_bit: data[bit] ...
    bool stuck_value = true;  // ... reads this value

    static fault start_skew(fault_trigger when, int lines, int pclks, int line_pclks) {
        fault f{fault_kind::start_skew, when};
        f.skew_pclks = lines * line_pclks + pclks;
        return f;
    }
    static fault dropped_line(fault_trigger when) { return {fault_kind::dropped_line, when}; }
    static fault dropped_frame(fault_trigger when) { return {fault_kind::dropped_frame, when}; }
    static fault extra_frame(fault_trigger when) { return {fault_kind::extra_frame, when}; }
    static fault vsync_glitch(fault_trigger when, int width_pclks = 1) {
        fault f{fault_kind::vsync_glitch, when};
        f.width_pclks = width_pclks;
        return f;
    }
    static fault href_glitch(fault_trigger when, int width_pclks = 1) {
        fault f{fault_kind::href_glitch, when};
        f.width_pclks = width_pclks;
        return f;
    }
    static fault pclk_drift(fault_trigger when, int32_t ppm) {
        fault f{fault_kind::pclk_drift, when};
        f.drift_ppm = ppm;
        return f;
    }
    static fault dark_leak(fault_trigger when, int level) {
        fault f{fault_kind::dark_leak, when};
        f.leak_level = level;
        return f;
    }
    static fault stuck_data_bit(fault_trigger when, int bit, bool value) {
        fault f{fault_kind::stuck_data_bit, when};
        f.bit = bit;
        f.stuck_value = value;
        return f;
    }
    static fault never_start(fault_trigger when = fault_trigger::at_time(0)) {
        return {fault_kind::never_start, when};
    }
    static fault ignore_oe(fault_trigger when = fault_trigger::at_time(0)) {
        return {fault_kind::ignore_oe, when};
    }
};

}  // namespace sensor
