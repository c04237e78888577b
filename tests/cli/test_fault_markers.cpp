// Fault markers merged into a finished waveform (tb/app/output/fault_markers.h)
// on files Verilator's own writers produce: a small FST / VCD written by
// VerilatedFstC / VerilatedVcdC through trace hooks the way waves_writer
// writes its signals (platform.faults.kind among them, 0 from the first time
// on), then add_fault_markers() and a read back. An FST is read back as the
// VCD text GTKWave's fst2vcd prints (same fstapi calls, in process).
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "gtkwave/fstapi.h"
#include "model/time/ticks.h"
#include "tb/app/output/fault_markers.h"
#include "verilated.h"
#include "verilated_fst_c.h"
#include "verilated_vcd_c.h"

namespace {

using output::fault_marker;
using output::waves_format;
using simtime::ticks;
using simtime::to_fs;

// The window the file was written for, and the ticks it has times at: the
// run ended (18400) before the window's end.
const platform::tick_window window{18000, 19000};
const ticks dump_ticks[] = {18000, 18100, 18200, 18300, 18400};
const char marker_name[] = "platform.faults.kind";

// ---- a small waveform through Verilator's writers ------------------------------------------

// Offsets from the init callback's base code (a double takes two). The
// marker last, as waves_writer declares it.
enum signal_code : uint32_t {
    pclk_code = 0,
    data_code = 1,
    count_code = 2,
    level_code = 3,
    state_code = 5,
    kind_code = 6,
};

struct trace_source {
    bool with_marker = true;
    uint32_t base = 0;
    uint8_t pclk = 0;
    uint16_t data = 0;
    uint32_t count = 0;
    double level = 0;
    uint8_t state = 0;
};

void declare(VerilatedFst* t, const trace_source& s) {
    const uint32_t b = s.base;
    const auto dir = FST_VD_IMPLICIT;
    const auto wire = FST_VT_VCD_WIRE;
    t->declBit(b + pclk_code, "sensor_L PCLK", -1, dir, wire, false, -1);
    t->declBus(b + data_code, "sensor_L DATA", -1, dir, wire, false, -1, 9, 0);
    t->declBus(b + count_code, "card count", -1, dir, wire, false, -1, 31, 0);
    t->declDouble(b + level_code, "card level", -1, dir, FST_VT_VCD_REAL, false, -1);
    // An enum table, an attribute the merge must carry over.
    const char* names[] = {"IDLE", "RUN"};
    const char* values[] = {"00", "01"};
    t->declDTypeEnum(1, "oe_state", 2, 2, names, values);
    t->declBus(b + state_code, "card state", 1, dir, wire, false, -1, 1, 0);
    if (s.with_marker) t->declBus(b + kind_code, "faults kind", -1, dir, wire, false, -1, 7, 0);
}

void declare(VerilatedVcd* t, const trace_source& s) {
    const uint32_t b = s.base;
    t->declBit(b + pclk_code, "sensor_L PCLK", false, -1);
    t->declBus(b + data_code, "sensor_L DATA", false, -1, 9, 0);
    t->declBus(b + count_code, "card count", false, -1, 31, 0);
    t->declDouble(b + level_code, "card level", false, -1);
    t->declBus(b + state_code, "card state", false, -1, 1, 0);
    if (s.with_marker) t->declBus(b + kind_code, "faults kind", false, -1, 7, 0);
}

template <class trace_type>
struct hooks {
    using buffer = typename trace_type::Buffer;

    static void init(void* self, trace_type* t, uint32_t code) {
        auto& s = *static_cast<trace_source*>(self);
        s.base = code;
        t->pushNamePrefix("platform ");
        declare(t, s);
        t->popNamePrefix();
    }
    static void dump(const trace_source& s, buffer* b, bool full) {
        uint32_t* old = b->oldp(s.base);
        if (full) {
            b->fullBit(old + pclk_code, s.pclk);
            b->fullSData(old + data_code, s.data, 10);
            b->fullIData(old + count_code, s.count, 32);
            b->fullDouble(old + level_code, s.level);
            b->fullCData(old + state_code, s.state, 2);
            if (s.with_marker) b->fullCData(old + kind_code, 0, 8);
        } else {  // the marker never changes while the run writes the file
            b->chgBit(old + pclk_code, s.pclk);
            b->chgSData(old + data_code, s.data, 10);
            b->chgIData(old + count_code, s.count, 32);
            b->chgDouble(old + level_code, s.level);
            b->chgCData(old + state_code, s.state, 2);
        }
    }
    static void full(void* self, buffer* b) { dump(*static_cast<trace_source*>(self), b, true); }
    static void changes(void* self, buffer* b) {
        dump(*static_cast<trace_source*>(self), b, false);
    }
};

template <class file_type, class trace_type>
void write_with(const std::string& path, bool with_marker) {
    trace_source s;
    s.with_marker = with_marker;
    file_type file;
    file.set_time_unit("1fs");
    file.set_time_resolution("1fs");
    file.spTrace()->addInitCb(&hooks<trace_type>::init, &s);
    file.spTrace()->addFullCb(&hooks<trace_type>::full, &s);
    file.spTrace()->addChgCb(&hooks<trace_type>::changes, &s);
    file.open(path.c_str());
    for (const ticks t : dump_ticks) {
        if (t == 18100) {
            s.pclk = 1;
            s.data = 5;
        } else if (t == 18200) {
            s.pclk = 0;
            s.count = 7;
            s.level = 1.5;
            s.state = 1;
        } else if (t == 18300) {
            s.pclk = 1;
            s.data = 1023;
        }  // 18400: nothing changes; the file still ends there.
        file.dump(static_cast<uint64_t>(to_fs(t)));
    }
    file.close();
}

void write_waves(waves_format format, const std::string& path, bool with_marker = true) {
    if (format == waves_format::fst) {
        write_with<VerilatedFstC, VerilatedFst>(path, with_marker);
    } else {
        write_with<VerilatedVcdC, VerilatedVcd>(path, with_marker);
    }
}

// ---- reading it back -----------------------------------------------------------------------

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// An FST as the VCD text fst2vcd prints for it.
std::string fst_as_vcd(const std::string& path) {
    void* reader = fstReaderOpen(path.c_str());
    if (!reader) return "";
    std::FILE* text = std::tmpfile();
    fstReaderProcessHier(reader, text);
    fstReaderSetFacProcessMaskAll(reader);
    fstReaderIterBlocks(reader, nullptr, nullptr, text);
    fstReaderClose(reader);
    std::fflush(text);
    std::rewind(text);
    std::string out;
    char chunk[4096];
    size_t n;
    while ((n = std::fread(chunk, 1, sizeof chunk, text)) > 0) out.append(chunk, n);
    std::fclose(text);
    return out;
}

// An FST's hierarchy as fstapi reads it, attributes (which the VCD text
// leaves out) included.
std::vector<std::string> fst_hierarchy(const std::string& path) {
    std::vector<std::string> items;
    void* reader = fstReaderOpen(path.c_str());
    if (!reader) return items;
    while (const fstHier* h = fstReaderIterateHier(reader)) {
        if (h->htyp == FST_HT_SCOPE) {
            items.push_back(std::string("scope ") + h->u.scope.name);
        } else if (h->htyp == FST_HT_UPSCOPE) {
            items.push_back("upscope");
        } else if (h->htyp == FST_HT_VAR) {
            items.push_back("var " + std::to_string(h->u.var.typ) + " " + h->u.var.name + " " +
                            std::to_string(h->u.var.length) + " " +
                            std::to_string(h->u.var.handle));
        } else if (h->htyp == FST_HT_ATTRBEGIN) {
            items.push_back("attr " + std::to_string(h->u.attr.subtype) + " " + h->u.attr.name +
                            " " + std::to_string(h->u.attr.arg));
        }
    }
    fstReaderClose(reader);
    return items;
}

using change_list = std::vector<std::pair<int64_t, std::string>>;  // (fs, value)

struct parsed_waves {
    std::vector<std::string> declarations;       // $scope .. $enddefinitions, trimmed lines
    std::map<std::string, std::string> code_of;  // full name -> identifier code
    std::vector<int64_t> times;
    std::map<std::string, change_list> changes;  // by full name
};

std::string trimmed(const std::string& line) {
    const size_t b = line.find_first_not_of(" \t\r");
    const size_t e = line.find_last_not_of(" \t\r");
    return b == std::string::npos ? "" : line.substr(b, e - b + 1);
}

void parse_declaration(const std::string& line, std::vector<std::string>* scopes, parsed_waves* w) {
    std::istringstream tokens(line);
    std::string command, a, b, code, name;
    tokens >> command;
    if (command == "$scope") {
        tokens >> a >> b;
        scopes->push_back(b);
    } else if (command == "$upscope") {
        scopes->pop_back();
    } else if (command == "$var") {
        tokens >> a >> b >> code >> name;
        std::string full;
        for (const std::string& s : *scopes) full += s + ".";
        w->code_of[full + name] = code;
    }
}

parsed_waves parse_vcd(const std::string& text) {
    parsed_waves w;
    std::vector<std::string> scopes;
    std::map<std::string, change_list> by_code;
    std::istringstream lines(text);
    std::string line;
    bool in_header = true, in_declarations = false;
    while (std::getline(lines, line)) {
        const std::string t = trimmed(line);
        if (in_header) {
            in_declarations = in_declarations || t.rfind("$scope", 0) == 0;
            if (in_declarations) w.declarations.push_back(t);
            parse_declaration(t, &scopes, &w);
            in_header = t.rfind("$enddefinitions", 0) != 0;
        } else if (!t.empty() && t[0] == '#') {
            w.times.push_back(std::stoll(t.substr(1)));
        } else if (!t.empty() && t[0] != '$') {
            const size_t space = t.find(' ');
            const bool vector = space != std::string::npos;
            const std::string code = vector ? t.substr(space + 1) : t.substr(1);
            by_code[code].emplace_back(w.times.back(),
                                       vector ? t.substr(0, space) : t.substr(0, 1));
        }
    }
    for (const auto& [name, code] : w.code_of) w.changes[name] = by_code[code];
    return w;
}

parsed_waves read_waves(waves_format format, const std::string& path) {
    return parse_vcd(format == waves_format::fst ? fst_as_vcd(path) : read_bytes(path));
}

// The marker's value as both writers print it.
std::string kind(uint8_t v) {
    std::string bits = "b";
    for (int b = 7; b >= 0; --b) bits.push_back(((v >> b) & 1) ? '1' : '0');
    return bits;
}

ino_t inode_of(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 ? st.st_ino : 0;
}

// ---- the tests -----------------------------------------------------------------------------

// A waveform's path in a temp dir of its own, removed after the test.
class waves_in_temp_dir : public ::testing::Test {
  protected:
    void use(waves_format format) {
        m_format = format;
        const std::string pattern =
            (std::filesystem::temp_directory_path() / "stereosim-fault-markers-XXXXXX").string();
        std::vector<char> name(pattern.begin(), pattern.end());
        name.push_back('\0');
        ASSERT_NE(mkdtemp(name.data()), nullptr);
        m_dir = name.data();
        m_path = m_dir + (format == waves_format::fst ? "/waves.fst" : "/waves.vcd");
    }
    void TearDown() override {
        if (!m_dir.empty()) std::filesystem::remove_all(m_dir);
    }

    bool merge(std::vector<fault_marker> markers, uint64_t* added, std::string* error) {
        return output::add_fault_markers(m_path, m_format, window, std::move(markers), added,
                                         error);
    }
    std::vector<std::string> files_in_dir() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(m_dir))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
    // Every signal but the marker, its declarations and its changes as before.
    static void expect_rest_unchanged(const parsed_waves& before, const parsed_waves& after) {
        EXPECT_EQ(after.declarations, before.declarations);
        EXPECT_EQ(after.code_of, before.code_of);
        for (const auto& [name, changes] : before.changes)
            if (name != marker_name) {
                EXPECT_EQ(after.changes.at(name), changes) << name;
            }
    }

    waves_format m_format = waves_format::vcd;
    std::string m_dir, m_path;
};

// Each case on both formats.
class fault_markers_test : public waves_in_temp_dir,
                           public ::testing::WithParamInterface<waves_format> {
  protected:
    void SetUp() override { use(GetParam()); }
};

class fst_markers_test : public waves_in_temp_dir {
  protected:
    void SetUp() override { use(waves_format::fst); }
};

class vcd_markers_test : public waves_in_temp_dir {
  protected:
    void SetUp() override { use(waves_format::vcd); }
};

TEST_P(fault_markers_test, markers_land_where_specified) {
    write_waves(m_format, m_path);
    const parsed_waves before = read_waves(m_format, m_path);
    ASSERT_EQ(before.changes.at(marker_name), (change_list{{to_fs(18000), kind(0)}}));

    // Any order; the two on tick 18250 keep theirs (the last one stands).
    const std::vector<fault_marker> markers = {
        {18200, 11},  // on an existing time: joins it
        {18050, 9},   // between existing times: a time of its own
        {19000, 16},  // at the window's end: not written
        {18250, 12},  // two on one tick
        {17500, 5},   // before the window: the latest sets the start value
        {18400, 14},  // on the file's last time: written
        {18450, 15},  // in the window but after the file's last time: not written
        {18250, 13},  // ... the last one stands
        {17000, 3},   // before the window too, but earlier
        {20000, 17},  // after the window
    };
    uint64_t added = 0;
    std::string error;
    ASSERT_TRUE(merge(markers, &added, &error)) << error;
    EXPECT_EQ(added, 4u);
    EXPECT_FALSE(std::filesystem::exists(m_path + ".markers"));

    const parsed_waves after = read_waves(m_format, m_path);
    const change_list expected = {{to_fs(18000), kind(5)},
                                  {to_fs(18050), kind(9)},
                                  {to_fs(18200), kind(11)},
                                  {to_fs(18250), kind(13)},
                                  {to_fs(18400), kind(14)}};
    EXPECT_EQ(after.changes.at(marker_name), expected);
    std::vector<int64_t> times = before.times;
    times.push_back(to_fs(18050));
    times.push_back(to_fs(18250));
    std::sort(times.begin(), times.end());
    EXPECT_EQ(after.times, times);
    expect_rest_unchanged(before, after);
}

TEST_F(fst_markers_test, keeps_hierarchy_attributes_and_span) {
    write_waves(m_format, m_path);
    const std::vector<std::string> hierarchy = fst_hierarchy(m_path);
    ASSERT_NE(std::find(hierarchy.begin(), hierarchy.end(), "attr 7 oe_state 2 IDLE RUN 00 01 1"),
              hierarchy.end());
    void* reader = fstReaderOpen(m_path.c_str());
    ASSERT_NE(reader, nullptr);
    const uint64_t start = fstReaderGetStartTime(reader), end = fstReaderGetEndTime(reader);
    const signed char timescale = fstReaderGetTimescale(reader);
    fstReaderClose(reader);
    EXPECT_EQ(end, static_cast<uint64_t>(to_fs(18400)));

    uint64_t added = 0;
    std::string error;
    ASSERT_TRUE(merge({{18050, 9}}, &added, &error)) << error;
    EXPECT_EQ(fst_hierarchy(m_path), hierarchy);
    reader = fstReaderOpen(m_path.c_str());
    ASSERT_NE(reader, nullptr);
    EXPECT_EQ(fstReaderGetStartTime(reader), start);
    EXPECT_EQ(fstReaderGetEndTime(reader), end);  // the empty last time stays
    EXPECT_EQ(fstReaderGetTimescale(reader), timescale);
    fstReaderClose(reader);
}

TEST_F(vcd_markers_test, keeps_verilators_header_and_line_format) {
    write_waves(m_format, m_path);
    const std::string before = read_bytes(m_path);
    uint64_t added = 0;
    std::string error;
    ASSERT_TRUE(merge({{18050, 9}}, &added, &error)) << error;
    const std::string after = read_bytes(m_path);
    const size_t header_end = before.find("$enddefinitions $end\n");
    ASSERT_NE(header_end, std::string::npos);
    EXPECT_EQ(after.substr(0, header_end), before.substr(0, header_end));
    const std::string code = parse_vcd(before).code_of.at(marker_name);
    EXPECT_NE(after.find("\n#" + std::to_string(to_fs(18050)) + "\n" + kind(9) + " " + code + "\n"),
              std::string::npos)
        << after;
    // The rest is the file as it was, line for line.
    std::string without_step = after;
    without_step.erase(after.find("#" + std::to_string(to_fs(18050))),
                       std::to_string(to_fs(18050)).size() + 2 + kind(9).size() + code.size() + 2);
    EXPECT_EQ(without_step, before);
}

TEST_P(fault_markers_test, marker_at_window_start_sets_the_first_value) {
    write_waves(m_format, m_path);
    const parsed_waves before = read_waves(m_format, m_path);
    uint64_t added = 0;
    std::string error;
    ASSERT_TRUE(merge({{17000, 3}, {18000, 7}}, &added, &error)) << error;
    EXPECT_EQ(added, 1u);
    const parsed_waves after = read_waves(m_format, m_path);
    EXPECT_EQ(after.changes.at(marker_name), (change_list{{to_fs(18000), kind(7)}}));
    EXPECT_EQ(after.times, before.times);  // the last, empty, time too
    expect_rest_unchanged(before, after);
}

TEST_P(fault_markers_test, marker_before_window_only_sets_the_first_value) {
    write_waves(m_format, m_path);
    const parsed_waves before = read_waves(m_format, m_path);
    uint64_t added = 1;
    std::string error;
    ASSERT_TRUE(merge({{17999, 2}}, &added, &error)) << error;
    EXPECT_EQ(added, 0u);
    const parsed_waves after = read_waves(m_format, m_path);
    EXPECT_EQ(after.changes.at(marker_name), (change_list{{to_fs(18000), kind(2)}}));
    EXPECT_EQ(after.times, before.times);
    expect_rest_unchanged(before, after);
}

TEST_P(fault_markers_test, no_effective_marker_leaves_the_file_as_it_was) {
    write_waves(m_format, m_path);
    const std::string before = read_bytes(m_path);
    const ino_t inode = inode_of(m_path);
    for (const std::vector<fault_marker>& markers :
         {std::vector<fault_marker>{},
          std::vector<fault_marker>{{18450, 3}, {19000, 4}, {25000, 5}}}) {
        uint64_t added = 7;
        std::string error;
        ASSERT_TRUE(merge(markers, &added, &error)) << error;
        EXPECT_EQ(added, 0u);
        EXPECT_EQ(read_bytes(m_path), before);
        EXPECT_EQ(inode_of(m_path), inode);  // not even rewritten
    }
    EXPECT_EQ(files_in_dir().size(), 1u);
}

TEST_P(fault_markers_test, missing_file_fails_and_leaves_nothing) {
    uint64_t added = 0;
    std::string error;
    EXPECT_FALSE(merge({{18100, 1}}, &added, &error));
    EXPECT_NE(error.find(m_path), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_TRUE(files_in_dir().empty());
}

TEST_P(fault_markers_test, unwritable_temp_file_fails_and_leaves_the_file) {
    write_waves(m_format, m_path);
    const std::string before = read_bytes(m_path);
    // PATH.markers a directory: cannot be written, even by root.
    std::filesystem::create_directory(m_path + ".markers");
    uint64_t added = 0;
    std::string error;
    EXPECT_FALSE(merge({{18100, 1}}, &added, &error));
    EXPECT_NE(error.find(m_path), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    EXPECT_EQ(read_bytes(m_path), before);
    EXPECT_TRUE(std::filesystem::is_directory(m_path + ".markers"));  // not ours to remove
    EXPECT_EQ(files_in_dir().size(), 2u);
}

TEST_P(fault_markers_test, file_without_the_marker_fails) {
    write_waves(m_format, m_path, false);
    const std::string before = read_bytes(m_path);
    uint64_t added = 0;
    std::string error;
    EXPECT_FALSE(merge({{18100, 1}}, &added, &error));
    EXPECT_NE(error.find(m_path), std::string::npos) << error;
    EXPECT_NE(error.find("platform.faults.kind"), std::string::npos) << error;
    EXPECT_EQ(read_bytes(m_path), before);
    EXPECT_EQ(files_in_dir().size(), 1u);
}

INSTANTIATE_TEST_SUITE_P(formats, fault_markers_test,
                         ::testing::Values(waves_format::fst, waves_format::vcd),
                         [](const ::testing::TestParamInfo<waves_format>& info) {
                             return std::string(info.param == waves_format::fst ? "fst" : "vcd");
                         });

}  // namespace
