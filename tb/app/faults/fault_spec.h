// Fault specs of the stereosim command (docs/faults.md): one fault per spec,
// `kind:key=value,...[@trigger]`, e.g. `skew:sensor=R,lines=3@frame=5`,
// `emif-wait:cycles=40@frame=3`. One kind per hook: the sensors' ten fault
// hooks (model/sensor/fault.h, docs/sensor-faults.md), the EMIF's ARDY wait
// states on the card's CE space (emif::ardy_fault) and the C6416's cycle
// scale (c6416_sc::set_cycle_scale). The kinds table below is the one source
// of `stereosim faults --list`, the parser and docs/faults.md.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tb/platform/platform_config.h"

namespace faults {

enum class fault_type : uint8_t {
    skew,         // sensor start_skew
    drop_line,    // sensor dropped_line
    drop_frame,   // sensor dropped_frame
    extra_frame,  // sensor extra_frame
    drift,        // sensor pclk_drift
    glitch,       // sensor vsync_glitch / href_glitch
    dark_leak,    // sensor dark_leak
    stuck_bit,    // sensor stuck_data_bit
    dead,         // sensor never_start
    oe_stuck,     // sensor ignore_oe
    emif_wait,    // emif::ardy_fault on the card's CE space
    cpu_slow,     // c6416_sc::set_cycle_scale
};
inline constexpr int fault_type_count = 12;

// One parameter of a kind: a choice ("L|R") or a number in [min, max].
struct param_info {
    const char* name;
    const char* choices;  // "L|R"; nullptr: a number
    double min = 0, max = 0;
    bool decimal = false;      // numbers: a decimal is allowed (else an integer)
    const char* default_text;  // nullptr: required
    const char* doc;
};

struct kind_info {
    fault_type type;
    const char* name;  // as written in a spec
    const char* hook;  // what it drives
    const char* doc;
    std::vector<param_info> params;
};

// Every kind, in fault_type order.
const std::vector<kind_info>& fault_kinds();
const kind_info& kind_of(fault_type type);
const char* fault_type_name(fault_type type);
bool is_sensor_fault(fault_type type);

// When a fault starts. `@frame=N`: for a sensor fault the sensor's own frame N
// (frames it started since power-on, model/sensor/truth.h), for emif-wait and
// cpu-slow the start of sync period N (N x 24.5 ms); `@ms=T`: simulated time
// T ms. No trigger: from the start (time 0).
struct trigger_spec {
    enum class by : uint8_t { start, frame, ms };
    by kind = by::start;
    uint64_t frame = 0;
    double ms = 0.0;
};

struct fault_spec {
    std::string text;  // as given
    fault_type type = fault_type::skew;
    trigger_spec when;
    int camera = -1;  // 0 L, 1 R (sensor faults)
    // Parameters (those of other kinds keep these defaults).
    int lines = 0, pixels = 0;  // skew
    int line = 0;               // drop-line: readout line of the trigger frame
    bool href = false;          // glitch: signal=href (else vsync)
    int width = 1;              // glitch
    int32_t ppm = 0;            // drift
    int level = 255;            // dark-leak
    int bit = 0, value = 1;     // stuck-bit
    uint32_t cycles = 0;        // emif-wait: extra ARDY wait states per access
    int ce = 3;                 // emif-wait: CE space (2 registers, 3 pixel ports)
    double factor = 1.0;        // cpu-slow
};

// Parses one spec; on failure returns nothing and sets *error to one line
// ("bad fault spec 'x': ...").
std::optional<fault_spec> parse_fault_spec(const std::string& text, std::string* error);

// The canonical spelling (every parameter, defaults included, and the trigger).
std::string canonical(const fault_spec& spec);

// The tick the trigger stands for where it is a time: @ms (exact to the
// tick), @frame for emif-wait / cpu-slow (N periods), 0 without a trigger;
// -1 for a sensor fault's @frame (its onset is the sensor's own timing).
simtime::ticks trigger_tick(const fault_spec& spec, simtime::ticks period);

// Adds the fault to the run: the sensor's fault list, the EMIF ARDY fault or
// the CPU's cycle scale (platform_config).
void apply(const fault_spec& spec, platform::platform_config& config);

// `stereosim faults --list`: every kind with its parameters, defaults and
// ranges, and the trigger grammar.
std::string kinds_listing();

}  // namespace faults
