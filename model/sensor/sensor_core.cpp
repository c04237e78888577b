#include "model/sensor/sensor_core.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace sensor {

namespace {

constexpr uint64_t startup_stream_salt = 0x53544152545550ull;  // "STARTUP"

// The profile, once it and the config are known to be consistent.
const sensor_profile& checked(const sensor_profile& profile, const sensor_config& config) {
    const std::string problem = profile.validate();
    if (!problem.empty())
        throw std::invalid_argument("sensor profile '" + profile.name + "': " + problem);
    if (config.gain_q8 <= 0 || config.exposure_lines < 0)
        throw std::invalid_argument("sensor config: gain_q8 must be > 0, exposure_lines >= 0");
    return profile;
}

}  // namespace

sensor_core::sensor_core(const sensor_profile& profile, scene::camera_id camera,
                         frame_source& source, const sensor_config& config)
    : m_profile(checked(profile, config)),
      m_camera(camera),
      m_source(source),
      m_config(config),
      m_pixels(m_profile, config),
      m_startup_rng(config.seed ^ startup_stream_salt) {
    m_exposure_lines = config.exposure_lines > 0 ? config.exposure_lines : m_profile.exposure_lines;
    set_gain_q8(config.gain_q8);

    const double p = m_profile.extra_delay_probability;
    m_extra_threshold = p >= 1.0 ? std::numeric_limits<uint64_t>::max()
                                 : static_cast<uint64_t>(p * 18446744073709551616.0L);

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

// Between frames the sensor drives its idle bus (valid); before its first
// frame after a start, and while stopped, it does not.
uint16_t sensor_core::const_word() const {
    return (m_phase == phase::gap && m_output_since_start) ? pin_word::valid_bit : 0;
}

void sensor_core::fill_const_segment() {
    m_seg_start_cycle = m_cycle;
    m_col = 0;
    uint64_t len = static_cast<uint64_t>(m_profile.line_pclks);
    if (m_phase_end != never) len = std::min(len, m_phase_end - m_cycle);
    m_seg_natural_end = static_cast<int>(len);
    std::fill(m_words.begin(), m_words.begin() + m_seg_natural_end, const_word());
    m_effects.apply(m_words.data(), 0, m_seg_natural_end, m_seg_start_cycle);
    m_line_href_col = m_line_first_active = m_line_last_active = -1;
    m_effects.drop_finished_glitches(m_cycle);
    limit_segment();
}

// ---------------------------------------------------------------------------
// Frames.

void sensor_core::begin_frame_or_gap() {
    const uint64_t k = m_frames_started;
    int skew = 0;
    for (pending& p : m_pending) {
        if (p.fired || p.f.kind != fault_kind::start_skew) continue;
        if (!frame_fault_reached(p.f, k, m_cycle)) continue;
        p.fired = true;
        p.in_gap = true;
        skew += p.f.skew_pclks;
    }
    m_skew_pending = skew;
    if (skew > 0)
        enter_const_phase(phase::gap, m_cycle + static_cast<uint64_t>(skew));
    else
        begin_frame();
}

void sensor_core::begin_frame() {
    frame_truth t = new_frame_truth();
    take_frame_faults(t);
    m_current_scene_frame = t.scene_frame;
    t.faults |= m_persistent_faults | m_effects.open_glitch_bits(m_cycle);
    if (!m_frame_dropped) load_frame_image(t);
    m_pixels.set_gain_q16((static_cast<int64_t>(m_config.gain_q8) * 256 * m_exposure_lines +
                           m_profile.exposure_lines / 2) /
                          m_profile.exposure_lines);

    m_truth.push_back(t);
    m_phase = phase::frame;
    m_phase_end = never;
    m_frame_start_cycle = m_cycle;
    m_line = 0;
    m_output_since_start = true;
    begin_line();
}

// The record of the frame starting now: its index, edges, start skew and
// scene frame.
frame_truth sensor_core::new_frame_truth() {
    frame_truth t;
    t.index = m_frames_started++;
    t.start_cycle = m_cycle;
    t.start_tick = rise_of(m_cycle);
    t.vsync_tick = fall_of(m_cycle);
    t.skew_before_pclks = m_skew_pending;
    if (m_skew_pending > 0) t.faults |= fault_bit(fault_kind::start_skew);
    m_skew_pending = 0;
    for (pending& p : m_pending) p.in_gap = false;

    if (m_next_is_extra) {
        t.scene_frame = m_current_scene_frame;
        t.repeated = true;
        t.faults |= fault_bit(fault_kind::extra_frame);
        m_next_is_extra = false;
    } else {
        m_fodd = (m_frames_since_oe++ & 1u) != 0;
        // The time slot, not a count of this sensor's frames: two sensors'
        // counts stay apart after an OE stop that came when one had begun a
        // frame and the other had not.
        t.scene_frame = scene_slot_of(t.start_tick);
    }
    t.fodd = m_fodd;
    return t;
}

// Only a repeated frame reuses the held image. A new frame in the slot of
// one cut short by OE asks again: a time-based source (the renderer) then
// renders its own exposure window, the same as an in-step partner's.
void sensor_core::load_frame_image(const frame_truth& t) {
    if (t.repeated && m_pixels.holds_image_of(t.scene_frame)) return;
    const dsp::rgb_cplane img = m_source.frame(image_request(t));
    if (img.data == nullptr || img.width != m_profile.active_cols ||
        img.height != m_profile.active_rows)
        throw std::runtime_error("sensor '" + m_profile.name + "': frame source gave a " +
                                 std::to_string(img.width) + "x" + std::to_string(img.height) +
                                 " image for scene frame " + std::to_string(t.scene_frame) +
                                 ", profile needs " + std::to_string(m_profile.active_cols) + "x" +
                                 std::to_string(m_profile.active_rows));
    m_pixels.hold_image(img, t.scene_frame);
}

frame_request sensor_core::image_request(const frame_truth& t) const {
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
    return req;
}

void sensor_core::finish_frame(bool complete) {
    m_truth.back().complete = complete;
    if (complete && m_extra_after) m_next_is_extra = true;
    m_extra_after = false;
}

// ---------------------------------------------------------------------------
// Lines.

void sensor_core::begin_line() {
    m_seg_start_cycle = m_cycle;
    m_col = 0;
    m_seg_natural_end = m_profile.line_pclks;
    m_line_dropped = false;
    m_effects.drop_finished_glitches(m_cycle);

    const int r = m_line - m_profile.first_row_line;
    const bool readout = !m_frame_dropped && r >= 0 && r < m_profile.readout_rows();
    if (readout) m_line_dropped = take_dropped_line();
    const bool carries = readout && !m_line_dropped;
    const bool active_row = carries && r >= m_profile.active_row0() &&
                            r < m_profile.active_row0() + m_profile.active_rows;
    m_line_href_col = carries ? m_profile.href_start : -1;
    m_line_first_active = active_row ? m_first_active_col : -1;
    m_line_last_active = active_row ? m_last_active_col : -1;
    build_line(0);
    limit_segment();
}

// The words of the current line from column from_col on: VSYNC, the
// readout (pixel_pipeline), then the pin faults.
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
    const uint16_t level = m_fodd ? static_cast<uint16_t>(valid | pin_word::fodd_bit) : valid;
    for (int c = from_col; c < line; ++c)
        w[c] = c < vsync_end ? static_cast<uint16_t>(level | pin_word::vsync_bit) : level;

    if (m_line_href_col >= 0) {
        m_pixels.read_row(m_line - m_profile.first_row_line,
                          std::max(0, from_col - m_profile.href_start),
                          m_effects.dark_level(m_profile.black_level), w + m_profile.href_start);
    }
    m_effects.apply(w, from_col, line, m_seg_start_cycle);
}

// ---------------------------------------------------------------------------
// OE, marks and segment ends.

void sensor_core::on_oe_edge(bool oe) {
    if (oe) {
        if (m_effects.never_start() || m_phase != phase::idle) return;
        start_record rec;
        rec.oe_cycle = m_cycle;
        m_frames_since_oe = 0;
        rec.latency_pclks = draw_startup_latency(&rec.extra_pclks);
        m_starts.push_back(rec);
        m_output_since_start = false;
        enter_const_phase(phase::starting, m_cycle + static_cast<uint64_t>(rec.latency_pclks));
    } else {
        if (m_effects.ignore_oe() && m_phase != phase::idle) return;
        if (m_phase == phase::frame) finish_frame(false);
        for (pending& p : m_pending) {
            if (p.in_gap) p.fired = false;
            p.in_gap = false;
        }
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
