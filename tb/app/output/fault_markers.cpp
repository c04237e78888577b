#include "tb/app/output/fault_markers.h"

#include <stdio.h>  // getline, fseeko, ftello (POSIX)
#include <sys/types.h>

#include <algorithm>
#include <bitset>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <sstream>
#include <string_view>
#include <utility>

// fstapi itself is compiled into the program once, by Verilator's
// verilated_fst_c.cpp; only its declarations here.
#include "gtkwave/fstapi.h"

namespace output {

namespace {

// The marker as waves_writer declares it: platform.faults.kind [7:0].
const std::vector<std::string> marker_scope{"platform", "faults"};
constexpr std::string_view marker_name = "kind";
constexpr int marker_width = 8;
constexpr int no_change = -1;

// A value in the writers' text form, most significant bit first: "00000011".
std::string marker_bits(uint8_t value) {
    return std::bitset<marker_width>(value).to_string();
}

// A variable's name without its range: "kind [7:0]" -> "kind".
std::string_view base_name(std::string_view name) {
    return name.substr(0, std::min(name.find(' '), name.find('[')));
}

bool fail(std::string* why, const std::string& reason) {
    *why = reason;
    return false;  // for `return fail(why, "...")`
}

// Empty if the file declares the marker once, 8 bits wide, with a VCD code
// or FST handle of its own (`users` variables have it); else why not.
std::string marker_problem(int declared, int width, long users) {
    if (declared != 1)
        return declared == 0 ? "it declares no platform.faults.kind"
                             : "it declares platform.faults.kind more than once";
    if (width != marker_width) return "platform.faults.kind is not 8 bits wide";
    if (users != 1) return "platform.faults.kind shares its code with another signal";
    return "";
}

// ---- the marker's changes --------------------------------------------------------------------

struct marker_change {
    int64_t fs;
    uint8_t value;
};

// The marker's value changes in time order, handed out as the merge walks
// the file's times.
class marker_schedule {
  public:
    // last_fs: the file's last time; a marker after it is not written (the
    // file would have to grow past its end).
    marker_schedule(std::vector<fault_marker> markers, platform::tick_window window,
                    int64_t last_fs) {
        std::stable_sort(
            markers.begin(), markers.end(),
            [](const fault_marker& a, const fault_marker& b) { return a.tick < b.tick; });
        for (const fault_marker& m : markers) {
            if (m.tick < window.from) {
                m_initial = m.value;  // the latest before the window stands at its start
                continue;
            }
            const int64_t fs = simtime::to_fs(m.tick);
            if (m.tick >= window.to || fs > last_fs) break;
            // Several markers on one tick: the last one stands.
            if (!m_changes.empty() && m_changes.back().fs == fs) {
                m_changes.back().value = m.value;
            } else {
                m_changes.push_back({fs, m.value});
            }
        }
    }

    // False when the file would come out as it is.
    bool changes_file() const { return m_initial != 0 || !m_changes.empty(); }

    // Steps to the file's next time `fs`: each change strictly before it goes
    // to insert(at, value) as a time step of its own; returns the value that
    // joins `fs`, or no_change. The first time always gets a value: the one
    // from before the window, or the last change at or before it (nothing
    // can go before the file's first time).
    template <class insert_step>
    int step_to(int64_t fs, insert_step insert) {
        if (!m_started) {
            m_started = true;
            int value = m_initial;
            const size_t first = m_next;
            while (m_next < m_changes.size() && m_changes[m_next].fs <= fs)
                value = m_changes[m_next++].value;
            if (m_next > first) ++m_added;
            return value;
        }
        for (; m_next < m_changes.size() && m_changes[m_next].fs < fs; ++m_next, ++m_added)
            insert(m_changes[m_next].fs, m_changes[m_next].value);
        if (m_next < m_changes.size() && m_changes[m_next].fs == fs) {
            ++m_added;
            return m_changes[m_next++].value;
        }
        return no_change;
    }

    uint64_t added() const { return m_added; }

  private:
    uint8_t m_initial = 0;
    std::vector<marker_change> m_changes;
    size_t m_next = 0;
    bool m_started = false;
    uint64_t m_added = 0;
};

// PATH.markers: removed unless the merge renamed it over PATH, and only if
// the merge created it (never something that was there before).
struct temp_file {
    std::string path;
    bool created = false;
    bool renamed = false;

    ~temp_file() {
        if (created && !renamed) std::remove(path.c_str());
    }
};

// ---- VCD -------------------------------------------------------------------------------------

// What a VCD header says about the marker. Verilator writes one command a
// line, indented by depth ("  $scope module faults $end",
// "   $var wire  8 \" kind [7:0] $end"); it is read as a stream of tokens, so
// line breaks do not matter.
class vcd_header_scan {
  public:
    void take_line(std::string_view line) {
        std::istringstream tokens{std::string(line)};
        for (std::string token; tokens >> token;) take_token(std::move(token));
    }

    bool finished() const { return m_finished; }
    const std::string& marker_code() const { return m_marker_code; }

    // Empty if the marker can be merged in, else why not.
    std::string problem() const {
        if (!m_finished) return "no $enddefinitions, not a VCD";
        if (m_timescale != "1fs") return "its timescale is '" + m_timescale + "', not 1fs";
        return marker_problem(m_markers, m_marker_width,
                              std::count(m_codes.begin(), m_codes.end(), m_marker_code));
    }

  private:
    void take_token(std::string token) {
        if (m_command.empty()) {
            if (token[0] == '$') m_command = std::move(token);
        } else if (token != "$end") {
            m_args.push_back(std::move(token));
        } else {
            finish_command();
            m_command.clear();
            m_args.clear();
        }
    }

    void finish_command() {
        if (m_command == "$scope" && m_args.size() >= 2) {
            m_scopes.push_back(m_args[1]);  // $scope module NAME $end
        } else if (m_command == "$upscope" && !m_scopes.empty()) {
            m_scopes.pop_back();
        } else if (m_command == "$var" && m_args.size() >= 4) {
            // $var TYPE WIDTH CODE NAME [RANGE] $end
            m_codes.push_back(m_args[2]);
            if (m_scopes == marker_scope && base_name(m_args[3]) == marker_name) {
                ++m_markers;
                m_marker_code = m_args[2];
                m_marker_width = std::atoi(m_args[1].c_str());
            }
        } else if (m_command == "$timescale") {
            m_timescale.clear();
            for (const std::string& a : m_args) m_timescale += a;  // "1fs" or "1 fs"
        } else if (m_command == "$enddefinitions") {
            m_finished = true;
        }
    }

    std::string m_command;  // the command being read, "" between commands
    std::vector<std::string> m_args;
    std::vector<std::string> m_scopes;
    std::vector<std::string> m_codes;  // every variable's code, to find a shared one
    std::string m_timescale;
    std::string m_marker_code;
    int m_marker_width = 0;
    int m_markers = 0;
    bool m_finished = false;
};

// The identifier code a value line names ("b00000011 \"" -> "\"",
// "1#" -> "#"), empty for any other line.
std::string_view vcd_value_code(std::string_view line) {
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.remove_suffix(1);
    if (line.empty()) return {};
    // A vector, real or string: "b0101 CODE"; a bit: "1CODE".
    if (std::string_view("bBrRsS").find(line[0]) != std::string_view::npos) {
        const size_t space = line.find(' ');
        return space == std::string_view::npos ? std::string_view() : line.substr(space + 1);
    }
    if (std::string_view("01xXzZ").find(line[0]) != std::string_view::npos) return line.substr(1);
    return {};
}

// "#123" -> 123; false if the line is not a time.
bool parse_vcd_time(std::string_view line, int64_t* fs) {
    size_t i = 1;
    int64_t t = 0;
    for (; i < line.size() && line[i] >= '0' && line[i] <= '9'; ++i) t = t * 10 + (line[i] - '0');
    *fs = t;
    return i > 1 && (i == line.size() || std::isspace(static_cast<unsigned char>(line[i])));
}

// Reads lines of any length without a copy per line.
class line_reader {
  public:
    explicit line_reader(std::FILE* in) : m_in(in) {}
    ~line_reader() { std::free(m_buffer); }
    line_reader(const line_reader&) = delete;
    line_reader& operator=(const line_reader&) = delete;

    bool next() {
        m_length = getline(&m_buffer, &m_capacity, m_in);
        return m_length > 0;
    }
    std::string_view line() const { return {m_buffer, static_cast<size_t>(m_length)}; }

  private:
    std::FILE* m_in;
    char* m_buffer = nullptr;
    size_t m_capacity = 0;
    ssize_t m_length = 0;
};

// The last time of a VCD body, read backwards from the end so a marker after
// it is known before the copy starts. Only time lines start with '#'. False
// if the body has no time.
bool find_last_vcd_time(std::FILE* in, off_t body_start, int64_t* last_fs) {
    if (fseeko(in, 0, SEEK_END) != 0) return false;
    constexpr off_t chunk = 1 << 16;
    std::vector<char> buffer(chunk + 1);
    // body_start > 0 follows a '\n', so a chunk read from one byte earlier
    // tells whether its first '#' starts a line.
    for (off_t end = ftello(in); end > body_start;) {
        const off_t begin = std::max(body_start, end - chunk);
        const size_t size = static_cast<size_t>(end - begin + 1);
        if (fseeko(in, begin - 1, SEEK_SET) != 0 || std::fread(buffer.data(), 1, size, in) != size)
            return false;
        for (size_t i = size - 1; i >= 1; --i) {
            if (buffer[i] != '#' || buffer[i - 1] != '\n') continue;
            if (fseeko(in, begin - 1 + static_cast<off_t>(i), SEEK_SET) != 0) return false;
            line_reader lines(in);
            return lines.next() && parse_vcd_time(lines.line(), last_fs);
        }
        end = begin;
    }
    return false;
}

// A VCD as Verilator's VerilatedVcdC writes it, copied with the marker's
// changes merged in.
class vcd_marker_merge {
  public:
    vcd_marker_merge() = default;
    ~vcd_marker_merge() {
        if (m_in) std::fclose(m_in);
        if (m_out) std::fclose(m_out);
    }
    vcd_marker_merge(const vcd_marker_merge&) = delete;
    vcd_marker_merge& operator=(const vcd_marker_merge&) = delete;

    // Reads the header and the last time; false + *why if the file cannot
    // take the marker.
    bool open(const std::string& path, std::string* why) {
        m_in = std::fopen(path.c_str(), "rb");
        if (!m_in) return fail(why, std::strerror(errno));
        vcd_header_scan header;
        line_reader lines(m_in);
        while (!header.finished() && lines.next()) {
            header.take_line(lines.line());
            m_header.append(lines.line());
        }
        if (std::ferror(m_in)) return fail(why, "read error");
        const std::string problem = header.problem();
        if (!problem.empty()) return fail(why, problem);
        m_code = header.marker_code();
        m_body_start = ftello(m_in);
        if (!find_last_vcd_time(m_in, m_body_start, &m_last_fs)) m_last_fs = -1;
        if (std::ferror(m_in)) return fail(why, "read error");
        return true;
    }

    // The file's last time, -1 if it has none.
    int64_t last_fs() const { return m_last_fs; }

    // Writes the merged file to `temp`.
    bool write(temp_file& temp, marker_schedule& schedule, std::string* why) {
        m_out = std::fopen(temp.path.c_str(), "wb");
        if (!m_out) return fail(why, "cannot create " + temp.path + ": " + std::strerror(errno));
        temp.created = true;
        std::setvbuf(m_out, nullptr, _IOFBF, 1 << 20);
        put(m_header);
        if (fseeko(m_in, m_body_start, SEEK_SET) != 0) return fail(why, "cannot seek");
        line_reader lines(m_in);
        while (lines.next()) {
            const std::string_view line = lines.line();
            if (line[0] == '#') {
                put_first_value();  // the first time had no marker line
                if (!copy_time(line, schedule)) return fail(why, "bad time line");
            } else if (vcd_value_code(line) != m_code) {
                put(line);
            } else {
                // The file's own marker value: the first becomes the start
                // value, in its place; a later one (none in a file
                // waves_writer wrote) goes, the schedule's stand.
                put_first_value();
            }
        }
        put_first_value();
        if (std::ferror(m_in)) return fail(why, "read error");
        const bool closed = std::fclose(m_out) == 0;
        m_out = nullptr;
        if (!closed || !m_write_ok) return fail(why, "cannot write " + temp.path);
        return true;
    }

  private:
    bool copy_time(std::string_view line, marker_schedule& schedule) {
        int64_t fs = 0;
        if (!parse_vcd_time(line, &fs)) return false;
        const int joined = schedule.step_to(fs, [this](int64_t at, uint8_t value) {
            put("#" + std::to_string(at) + "\n");
            put_marker(value);
        });
        put(line);
        if (line.back() != '\n') put("\n");
        if (!m_seen_time) {
            m_seen_time = true;
            m_first_value = joined;  // written where the file has the marker's value
        } else if (joined != no_change) {
            put_marker(static_cast<uint8_t>(joined));
        }
        return true;
    }

    void put_first_value() {
        if (m_first_value == no_change) return;
        put_marker(static_cast<uint8_t>(m_first_value));
        m_first_value = no_change;
    }

    // As Verilator writes an 8-bit bus: every bit, a space, the code.
    void put_marker(uint8_t value) { put("b" + marker_bits(value) + " " + m_code + "\n"); }

    void put(std::string_view text) {
        if (std::fwrite(text.data(), 1, text.size(), m_out) != text.size()) m_write_ok = false;
    }

    std::FILE* m_in = nullptr;
    std::FILE* m_out = nullptr;
    std::string m_header;  // up to and including the $enddefinitions line
    std::string m_code;    // the marker's identifier code
    off_t m_body_start = 0;
    int64_t m_last_fs = -1;
    bool m_seen_time = false;
    int m_first_value = no_change;  // the value at the first time, until written
    bool m_write_ok = true;
};

bool merge_vcd(const std::string& path, temp_file& temp, platform::tick_window window,
               std::vector<fault_marker> markers, uint64_t* added, std::string* why) {
    vcd_marker_merge vcd;
    if (!vcd.open(path, why)) return false;
    if (vcd.last_fs() < 0) return true;  // no time to put a value at
    marker_schedule schedule(std::move(markers), window, vcd.last_fs());
    if (!schedule.changes_file()) return true;
    if (!vcd.write(temp, schedule, why)) return false;
    *added = schedule.added();
    return true;
}

// ---- FST -------------------------------------------------------------------------------------

using fst_reader = std::unique_ptr<void, decltype(&fstReaderClose)>;

// The marker's handle; false + *why unless the hierarchy has it once,
// 8 bits wide, with a handle no other variable shares.
bool find_fst_marker(void* reader, fstHandle* marker, std::string* why) {
    std::vector<std::string> scopes;
    std::vector<fstHandle> handles;  // every variable's, to find a shared one
    int found = 0;
    uint32_t width = 0;
    while (const fstHier* h = fstReaderIterateHier(reader)) {
        if (h->htyp == FST_HT_SCOPE) {
            scopes.emplace_back(h->u.scope.name);
        } else if (h->htyp == FST_HT_UPSCOPE && !scopes.empty()) {
            scopes.pop_back();
        } else if (h->htyp == FST_HT_VAR) {
            handles.push_back(h->u.var.handle);
            if (scopes == marker_scope && base_name(h->u.var.name) == marker_name) {
                ++found;
                *marker = h->u.var.handle;
                width = h->u.var.length;
            }
        }
    }
    fstReaderIterateHierRewind(reader);
    *why = marker_problem(found, static_cast<int>(width),
                          std::count(handles.begin(), handles.end(), *marker));
    return why->empty();
}

void copy_fst_header(void* reader, void* writer) {
    fstWriterSetPackType(writer, FST_WR_PT_LZ4);  // as VerilatedFst writes
    fstWriterSetTimescale(writer, fstReaderGetTimescale(reader));
    fstWriterSetTimezero(writer, fstReaderGetTimezero(reader));
    fstWriterSetFileType(writer, static_cast<fstFileType>(fstReaderGetFileType(reader)));
    if (const char* version = fstReaderGetVersionString(reader))
        fstWriterSetVersion(writer, version);
    if (const char* date = fstReaderGetDateString(reader)) fstWriterSetDate(writer, date);
}

void copy_fst_var(void* writer, const fstHier& h, std::vector<fstHandle>* handles) {
    const auto& var = h.u.var;
    // The reader reports a port's width in bits; the writer takes it as stored.
    const uint32_t length = var.typ == FST_VT_VCD_PORT ? var.length * 3 + 2 : var.length;
    const fstHandle alias = var.is_alias ? (*handles)[var.handle] : 0;
    const fstHandle created =
        fstWriterCreateVar(writer, static_cast<fstVarType>(var.typ),
                           static_cast<fstVarDir>(var.direction), length, var.name, alias);
    if (!var.is_alias) (*handles)[var.handle] = created;
}

// Copies the hierarchy as it is: scopes, attributes (enum tables among
// them), variables and their aliases. (*handles)[reader's] = writer's.
void copy_fst_hierarchy(void* reader, void* writer, std::vector<fstHandle>* handles) {
    handles->assign(static_cast<size_t>(fstReaderGetMaxHandle(reader)) + 1, 0);
    while (const fstHier* h = fstReaderIterateHier(reader)) {
        if (h->htyp == FST_HT_SCOPE) {
            fstWriterSetScope(writer, static_cast<fstScopeType>(h->u.scope.typ), h->u.scope.name,
                              h->u.scope.component);
        } else if (h->htyp == FST_HT_UPSCOPE) {
            fstWriterSetUpscope(writer);
        } else if (h->htyp == FST_HT_ATTRBEGIN) {
            fstWriterSetAttrBegin(writer, static_cast<fstAttrType>(h->u.attr.typ),
                                  h->u.attr.subtype, h->u.attr.name, h->u.attr.arg);
        } else if (h->htyp == FST_HT_ATTREND) {
            fstWriterSetAttrEnd(writer);
        } else if (h->htyp == FST_HT_VAR) {
            copy_fst_var(writer, *h, handles);
        }
    }
}

// The reader's value changes (in time order) to the writer, the marker's
// replaced by the schedule's.
class fst_value_copy {
  public:
    fst_value_copy(void* writer, const std::vector<fstHandle>& handles, fstHandle marker,
                   marker_schedule& schedule)
        : m_writer(writer), m_handles(handles), m_marker(marker), m_schedule(schedule) {}

    static void on_value(void* self, uint64_t time, fstHandle fac, const unsigned char* value) {
        auto& copy = *static_cast<fst_value_copy*>(self);
        copy.advance(time);
        if (fac != copy.m_marker)
            fstWriterEmitValueChange(copy.m_writer, copy.m_handles[fac], value);
    }

    static void on_varlen(void* self, uint64_t time, fstHandle fac, const unsigned char* value,
                          uint32_t length) {
        auto& copy = *static_cast<fst_value_copy*>(self);
        copy.advance(time);
        if (fac != copy.m_marker)
            fstWriterEmitVariableLengthValueChange(copy.m_writer, copy.m_handles[fac], value,
                                                   length);
    }

    // The file's end time, a time step of its own if no change is at it
    // (a viewer shows the file up to it).
    void finish(uint64_t end_time) { advance(end_time); }

  private:
    void advance(uint64_t time) {
        if (m_started && time <= m_time) return;
        const int joined =
            m_schedule.step_to(static_cast<int64_t>(time), [this](int64_t at, uint8_t value) {
                emit_time(static_cast<uint64_t>(at));
                emit_marker(value);
            });
        emit_time(time);
        if (joined != no_change) emit_marker(static_cast<uint8_t>(joined));
    }

    void emit_time(uint64_t time) {
        fstWriterEmitTimeChange(m_writer, time);
        m_time = time;
        m_started = true;
    }

    void emit_marker(uint8_t value) {
        fstWriterEmitValueChange(m_writer, m_handles[m_marker], marker_bits(value).c_str());
    }

    void* m_writer;
    const std::vector<fstHandle>& m_handles;
    fstHandle m_marker;  // the reader's handle
    marker_schedule& m_schedule;
    uint64_t m_time = 0;
    bool m_started = false;
};

bool merge_fst(const std::string& path, temp_file& temp, platform::tick_window window,
               std::vector<fault_marker> markers, uint64_t* added, std::string* why) {
    std::FILE* exists = std::fopen(path.c_str(), "rb");  // fstReaderOpen does not say why
    if (!exists) return fail(why, std::strerror(errno));
    std::fclose(exists);
    const fst_reader reader(fstReaderOpen(path.c_str()), &fstReaderClose);
    if (!reader) return fail(why, "not an FST file");
    void* const r = reader.get();
    if (fstReaderGetTimescale(r) != -15) return fail(why, "its timescale is not 1fs");
    fstHandle marker = 0;
    if (!find_fst_marker(r, &marker, why)) return false;
    const uint64_t end_time = fstReaderGetEndTime(r);
    marker_schedule schedule(std::move(markers), window, static_cast<int64_t>(end_time));
    if (!schedule.changes_file()) return true;

    void* const writer = fstWriterCreate(temp.path.c_str(), 1);
    if (!writer) return fail(why, "cannot create " + temp.path + ": " + std::strerror(errno));
    temp.created = true;
    copy_fst_header(r, writer);
    std::vector<fstHandle> handles;
    copy_fst_hierarchy(r, writer, &handles);
    fst_value_copy copy(writer, handles, marker, schedule);
    fstReaderSetFacProcessMaskAll(r);
    fstReaderIterBlocksSetNativeDoublesOnCallback(r, 1);  // a real as the writer takes it
    const bool read = fstReaderIterBlocks2(r, &fst_value_copy::on_value, &fst_value_copy::on_varlen,
                                           &copy, nullptr) != 0;
    if (read) copy.finish(end_time);
    const bool seek_failed = fstWriterGetFseekFailed(writer) != 0;
    fstWriterClose(writer);
    if (!read) return fail(why, "cannot read its value changes");
    // The writer reports no write error: the file must read back, ending
    // where the original did.
    const fst_reader written(seek_failed ? nullptr : fstReaderOpen(temp.path.c_str()),
                             &fstReaderClose);
    if (!written || fstReaderGetEndTime(written.get()) != end_time)
        return fail(why, "cannot write " + temp.path);
    *added = schedule.added();
    return true;
}

}  // namespace

bool add_fault_markers(const std::string& path, waves_format format, platform::tick_window window,
                       std::vector<fault_marker> markers, uint64_t* added, std::string* error) {
    uint64_t written = 0;
    temp_file temp{path + ".markers"};
    std::string why;
    bool ok = format == waves_format::fst
                  ? merge_fst(path, temp, window, std::move(markers), &written, &why)
                  : merge_vcd(path, temp, window, std::move(markers), &written, &why);
    if (ok && temp.created) {  // else nothing to change: PATH stays as it is
        temp.renamed = std::rename(temp.path.c_str(), path.c_str()) == 0;
        if (!temp.renamed)
            ok = fail(&why, "cannot rename " + temp.path + ": " + std::strerror(errno));
    }
    if (!ok) {
        if (error) *error = "cannot add fault markers to " + path + ": " + why;
        return false;
    }
    if (added) *added = written;
    return true;
}

}  // namespace output
