#include "dsp/control_program.h"

namespace dsp {

namespace {

namespace edma = c6416::edma;
namespace irq = c6416::irq;
namespace emifa = c6416::emifa;
namespace timer = c6416::timer;
using dma = control_program_edma;

// Link (reload) entries: 0 = the trigger's drain setting, 1 + chain = the
// left channel of chain A / B / drain, 4 + chain = the right one.
constexpr int link_trigger_drain = 0;
constexpr int link_left(int chain) {
    return 1 + chain;
}
constexpr int link_right(int chain) {
    return 4 + chain;
}

constexpr uint32_t link_field(int link) {
    return edma::make_rld(0, edma::link_entry(link));
}

constexpr uint32_t channel_bit_low(int channel) {
    return channel < 32 ? 1u << channel : 0u;
}
constexpr uint32_t channel_bit_high(int channel) {
    return channel >= 32 ? 1u << (channel - 32) : 0u;
}

// Every VERDICT field but FRAME is a cause (docs/card-registers.md): a pair with any is not used.
constexpr uint32_t verdict_causes_mask =
    card_regs::verdict_fields_mask & ~card_regs::verdict_frame_mask;
constexpr uint32_t timer1 = timer::base1;

}  // namespace

const char* pipeline_mode_name(pipeline_mode m) {
    return m == pipeline_mode::sequential ? "sequential" : "overlapped";
}

uint32_t control_program::buffer_stride() const {
    const uint32_t bytes = header_size() + 2 * frame_bytes();
    return (bytes + 4095u) & ~4095u;
}

uint32_t control_program::buffer_address(int buffer) const {
    return m_config.buffer_base + static_cast<uint32_t>(buffer) * buffer_stride();
}

bool control_program::init(const control_program_config& config, hal& hardware) {
    m_config = config;
    m_hal = &hardware;
    m_ready = false;
    m_width = config.card.active_cols;
    m_height = config.card.active_rows;
    m_buffers = config.mode == pipeline_mode::overlapped ? 2 : 1;
    m_stats = control_stats{};
    const bool size_ok = m_width >= 4 && m_height >= 4 && m_width % 4 == 0 && m_height % 2 == 0 &&
                         m_width <= static_cast<uint32_t>(config.pipeline.max_width) &&
                         m_height <= static_cast<uint32_t>(config.pipeline.max_height) &&
                         m_width / 4 <= 0xFFFFu && m_height <= 0x10000u;
    if (!size_ok) return false;
    // Both buffers inside L2 or inside the SDRAM; the control block in L2.
    const uint64_t begin = config.buffer_base;
    const uint64_t end = begin + static_cast<uint64_t>(buffer_stride()) * m_buffers;
    const bool in_l2 = end <= c6416::l2_base + uint64_t{c6416::l2_bytes};
    const bool in_sdram =
        begin >= c6416::sdram_base && end <= c6416::sdram_base + uint64_t{c6416::sdram_bytes};
    const uint64_t control_end = uint64_t{config.control_base} + 128;
    const bool control_ok = control_end <= c6416::l2_bytes &&
                            (!in_l2 || control_end <= begin || config.control_base >= end);
    if (!(in_l2 || in_sdram) || !control_ok || (config.buffer_base & 63u) != 0) return false;
    if (!hardware.memory(config.buffer_base, static_cast<uint32_t>(end - begin))) return false;
    m_controller.init(config.pipeline, hardware);
    m_ready = true;
    return true;
}

void control_program::report(firmware_event kind, uint32_t pair, uint32_t value, uint32_t detail) {
    event_record e;
    e.kind = kind;
    e.pair = pair;
    e.value = value;
    e.detail = detail;
    m_hal->report(e);
}

uint32_t card_cectl(const control_program_config& config) {
    uint32_t v =
        config.dsk == dsk_version::v1 ? emifa::dsk_cectl_card_v1 : emifa::dsk_cectl_card_v2;
    const auto put = [&v](uint32_t value, uint32_t mask, uint32_t shift) {
        if (value != 0) v = (v & ~mask) | ((value << shift) & mask);
    };
    const card_bus_timing& t = config.card_timing;
    put(t.setup, emifa::cectl_wrsetup_mask, emifa::cectl_wrsetup_shift);
    put(t.setup, emifa::cectl_rdsetup_mask, emifa::cectl_rdsetup_shift);
    put(t.strobe, emifa::cectl_wrstrb_mask, emifa::cectl_wrstrb_shift);
    put(t.strobe, emifa::cectl_rdstrb_mask, emifa::cectl_rdstrb_shift);
    put(t.hold, emifa::cectl_wrhld_mask, emifa::cectl_wrhld_shift);
    put(t.hold, emifa::cectl_rdhld_mask, emifa::cectl_rdhld_shift);
    return v;
}

// ---- boot --------------------------------------------------------------------------------
void control_program::program_emif() {
    const bool v1 = m_config.dsk == dsk_version::v1;
    const uint32_t card_cectl = dsp::card_cectl(m_config);
    const uint32_t sdtim = v1 ? emifa::dsk_sdtim_v1 : emifa::dsk_sdtim_v2;
    m_hal->write32(emifa::gblctl, emifa::dsk_gblctl);
    m_hal->write32(emifa::cectl0, emifa::dsk_cectl0_sdram);
    m_hal->write32(emifa::sdctl, emifa::dsk_sdctl);
    m_hal->write32(emifa::sdtim, sdtim);
    m_hal->write32(emifa::sdext, v1 ? emifa::dsk_sdext_v1 : emifa::dsk_sdext_v2);
    m_hal->write32(emifa::cectl2, card_cectl);
    m_hal->write32(emifa::cectl3, card_cectl);
    report(firmware_event::emif_programmed, 0, card_cectl, sdtim);
}

void control_program::setup_interrupts() {
    m_hal->write32(irq::muxl, irq::muxl_reset);
    m_hal->write32(irq::muxh, irq::muxh_reset);
    m_hal->write32(irq::extpol, 0);  // the card's pins pulse high: rising edges
    uint32_t ier = (1u << irq::int_ext5) | (1u << irq::int_ext6) | (1u << irq::int_edma);
    if (m_config.watchdog_ms != 0) ier |= 1u << irq::int_tint1;
    m_hal->clear_interrupt_flags(0xFFFFu);
    m_hal->set_interrupt_enable(ier);
}

bool control_program::probe_card() {
    const uint32_t id = card_read(card_regs::id);
    const uint32_t magic = card_regs::id_reset & card_regs::id_magic_mask;
    if ((id & card_regs::id_magic_mask) != magic) {
        report(firmware_event::card_missing, 0, id);
        return false;
    }
    report(firmware_event::card_found, 0, id);
    return true;
}

void control_program::configure_card() {
    const card_setup& c = m_config.card;
    card_write(card_regs::ctrl, 0);
    card_write(card_regs::irq_status, card_regs::irq_status_frame_ready_mask |
                                          card_regs::irq_status_sync_error_mask |
                                          card_regs::irq_status_overflow_mask);
    card_write(card_regs::dark_threshold, c.dark_threshold);
    card_write(card_regs::h_start, c.h_start);
    card_write(card_regs::dark_cols_left, c.dark_cols_left);
    card_write(card_regs::border_cols_left, c.border_cols_left);
    card_write(card_regs::active_cols, c.active_cols);
    card_write(card_regs::border_cols_right, c.border_cols_right);
    card_write(card_regs::dark_cols_right, c.dark_cols_right);
    card_write(card_regs::line_total, c.line_total);
    card_write(card_regs::v_start, c.v_start);
    card_write(card_regs::dark_rows_top, c.dark_rows_top);
    card_write(card_regs::border_rows_top, c.border_rows_top);
    card_write(card_regs::active_rows, c.active_rows);
    card_write(card_regs::border_rows_bottom, c.border_rows_bottom);
    card_write(card_regs::dark_rows_bottom, c.dark_rows_bottom);
    card_write(card_regs::frame_lines, c.frame_lines);
    card_write(card_regs::retry_limit, c.retry_limit);
    card_write(card_regs::oe_low_cycles, c.oe_low_cycles);
    card_write(card_regs::start_timeout, c.start_timeout);
    card_write(card_regs::checks, c.checks);
    const uint32_t enable = card_regs::irq_enable_frame_ready_mask |
                            card_regs::irq_enable_sync_error_mask |
                            card_regs::irq_enable_overflow_mask;
    card_write(card_regs::irq_enable, enable);
    report(firmware_event::card_configured, 0, enable);
}

void control_program::write_entry(uint32_t address, const uint32_t words[6]) {
    for (uint32_t i = 0; i < edma::entry_words; ++i) m_hal->write32(address + 4 * i, words[i]);
}

// Channel 4: the card's VERDICT .. PAIRS_OK into the chain's header, then
// the chain's left channel.
void control_program::trigger_entry(int chain, uint32_t w[6]) const {
    const uint32_t header = chain == dma::drain ? drain_header() : buffer_address(chain);
    w[0] = (edma::esize_32 << edma::opt_esize_shift) | (edma::mode_inc << edma::opt_sum_shift) |
           (edma::mode_inc << edma::opt_dum_shift) | edma::opt_tcint |
           edma::opt_tcc(static_cast<uint32_t>(dma::left_channel[chain])) | edma::opt_link |
           edma::opt_fs;
    w[1] = card_regs::ce2_base + card_regs::verdict;
    w[2] = edma::make_cnt(0, dma::status_words);
    w[3] = header;
    w[4] = 0;
    w[5] = link_field(link_trigger_drain);
}

// A frame from a pixel port (fixed address) into the buffer line by line
// (2-D destination, one array per line), or for the drain chain every word
// into the sink.
void control_program::left_entry(int chain, uint32_t w[6]) const {
    const bool drain = chain == dma::drain;
    w[0] = (edma::esize_32 << edma::opt_esize_shift) | (edma::mode_fixed << edma::opt_sum_shift) |
           (drain ? 0u : edma::opt_2dd) |
           ((drain ? edma::mode_fixed : edma::mode_inc) << edma::opt_dum_shift) | edma::opt_tcint |
           edma::opt_tcc(static_cast<uint32_t>(dma::right_channel[chain])) | edma::opt_link |
           edma::opt_fs;
    w[1] = card_regs::data_left;
    w[2] = edma::make_cnt(m_height - 1, m_width / card_regs::pixels_per_word);
    w[3] = drain ? drain_sink() : left_address(chain);
    w[4] = edma::make_idx(static_cast<int32_t>(m_width), 0);
    w[5] = link_field(link_left(chain));
}

void control_program::right_entry(int chain, uint32_t w[6]) const {
    left_entry(chain, w);
    w[0] =
        (w[0] & ~(edma::opt_tcc_mask | edma::opt_tccm_mask)) | edma::opt_tcc(dma::done_code[chain]);
    w[1] = card_regs::data_right;
    w[3] = chain == dma::drain ? drain_sink() : right_address(chain);
    w[5] = link_field(link_right(chain));
}

void control_program::setup_edma() {
    m_hal->write32(edma::eer_l, 0);
    m_hal->write32(edma::eer_h, 0);
    m_hal->write32(edma::ecr_l, 0xFFFFFFFFu);
    m_hal->write32(edma::ecr_h, 0xFFFFFFFFu);
    m_hal->write32(edma::cipr_l, 0xFFFFFFFFu);
    m_hal->write32(edma::cipr_h, 0xFFFFFFFFu);
    uint32_t w[6];
    trigger_entry(dma::drain, w);
    write_entry(edma::link_entry(link_trigger_drain), w);
    uint32_t ccer_l = 0, ccer_h = 0;
    for (int chain = 0; chain < 3; ++chain) {
        left_entry(chain, w);
        write_entry(edma::link_entry(link_left(chain)), w);
        write_entry(edma::entry(dma::left_channel[chain]), w);
        right_entry(chain, w);
        write_entry(edma::link_entry(link_right(chain)), w);
        write_entry(edma::entry(dma::right_channel[chain]), w);
        ccer_l |=
            channel_bit_low(dma::left_channel[chain]) | channel_bit_low(dma::right_channel[chain]);
        ccer_h |= channel_bit_high(dma::left_channel[chain]) |
                  channel_bit_high(dma::right_channel[chain]);
    }
    m_hal->write32(edma::ccer_l, ccer_l);
    m_hal->write32(edma::ccer_h, ccer_h);
    // Captures into A / B interrupt; drains do not (they are counted from
    // the pair numbers).
    m_hal->write32(edma::cier_l,
                   (1u << dma::done_code[dma::buffer_a]) | (1u << dma::done_code[dma::buffer_b]));
    m_hal->write32(edma::cier_h, 0);
    trigger_entry(dma::drain, w);
    write_entry(edma::entry(dma::trigger_channel), w);
    arm(dma::buffer_a);
}

// Points channel 4 at `buffer`'s chain. The event is disabled meanwhile: a
// FRAME_READY in between stays latched in ER and starts the new setting.
void control_program::arm(int buffer) {
    uint32_t w[6];
    trigger_entry(buffer, w);
    m_hal->write32(edma::eer_l, 0);
    write_entry(edma::entry(dma::trigger_channel), w);
    m_state[buffer] = buffer_state::armed;
    m_hal->write32(edma::eer_l, channel_bit_low(dma::trigger_channel));
}

int control_program::armed_buffer() const {
    for (int b = 0; b < m_buffers; ++b) {
        if (m_state[b] == buffer_state::armed) return b;
    }
    return -1;
}

void control_program::arm_free_buffer() {
    if (armed_buffer() >= 0) return;
    for (int b = 0; b < m_buffers; ++b) {
        if (m_state[b] == buffer_state::free) {
            arm(b);
            return;
        }
    }
}

void control_program::restart_watchdog() {
    if (m_config.watchdog_ms == 0) return;
    uint32_t mhz = m_config.cpu_mhz;
    if (mhz == 0) {
        mhz = m_config.dsk == dsk_version::v1   ? 600u
              : m_config.dsk == dsk_version::v2 ? 720u
                                                : 1000u;
    }
    const uint64_t clocks =
        uint64_t{m_config.watchdog_ms} * mhz * 1000u / timer::cpu_cycles_per_internal_clock;
    m_hal->write32(timer1 + timer::ctl, 0);  // hold
    m_hal->write32(timer1 + timer::prd, clocks > 0xFFFFFFFFu ? 0xFFFFFFFFu : uint32_t(clocks));
    m_hal->write32(timer1 + timer::ctl, timer::ctl_clksrc | timer::ctl_hld | timer::ctl_go);
    m_hal->clear_interrupt_flags(1u << irq::int_tint1);
}

void control_program::raise_oe() {
    if (m_config.watchdog_ms != 0) {
        m_watchdog_progress = card_progress();
        restart_watchdog();
    }
    card_write(card_regs::ctrl, card_regs::ctrl_enable_mask);
    ++m_stats.oe_raises;
    m_awaiting_in_step = true;
    report(firmware_event::oe_raised, 0, m_stats.oe_raises);
}

void control_program::lower_oe() {
    card_write(card_regs::ctrl, 0);
}

// ---- frame loop --------------------------------------------------------------------------
bool control_program::finished() const {
    return (m_config.max_pairs != 0 && m_stats.pairs_processed >= m_config.max_pairs) ||
           m_stats.gave_up || m_hal->stop_requested();
}

void control_program::run() {
    if (!m_ready) return;
    report(firmware_event::boot, 0, static_cast<uint32_t>(m_config.dsk),
           static_cast<uint32_t>(m_config.mode));
    program_emif();
    setup_interrupts();
    if (!probe_card()) return;
    configure_card();
    for (buffer_state& s : m_state) s = buffer_state::free;
    m_captures = 0;
    m_have_pair = false;
    m_failures = 0;
    setup_edma();
    raise_oe();

    while (!finished()) {
        service_pending_interrupts();
        const int full = oldest_full_buffer();
        if (full >= 0) {
            process_buffer(full);
            continue;
        }
        const int n = m_hal->wait_for_interrupt();
        if (n == hal::no_interrupt) break;
        handle_interrupt(n);
    }

    m_hal->write32(edma::eer_l, 0);
    lower_oe();
    if (m_config.watchdog_ms != 0) m_hal->write32(timer1 + timer::ctl, 0);
    report(firmware_event::stopped, 0, m_stats.pairs_processed);
}

void control_program::service_pending_interrupts() {
    uint32_t pending = m_hal->interrupt_flags() & 0xFFF0u;
    // Only the enabled ones: the others are latched but not taken.
    const uint32_t enabled = (1u << irq::int_ext5) | (1u << irq::int_ext6) | (1u << irq::int_edma) |
                             (m_config.watchdog_ms != 0 ? 1u << irq::int_tint1 : 0u);
    pending &= enabled;
    for (int n = 4; n <= 15; ++n) {
        if ((pending >> n) & 1u) {
            m_hal->clear_interrupt_flags(1u << n);
            handle_interrupt(n);
        }
    }
}

void control_program::handle_interrupt(int n) {
    switch (n) {
        case irq::int_edma:
            handle_edma();
            break;
        case irq::int_ext5:
            handle_sync_error();
            break;
        case irq::int_ext6:
            handle_overflow();
            break;
        case irq::int_tint1:
            handle_watchdog();
            break;
        default:
            break;
    }
}

void control_program::handle_edma() {
    const uint32_t cipr = m_hal->read32(edma::cipr_l);
    const uint32_t drain_bit = 1u << dma::done_code[dma::drain];
    if (cipr & drain_bit) m_hal->write32(edma::cipr_l, drain_bit);
    for (int b = 0; b < m_buffers; ++b) {
        const uint32_t bit = 1u << dma::done_code[b];
        if (!(cipr & bit)) continue;
        m_hal->write32(edma::cipr_l, bit);
        if (m_state[b] != buffer_state::armed) continue;  // not ours to take (cannot happen)
        m_state[b] = buffer_state::full;
        m_full_order[b] = m_captures++;
        ++m_stats.pairs_captured;
    }
    // The next pair goes to a free buffer if there is one (overlapped mode:
    // the other buffer, while this one waits to be processed).
    arm_free_buffer();
}

int control_program::oldest_full_buffer() const {
    int best = -1;
    for (int b = 0; b < m_buffers; ++b) {
        if (m_state[b] == buffer_state::full &&
            (best < 0 || m_full_order[b] < m_full_order[best])) {
            best = b;
        }
    }
    return best;
}

void control_program::handle_sync_error() {
    const uint32_t verdict = card_read(card_regs::verdict);
    const uint32_t position = card_read(card_regs::mismatch_pos);
    const uint32_t status = card_read(card_regs::status);
    card_write(card_regs::irq_status, card_regs::irq_status_sync_error_mask);
    ++m_stats.sync_errors;
    report(firmware_event::sync_error, 0, verdict, position);
    if ((status & card_regs::status_hard_error_mask) != 0) {
        rearm(rearm_cause::hard_error);
    } else if (m_config.rearm_on_every_sync_error) {
        rearm(rearm_cause::sync_error);
    }
}

void control_program::handle_overflow() {
    const uint32_t status = card_read(card_regs::status);
    const uint32_t count = card_read(card_regs::overflows);
    card_write(card_regs::irq_status, card_regs::irq_status_overflow_mask);
    ++m_stats.overflows;
    report(firmware_event::overflow, 0, status, count);
    if (m_config.rearm_on_overflow) rearm(rearm_cause::overflow);
}

uint32_t control_program::card_progress() {
    return card_read(card_regs::pairs_ok) + card_read(card_regs::mismatches) +
           card_read(card_regs::overflows);
}

// Timer 1 fires every watchdog period; the card is silent if none of its
// event counters moved since the last tick (or since OE was raised).
void control_program::handle_watchdog() {
    const uint32_t progress = card_progress();
    if (progress != m_watchdog_progress) {
        m_watchdog_progress = progress;
        return;
    }
    ++m_stats.watchdogs;
    report(firmware_event::watchdog, 0, m_hal->read32(timer1 + timer::prd));
    rearm(rearm_cause::watchdog);
}

// ENABLE 0 -> 1: the card drops OE, returns to IDLE, and starts again (a new
// dark-pixel check). Waits for IDLE so the card surely sees the 0. A card
// that keeps failing (hard errors or silence with no good pair in between)
// is given up after config.hard_error_rearms re-arms: no hang, a reported
// hard error (docs/fault-contract.md).
void control_program::rearm(rearm_cause cause) {
    if (cause == rearm_cause::hard_error || cause == rearm_cause::watchdog) {
        if (++m_failures > m_config.hard_error_rearms) {
            lower_oe();
            m_stats.gave_up = true;
            report(firmware_event::hard_error, 0, static_cast<uint32_t>(cause), m_failures);
            return;
        }
    }
    lower_oe();
    for (uint32_t i = 0; i < m_config.rearm_idle_polls; ++i) {
        const uint32_t state = (card_read(card_regs::status) & card_regs::status_state_mask) >>
                               card_regs::status_state_shift;
        if (state == 0) break;
    }
    card_write(card_regs::irq_status,
               card_regs::irq_status_sync_error_mask | card_regs::irq_status_overflow_mask);
    ++m_stats.rearms;
    report(firmware_event::card_rearmed, 0, static_cast<uint32_t>(cause));
    raise_oe();
}

void control_program::process_buffer(int buffer) {
    // The other buffer (overlapped mode) is armed already: a buffer is only
    // ever free while another one is armed (handle_edma, below).
    m_state[buffer] = buffer_state::busy;

    const uint8_t* header = m_hal->memory(buffer_address(buffer), header_size());
    uint32_t words[dma::status_words] = {};
    for (uint32_t i = 0; i < dma::status_words; ++i) {
        const uint8_t* p = header + 4 * i;
        words[i] = uint32_t{p[0]} | uint32_t{p[1]} << 8 | uint32_t{p[2]} << 16 |
                   uint32_t{p[3]} << 24;  // little endian, as the C6416 stores it
    }
    const uint32_t verdict = words[dma::hdr_verdict];
    const uint32_t pair = words[dma::hdr_pairs_ok];

    m_hal->stage_begin(stage::capture);
    m_hal->charge_cycles(stage::capture, m_config.capture_cycles);
    m_hal->stage_end(stage::capture);

    if (m_have_pair && pair > m_stats.last_pair + 1) {
        const uint32_t dropped = pair - m_stats.last_pair - 1;
        m_stats.pairs_dropped += dropped;
        report(firmware_event::pair_dropped, pair, dropped);
    }
    m_have_pair = true;
    m_stats.last_pair = pair;
    report(firmware_event::pair_captured, pair, verdict, static_cast<uint32_t>(buffer));

    if ((verdict & verdict_causes_mask) != 0) {
        ++m_stats.pairs_rejected;
        report(firmware_event::pair_rejected, pair, verdict);
    } else {
        m_failures = 0;  // a good pair: the card works
        if (m_awaiting_in_step) {
            m_awaiting_in_step = false;
            report(firmware_event::in_step, pair, verdict);
        }
        const uint32_t left_at = left_address(buffer), right_at = right_address(buffer);
        const uint8_t* left = m_hal->memory(left_at, frame_bytes());
        const uint8_t* right = m_hal->memory(right_at, frame_bytes());
        report(firmware_event::frames_used, pair, left_at, right_at);
        const int w = static_cast<int>(m_width), h = static_cast<int>(m_height);
        const frame_output out =
            m_controller.process_pair(gray_cplane{left, w, h, w}, gray_cplane{right, w, h, w});
        ++m_stats.pairs_processed;
        m_hal->report_result(pair, out);
        report(firmware_event::pair_processed, pair, static_cast<uint32_t>(buffer),
               out.has_point ? 1u : 0u);
    }
    m_state[buffer] = buffer_state::free;
    arm_free_buffer();
}

}  // namespace dsp
