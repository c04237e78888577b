// The waveform file of a run (docs/waveforms.md): `stereosim run --waves
// fst|vcd` writes one FST or VCD of a window [from, to) through Verilator's
// own writer (VerilatedFstC / VerilatedVcdC). Two kinds of signal share it,
// on one time base:
//   - the card's whole RTL hierarchy, traced by the traced build of the card
//     the island runs (tb/platform/island/card_waves.h), under platform.card;
//   - the pin trace's signals (pin_trace.h: sensor pins, EMIF, interrupts,
//     firmware stage and state) and the fault marker platform.faults.kind,
//     written through the writer's trace hooks (init / full / change
//     callbacks) as if they were RTL signals.
//
// Time: 1 fs. A tick is 1/18 ns; each time is written at to_fs(tick), the
// tick rounded to the nearest fs once (model/time/ticks.h), which is exactly
// the SystemC time of that edge. The writer dumps a time once every change
// of it is known and before the card moves on (pin_trace::seal_before), so
// the card's values at a time are the ones the island's edges left there.
//
// Both formats are two-state (Verilator's writers): a bus nobody drives
// (release(): ED, the card's ED) reads 0.
//
// Written to PATH.part and renamed to PATH by finish(), so a failed run
// leaves no half-written file (a writer destroyed unfinished removes it).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "tb/app/output/waves_format.h"
#include "tb/platform/island/card_waves.h"
#include "tb/platform/island/pin_trace.h"

namespace output {

// --waves-scope groups (platform::trace_group bits) of a signal's scope.
unsigned trace_group_of_scope(const std::string& scope);
// "sensors,card" -> bits; false on an unknown name (*bad names it).
bool parse_trace_groups(const std::string& list, unsigned* groups, std::string* bad);

// The fault marker signal every file declares after the traced ones.
const platform::trace_signal& fault_marker_signal();
bool is_fault_marker(const platform::trace_signal& s);

class waves_writer final : public platform::pin_trace, public platform::card_waves {
  public:
    struct signal {
        platform::trace_signal info;
        bool included = false;  // its group was selected
        uint32_t code = 0;      // the writer's code (0: not in the file)
        std::string full_name;  // as GTKWave names it: platform.sensor_L.DATA[7:0]
    };

    // As GTKWave names a signal of the file: platform.sensor_L.DATA[7:0].
    static std::string full_name_of(const platform::trace_signal& s);

    waves_writer(waves_format format, platform::tick_window window,
                 unsigned groups = platform::trace_all_groups);
    ~waves_writer() override;
    waves_writer(const waves_writer&) = delete;
    waves_writer& operator=(const waves_writer&) = delete;

    // Where finish() puts the file; false + error() if PATH.part cannot be
    // written. The file itself opens at the first change, when the card
    // has registered its signals.
    bool open(const std::string& path);

    platform::trace_id declare(const platform::trace_signal& s) override;
    void change(simtime::ticks t, platform::trace_id id, uint64_t value) override;
    void release(simtime::ticks t, platform::trace_id id) override;
    void seal_before(simtime::ticks t) override;
    // Dumps the end time, closes and renames the file.
    void finish(simtime::ticks end) override;
    platform::card_waves* card_file() override { return this; }

    VerilatedFstC* fst_writer() override;
    VerilatedVcdC* vcd_writer() override;

    waves_format format() const { return m_format; }
    bool ok() const { return m_error.empty(); }
    bool finished() const { return m_finished; }
    const std::string& error() const { return m_error; }
    const std::string& path() const { return m_path; }
    const std::vector<signal>& signals() const { return m_signals; }
    // Changes that arrived out of tick order (a source bug): written at the
    // pending time instead.
    uint64_t out_of_order() const { return m_out_of_order; }

  private:
    template <class trace_type>
    struct hooks;
    void open_file();
    void dump_pending();
    void close_file();

    waves_format m_format;
    platform::tick_window m_window;
    unsigned m_groups;
    std::string m_path;
    std::string m_error;
    std::unique_ptr<VerilatedFstC> m_fst;
    std::unique_ptr<VerilatedVcdC> m_vcd;
    std::vector<signal> m_signals;
    std::vector<uint64_t> m_value;
    bool m_file_open = false;
    bool m_finished = false;
    bool m_pending = false;      // changes at m_time not yet dumped
    simtime::ticks m_time = -1;  // the time of the pending changes, or the last dumped
    uint64_t m_out_of_order = 0;
};

}  // namespace output
