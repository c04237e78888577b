// The budget checker (docs/design-brief.md "What the budget means"; docs/budget.md):
// per 24.5 ms sync period the CPU's and the EMIF's busy time, the card's
// FIFO peaks and overflows, the pairs dropped and each stage's modelled
// time; per pair its capture time on the bus, its processing time on the
// CPU and its latency from first pixel to 3D output.
//
// A period is judged once the platform is in steady state (from the first
// pair the card forwarded to the end of the run). The run is within budget
// when no judged period and no pair overruns. Every overrun names the
// resource and the stage that caused it:
//   cpu           a pair's processing took longer than the period, or the
//                 CPU was busy the whole period: the stage that took longest;
//   emif          a pair's capture took longer than the period, or the bus
//                 was busy the whole period: stage capture;
//   fifo          a card FIFO overflowed: stage capture (the bus did not
//                 drain it in time);
//   pair_buffers  a pair became ready while no pair buffer was free and was
//                 dropped: the stage the CPU was in at that moment.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "stereosim/firmware.h"
#include "tb/platform/platform.h"
#include "tb/platform/scoreboard.h"

namespace platform {

// Stages a firmware may declare (the ABI's limit); the tables show the ones
// the firmware under test declares, by its names.
inline constexpr int max_stages = STEREOSIM_FW_MAX_STAGES;

enum class resource : uint8_t { cpu, emif, fifo, pair_buffers };
const char* resource_name(resource r);

struct overrun {
    resource what = resource::cpu;
    int stage = 0;           // the firmware's declared stage index ...
    std::string stage_name;  // ... and its name
    int period = -1;         // index of the sync period, -1 if a pair's figure
    uint32_t pair = 0;       // the pair concerned, 0 if a period's figure
    double value_ms = 0.0;
    double limit_ms = 0.0;
    std::string describe() const;
};

struct period_budget {
    int index = 0;
    simtime::ticks begin = 0, end = 0;
    bool judged = false;
    double cpu_busy_ms = 0.0;
    double emif_busy_ms = 0.0;  // every requester: capture, CPU registers, firmware SDRAM
    uint64_t cpu_words = 0;     // words the CPU moved on the bus (SDRAM lines, registers)
    uint32_t fifo_peak_words[2] = {};
    bool overflow = false;
    int drops = 0;
    double stage_ms[max_stages] = {};  // CPU time charged per stage in the period
};

struct pair_budget {
    uint32_t pair = 0;
    bool processed = false;
    bool judged = false;
    double capture_ms = 0.0;     // FRAME_READY to the last EDMA burst of its chain
    double processing_ms = 0.0;  // the CPU cycles of the pair, capture stage included
    double stage_ms[max_stages] = {};
    double latency_ms = 0.0;  // first active pixel to the 3D output
};

struct budget_report {
    double period_ms = 0.0;
    double cpu_hz = 0.0;
    std::vector<std::string> stage_names;  // the firmware's declared stages, in order
    std::vector<period_budget> periods;
    std::vector<pair_budget> pairs;
    std::vector<overrun> overruns;
    int judged_periods = 0;
    bool fits = false;  // judged periods exist and none overran

    double max_cpu_busy_ms = 0.0, max_emif_busy_ms = 0.0;  // over judged periods
    double max_capture_ms = 0.0, mean_capture_ms = 0.0;    // over judged captured pairs
    double max_processing_ms = 0.0;                        // over processed pairs
    uint32_t fifo_peak_words[2] = {};                      // whole run
    int drops = 0;
    int overflows = 0;
    double stage_ms_max[max_stages] = {};          // per processed pair
    double stage_ms_mean[max_stages] = {};         // per processed pair
    uint64_t stage_cycles_total[max_stages] = {};  // whole run, as charged
    double latency_ms_max = 0.0;
    // The firmware's declared stages that never ran, but those its policy
    // names optional (stereosim_fw_policy::optional_stages): the budget says
    // nothing about them.
    std::vector<int> stages_not_run;

    // The first overrun of a resource, or nullptr.
    const overrun* first(resource r) const;
};

budget_report check_budget(const platform_top& top, const scoreboard_report& score);

}  // namespace platform
