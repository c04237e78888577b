#include "model/sensor/sensor_core.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sensor {

namespace {

// Image coordinate of a border pixel: the outermost 2x2 CFA cell repeats, so
// the colour (parity) of every position is kept.
int clamp_keep_parity(int v, int size) {
    if (v < 0) return v & 1;
    if (v >= size) return size - 2 + ((v - size) & 1);
    return v;
}

// Channel (0 = R, 1 = G, 2 = B) sampled at (x & 1, y & 1) for each CFA order,
// as dsp::cfa_order defines them (rggb = R at (0,0), G at (1,0), G at (0,1)).
constexpr uint8_t cfa_channel[4][2][2] = {
    {{0, 1}, {1, 2}},  // rggb
    {{2, 1}, {1, 0}},  // bggr
    {{1, 0}, {2, 1}},  // grbg
    {{1, 2}, {0, 1}},  // gbrg
};

int clamp_u8(int v) {
    return v < 0 ? 0 : (v > 255 ? 255 : v);
}

constexpr uint64_t startup_stream_salt = 0x53544152545550ull;  // "STARTUP"
constexpr uint64_t noise_stream_salt = 0x4E4F495345ull;        // "NOISE"

}  // namespace

const char* fault_kind_name(fault_kind kind) {
    switch (kind) {
        case fault_kind::start_skew:
            return "start_skew";
        case fault_kind::dropped_line:
            return "dropped_line";
        case fault_kind::dropped_frame:
            return "dropped_frame";
        case fault_kind::extra_frame:
            return "extra_frame";
        case fault_kind::vsync_glitch:
            return "vsync_glitch";
        case fault_kind::href_glitch:
            return "href_glitch";
        case fault_kind::pclk_drift:
            return "pclk_drift";
        case fault_kind::dark_leak:
            return "dark_leak";
        case fault_kind::stuck_data_bit:
            return "stuck_data_bit";
        case fault_kind::never_start:
            return "never_start";
        case fault_kind::ignore_oe:
            return "ignore_oe";
    }
    return "?";
}

uint32_t timing_fault_mask() {
    return fault_bit(fault_kind::dropped_line) | fault_bit(fault_kind::dropped_frame) |
           fault_bit(fault_kind::vsync_glitch) | fault_bit(fault_kind::href_glitch);
}

bool pair_in_step(const frame_truth& a, const frame_truth& b, simtime::rational_ticks pclk) {
    if (!a.complete || !b.complete || a.dropped || b.dropped) return false;
    if (!a.have_active || !b.have_active) return false;
    if (a.scene_frame != b.scene_frame) return false;
    if (((a.faults | b.faults) & timing_fault_mask()) != 0) return false;
    const auto within_one_clock = [&](simtime::ticks x, simtime::ticks y) {
        const simtime::ticks d = x > y ? x - y : y - x;
        return static_cast<__int128>(d) * pclk.den < pclk.num;
    };
    return within_one_clock(a.first_active_tick, b.first_active_tick) &&
           within_one_clock(a.last_active_tick, b.last_active_tick);
}

sensor_core::sensor_core(const sensor_profile& profile, scene::camera_id camera,
                         frame_source& source, const sensor_config& config)
    : m_profile(profile),
      m_camera(camera),
      m_source(source),
      m_config(config),
      m_startup_rng(config.seed ^ startup_stream_salt) {
    const std::string problem = m_profile.validate();
    if (!problem.empty())
        throw std::invalid_argument("sensor profile '" + m_profile.name + "': " + problem);
    if (config.gain_q8 <= 0 || config.exposure_lines < 0)
        throw std::invalid_argument("sensor config: gain_q8 must be > 0, exposure_lines >= 0");

    m_exposure_lines = config.exposure_lines > 0 ? config.exposure_lines : m_profile.exposure_lines;
    set_gain_q8(config.gain_q8);

    const double p = m_profile.extra_delay_probability;
    m_extra_threshold = p >= 1.0 ? std::numeric_limits<uint64_t>::max()
                                 : static_cast<uint64_t>(p * 18446744073709551616.0L);

    m_noise.configure(config.noise, config.read_noise_dn, config.shot_noise_dn2_per_dn,
                      config.seed ^ noise_stream_salt);

    m_col_image_x.resize(m_profile.readout_cols());
    for (int i = 0; i < m_profile.readout_cols(); ++i) {
        const int dark_end = m_profile.readout_cols() - m_profile.dark_cols_right;
        const bool dark = i < m_profile.dark_cols_left || i >= dark_end;
        m_col_image_x[i] =
            dark ? -1 : clamp_keep_parity(i - m_profile.active_col0(), m_profile.active_cols);
    }
    m_row_image_y.resize(m_profile.readout_rows());
    for (int r = 0; r < m_profile.readout_rows(); ++r) {
        const int dark_end = m_profile.readout_rows() - m_profile.dark_rows_bottom;
        const bool dark = r < m_profile.dark_rows_top || r >= dark_end;
        m_row_image_y[r] =
            dark ? -1 : clamp_keep_parity(r - m_profile.active_row0(), m_profile.active_rows);
    }
    m_first_active_col = m_profile.href_start + m_profile.active_col0();
    m_last_active_col = m_first_active_col + m_profile.active_cols - 1;

    m_clock = simtime::tick_clock(m_profile.pclk_period(), config.clock_origin);
    m_cursor.reset(m_clock);
    m_words.assign(static_cast<size_t>(m_profile.line_pclks), 0);
    enter_const_phase(phase::idle, never);
}

uint64_t sensor_core::scene_slot_of(simtime::ticks start_tick) const {
    // P = frame_pclks * N / D ticks, so floor((x + P/2) / P) =
    // floor((2 D x + F N) / (2 F N)) in integers (128-bit: x up to 2^62).
    const simtime::rational_ticks pclk = m_profile.pclk_period();
    const __int128 fn = static_cast<__int128>(m_profile.frame_pclks()) * pclk.num;
    const __int128 x = static_cast<__int128>(start_tick) - m_config.scene_origin;
    const __int128 num = 2 * static_cast<__int128>(pclk.den) * x + fn;
    if (num < 0) return 0;
    return static_cast<uint64_t>(num / (2 * fn));
}

void sensor_core::set_gain_q8(int gain_q8) {
    if (gain_q8 <= 0) throw std::invalid_argument("gain_q8 must be > 0");
    m_config.gain_q8 = gain_q8;
}

void sensor_core::set_exposure_lines(int lines) {
    if (lines <= 0) throw std::invalid_argument("exposure_lines must be > 0");
    m_exposure_lines = lines;
}

void sensor_core::add_fault(const fault& f) {
    if (f.kind == fault_kind::stuck_data_bit && (f.bit < 0 || f.bit > 7))
        throw std::invalid_argument("stuck_data_bit: bit must be 0..7");
    if ((f.kind == fault_kind::vsync_glitch || f.kind == fault_kind::href_glitch) &&
        f.width_pclks < 1)
        throw std::invalid_argument("glitch width must be >= 1 pclk");
    if (f.kind == fault_kind::start_skew && f.skew_pclks < 0)
        throw std::invalid_argument("start_skew must be >= 0 pclk");
    if (f.kind == fault_kind::pclk_drift && (f.drift_ppm <= -1000000 || f.drift_ppm >= 1000000))
        throw std::invalid_argument("pclk_drift: |ppm| must be < 1e6");
    m_pending.push_back({f, false});
    // A pixel fault may now start inside the current segment.
    limit_segment();
}

// ---------------------------------------------------------------------------
// The slow path: segment ends, fault onsets, OE edges, marked columns.

pin_word sensor_core::step_slow(bool oe) {
    settle();
    if (oe != m_oe) {
        m_oe = oe;
        on_oe_edge(oe);
    }
    advance_clock();
    note_marks();
    const pin_word w{m_words[m_col]};
    ++m_col;
    ++m_cycle;
    limit_segment();
    return w;
}

void sensor_core::settle() {
    for (;;) {
        activate_due_faults();
        if (m_col < m_seg_natural_end) break;
        advance_segment();
    }
    limit_segment();
}

void sensor_core::advance_segment() {
    switch (m_phase) {
        case phase::frame:
            if (m_line + 1 < m_profile.frame_lines) {
                ++m_line;
                begin_line();
            } else {
                finish_frame(true);
                begin_frame_or_gap();
            }
            break;
        case phase::idle:
            fill_const_segment();
            break;
        case phase::starting:
            if (m_cycle >= m_phase_end)
                begin_frame_or_gap();
            else
                fill_const_segment();
            break;
        case phase::gap:
            if (m_cycle >= m_phase_end)
                begin_frame();
            else
                fill_const_segment();
            break;
    }
}

void sensor_core::enter_const_phase(phase p, uint64_t end_cycle) {
    m_phase = p;
    m_phase_end = end_cycle;
    fill_const_segment();
}

void sensor_core::fill_const_segment() {
    m_seg_start_cycle = m_cycle;
    m_col = 0;
    uint64_t len = static_cast<uint64_t>(m_profile.line_pclks);
    if (m_phase_end != never) len = std::min(len, m_phase_end - m_cycle);
    m_seg_natural_end = static_cast<int>(len);
    // Between frames the sensor drives its idle bus (valid); before its first
    // frame after a start, and while stopped, it does not.
    const uint16_t word = (m_phase == phase::gap && m_output_since_start) ? pin_word::valid_bit : 0;
    std::fill(m_words.begin(), m_words.begin() + m_seg_natural_end, word);
    finalize_words(0, m_seg_natural_end, m_seg_start_cycle);
    m_line_href_col = m_line_first_active = m_line_last_active = -1;
    drop_finished_glitches();
    limit_segment();
}

void sensor_core::begin_frame_or_gap() {
    const uint64_t k = m_frames_started;
    int skew = 0;
    for (pending& p : m_pending) {
        if (p.fired || p.f.kind != fault_kind::start_skew) continue;
        if (!frame_fault_reached(p.f, k, m_cycle)) continue;
        p.fired = true;
        skew += p.f.skew_pclks;
    }
    m_skew_pending = skew;
    if (skew > 0)
        enter_const_phase(phase::gap, m_cycle + static_cast<uint64_t>(skew));
    else
        begin_frame();
}

void sensor_core::begin_frame() {
    frame_truth t;
    t.index = m_frames_started++;
    t.start_cycle = m_cycle;
    t.start_tick = rise_of(m_cycle);
    t.vsync_tick = fall_of(m_cycle);
    t.skew_before_pclks = m_skew_pending;
    if (m_skew_pending > 0) t.faults |= fault_bit(fault_kind::start_skew);
    m_skew_pending = 0;

    if (m_next_is_extra) {
        t.scene_frame = m_current_scene_frame;
        t.repeated = true;
        t.faults |= fault_bit(fault_kind::extra_frame);
        m_next_is_extra = false;
    } else {
        // The time slot, not a count of this sensor's frames: two sensors'
        // counts stay apart after an OE stop that came when one had begun a
        // frame and the other had not.
        t.scene_frame = scene_slot_of(t.start_tick);
    }
    m_extra_after = false;
    m_frame_dropped = false;
    for (pending& p : m_pending) {
        if (p.fired) continue;
        if (p.f.kind != fault_kind::dropped_frame && p.f.kind != fault_kind::extra_frame) continue;
        if (!frame_fault_reached(p.f, t.index, m_cycle)) continue;
        p.fired = true;
        if (p.f.kind == fault_kind::dropped_frame) {
            m_frame_dropped = true;
            t.dropped = true;
            t.faults |= fault_bit(fault_kind::dropped_frame);
        } else {
            m_extra_after = true;
        }
    }
    m_current_scene_frame = t.scene_frame;
    t.faults |= m_persistent_faults;
    for (const glitch_window& g : m_glitches)
        if (g.end > m_cycle)
            t.faults |= fault_bit(g.bit == pin_word::vsync_bit ? fault_kind::vsync_glitch
                                                               : fault_kind::href_glitch);

    // Only a repeated frame reuses the held image. A new frame in the slot of
    // one cut short by OE asks again: a time-based source (the renderer) then
    // renders its own exposure window, the same as an in-step partner's.
    const bool reuse = t.repeated && m_have_image && m_image_scene_frame == t.scene_frame;
    if (!m_frame_dropped && !reuse) {
        const int64_t line = m_profile.line_pclks;
        const uint64_t first_active =
            m_cycle +
            static_cast<uint64_t>((m_profile.first_row_line + m_profile.active_row0()) * line +
                                  m_first_active_col);
        frame_request req;
        req.camera = m_camera;
        req.scene_frame = t.scene_frame;
        req.frame_start = t.start_tick;
        req.exposure =
            m_clock.rise(static_cast<uint64_t>(m_exposure_lines) * static_cast<uint64_t>(line)) -
            m_clock.origin();
        req.exposure_start = rise_of(first_active) - req.exposure;
        const dsp::rgb_cplane img = m_source.frame(req);
        if (img.data == nullptr || img.width != m_profile.active_cols ||
            img.height != m_profile.active_rows)
            throw std::runtime_error("sensor '" + m_profile.name + "': frame source gave a " +
                                     std::to_string(img.width) + "x" + std::to_string(img.height) +
                                     " image for scene frame " + std::to_string(t.scene_frame) +
                                     ", profile needs " + std::to_string(m_profile.active_cols) +
                                     "x" + std::to_string(m_profile.active_rows));
        m_image = img;
        m_have_image = true;
        m_image_scene_frame = t.scene_frame;
    }
    m_gain_q16 = (static_cast<int64_t>(m_config.gain_q8) * 256 * m_exposure_lines +
                  m_profile.exposure_lines / 2) /
                 m_profile.exposure_lines;

    m_truth.push_back(t);
    m_phase = phase::frame;
    m_phase_end = never;
    m_frame_start_cycle = m_cycle;
    m_line = 0;
    m_output_since_start = true;
    begin_line();
}

void sensor_core::begin_line() {
    m_seg_start_cycle = m_cycle;
    m_col = 0;
    m_seg_natural_end = m_profile.line_pclks;
    m_line_dropped = false;
    drop_finished_glitches();

    const int r = m_line - m_profile.first_row_line;
    const bool readout = !m_frame_dropped && r >= 0 && r < m_profile.readout_rows();
    if (readout) {
        for (pending& p : m_pending) {
            if (p.fired || p.f.kind != fault_kind::dropped_line) continue;
            const bool reached = p.f.when.by_time
                                     ? p.f.when.tick <= rise_of(m_cycle)
                                     : position_reached(p.f.when, m_truth.back().index, m_line, 0);
            if (!reached) continue;
            p.fired = true;
            m_line_dropped = true;
            m_truth.back().faults |= fault_bit(fault_kind::dropped_line);
        }
    }
    const bool carries = readout && !m_line_dropped;
    const bool active_row = carries && r >= m_profile.active_row0() &&
                            r < m_profile.active_row0() + m_profile.active_rows;
    m_line_href_col = carries ? m_profile.href_start : -1;
    m_line_first_active = active_row ? m_first_active_col : -1;
    m_line_last_active = active_row ? m_last_active_col : -1;
    build_line(0);
    limit_segment();
}

int sensor_core::pixel_value(int x, int y) {
    const dsp::rgb8 px = m_image.at(x, y);
    const uint8_t ch = cfa_channel[static_cast<int>(m_profile.cfa)][y & 1][x & 1];
    const int s = ch == 0 ? px.r : (ch == 1 ? px.g : px.b);
    // 64-bit: gain x exposure ratio may exceed 2^15 / 255; the signal
    // saturates far above 255 (the clamp below) and the noise table's range.
    const int64_t scaled = (static_cast<int64_t>(s) * m_gain_q16 + 32768) >> 16;
    const int signal = static_cast<int>(std::min<int64_t>(scaled, 1 << 20));
    int v = m_profile.black_level + signal;
    if (m_noise.enabled()) v += m_noise.sample(signal);
    return clamp_u8(v);
}

void sensor_core::build_line(int from_col) {
    const int line = m_profile.line_pclks;
    uint16_t* w = m_words.data();
    const uint16_t valid = pin_word::valid_bit;

    // VSYNC: the first vsync_pclks clocks of the frame (none in a dropped frame).
    const int64_t line_offset = static_cast<int64_t>(m_line) * line;
    int vsync_end = 0;
    if (!m_frame_dropped)
        vsync_end =
            static_cast<int>(std::clamp<int64_t>(m_profile.vsync_pclks - line_offset, 0, line));
    for (int c = from_col; c < line; ++c)
        w[c] = c < vsync_end ? static_cast<uint16_t>(valid | pin_word::vsync_bit) : valid;

    if (m_line_href_col >= 0) {
        const int y = m_row_image_y[m_line - m_profile.first_row_line];
        const int dark_level = m_leak ? m_leak_level : m_profile.black_level;
        const int n = m_profile.readout_cols();
        for (int i = std::max(0, from_col - m_profile.href_start); i < n; ++i) {
            const int x = m_col_image_x[i];
            int v;
            if (x < 0 || y < 0) {
                v = dark_level;
                if (m_noise.enabled()) v = clamp_u8(v + m_noise.sample(0));
            } else {
                v = pixel_value(x, y);
            }
            w[m_profile.href_start + i] =
                static_cast<uint16_t>(valid | pin_word::href_bit | static_cast<uint16_t>(v));
        }
    }
    finalize_words(from_col, line, m_seg_start_cycle);
}

void sensor_core::finalize_words(int from_col, int to_col, uint64_t cycle_of_col0) {
    uint16_t* w = m_words.data();
    if (m_stuck_mask != 0) {
        const uint16_t keep = static_cast<uint16_t>(~m_stuck_mask);
        for (int c = from_col; c < to_col; ++c)
            if (w[c] & pin_word::valid_bit)
                w[c] = static_cast<uint16_t>((w[c] & keep) | m_stuck_set);
    }
    for (const glitch_window& g : m_glitches) {
        const uint64_t lo = std::max(g.begin, cycle_of_col0 + static_cast<uint64_t>(from_col));
        const uint64_t hi = std::min(g.end, cycle_of_col0 + static_cast<uint64_t>(to_col));
        for (uint64_t cyc = lo; cyc < hi; ++cyc) {
            uint16_t& word = w[cyc - cycle_of_col0];
            if (word & pin_word::valid_bit) word ^= g.bit;
        }
    }
}

void sensor_core::finish_frame(bool complete) {
    m_truth.back().complete = complete;
    if (complete && m_extra_after) m_next_is_extra = true;
    m_extra_after = false;
}

void sensor_core::on_oe_edge(bool oe) {
    if (oe) {
        if (m_never_start || m_phase != phase::idle) return;
        start_record rec;
        rec.oe_cycle = m_cycle;
        rec.latency_pclks = draw_startup_latency(&rec.extra_pclks);
        m_starts.push_back(rec);
        m_output_since_start = false;
        enter_const_phase(phase::starting, m_cycle + static_cast<uint64_t>(rec.latency_pclks));
    } else {
        if (m_ignore_oe && m_phase != phase::idle) return;
        if (m_phase == phase::frame) finish_frame(false);
        m_skew_pending = 0;
        m_next_is_extra = false;
        m_output_since_start = false;
        enter_const_phase(phase::idle, never);
    }
}

void sensor_core::note_marks() {
    if (m_phase != phase::frame) return;
    frame_truth& t = m_truth.back();
    if (m_line == 0 && m_col == 0) {
        t.start_tick = m_last_rise;
        t.vsync_tick = m_last_fall;
    }
    if (m_col == m_line_href_col) ++t.lines_with_href;
    if (m_col == m_line_first_active && !t.have_active) {
        t.have_active = true;
        t.first_active_cycle = m_cycle;
        t.first_active_tick = m_last_fall;
    }
    if (m_col == m_line_last_active) {
        t.last_active_cycle = m_cycle;
        t.last_active_tick = m_last_fall;
    }
}

void sensor_core::limit_segment() {
    int end = m_seg_natural_end;
    const uint64_t onset = next_pixel_fault_onset();
    if (onset != never && onset < m_seg_start_cycle + static_cast<uint64_t>(end))
        end = static_cast<int>(onset - m_seg_start_cycle);
    if (m_phase == phase::frame) {
        const int marks[] = {m_line == 0 ? 0 : -1, m_line_href_col, m_line_first_active,
                             m_line_last_active};
        for (int mark : marks)
            if (mark >= m_col && mark < end) end = mark;
    }
    m_seg_end = end;
}

// ---------------------------------------------------------------------------
// Faults.

void sensor_core::drop_finished_glitches() {
    const uint64_t now = m_cycle;
    m_glitches.erase(std::remove_if(m_glitches.begin(), m_glitches.end(),
                                    [now](const glitch_window& g) { return g.end <= now; }),
                     m_glitches.end());
}

bool sensor_core::position_reached(const fault_trigger& t, uint64_t frame, int line,
                                   int col) const {
    if (t.frame != frame) return t.frame < frame;
    if (t.line != line) return t.line < line;
    return t.col <= col;
}

bool sensor_core::frame_fault_reached(const fault& f, uint64_t frame_index,
                                      uint64_t start_cycle) const {
    if (f.when.by_time) return f.when.tick <= rise_of(start_cycle);
    return position_reached(f.when, frame_index, 0, 0);
}

uint64_t sensor_core::onset_cycle(const fault& f) const {
    if (f.when.by_time) {
        const uint64_t n = m_clock_origin_cycle + m_clock.first_rise_at_or_after(f.when.tick);
        return std::max(n, m_cycle);
    }
    if (m_phase != phase::frame) return never;  // positions do not advance between frames
    const uint64_t current = m_truth.back().index;
    if (f.when.frame < current) return m_cycle;
    if (f.when.frame > current) return never;
    const uint64_t at = m_frame_start_cycle +
                        static_cast<uint64_t>(f.when.line) * m_profile.line_pclks +
                        static_cast<uint64_t>(f.when.col);
    return std::max(at, m_cycle);
}

static bool is_pixel_fault(fault_kind k) {
    return k != fault_kind::start_skew && k != fault_kind::dropped_frame &&
           k != fault_kind::extra_frame && k != fault_kind::dropped_line;
}

uint64_t sensor_core::next_pixel_fault_onset() const {
    uint64_t next = never;
    for (const pending& p : m_pending)
        if (!p.fired && is_pixel_fault(p.f.kind)) next = std::min(next, onset_cycle(p.f));
    return next;
}

bool sensor_core::activate_due_faults() {
    bool any = false;
    // Index loop: activate() never adds to m_pending.
    for (size_t i = 0; i < m_pending.size(); ++i) {
        pending& p = m_pending[i];
        if (p.fired || !is_pixel_fault(p.f.kind)) continue;
        if (onset_cycle(p.f) > m_cycle) continue;
        p.fired = true;
        activate(p.f);
        any = true;
    }
    if (any) {
        // Re-derive the rest of the current segment with the new fault state.
        if (m_phase == phase::frame) {
            build_line(m_col);
        } else {
            const uint16_t word =
                (m_phase == phase::gap && m_output_since_start) ? pin_word::valid_bit : 0;
            std::fill(m_words.begin() + m_col, m_words.begin() + m_seg_natural_end, word);
            finalize_words(m_col, m_seg_natural_end, m_seg_start_cycle);
        }
    }
    return any;
}

void sensor_core::activate(const fault& f) {
    const uint32_t bit = fault_bit(f.kind);
    switch (f.kind) {
        case fault_kind::vsync_glitch:
        case fault_kind::href_glitch:
            m_glitches.push_back(
                {m_cycle, m_cycle + static_cast<uint64_t>(f.width_pclks),
                 f.kind == fault_kind::vsync_glitch ? pin_word::vsync_bit : pin_word::href_bit});
            if (m_phase == phase::frame) m_truth.back().faults |= bit;
            return;
        case fault_kind::pclk_drift: {
            // The new oscillator's first edge is this cycle's rising edge, as
            // the master clock would have placed it (m_cursor is on it).
            const simtime::ticks origin = m_cursor.tick();
            m_clock = simtime::tick_clock(m_profile.pclk_period(), origin, f.drift_ppm);
            m_clock_origin_cycle = m_cycle;
            m_cursor.reset(m_clock);
            m_on_master_clock = false;
            break;
        }
        case fault_kind::dark_leak:
            m_leak = true;
            m_leak_level = clamp_u8(f.leak_level);
            break;
        case fault_kind::stuck_data_bit: {
            const uint16_t bit_mask = static_cast<uint16_t>(1u << f.bit);
            m_stuck_mask |= bit_mask;
            m_stuck_set = static_cast<uint16_t>(f.stuck_value ? (m_stuck_set | bit_mask)
                                                              : (m_stuck_set & ~bit_mask));
        } break;
        case fault_kind::never_start:
            m_never_start = true;
            break;
        case fault_kind::ignore_oe:
            m_ignore_oe = true;
            break;
        default:
            return;
    }
    m_persistent_faults |= bit;
    if (m_phase == phase::frame) m_truth.back().faults |= bit;
}

int sensor_core::draw_startup_latency(int* extra) {
    // Two draws per start whatever the outcome, so later starts do not depend
    // on earlier outcomes.
    const uint64_t u = m_startup_rng.next();
    const uint64_t v = m_startup_rng.next();
    *extra = 0;
    if (m_profile.extra_delay_probability > 0.0 && u < m_extra_threshold)
        *extra = 1 + static_cast<int>(v % static_cast<uint64_t>(m_profile.extra_delay_max_pclks));
    return m_profile.startup_latency_pclks + *extra;
}

}  // namespace sensor
