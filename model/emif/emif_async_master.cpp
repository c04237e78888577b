#include "model/emif/emif_async_master.h"

#include <algorithm>
#include <iterator>

namespace emif {

namespace {

constexpr uint32_t history_mask = 15;  // m_ardy_history: ardy_lead must stay below 16

uint32_t load_word(const uint8_t* p) {
    return uint32_t{p[0]} | (uint32_t{p[1]} << 8) | (uint32_t{p[2]} << 16) | (uint32_t{p[3]} << 24);
}

void store_word(uint8_t* p, uint32_t w) {
    p[0] = static_cast<uint8_t>(w);
    p[1] = static_cast<uint8_t>(w >> 8);
    p[2] = static_cast<uint8_t>(w >> 16);
    p[3] = static_cast<uint8_t>(w >> 24);
}

}  // namespace

const char* requester_name(requester r) {
    return r == requester::cpu ? "cpu" : "edma";
}

bool operator==(const emif_pins& a, const emif_pins& b) {
    for (int i = 0; i < ce_count; ++i)
        if (a.ce_n[i] != b.ce_n[i]) return false;
    return a.ea == b.ea && a.be_n == b.be_n && a.ed_out == b.ed_out && a.ed_oe == b.ed_oe &&
           a.aoe_n == b.aoe_n && a.are_n == b.are_n && a.awe_n == b.awe_n;
}

emif_async_master::emif_async_master(const emif_config& config) : m_config(config) {
    for (int ce = 0; ce < ce_count; ++ce) set_cectl(ce, config.cectl[ce]);
    m_config.ardy_lead = std::min<uint32_t>(config.ardy_lead, history_mask);
    m_next_refresh = config.sdram.refresh_period;
    std::fill(std::begin(m_ardy_history), std::end(m_ardy_history), true);
}

void emif_async_master::set_cectl(int ce, uint32_t value) {
    m_cectl[ce] = value;
    m_timing[ce] = decode_cectl(value);
}

void emif_async_master::set_completion_handler(completion_fn fn, void* context) {
    m_on_done = fn;
    m_on_done_context = context;
}

void emif_async_master::set_sdram_storage(uint8_t* bytes, size_t size) {
    m_sdram = bytes;
    m_sdram_size = size;
}

void emif_async_master::set_ardy_fault(const ardy_fault& fault) {
    if (fault.ce < 0 || fault.ce >= ce_count) return;
    m_fault[fault.ce] = fault;
    m_fault_from_edge[fault.ce] = m_config.eclk.first_rise_at_or_after(fault.from_tick);
}

void emif_async_master::clear_ardy_faults() {
    for (auto& f : m_fault) f = ardy_fault{};
}

// ---- requests --------------------------------------------------------------------------------

bool emif_async_master::validate(emif_access& a) const {
    const int ce = ce_of_address(a.address);
    const uint64_t last = uint64_t{a.address} + (a.increment ? 4ull * (a.words - 1) : 0);
    if (ce < 0 || (a.address & 3u) != 0 || a.words == 0 || a.data == nullptr ||
        ce_of_address(static_cast<uint32_t>(last)) != ce || last > 0xFFFFFFFFull) {
        a.status = access_status::address_error;
        return false;
    }
    const memory_type t = m_timing[ce].type;
    if (t != memory_type::async32 && !is_sdram(t)) {
        a.status = access_status::unsupported_memory;
        return false;
    }
    return true;
}

void emif_async_master::enqueue(emif_access& a) {
    a.status = access_status::pending;
    a.words_done = 0;
    a.wait_cycles = 0;
    a.turnaround_cycles = 0;
    a.grant_edge = not_granted;
    a.done_edge = 0;
    a.queue_next = nullptr;
    queue& q = m_queue[static_cast<int>(a.who)];
    if (q.tail)
        q.tail->queue_next = &a;
    else
        q.head = &a;
    q.tail = &a;
}

bool emif_async_master::submit(emif_access& a) {
    if (!validate(a)) return false;
    a.eligible_edge = m_next;
    enqueue(a);
    return true;
}

bool emif_async_master::submit_at(emif_access& a, simtime::ticks t) {
    if (!validate(a)) return false;
    a.eligible_edge = std::max(m_next, m_config.eclk.first_rise_at_or_after(t + 1));
    enqueue(a);
    return true;
}

// ---- state -----------------------------------------------------------------------------------

bool emif_async_master::idle() const {
    return m_phase == phase::idle && m_refresh_pending == 0 && m_queue[0].head == nullptr &&
           m_queue[1].head == nullptr;
}

bool emif_async_master::arbitrates_at_next_edge() const {
    switch (m_phase) {
        case phase::idle:
            return true;
        case phase::hold:
        case phase::sdram:
        case phase::refresh:
            return m_next >= m_phase_end;
        default:
            return false;
    }
}

uint64_t emif_async_master::sdram_row(uint32_t address) const {
    const uint32_t offset = address - ce_base(0);
    return offset / std::max(1u, m_config.sdram.row_bytes);
}

uint32_t emif_async_master::word_address(const emif_access& a) const {
    return a.increment ? a.address + 4u * a.words_done : a.address;
}

void emif_async_master::release_pins() {
    for (bool& c : m_pins.ce_n) c = true;
    m_pins.aoe_n = m_pins.are_n = m_pins.awe_n = true;
    m_pins.ed_oe = false;
    m_pins.be_n = 0xF;
    // EA and ED keep their last values, as real address/data pins do.
}

// ---- stepping --------------------------------------------------------------------------------

void emif_async_master::step(const emif_inputs& in) {
    const uint64_t e = m_next++;
    m_ardy_history[e & history_mask] = in.ardy;
    if (m_config.sdram.refresh_period != 0 && e >= m_next_refresh) {
        ++m_refresh_pending;
        m_next_refresh += m_config.sdram.refresh_period;
    }
    switch (m_phase) {
        case phase::idle:
            arbitrate(e);
            break;
        case phase::turnaround:
            if (e >= m_phase_end) start_op(e);
            break;
        case phase::setup:
            if (e >= m_phase_end) begin_strobe(e);
            break;
        case phase::strobe:
            strobe_edge(e, in);
            break;
        case phase::hold:
        case phase::sdram:
        case phase::refresh:
            if (e >= m_phase_end) {
                finish_op(e);
                arbitrate(e);
            }
            break;
    }
    if (m_phase != phase::idle) {
        ++m_stats.busy_edges;
        if (m_phase == phase::turnaround) ++m_stats.turnaround_edges;
        if (m_phase == phase::sdram || m_phase == phase::refresh) ++m_stats.sdram_edges;
    }
    if (m_observer) m_observer->observe(e, m_pins, in);
}

void emif_async_master::skip_idle_to(uint64_t edge) {
    const emif_inputs idle_inputs{};
    while (m_next < edge) {
        if (m_phase == phase::idle && m_refresh_pending == 0) {
            uint64_t target = edge;
            if (m_config.sdram.refresh_period != 0) target = std::min(target, m_next_refresh);
            for (const queue& q : m_queue)
                if (q.head) target = std::min(target, std::max(m_next, q.head->eligible_edge));
            if (target > m_next) {
                std::fill(std::begin(m_ardy_history), std::end(m_ardy_history), true);
                m_next = target;
                continue;
            }
        }
        step(idle_inputs);
    }
}

// Fixed priority at every word boundary (docs/emif.md, "Arbitration"):
// refresh due > CPU > EDMA; within a requester first come, first served.
void emif_async_master::arbitrate(uint64_t e) {
    bus_op next;
    if (m_refresh_pending != 0) {
        next.kind = op_kind::refresh;
        next.ce = 0;
    } else {
        for (queue& q : m_queue) {  // index order = priority: cpu, then edma
            if (q.head && q.head->eligible_edge <= e) {
                next = next_op_of(*q.head);
                break;
            }
        }
    }
    if (next.kind == op_kind::none) {
        m_phase = phase::idle;
        release_pins();
        return;
    }
    m_op = next;
    if (next.access && next.access->grant_edge == not_granted) next.access->grant_edge = e;
    const uint32_t gap = turnaround_between(m_last, next);
    const uint64_t idle_edges = e - m_bus_free_edge;
    if (gap > idle_edges) {
        m_phase = phase::turnaround;
        m_phase_end = m_bus_free_edge + gap;
        if (next.access) next.access->turnaround_cycles += static_cast<uint32_t>(m_phase_end - e);
        release_pins();
        return;
    }
    start_op(e);
}

emif_async_master::bus_op emif_async_master::next_op_of(emif_access& a) const {
    bus_op op;
    op.access = &a;
    op.ce = ce_of_address(a.address);
    op.write = a.write;
    if (is_sdram(m_timing[op.ce].type)) {
        op.kind = op_kind::sdram_chunk;
        op.words = std::min(a.words - a.words_done, std::max(1u, m_config.sdram.chunk_words));
    } else {
        op.kind = op_kind::async_word;
        op.words = 1;
    }
    return op;
}

// TA idle cycles between two ops when an async access is on either side and
// they differ in CE space or direction: the larger TA of the async spaces
// involved. SDRAM and refresh ops follow each other directly.
uint32_t emif_async_master::turnaround_between(const bus_op& last, const bus_op& next) const {
    if (last.kind == op_kind::none) return 0;  // nothing on the bus before
    const bool last_async = last.kind == op_kind::async_word;
    const bool next_async = next.kind == op_kind::async_word;
    if (!last_async && !next_async) return 0;
    if (last_async && next_async && last.ce == next.ce && last.write == next.write) return 0;
    uint32_t gap = 0;
    if (last_async) gap = std::max(gap, m_timing[last.ce].turnaround);
    if (next_async) gap = std::max(gap, m_timing[next.ce].turnaround);
    return gap;
}

void emif_async_master::start_op(uint64_t e) {
    const bus_op& op = m_op;
    for (int i = 0; i < ce_count; ++i) m_pins.ce_n[i] = i != op.ce;
    m_pins.aoe_n = m_pins.are_n = m_pins.awe_n = true;
    m_pins.ed_oe = false;
    switch (op.kind) {
        case op_kind::async_word: {
            emif_access& a = *op.access;
            const async_timing& t = m_timing[op.ce];
            m_pins.ea = (word_address(a) >> 2) & 0xFFFFFu;
            if (a.write) {
                m_pins.be_n = a.be_n & 0xF;
                m_pins.ed_out = load_word(a.data + 4ull * a.words_done);
                m_pins.ed_oe = true;
            } else {
                m_pins.be_n = 0;
                m_pins.aoe_n = false;
            }
            m_phase = phase::setup;
            m_phase_end = e + (a.write ? t.write_setup : t.read_setup);
            const uint64_t index = m_ce_accesses[op.ce]++;
            const ardy_fault& f = m_fault[op.ce];
            m_fault_left = 0;
            if (f.extra_cycles != 0 && e >= m_fault_from_edge[op.ce] && index >= f.from_access &&
                index - f.from_access < f.access_count)
                m_fault_left = f.extra_cycles;
            break;
        }
        case op_kind::sdram_chunk: {
            // Row accesses: one if the first word's row is not the open one,
            // one more per row boundary inside the chunk.
            const emif_access& a = *op.access;
            const uint32_t first = word_address(a);
            const uint32_t last = a.increment ? first + 4u * (op.words - 1) : first;
            const uint64_t first_row = sdram_row(first), last_row = sdram_row(last);
            const bool row_open =
                m_last.kind == op_kind::sdram_chunk && m_sdram_open_row == first_row;
            const uint64_t row_accesses = (row_open ? 0 : 1) + (last_row - first_row);
            m_phase = phase::sdram;
            m_phase_end = e + row_accesses * m_config.sdram.access_cycles + (op.words + 1) / 2;
            m_pins.be_n = 0xF;
            break;
        }
        case op_kind::refresh:
            --m_refresh_pending;
            m_phase = phase::refresh;
            m_phase_end = e + std::max(1u, m_config.sdram.refresh_cycles);
            m_pins.be_n = 0xF;
            break;
        case op_kind::none:
            break;
    }
}

void emif_async_master::begin_strobe(uint64_t e) {
    const async_timing& t = m_timing[m_op.ce];
    const uint32_t programmed = m_op.write ? t.write_strobe : t.read_strobe;
    m_strobe_cycles = std::max(1u, programmed);
    m_strobe_start = e;
    if (m_op.write)
        m_pins.awe_n = false;
    else
        m_pins.are_n = false;
    m_phase = phase::strobe;
}

void emif_async_master::strobe_edge(uint64_t e, const emif_inputs& in) {
    if (e - m_strobe_start < m_strobe_cycles) return;
    const uint32_t lead = m_config.ardy_lead;
    const bool ready = lead == 0 ? in.ardy : m_ardy_history[(e - lead) & history_mask];
    emif_access& a = *m_op.access;
    if (!ready || m_fault_left != 0) {
        if (ready) --m_fault_left;  // the injected fault holds ARDY low one more cycle
        ++a.wait_cycles;
        ++m_stats.wait_edges;
        return;
    }
    if (!a.write) store_word(a.data + 4ull * a.words_done, in.ed_in);  // sampled where ARE rises
    m_pins.are_n = m_pins.awe_n = true;
    const async_timing& t = m_timing[m_op.ce];
    m_phase = phase::hold;
    m_phase_end = e + (a.write ? t.write_hold : t.read_hold);
}

void emif_async_master::finish_op(uint64_t e) {
    const bus_op op = m_op;
    m_last = op;
    m_bus_free_edge = e;
    m_sdram_open_row = no_row;
    if (op.kind == op_kind::refresh) {
        ++m_stats.refreshes;
        return;
    }
    emif_access& a = *op.access;
    if (op.kind == op_kind::sdram_chunk) {
        m_sdram_open_row =
            sdram_row(a.increment ? word_address(a) + 4u * (op.words - 1) : word_address(a));
        if (m_sdram && m_sdram_size >= 4) {
            for (uint32_t k = 0; k < op.words; ++k) {
                const uint32_t address = word_address(a);
                const size_t offset = ((address - ce_base(0)) % m_sdram_size) & ~size_t{3};
                uint8_t* buffer = a.data + 4ull * a.words_done;
                if (a.write)
                    std::copy(buffer, buffer + 4, m_sdram + offset);
                else
                    std::copy(m_sdram + offset, m_sdram + offset + 4, buffer);
                ++a.words_done;
            }
        } else {
            if (!a.write)
                std::fill(a.data + 4ull * a.words_done, a.data + 4ull * (a.words_done + op.words),
                          0);
            a.words_done += op.words;
        }
        m_stats.words[static_cast<int>(a.who)] += op.words;
    } else {
        ++a.words_done;
        ++m_stats.words[static_cast<int>(a.who)];
    }
    if (a.words_done == a.words) complete(a, e);
}

void emif_async_master::complete(emif_access& a, uint64_t e) {
    queue& q = m_queue[static_cast<int>(a.who)];
    // The access on the bus is always the head of its requester's queue.
    q.head = a.queue_next;
    if (!q.head) q.tail = nullptr;
    a.queue_next = nullptr;
    a.status = access_status::ok;
    a.done_edge = e;
    ++m_stats.accesses[static_cast<int>(a.who)];
    if (m_on_done) m_on_done(m_on_done_context, a);
}

}  // namespace emif
