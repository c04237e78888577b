// GTKWave save file and translate filters of a run's VCD (docs/waveforms.md).
//
// A run with --waves writes into DIR/waves/: NAME.fst or NAME.vcd, NAME.gtkw and the
// translate filter files (*.txt) the save file names. Every path in the save
// file is RELATIVE (the waveform and the filters beside it), so the folder can be
// moved or archived and still opens with `gtkwave DIR/waves/NAME.gtkw`.
//
// The save file shows the signals in named groups: sensor L, sensor R, sync
// check, FIFOs, card RTL (a few of the card's own RTL signals: sync_check's
// counters, the OE controller, the left FIFO's pointers), EMIF, interrupts,
// firmware stage and state, faults (the fault marker, waves_writer.h). Enumerated signals are shown
// in decimal through a translate filter ("value name" lines, decimal so no leading-zero ambiguity):
// the card's OE controller state, the sync check's causes and verdict, the card register an access
// on CE2 names, the interrupt the CPU took, the firmware stage, the tracker state and the kind of
// the latest injected fault. The same files, for a full-scope run named `stereosim`, are committed
// in waves/ (tests/cli/test_waves_vcd.cpp and test_faults_vcd.cpp check they match).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "stereosim/firmware.h"
#include "tb/app/output/waves_writer.h"
#include "tb/platform/island/pin_trace.h"

namespace output {

struct translate_filter {
    std::string file_name;  // e.g. "oe_state.txt"
    std::string text;       // "value name" lines
};

// Every translate filter a save file may name; the firmware stage and
// tracker state by the names `firmware` declares.
std::vector<translate_filter> translate_filters(const stereosim_fw_descriptor& firmware);
// The filter file for a signal format, or nullptr (shown as bits / decimal).
const char* filter_file_of(platform::trace_format format);
// The same for a signal: its format's, or fault_kind.txt for the fault marker.
const char* filter_file_of(const platform::trace_signal& s);

// The save-file group a signal belongs to (one of the nine names above).
std::string wave_group_of(const platform::trace_signal& s);

// The save file's text for `dump_file` (a name in the same folder) holding
// `signals` (only the included ones are named); the view starts at `from`
// and spans `span` ticks. The card's RTL hierarchy is in GTKWave's tree
// (platform.card, opened), not in the groups.
std::string gtkw_text(const std::string& dump_file,
                      const std::vector<waves_writer::signal>& signals, simtime::ticks from,
                      simtime::ticks span);

// Writes NAME.gtkw and the filter files: each file F to path_of(F) (a .part
// name first, then renamed). False with *error set on failure.
bool write_gtkw(const std::function<std::string(const std::string&)>& path_of,
                const stereosim_fw_descriptor& firmware, const std::string& name,
                const std::string& dump_file, const std::vector<waves_writer::signal>& signals,
                simtime::ticks view_from, simtime::ticks view_span, std::string* error);

}  // namespace output
