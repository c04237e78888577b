// A minimal sensor pin generator for the card tests (independent of
// model/sensor, so the card is proven against a timing written plainly
// here). One call of step() is one master pixel clock: the pins it returns are
// driven after that clock's rising edge and sampled by the card at the next.
//
// Timing (the same conventions as docs/sensor.md): line 0, column 0 of a frame
// is where VSYNC rises; VSYNC stays high vsync_pclks clocks. Readout rows are
// lines v_start.. and readout columns h_start..; there HREF and VALID are
// high. A readout line is: dark left | border left | active | border right |
// dark right; a readout frame: dark top | border top | active | border bottom
// | dark bottom. After OE is seen high the first frame starts after
// startup_latency (+ an injected extra delay) clocks; OE low stops the sensor
// at once. Pixel values are a fixed function of (camera, frame serial, row,
// column), the serial being frame_serial(OE start, frame within it), so a
// test can say what every word read from the card must hold and which frame
// of which start it is (the same serial in both sensors for the same slot).
#pragma once

#include <cstdint>
#include <vector>

namespace rtl_test {

struct sensor_layout {
    int line_total = 800;
    int h_start = 0;
    int dark_left = 16, border_left = 0, active_cols = 640, border_right = 0, dark_right = 0;
    int frame_lines = 525;
    int v_start = 27;
    int dark_top = 8, border_top = 0, active_rows = 480, border_bottom = 0, dark_bottom = 0;
    int vsync_pclks = 1600;

    int readout_cols() const {
        return dark_left + border_left + active_cols + border_right + dark_right;
    }
    int readout_rows() const {
        return dark_top + border_top + active_rows + border_bottom + dark_bottom;
    }
    int64_t frame_pclks() const { return int64_t{line_total} * frame_lines; }
    int words_per_line() const { return active_cols / 4; }
    int words_per_frame() const { return words_per_line() * active_rows; }
};

// docs/design-brief.md default profile, as model/sensor's default_profile() lays it out:
// 800 x 525 pclk, 16 dark columns then 640 active, VSYNC 2 lines, first
// readout row at line 27, 8 dark rows then 480 active.
inline sensor_layout vga_layout() {
    return sensor_layout{};
}

// 32 x 16 active pixels with every layout element present (border and dark
// on all sides): 50 pclk x 25 lines = 1250 pclk per frame.
inline sensor_layout small_layout() {
    sensor_layout l;
    l.line_total = 50;
    l.h_start = 2;
    l.dark_left = 4;
    l.border_left = 2;
    l.active_cols = 32;
    l.border_right = 2;
    l.dark_right = 2;
    l.frame_lines = 25;
    l.v_start = 2;
    l.dark_top = 2;
    l.border_top = 1;
    l.active_rows = 16;
    l.border_bottom = 1;
    l.dark_bottom = 1;
    l.vsync_pclks = 50;
    return l;
}

// The smallest frame with every region the check needs: 8 x 2 active pixels
// in a 16 x 8 pclk frame (128 pclk), so 2^16 frames are 8.4 M pixel clocks.
inline sensor_layout tiny_layout() {
    sensor_layout l;
    l.line_total = 16;
    l.h_start = 1;
    l.dark_left = 2;
    l.border_left = 0;
    l.active_cols = 8;
    l.border_right = 0;
    l.dark_right = 1;
    l.frame_lines = 8;
    l.v_start = 1;
    l.dark_top = 1;
    l.border_top = 0;
    l.active_rows = 2;
    l.border_bottom = 0;
    l.dark_bottom = 1;
    l.vsync_pclks = 16;
    return l;
}

struct sensor_pin_state {
    bool vsync = false, href = false, valid = false;
    bool fodd = false;  // frame identity: toggles per new frame since the OE start
    uint8_t data = 0;
};

constexpr uint8_t test_black_level = 12;  // dark pixels read 12..15, below the threshold 32
constexpr uint8_t test_border_value = 200;

constexpr uint32_t frames_per_start = 1024;
inline uint32_t frame_serial(unsigned start, uint32_t frame) {
    return start * frames_per_start + frame;
}

// Active pixel value of camera cam (0 left, 1 right), frame serial f, active row y, column x.
inline uint8_t active_pixel(int cam, uint32_t f, int y, int x) {
    uint32_t h = static_cast<uint32_t>(cam) * 0x9E3779B1u ^ f * 0x85EBCA77u ^
                 static_cast<uint32_t>(y) * 0xC2B2AE3Du ^ static_cast<uint32_t>(x) * 0x27D4EB2Fu;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    return static_cast<uint8_t>(h);
}

// Word w (0-based) of active row y: pixel 4w + n in bits 8n+7..8n.
inline uint32_t active_word(int cam, uint32_t f, int y, int w) {
    uint32_t word = 0;
    for (int n = 0; n < 4; ++n) word |= uint32_t{active_pixel(cam, f, y, 4 * w + n)} << (8 * n);
    return word;
}

class test_sensor {
  public:
    struct frame_record {
        uint64_t start_cycle;  // step() index at which line 0 column 0 was driven
        uint32_t serial;       // frame_serial(start, frame)
        unsigned start;        // OE start it belongs to (0 = first)
    };

    test_sensor(const sensor_layout& layout, int camera, int startup_latency)
        : m_l(layout), m_cam(camera), m_latency(startup_latency) {}

    // Faults (docs/card.md lists what the card must conclude for each).
    void set_start_extra(std::vector<int> extra_per_start) { m_start_extra = extra_per_start; }
    void set_start_extra_always(int extra) { m_extra_always = extra; }
    void never_start() { m_dead = true; }
    // In-run faults act in frame `frame` counted from OE start number `start`
    // (0 = the first start), so a restart does not repeat them.
    // Before that frame insert `pclks` idle clocks (the sensor slips).
    void slip_before_frame(uint32_t frame, int pclks, unsigned start = 0) {
        m_slip_frame = frame;
        m_slip_pclks = pclks;
        m_slip_start = start;
    }
    // Readout row `row` of the frame carries no HREF / VALID.
    void drop_line(uint32_t frame, int row, unsigned start = 0) {
        m_drop_frame = key(start, frame);
        m_drop_row = row;
    }
    // An extra one-line VSYNC pulse starting at (line, col) of the frame.
    void extra_vsync(uint32_t frame, int line, int col, unsigned start = 0) {
        m_xvs_frame = key(start, frame);
        m_xvs_begin = int64_t{line} * m_l.line_total + col;
    }
    // The pixel at readout (row, col) of the frame reads `value` (light leak).
    void poke_pixel(uint32_t frame, int row, int col, uint8_t value, unsigned start = 0) {
        m_poke_frame = key(start, frame);
        m_poke_row = row;
        m_poke_col = col;
        m_poke_value = value;
    }

    // The frame is sent twice: a repeat (same pixels, same FODD) is inserted
    // after it, in the next frame's place; the frames after it go on.
    void repeat_frame(uint32_t frame, unsigned start = 0) { m_repeat_after = key(start, frame); }
    // FODD inverted in every frame (a sensor one frame count out of step).
    void invert_fodd() { m_fodd_inverted = true; }

    // One pixel clock. oe: the OE level this clock's rising edge sampled.
    sensor_pin_state step(bool oe) {
        const uint64_t cycle = m_cycle++;
        if (!oe) {
            m_phase = phase::idle;
            return {};
        }
        if (m_phase == phase::idle) {
            if (m_dead) return {};
            const int extra = m_starts < m_start_extra.size() ? m_start_extra[m_starts] : 0;
            ++m_starts;
            m_countdown = m_latency + extra + m_extra_always;
            m_phase = phase::starting;
            m_frame = 0;
        }
        if (m_phase == phase::starting || m_phase == phase::gap) {
            if (m_countdown-- > 0) return {};
            m_phase = phase::frame;
            m_pos = 0;
            m_frames.push_back({cycle, frame_serial(m_starts - 1, m_frame), m_starts - 1});
        }
        const sensor_pin_state pins = pins_at(m_pos);
        if (++m_pos == m_l.frame_pclks()) {
            m_pos = 0;
            if (m_repeating) {
                m_repeating = false;
            } else if (key(m_starts - 1, m_frame) == m_repeat_after) {
                m_repeating = true;  // the same frame again (m_frame unchanged)
                m_frames.push_back({cycle + 1, frame_serial(m_starts - 1, m_frame), m_starts - 1});
                return pins;
            }
            ++m_frame;
            if (m_frame == m_slip_frame && m_starts - 1 == m_slip_start && m_slip_pclks > 0) {
                m_phase = phase::gap;
                m_countdown = m_slip_pclks;  // this many idle clocks, then the frame
                m_slip_frame = UINT32_MAX;
            } else {
                m_frames.push_back({cycle + 1, frame_serial(m_starts - 1, m_frame), m_starts - 1});
            }
        }
        return pins;
    }

    const std::vector<frame_record>& frames() const { return m_frames; }
    unsigned starts() const { return m_starts; }
    uint32_t frame() const { return m_frame; }

  private:
    enum class phase { idle, starting, gap, frame };
    static uint64_t key(unsigned start, uint32_t frame) { return (uint64_t{start} << 32) | frame; }

    sensor_pin_state pins_at(int64_t pos) const {
        sensor_pin_state p;
        const int line = static_cast<int>(pos / m_l.line_total);
        const int col = static_cast<int>(pos % m_l.line_total);
        const uint64_t now_key = key(m_starts - 1, m_frame);
        p.fodd = ((m_frame & 1u) != 0) != m_fodd_inverted;
        p.vsync = pos < m_l.vsync_pclks || (now_key == m_xvs_frame && pos >= m_xvs_begin &&
                                            pos < m_xvs_begin + m_l.line_total);
        const int row = line - m_l.v_start;
        const int rc = col - m_l.h_start;
        if (row < 0 || row >= m_l.readout_rows() || rc < 0 || rc >= m_l.readout_cols()) return p;
        if (now_key == m_drop_frame && row == m_drop_row) return p;
        p.href = p.valid = true;
        const int act_c0 = m_l.dark_left + m_l.border_left;
        const int act_r0 = m_l.dark_top + m_l.border_top;
        const bool dark_col = rc < m_l.dark_left || rc >= m_l.readout_cols() - m_l.dark_right;
        const bool dark_row = row < m_l.dark_top || row >= m_l.readout_rows() - m_l.dark_bottom;
        const bool active = rc >= act_c0 && rc < act_c0 + m_l.active_cols && row >= act_r0 &&
                            row < act_r0 + m_l.active_rows;
        if (dark_col || dark_row)
            p.data = static_cast<uint8_t>(test_black_level + ((row + rc) & 3));
        else if (active)
            p.data =
                active_pixel(m_cam, frame_serial(m_starts - 1, m_frame), row - act_r0, rc - act_c0);
        else
            p.data = test_border_value;
        if (now_key == m_poke_frame && row == m_poke_row && rc == m_poke_col) p.data = m_poke_value;
        return p;
    }

    sensor_layout m_l;
    int m_cam;
    int m_latency;
    std::vector<int> m_start_extra;
    int m_extra_always = 0;
    bool m_dead = false;
    uint32_t m_slip_frame = UINT32_MAX;
    unsigned m_slip_start = 0;
    int m_slip_pclks = 0;
    uint64_t m_drop_frame = UINT64_MAX;
    int m_drop_row = -1;
    uint64_t m_xvs_frame = UINT64_MAX;
    int64_t m_xvs_begin = 0;
    uint64_t m_poke_frame = UINT64_MAX;
    int m_poke_row = -1, m_poke_col = -1;
    uint8_t m_poke_value = 0;

    phase m_phase = phase::idle;
    uint64_t m_cycle = 0;
    unsigned m_starts = 0;
    int m_countdown = 0;
    int64_t m_pos = 0;
    uint32_t m_frame = 0;  // frames since the current start (a repeat not counted)
    uint64_t m_repeat_after = UINT64_MAX;
    bool m_repeating = false;  // the current frame is the repeat
    bool m_fodd_inverted = false;
    std::vector<frame_record> m_frames;
};

}  // namespace rtl_test
