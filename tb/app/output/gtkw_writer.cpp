#include "tb/app/output/gtkw_writer.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "dsp/card_regs.h"
#include "tb/app/faults/fault_spec.h"

namespace output {

using platform::trace_format;

namespace {

struct named_value {
    uint32_t value;
    const char* name;
};

// Byte offsets of dsp/card_regs.h (generated from rtl/card_regs.csv); the
// filter shows their word index EA[7:2].
const named_value card_registers[] = {
#include "tb/app/output/card_register_names.inc"
};

// VERDICT / sync-check cause bits (docs/card-registers.md).
const char* const cause_names[10] = {"L_WINDOW",   "R_WINDOW",  "L_DARK",        "R_DARK",
                                     "L_VSYNC",    "R_VSYNC",   "START_TIMEOUT", "OVERFLOW",
                                     "L_FRAME_ID", "R_FRAME_ID"};

std::string causes_text(unsigned v) {
    if (v == 0) return "ok";
    std::string s;
    for (int b = 0; b < 10; ++b) {
        if (!((v >> b) & 1u)) continue;
        if (!s.empty()) s += "|";
        s += cause_names[b];
    }
    return s;
}

bool write_file(const std::string& path, const std::string& text, std::string* error) {
    const std::string part = path + ".part";
    std::FILE* f = std::fopen(part.c_str(), "wb");
    if (!f) {
        if (error) *error = "cannot write " + part + ": " + std::strerror(errno);
        return false;
    }
    const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    const bool closed = std::fclose(f) == 0;
    if (!written || !closed || std::rename(part.c_str(), path.c_str()) != 0) {
        std::remove(part.c_str());
        if (error) *error = "cannot write " + path;
        return false;
    }
    return true;
}

}  // namespace

std::vector<translate_filter> translate_filters(const stereosim_fw_descriptor& firmware) {
    std::vector<translate_filter> filters;
    {
        // card_regs STATUS.STATE: 0 IDLE 1 OE_LOW 2 WAIT_VSYNC 3 RUN 4 HARD_ERROR
        filters.push_back({"oe_state.txt",
                           "# card OE controller state (rtl/oe_control.v, STATUS.STATE)\n"
                           "0 IDLE\n1 OE_LOW\n2 WAIT_VSYNC\n3 RUN\n4 HARD_ERROR\n"});
    }
    {
        std::string t = "# sync check causes / VERDICT bits 9..0 (docs/card-registers.md)\n";
        for (unsigned v = 0; v < 1024; ++v) t += std::to_string(v) + " " + causes_text(v) + "\n";
        filters.push_back({"verdict.txt", t});
    }
    {
        std::string t = "# card register on CE2: word index EA[7:2] (docs/card-registers.md)\n";
        for (const named_value& r : card_registers)
            t += std::to_string(r.value / 4) + " " + r.name + "\n";
        t += std::to_string(platform::register_no_access) + " (no access)\n";  // CE2 is high
        filters.push_back({"card_register.txt", t});
    }
    {
        std::string t = "# firmware stage (its descriptor's names); " +
                        std::to_string(platform::stage_idle) + ": no stage running\n";
        for (uint32_t s = 0; s < firmware.stage_count; ++s)
            t += std::to_string(s) + " " + firmware.stage_names[s] + "\n";
        t += std::to_string(platform::stage_idle) + " idle\n";
        filters.push_back({"firmware_stage.txt", t});
    }
    {
        std::string t = "# tracker state after the last pair (the firmware's descriptor)\n";
        for (uint32_t s = 0; s < firmware.tracker_state_count; ++s)
            t += std::to_string(s) + " " + firmware.tracker_state_names[s] + "\n";
        filters.push_back({"tracker_state.txt", t});
    }
    {
        // dsp/control_program.h: INT4-6 = EXT_INT4-6, INT8 = EDMA_INT, INT15 = TINT1.
        filters.push_back({"interrupt.txt",
                           "# CPU interrupt the firmware woke on (dsp/control_program.h)\n"
                           "0 none\n4 INT4_FRAME_READY\n5 INT5_SYNC_ERROR\n6 INT6_OVERFLOW\n"
                           "8 INT8_EDMA\n15 INT15_WATCHDOG\n255 stop\n"});
    }
    {
        std::string t =
            "# kind of the latest injected fault (docs/faults.md): 1 + fault_type\n0 none\n";
        for (int k = 0; k < faults::fault_type_count; ++k)
            t += std::to_string(k + 1) + " " +
                 faults::fault_type_name(static_cast<faults::fault_type>(k)) + "\n";
        filters.push_back({"fault_kind.txt", t});
    }
    return filters;
}

const char* filter_file_of(const platform::trace_signal& s) {
    if (is_fault_marker(s)) return "fault_kind.txt";
    return filter_file_of(s.format);
}

const char* filter_file_of(trace_format format) {
    switch (format) {
        case trace_format::oe_state:
            return "oe_state.txt";
        case trace_format::verdict:
            return "verdict.txt";
        case trace_format::card_register:
            return "card_register.txt";
        case trace_format::firmware_stage:
            return "firmware_stage.txt";
        case trace_format::tracker_state:
            return "tracker_state.txt";
        case trace_format::interrupt:
            return "interrupt.txt";
        case trace_format::bits:
        case trace_format::decimal:
            break;
    }
    return nullptr;
}

namespace {

const char* const group_order[] = {"sensor L", "sensor R", "sync check", "FIFOs",
                                   "card RTL", "EMIF",     "interrupts", "firmware stage and state",
                                   "faults"};

// A first view into the card's RTL hierarchy (the file holds all of it, in
// GTKWave's tree): sync_check's position counters and each stream's last
// frame identity, the OE controller, the left FIFO's pointers on both sides
// (rtl/sync_check.v, oe_control.v, async_fifo.v).
const platform::trace_signal card_rtl_view[] = {
    {"card.card_top.u_capture.u_check", "col_q", 16, trace_format::decimal},
    {"card.card_top.u_capture.u_check", "line_q", 16, trace_format::decimal},
    {"card.card_top.u_capture.u_check", "l_id_prev", 1, trace_format::bits},
    {"card.card_top.u_capture.u_check", "r_id_prev", 1, trace_format::bits},
    {"card.card_top.u_capture.u_check", "l_id_seen", 1, trace_format::bits},
    {"card.card_top.u_capture.u_check", "r_id_seen", 1, trace_format::bits},
    {"card.card_top.u_capture.u_oe", "state_q", 3, trace_format::oe_state},
    {"card.card_top.u_fifo_l", "wr_ptr", 18, trace_format::decimal},
    {"card.card_top.u_fifo_l", "rd_ptr", 18, trace_format::decimal},
};

}  // namespace

std::string wave_group_of(const platform::trace_signal& s) {
    if (s.scope == "sensor_L") return "sensor L";
    if (s.scope == "sensor_R") return "sensor R";
    if (s.scope == "card.sync_check" || (s.scope == "card" && s.name == "MCLK"))
        return "sync check";
    if (s.scope == "card.fifo") return "FIFOs";
    if (s.scope.rfind("card.card_top", 0) == 0) return "card RTL";
    if (s.scope == "emif" || s.scope == "card.emif_slave") return "EMIF";
    if (s.scope == "interrupts" || (s.scope == "card" && s.name.rfind("EXT_INT", 0) == 0))
        return "interrupts";
    if (is_fault_marker(s)) return "faults";
    return "firmware stage and state";
}

std::string gtkw_text(const std::string& dump_file, const std::vector<waves_writer::signal>& traced,
                      simtime::ticks from, simtime::ticks span) {
    std::vector<waves_writer::signal> signals = traced;
    for (const platform::trace_signal& rtl : card_rtl_view)
        signals.push_back({rtl, true, 0, waves_writer::full_name_of(rtl)});
    std::string t;
    t += "[*]\n[*] stereosim: one run's waveforms (docs/waveforms.md); paths are relative\n[*]\n";
    // GTKWave resolves a relative [dumpfile] through [savefile] (both in the
    // same folder), whatever the current directory; filters likewise.
    t += "[dumpfile] \"" + dump_file + "\"\n";
    t += "[savefile] \"" + dump_file.substr(0, dump_file.rfind('.')) + ".gtkw\"\n";
    t += "[timestart] " + std::to_string(simtime::to_fs(from)) + "\n";
    t += "[size] 1400 860\n[pos] -1 -1\n";
    // Zoom: measured with GTKWave 3.3.118 on a 1 fs timescale, a zoom z shows
    // 2^-z / 200 fs per pixel; fit `span` in the ~800 px of the wave pane.
    const double fs_per_pixel = static_cast<double>(simtime::to_fs(span)) / 800.0;
    char zoom[64];
    std::snprintf(zoom, sizeof zoom, "*%.6f %lld", -std::log2(200.0 * std::max(1.0, fs_per_pixel)),
                  static_cast<long long>(simtime::to_fs(from)));
    t += zoom;
    t += " -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1\n";
    t += "[treeopen] platform.\n[treeopen] platform.card.\n[sst_width] 200\n[signals_width] "
         "300\n[sst_expanded] 1\n"
         "[sst_vpaned_height] 200\n";
    int next_filter = 1;
    std::vector<std::pair<std::string, int>> filter_numbers;
    for (const char* group : group_order) {
        bool any = false;
        for (const waves_writer::signal& s : signals)
            any = any || (s.included && wave_group_of(s.info) == group);
        if (!any) continue;
        t += "@800200\n-";
        t += group;
        t += "\n";
        for (const waves_writer::signal& s : signals) {
            if (!s.included || wave_group_of(s.info) != group) continue;
            const char* filter = filter_file_of(s.info);
            if (filter) {
                int number = 0;
                for (const auto& f : filter_numbers)
                    if (f.first == filter) number = f.second;
                if (number == 0) {
                    number = next_filter++;
                    filter_numbers.emplace_back(filter, number);
                }
                // 0x2000 translated | 0x20 right-justified | 0x4 decimal
                t += "@2024\n^" + std::to_string(number) + " " + filter + "\n";
            } else if (s.info.format == trace_format::decimal) {
                t += "@24\n";
            } else if (s.info.width == 1) {
                t += "@28\n";
            } else {
                t += "@22\n";
            }
            t += s.full_name + "\n";
        }
        t += "@1000200\n-";
        t += group;
        t += "\n";
    }
    t += "[pattern_trace] 1\n[pattern_trace] 0\n";
    return t;
}

bool write_gtkw(const std::function<std::string(const std::string&)>& path_of,
                const stereosim_fw_descriptor& firmware, const std::string& name,
                const std::string& dump_file, const std::vector<waves_writer::signal>& signals,
                simtime::ticks view_from, simtime::ticks view_span, std::string* error) {
    for (const translate_filter& f : translate_filters(firmware))
        if (!write_file(path_of(f.file_name), f.text, error)) return false;
    return write_file(path_of(name + ".gtkw"), gtkw_text(dump_file, signals, view_from, view_span),
                      error);
}

}  // namespace output
