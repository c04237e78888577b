#include "tb/app/output/waves_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include "verilated.h"
#include "verilated_fst_c.h"
#include "verilated_vcd_c.h"

namespace output {

using platform::trace_group;
using simtime::ticks;

unsigned trace_group_of_scope(const std::string& scope) {
    if (scope.rfind("sensor", 0) == 0) return static_cast<unsigned>(trace_group::sensors);
    if (scope == "card" || scope.rfind("card.", 0) == 0)
        return static_cast<unsigned>(trace_group::card);
    if (scope == "emif" || scope.rfind("emif.", 0) == 0)
        return static_cast<unsigned>(trace_group::emif);
    return static_cast<unsigned>(trace_group::firmware);  // interrupts, firmware
}

bool parse_trace_groups(const std::string& list, unsigned* groups, std::string* bad) {
    unsigned g = 0;
    size_t begin = 0;
    while (begin <= list.size()) {
        size_t end = list.find(',', begin);
        if (end == std::string::npos) end = list.size();
        const std::string name = list.substr(begin, end - begin);
        if (name == "sensors") {
            g |= static_cast<unsigned>(trace_group::sensors);
        } else if (name == "card") {
            g |= static_cast<unsigned>(trace_group::card);
        } else if (name == "emif") {
            g |= static_cast<unsigned>(trace_group::emif);
        } else if (name == "firmware") {
            g |= static_cast<unsigned>(trace_group::firmware);
        } else if (name == "all") {
            g |= platform::trace_all_groups;
        } else {
            if (bad) *bad = name;
            return false;
        }
        begin = end + 1;
    }
    *groups = g;
    return g != 0;
}

const platform::trace_signal& fault_marker_signal() {
    static const platform::trace_signal marker{"faults", "kind", 8, platform::trace_format::bits};
    return marker;
}

bool is_fault_marker(const platform::trace_signal& s) {
    const platform::trace_signal& m = fault_marker_signal();
    return s.scope == m.scope && s.name == m.name;
}

namespace {

// The writer's name of a signal: scopes and name separated by spaces.
std::string spaced_name(const platform::trace_signal& s) {
    std::string n = s.scope + " " + s.name;
    for (char& c : n)
        if (c == '.') c = ' ';
    return n;
}

void declare_in(VerilatedFst* t, uint32_t code, const std::string& name, int width) {
    if (width == 1) {
        t->declBit(code, name.c_str(), -1, FST_VD_IMPLICIT, FST_VT_VCD_WIRE, false, -1);
    } else if (width <= 32) {
        t->declBus(code, name.c_str(), -1, FST_VD_IMPLICIT, FST_VT_VCD_WIRE, false, -1, width - 1,
                   0);
    } else {
        t->declQuad(code, name.c_str(), -1, FST_VD_IMPLICIT, FST_VT_VCD_WIRE, false, -1, width - 1,
                    0);
    }
}

void declare_in(VerilatedVcd* t, uint32_t code, const std::string& name, int width) {
    if (width == 1) {
        t->declBit(code, name.c_str(), false, -1);
    } else if (width <= 32) {
        t->declBus(code, name.c_str(), false, -1, width - 1, 0);
    } else {
        t->declQuad(code, name.c_str(), false, -1, width - 1, 0);
    }
}

// One value through a buffer: `full` at the first dump, else only a change.
template <class buffer>
void put(buffer* b, bool full, uint32_t code, int width, uint64_t v) {
    uint32_t* old = b->oldp(code);
    if (width == 1) {
        full ? b->fullBit(old, static_cast<CData>(v)) : b->chgBit(old, static_cast<CData>(v));
    } else if (width <= 8) {
        full ? b->fullCData(old, static_cast<CData>(v), width)
             : b->chgCData(old, static_cast<CData>(v), width);
    } else if (width <= 16) {
        full ? b->fullSData(old, static_cast<SData>(v), width)
             : b->chgSData(old, static_cast<SData>(v), width);
    } else if (width <= 32) {
        full ? b->fullIData(old, static_cast<IData>(v), width)
             : b->chgIData(old, static_cast<IData>(v), width);
    } else {
        full ? b->fullQData(old, v, width) : b->chgQData(old, v, width);
    }
}

}  // namespace

// The trace hooks of the pin trace's signals for one writer type: the
// "platform" scope around everything (the card's model registers between
// begin and declare), the declarations, the values at each dump.
template <class trace_type>
struct waves_writer::hooks {
    using buffer = typename trace_type::Buffer;
    static void begin(void*, trace_type* t, uint32_t) { t->pushNamePrefix("platform "); }
    static void declare(void* self, trace_type* t, uint32_t code) {
        auto& w = *static_cast<waves_writer*>(self);
        for (signal& s : w.m_signals) {
            if (!s.included) continue;
            s.code = code;
            declare_in(t, code, spaced_name(s.info), s.info.width);
            code += s.info.width > 32 ? 2 : 1;
        }
        t->popNamePrefix(1);
    }
    static void dump(waves_writer& w, buffer* b, bool full) {
        for (size_t i = 0; i < w.m_signals.size(); ++i) {
            const signal& s = w.m_signals[i];
            if (s.code != 0) put(b, full, s.code, s.info.width, w.m_value[i]);
        }
    }
    static void full(void* self, buffer* b) { dump(*static_cast<waves_writer*>(self), b, true); }
    static void changes(void* self, buffer* b) {
        dump(*static_cast<waves_writer*>(self), b, false);
    }
    // Only `scopes` (and what is below them) are written; time in fs.
    template <class writer>
    static bool open(writer& file, waves_writer* self, const std::vector<std::string>& scopes,
                     const std::string& path) {
        for (const std::string& scope : scopes) file.dumpvars(99, scope);
        file.spTrace()->addInitCb(&declare, self);
        file.spTrace()->addFullCb(&full, self);
        file.spTrace()->addChgCb(&changes, self);
        file.set_time_unit("1fs");
        file.set_time_resolution("1fs");
        file.open(path.c_str());
        return file.isOpen();
    }
};

waves_writer::waves_writer(waves_format format, platform::tick_window window, unsigned groups)
    : m_format(format), m_window(window), m_groups(groups) {
    // The platform scope opens before the card registers its own signals.
    if (format == waves_format::fst) {
        m_fst = std::make_unique<VerilatedFstC>();
        m_fst->spTrace()->addInitCb(&hooks<VerilatedFst>::begin, this);
    } else {
        m_vcd = std::make_unique<VerilatedVcdC>();
        m_vcd->spTrace()->addInitCb(&hooks<VerilatedVcd>::begin, this);
    }
}

waves_writer::~waves_writer() {
    if (m_finished || m_path.empty()) return;
    // Not finished: a failed run leaves no waveform behind.
    close_file();
    std::remove((m_path + ".part").c_str());
}

VerilatedFstC* waves_writer::fst_writer() {
    return m_fst.get();
}
VerilatedVcdC* waves_writer::vcd_writer() {
    return m_vcd.get();
}

bool waves_writer::open(const std::string& path) {
    m_path = path;
    const std::string part = m_path + ".part";
    std::FILE* f = std::fopen(part.c_str(), "wb");
    if (!f) {
        m_error = "cannot write " + part + ": " + std::strerror(errno);
        return false;
    }
    std::fclose(f);
    return true;
}

std::string waves_writer::full_name_of(const platform::trace_signal& s) {
    std::string n = "platform." + s.scope + "." + s.name;
    if (s.width > 1) n += "[" + std::to_string(s.width - 1) + ":0]";
    return n;
}

platform::trace_id waves_writer::declare(const platform::trace_signal& s) {
    signal sig;
    sig.info = s;
    sig.included = (trace_group_of_scope(s.scope) & m_groups) != 0 || is_fault_marker(s);
    sig.full_name = full_name_of(s);
    m_signals.push_back(sig);
    m_value.push_back(0);
    return static_cast<platform::trace_id>(m_signals.size() - 1);
}

void waves_writer::open_file() {
    if (m_file_open || m_finished || m_path.empty()) return;
    // The fault marker, last and in every file (0 until add_fault_markers).
    declare(fault_marker_signal());
    const std::string part = m_path + ".part";
    // The card's RTL hierarchy (card_top and below) and the pin trace's own
    // signals: not the verilated --cc model's copies of card_top's ports,
    // which a --sc model (the pin-level arrangement) does not trace, so both
    // arrangements write the same signals.
    std::vector<std::string> scopes = {"platform.card.card_top"};
    for (const signal& s : m_signals)
        if (s.included) scopes.push_back("platform." + s.info.scope + "." + s.info.name);
    m_file_open = m_fst ? hooks<VerilatedFst>::open(*m_fst, this, scopes, part)
                        : hooks<VerilatedVcd>::open(*m_vcd, this, scopes, part);
    if (!m_file_open) m_error = "cannot write " + part;
}

void waves_writer::change(ticks t, platform::trace_id id, uint64_t value) {
    if (id >= m_signals.size() || !m_signals[id].included || m_finished) return;
    open_file();
    if (!m_file_open) return;
    if (m_pending && t > m_time) dump_pending();
    if (t < m_time) {
        ++m_out_of_order;
    } else {
        m_time = t;
    }
    m_value[id] = value;
    m_pending = true;
}

void waves_writer::release(ticks t, platform::trace_id id) {
    change(t, id, 0);  // two-state: nobody drives it, it reads 0
}

void waves_writer::seal_before(ticks t) {
    if (m_pending && m_time < t) dump_pending();
}

void waves_writer::dump_pending() {
    m_pending = false;
    const uint64_t fs = static_cast<uint64_t>(simtime::to_fs(m_time));
    if (m_fst) {
        m_fst->dump(fs);
    } else {
        m_vcd->dump(fs);
    }
}

void waves_writer::finish(ticks end) {
    if (m_finished || m_path.empty()) return;
    open_file();  // a window nothing reached still gets its file
    if (m_pending) dump_pending();
    // The window's end, as a time of its own.
    if (m_file_open && end > m_time) {
        m_time = end;
        dump_pending();
    }
    close_file();
    m_finished = true;
    const std::string part = m_path + ".part";
    if (!ok()) {
        std::remove(part.c_str());
        return;
    }
    if (std::rename(part.c_str(), m_path.c_str()) != 0) {
        m_error = "cannot rename " + part + " to " + m_path;
        std::remove(part.c_str());
        return;
    }
}

void waves_writer::close_file() {
    if (!m_file_open) return;
    if (m_fst) m_fst->close();
    if (m_vcd) m_vcd->close();
    m_file_open = false;
}

}  // namespace output
