// Closed-form figures the simulation is checked against (docs/budget.md
// derives each one): the sensor readout, the EMIF time of one pair's capture
// by the firmware's EDMA chain, and the budget estimate of the sequential and
// overlapped modes. Plain arithmetic on the documented timing rules; nothing
// here runs the models.
#pragma once

#include <cstdint>
#include <vector>

#include "model/emif/emif_async_master.h"
#include "model/sensor/profile.h"
#include "tb/platform/firmware_report.h"
#include "tb/platform/platform_config.h"

namespace platform {

// One sensor frame on its pins, in pixel clocks from the frame's line 0,
// column 0 (docs/sensor.md, "Frame layout").
struct readout_figures {
    int64_t first_active_pclk = 0;  // clock of the first active pixel
    int64_t last_active_pclk = 0;   // clock of the last active pixel
    int64_t frame_pclks = 0;
    double pclk_ns = 0.0;
    double first_active_ms() const { return first_active_pclk * pclk_ns * 1e-6; }
    double active_span_ms() const {
        return (last_active_pclk - first_active_pclk) * pclk_ns * 1e-6;
    }
    double frame_ms() const { return frame_pclks * pclk_ns * 1e-6; }
};
readout_figures readout(const sensor::sensor_profile& p);

// A capture chain for one pair as the card's protocol asks (docs/budget.md):
// the card's 5 status registers into the pair buffer, then the left and the
// right frame line by line, each line a fixed-address burst from the card's
// pixel port (CE3) followed by an incrementing burst into the SDRAM buffer
// (CE0), every transfer started when the one before completed.
struct capture_figures {
    uint64_t header_eclk = 0;       // status registers + header write
    uint64_t line_eclk = 0;         // one line: card read + SDRAM write + turnarounds
    uint64_t row_crossings = 0;     // SDRAM row boundaries inside the pair's line bursts
    uint64_t pair_eclk = 0;         // header + 2 x rows x line + row crossings, without refresh
    double refresh_fraction = 0.0;  // bus time refresh adds (fraction of pair_eclk)
    uint64_t total_eclk = 0;        // with refresh
    double eclk_ns = 0.0;
    double total_ms() const { return total_eclk * eclk_ns * 1e-6; }
};
// Where the chain writes the frames in SDRAM: only their place within an
// SDRAM row matters (a line burst crossing a row pays a row access).
struct frame_placement {
    uint64_t left = 0, right = 0;  // the frames' first bytes
};
// The reference firmware's pair buffer: 4 KB aligned, a 64-byte status
// header, then the left frame and the right (dsp/control_program.h). What
// the closed form assumes before a run has shown where a firmware puts them.
frame_placement reference_placement(int cols, int rows);
// Where the firmware's first PAIR_CAPTURED that names two frames in SDRAM
// (EMIFA CE0) put them; the reference's placement if none did.
frame_placement reported_placement(const std::vector<fw_event>& events, int cols, int rows);
// cols x rows active pixels (4 per 32-bit word); card_cectl = CECTL2/3; the
// SDRAM numbers and the ECLK period of the engine's configuration.
capture_figures capture(int cols, int rows, uint32_t card_cectl, const emif::emif_config& emif,
                        const frame_placement& frames);

// The firmware's own SDRAM traffic per pair on EMIFA (dsp/controller.h memory
// plan: the raw pair read once through the L2 cache, 2 cols rows bytes in
// line transfers of l2_line_bytes; nothing else frame-scale). In overlapped
// mode the lines run while the next pair is captured: a line inside a card
// burst costs the burst TA + row access + data + TA ECLK (the row is closed
// by the card words before it). line_eclk is that worst case; eclk = lines
// x line_eclk, the bus time the traffic can add to one period.
struct traffic_figures {
    uint64_t lines = 0;
    uint64_t line_eclk = 0;
    uint64_t eclk = 0;
    double eclk_ns = 0.0;
    double ms() const { return eclk * eclk_ns * 1e-6; }
};
traffic_figures firmware_traffic(int cols, int rows, uint32_t card_cectl,
                                 const emif::emif_config& emif, uint32_t l2_line_bytes = 128);

// docs/design-brief.md "What the budget means", with the paper's two modes:
//   sequential: the pair is read, then processed, before the next can be
//               taken: fits when capture + processing (+ the interrupt
//               path) <= period;
//   overlapped: capture of pair N+1 runs while pair N is processed: fits
//               when capture <= period and processing <= period.
struct mode_estimate {
    bool fits = false;
    double need_ms = 0.0;  // the binding figure compared with the period
};
mode_estimate estimate_sequential(double capture_ms, double processing_ms, double period_ms);
mode_estimate estimate_overlapped(double capture_ms, double processing_ms, double period_ms);
// With the firmware's SDRAM traffic on the bus (traffic_figures::ms()):
// overlapped, the bus must carry capture + traffic in a period (need =
// max(capture + traffic, processing)); sequential, the traffic runs inside
// the processing time (its stalls are in the charged cycles), so need =
// capture + processing as above.
mode_estimate estimate_overlapped(double capture_ms, double traffic_ms, double processing_ms,
                                  double period_ms);
mode_estimate estimate_sequential(double capture_ms, double traffic_ms, double processing_ms,
                                  double period_ms);

// The closed-form budget of a whole configuration (docs/budget.md
// "Sequential against overlapped"): C and T from its profile, the CECTL the
// board asks the firmware to program (card_cectl_asked) and its EMIF clock,
// P_max given (e.g. the largest pair of the firmware's host entry,
// tb/platform/host), judged for the firmware overlapping its processing
// with the next capture or not.
struct budget_estimate {
    double capture_ms = 0.0;     // C
    double traffic_ms = 0.0;     // T (0 when the traffic is off the bus)
    double processing_ms = 0.0;  // P_max
    mode_estimate verdict;
};
budget_estimate estimate_budget(const platform_config& config, double processing_ms,
                                bool overlapped);

}  // namespace platform
