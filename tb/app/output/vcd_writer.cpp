#include "tb/app/output/vcd_writer.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

namespace output {

using platform::trace_group;
using simtime::ticks;

namespace {

// VCD identifier codes: printable ASCII 33..126, shortest first.
std::string code_of(size_t index) {
    std::string code;
    do {
        code.push_back(static_cast<char>(33 + index % 94));
        index /= 94;
    } while (index > 0);
    return code;
}

void append_u64(std::string& out, uint64_t v) {
    char digits[24];
    int n = 0;
    do {
        digits[n++] = static_cast<char>('0' + v % 10);
        v /= 10;
    } while (v > 0);
    while (n > 0) out.push_back(digits[--n]);
}

}  // namespace

vcd_writer::vcd_writer(platform::tick_window window, unsigned groups)
    : m_window(window), m_groups(groups) {
    m_buffer.reserve(1 << 20);
}

bool vcd_writer::open(const std::string& path) {
    m_path = path;
    m_file = std::fopen((m_path + ".part").c_str(), "wb");
    if (!m_file) m_error = "cannot write " + m_path + ".part: " + std::strerror(errno);
    return m_file != nullptr;
}

vcd_writer::~vcd_writer() {
    if (m_file) {
        // Not finished: a failed run leaves no VCD behind.
        std::fclose(m_file);
        std::remove((m_path + ".part").c_str());
    }
}

platform::trace_id vcd_writer::declare(const platform::trace_signal& s) {
    // The source's ids are indices into m_signals: the marker, declared
    // last, must stay after them.
    if (m_marker != SIZE_MAX) return static_cast<platform::trace_id>(m_signals.size());
    signal sig;
    sig.info = s;
    sig.included = (trace_group_of_scope(s.scope) & m_groups) != 0;
    sig.full_name = "platform." + s.scope + "." + s.name;
    if (s.width > 1) sig.full_name += "[" + std::to_string(s.width - 1) + ":0]";
    m_signals.push_back(sig);
    m_value.push_back(0);
    m_state.push_back(0);
    return static_cast<platform::trace_id>(m_signals.size() - 1);
}

void vcd_writer::declare_fault_marker() {
    if (m_marker != SIZE_MAX) return;
    signal sig;
    sig.info = fault_marker_signal();
    sig.included = true;  // a fault is worth seeing whatever the scope
    sig.full_name = "platform." + sig.info.scope + "." + sig.info.name + "[7:0]";
    m_signals.push_back(sig);
    m_value.push_back(0);  // no fault yet
    m_state.push_back(1);
    m_marker = m_signals.size() - 1;
}

void vcd_writer::write_header() {
    declare_fault_marker();
    m_header_written = true;
    size_t next_code = 0;
    for (signal& s : m_signals)
        if (s.included) s.code = code_of(next_code++);
    m_buffer +=
        "$version stereosim (tb/app/output/vcd_writer) $end\n"
        "$comment 1 tick = 1/18 ns; each time is its tick rounded to the nearest fs once "
        "(simtime::to_fs), as SystemC times are $end\n"
        "$timescale 1fs $end\n"
        "$scope module platform $end\n";
    // Scopes as a tree, in the order of first declaration.
    std::vector<std::string> open;  // components of the scope path currently open
    std::vector<std::string> order;
    for (const signal& s : m_signals)
        if (s.included && (order.empty() || order.back() != s.info.scope)) {
            bool seen = false;
            for (const std::string& o : order) seen = seen || o == s.info.scope;
            if (!seen) order.push_back(s.info.scope);
        }
    // Sort scopes so children follow their parent (stable: first-declared order otherwise).
    std::vector<std::string> sorted;
    for (const std::string& scope : order) {
        if (std::find(sorted.begin(), sorted.end(), scope) != sorted.end()) continue;
        sorted.push_back(scope);
        for (const std::string& child : order)
            if (child.rfind(scope + ".", 0) == 0 &&
                std::find(sorted.begin(), sorted.end(), child) == sorted.end())
                sorted.push_back(child);
    }
    for (const std::string& scope : sorted) {
        std::vector<std::string> parts;
        for (size_t b = 0;;) {
            const size_t e = scope.find('.', b);
            parts.push_back(scope.substr(b, e == std::string::npos ? std::string::npos : e - b));
            if (e == std::string::npos) break;
            b = e + 1;
        }
        size_t common = 0;
        while (common < open.size() && common < parts.size() && open[common] == parts[common])
            ++common;
        while (open.size() > common) {
            m_buffer += "$upscope $end\n";
            open.pop_back();
        }
        for (size_t i = common; i < parts.size(); ++i) {
            m_buffer += "$scope module " + parts[i] + " $end\n";
            open.push_back(parts[i]);
        }
        for (const signal& s : m_signals) {
            if (!s.included || s.info.scope != scope) continue;
            m_buffer +=
                "$var wire " + std::to_string(s.info.width) + " " + s.code + " " + s.info.name;
            if (s.info.width > 1) m_buffer += " [" + std::to_string(s.info.width - 1) + ":0]";
            m_buffer += " $end\n";
        }
    }
    while (!open.empty()) {
        m_buffer += "$upscope $end\n";
        open.pop_back();
    }
    m_buffer += "$upscope $end\n$enddefinitions $end\n";
    // The values at the window start.
    m_buffer += "#";
    append_u64(m_buffer, static_cast<uint64_t>(simtime::to_fs(m_window.from)));
    m_buffer += "\n$dumpvars\n";
    m_time = m_window.from;
    for (size_t i = 0; i < m_signals.size(); ++i)
        if (m_signals[i].included) write_value(i);
    m_buffer += "$end\n";
}

void vcd_writer::write_value(size_t i) {
    const signal& s = m_signals[i];
    const uint8_t state = m_state[i];
    if (s.info.width == 1) {
        m_buffer.push_back(state == 0 ? 'x' : state == 2 ? 'z' : (m_value[i] & 1) ? '1' : '0');
    } else {
        m_buffer.push_back('b');
        if (state != 1) {
            m_buffer.push_back(state == 0 ? 'x' : 'z');
        } else {
            const uint64_t v = m_value[i];
            int top = 63;
            while (top > 0 && !((v >> top) & 1)) --top;
            for (int b = top; b >= 0; --b) m_buffer.push_back(((v >> b) & 1) ? '1' : '0');
        }
        m_buffer.push_back(' ');
    }
    m_buffer += s.code;
    m_buffer.push_back('\n');
    ++m_changes;
    if (m_buffer.size() >= (1u << 20)) flush_buffer();
}

void vcd_writer::set_time(ticks t) {
    if (t < m_time) {
        ++m_out_of_order;
        return;
    }
    if (t == m_time) return;
    m_time = t;
    m_buffer.push_back('#');
    append_u64(m_buffer, static_cast<uint64_t>(simtime::to_fs(t)));
    m_buffer.push_back('\n');
}

void vcd_writer::change(ticks t, platform::trace_id id, uint64_t value) {
    if (m_finished || !m_window.contains(t) || id >= m_signals.size()) return;
    const int width = m_signals[id].info.width;
    if (width < 64) value &= (uint64_t{1} << width) - 1;
    if (!m_header_written) {
        if (t == m_window.from) {  // part of the snapshot
            m_value[id] = value;
            m_state[id] = 1;
            return;
        }
        write_header();
    }
    // (write_header() adds the fault marker: no reference into m_signals across it.)
    if (!m_signals[id].included || (m_state[id] == 1 && m_value[id] == value)) return;
    m_value[id] = value;
    m_state[id] = 1;
    set_time(t);
    write_value(id);
}

void vcd_writer::release(ticks t, platform::trace_id id) {
    if (m_finished || !m_window.contains(t) || id >= m_signals.size()) return;
    if (!m_header_written) {
        if (t == m_window.from) {
            m_state[id] = 2;
            return;
        }
        write_header();
    }
    if (!m_signals[id].included || m_state[id] == 2) return;
    m_state[id] = 2;
    set_time(t);
    write_value(id);
}

void vcd_writer::flush_buffer() {
    if (!m_file) return;  // not opened yet: keep it
    if (!m_buffer.empty()) {
        if (std::fwrite(m_buffer.data(), 1, m_buffer.size(), m_file) != m_buffer.size() &&
            m_error.empty())
            m_error = "cannot write " + m_path + ".part: " + std::strerror(errno);
        m_bytes += m_buffer.size();
    }
    m_buffer.clear();
}

void vcd_writer::finish(ticks end) {
    if (m_finished) return;
    if (!m_header_written) write_header();
    m_finished = true;
    // The end of the window (or of the run) as the last time, so a viewer
    // shows the whole window.
    const ticks last = std::min(end, m_window.to);
    if (last > m_time) {
        m_buffer.push_back('#');
        append_u64(m_buffer, static_cast<uint64_t>(simtime::to_fs(last)));
        m_buffer.push_back('\n');
        m_time = last;
    }
    flush_buffer();
    if (!m_file) {
        if (m_error.empty()) m_error = "the VCD was never opened";
        return;
    }
    const bool closed = std::fclose(m_file) == 0;
    m_file = nullptr;
    const std::string part = m_path + ".part";
    if (!closed && m_error.empty()) m_error = "cannot write " + part;
    if (!m_error.empty() || std::rename(part.c_str(), m_path.c_str()) != 0) {
        if (m_error.empty()) m_error = "cannot rename " + part + " to " + m_path;
        std::remove(part.c_str());
    }
}

namespace {

std::string marker_line(uint8_t value, const std::string& code) {
    std::string line = "b";
    int top = 7;
    while (top > 0 && !((value >> top) & 1)) --top;
    for (int b = top; b >= 0; --b) line.push_back(((value >> b) & 1) ? '1' : '0');
    return line + " " + code + "\n";
}

// Copies a finished VCD line by line: header and $dumpvars as they are (the
// marker's dumped value replaced by `initial`), each onset of
// markers[next, end) inserted before the first later time.
class marker_splicer {
  public:
    marker_splicer(const std::vector<fault_marker>& markers, size_t next, size_t end,
                   const std::string& code, uint8_t initial, int64_t window_from_fs)
        : m_markers(markers),
          m_next(next),
          m_end(end),
          m_code(code),
          m_dumped(marker_line(0, code)),
          m_initial(initial),
          m_window_from_fs(window_from_fs) {
        m_buffer.reserve(1 << 20);
    }

    // False if a write failed.
    bool copy(std::FILE* in, std::FILE* out) {
        m_out = out;
        char chunk[4096];
        std::string line;
        while (std::fgets(chunk, sizeof chunk, in)) {
            line += chunk;
            if (line.back() != '\n' && !std::feof(in)) continue;  // a longer line: read on
            take(line);
            line.clear();
        }
        m_buffer += line;
        flush();
        return m_write_ok;
    }

    uint64_t added() const { return m_added; }
    uint64_t bytes() const { return m_bytes; }

  private:
    // One whole line of the source.
    void take(std::string& line) {
        if (m_in_dumpvars) {
            if (line == m_dumped) {
                line = marker_line(m_initial, m_code);
            } else if (line.rfind("$end", 0) == 0) {
                m_in_dumpvars = false;
                m_in_body = true;
                m_buffer += line;
                // An onset at the window start: a change right after the snapshot.
                emit_markers_up_to(m_window_from_fs, true);
                return;
            }
        } else if (!m_in_body) {
            if (line.rfind("$dumpvars", 0) == 0) m_in_dumpvars = true;
        } else if (line[0] == '#') {
            const int64_t fs = std::stoll(line.substr(1));
            // Markers strictly between the previous time and this one.
            emit_markers_up_to(fs - 1, false);
            m_buffer += line;
            emit_markers_up_to(fs, true);
            if (m_buffer.size() >= (1u << 20)) flush();
            return;
        }
        m_buffer += line;
        if (m_buffer.size() >= (1u << 20)) flush();
    }

    void emit_markers_up_to(int64_t fs, bool same_time_written) {
        // Onsets before `fs` get their own time; one at `fs` joins that time.
        while (m_next < m_end && simtime::to_fs(m_markers[m_next].tick) <= fs) {
            const int64_t at = simtime::to_fs(m_markers[m_next].tick);
            if (at < fs || !same_time_written) {
                m_buffer.push_back('#');
                append_u64(m_buffer, static_cast<uint64_t>(at));
                m_buffer.push_back('\n');
            }
            // Several onsets on one tick: the last one's kind stands.
            while (m_next + 1 < m_end && m_markers[m_next + 1].tick == m_markers[m_next].tick)
                ++m_next;
            m_buffer += marker_line(m_markers[m_next].value, m_code);
            ++m_added;
            ++m_next;
        }
    }

    void flush() {
        if (std::fwrite(m_buffer.data(), 1, m_buffer.size(), m_out) != m_buffer.size())
            m_write_ok = false;
        m_bytes += m_buffer.size();
        m_buffer.clear();
    }

    const std::vector<fault_marker>& m_markers;
    size_t m_next, m_end;
    const std::string& m_code;
    const std::string m_dumped;  // the marker's line in $dumpvars
    const uint8_t m_initial;
    const int64_t m_window_from_fs;
    std::FILE* m_out = nullptr;
    std::string m_buffer;
    bool m_in_body = false, m_in_dumpvars = false, m_write_ok = true;
    uint64_t m_added = 0, m_bytes = 0;
};

}  // namespace

bool vcd_writer::add_fault_markers(std::vector<fault_marker> markers) {
    if (!m_finished || !ok() || m_marker == SIZE_MAX) {
        if (m_error.empty()) m_error = "fault markers need a finished VCD";
        return false;
    }
    std::stable_sort(markers.begin(), markers.end(),
                     [](const fault_marker& a, const fault_marker& b) { return a.tick < b.tick; });
    // The value at the window start: the latest fault before it.
    uint8_t initial = 0;
    size_t next = 0;
    while (next < markers.size() && markers[next].tick < m_window.from)
        initial = markers[next++].value;
    // Only onsets inside what the file covers: [from, the last time written).
    size_t end = next;
    while (end < markers.size() && markers[end].tick < m_window.to && markers[end].tick < m_time)
        ++end;
    if (initial == 0 && next == end) return true;  // nothing changes the file

    const std::string temp = m_path + ".markers";
    std::FILE* in = std::fopen(m_path.c_str(), "rb");
    std::FILE* out = in ? std::fopen(temp.c_str(), "wb") : nullptr;
    if (!in || !out) {
        m_error = "cannot add fault markers to " + m_path + ": " + std::strerror(errno);
        if (in) std::fclose(in);
        return false;
    }
    marker_splicer splicer(markers, next, end, m_signals[m_marker].code, initial,
                           simtime::to_fs(m_window.from));
    const bool write_ok = splicer.copy(in, out);
    const bool read_ok = !std::ferror(in);
    std::fclose(in);
    const bool closed = std::fclose(out) == 0;
    if (!read_ok || !write_ok || !closed || std::rename(temp.c_str(), m_path.c_str()) != 0) {
        m_error = "cannot add fault markers to " + m_path;
        std::remove(temp.c_str());
        return false;
    }
    m_changes += splicer.added();
    m_bytes = splicer.bytes();
    return true;
}

}  // namespace output
