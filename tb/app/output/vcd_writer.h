// VCD writer (docs/waveforms.md): a pin_trace sink that writes one Value
// Change Dump of a window [from, to) of a run, every traced signal on one
// timeline.
//
// Time: `$timescale 1fs`. A tick is 1/18 ns = 55,555.5... fs, which no
// decimal unit holds exactly; each change is written at to_fs(tick), the tick
// rounded to the nearest fs ONCE (model/time/ticks.h), which is exactly the
// SystemC time of that edge (resolution 1 fs). The error is < 0.5 fs per
// edge and never accumulates; the tick is recovered exactly as
// round(fs * 18 / 10^6). 1 ps would round by up to 0.5 ps, still
// recoverable, but would no longer equal the SystemC time.
//
// Layout: one top scope `platform`, below it the signal scopes in the order
// they were declared (sensor_L, sensor_R, card with sync_check / fifo /
// emif_slave, emif, interrupts, firmware). Vectors are named NAME[msb:0].
// The initial values are dumped at the window start ($dumpvars), signals the
// source never gave as x. Written to PATH.part and renamed to PATH by
// finish(), so a failed run leaves no half-written VCD (a writer destroyed
// unfinished removes its .part).
//
// Fault markers: every VCD also declares `platform.faults.kind[7:0]` (last,
// whatever --vcd-scope selects), 0 in $dumpvars. Fault onsets are known only
// after the run (tb/app/faults/observe.cpp), when this file is finished, so
// add_fault_markers() merges them in by one streaming pass over the finished
// file: at each onset tick the signal becomes 1 + faults::fault_type, the
// kind of the latest fault to take effect (a fault before the window sets
// its $dumpvars value; one at or after the window's end is not written).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "tb/app/output/fault_markers.h"
#include "tb/app/output/waves_writer.h"
#include "tb/platform/island/pin_trace.h"

namespace output {

// (The scope groups, the fault marker signal and fault_marker are shared
// with --waves: waves_writer.h, fault_markers.h.)

class vcd_writer final : public platform::pin_trace {
  public:
    struct signal {
        platform::trace_signal info;
        bool included = false;  // its group was selected
        std::string code;       // VCD identifier code
        std::string full_name;  // as GTKWave names it: platform.sensor_L.DATA[7:0]
    };

    explicit vcd_writer(platform::tick_window window, unsigned groups = platform::trace_all_groups);
    // Opens PATH.part (call before the first change; false + error() if it
    // cannot be written). Changes before open() are kept in memory.
    bool open(const std::string& path);
    ~vcd_writer() override;
    vcd_writer(const vcd_writer&) = delete;
    vcd_writer& operator=(const vcd_writer&) = delete;

    platform::trace_id declare(const platform::trace_signal& s) override;
    void change(simtime::ticks t, platform::trace_id id, uint64_t value) override;
    void release(simtime::ticks t, platform::trace_id id) override;
    // Writes the end time, closes and renames the file.
    void finish(simtime::ticks end) override;
    // After finish(): merges `markers` (any order) into the finished file by
    // a streaming copy to PATH.markers, renamed to PATH. False + error() if
    // the file cannot be read or written (PATH is then left as it was).
    bool add_fault_markers(std::vector<fault_marker> markers);

    bool ok() const { return m_error.empty(); }
    bool finished() const { return m_finished; }
    const std::string& error() const { return m_error; }
    const std::string& path() const { return m_path; }
    const std::vector<signal>& signals() const { return m_signals; }
    uint64_t changes_written() const { return m_changes; }
    uint64_t bytes_written() const { return m_bytes; }
    // Changes that arrived out of tick order (a source bug): written at the
    // current time instead.
    uint64_t out_of_order() const { return m_out_of_order; }

    // Adds the fault marker after the declared signals (idempotent; the
    // header does it, so signals() holds the marker once a change arrived).
    void declare_fault_marker();

  private:
    void write_header();
    void write_value(size_t index);
    void set_time(simtime::ticks t);
    void flush_buffer();

    std::string m_path;
    platform::tick_window m_window;
    unsigned m_groups;
    std::FILE* m_file = nullptr;
    std::string m_error;
    std::vector<signal> m_signals;
    std::vector<uint64_t> m_value;
    std::vector<uint8_t> m_state;  // 0 x, 1 value, 2 z
    bool m_header_written = false;
    bool m_finished = false;
    simtime::ticks m_time = -1;  // tick of the last "#" written
    std::string m_buffer;
    uint64_t m_changes = 0;
    uint64_t m_bytes = 0;
    uint64_t m_out_of_order = 0;
    size_t m_marker = SIZE_MAX;  // index of the fault marker in m_signals
};

}  // namespace output
