// The CMOS sensor model's core: plain C++, stepped one pixel clock at a time
// (for the fast RTL island); model/sensor/sensor_sc.h puts SystemC pins around
// the same core. The core is the timing FSM (sensor_core.cpp: start-up,
// frames, lines, segments); the pixels come from pixel_pipeline, the fault
// triggers are sensor_core_faults.cpp and their effects on the pins
// fault_effects. docs/sensor.md describes the pins and timing decisions,
// docs/sensor-faults.md the fault outcomes.
//
// Clocking: cycle n of the pixel clock starts with a rising edge (rise tick)
// and has a falling edge half a period later (fall tick). step(oe) runs cycle
// n: OE is the value sampled at the rising edge; the returned pins are driven
// from the falling edge and held until the next falling edge, so a receiver
// samples them at the following rising edge.
//
// Speed: the pins of each line are precomputed once per line (pixel values,
// noise, faults) into a buffer; step() is then an inline compare, two clock
// accumulator steps and a load. The slow path runs only at segment ends (line
// ends, OE edges, fault onsets and a few marked columns per line). No
// allocation and no virtual call per pixel; the frame source is asked once
// per frame.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "model/scene/camera.h"
#include "model/sensor/fault.h"
#include "model/sensor/fault_effects.h"
#include "model/sensor/frame_source.h"
#include "model/sensor/pin_word.h"
#include "model/sensor/pixel_noise.h"
#include "model/sensor/pixel_pipeline.h"
#include "model/sensor/profile.h"
#include "model/sensor/sensor_config.h"
#include "model/sensor/truth.h"
#include "model/time/ticks.h"

namespace sensor {

// One OE start: when OE was sampled high and how long the start-up took.
struct start_record {
    uint64_t oe_cycle = 0;  // cycle whose rising edge sampled OE high
    int latency_pclks = 0;  // fixed + extra: the frame starts at oe_cycle + latency
    int extra_pclks = 0;    // the random extra delay (0 in ~75% of starts)
};

class sensor_core {
  public:
    // Throws std::invalid_argument for an inconsistent profile. The source must
    // outlive the core.
    sensor_core(const sensor_profile& profile, scene::camera_id camera, frame_source& source,
                const sensor_config& config = {});

    // Adds a fault hook (before or during the run; a trigger already passed
    // acts at the next unit, see fault.h).
    void add_fault(const fault& f);

    // Runs the next pixel clock. oe: OE as sampled at its rising edge.
    pin_word step(bool oe) {
        if (oe != m_oe || m_col >= m_seg_end) return step_slow(oe);
        advance_clock();
        ++m_cycle;
        return pin_word{m_words[m_col++]};
    }

    // The cycle step() will run next (= cycles run so far).
    uint64_t cycle() const { return m_cycle; }
    // Edges of the cycle step() will run next, on the current clock.
    simtime::ticks next_rise_tick() const { return m_cursor.tick(); }
    // Edges of the cycle the last step() ran.
    simtime::ticks last_rise_tick() const { return m_last_rise; }
    simtime::ticks last_fall_tick() const { return m_last_fall; }
    // False once a pclk_drift fault has put the sensor on its own oscillator.
    bool on_master_clock() const { return m_on_master_clock; }
    const simtime::tick_clock& pclk_clock() const { return m_clock; }

    const sensor_profile& profile() const { return m_profile; }
    scene::camera_id camera() const { return m_camera; }
    const std::vector<frame_truth>& truth() const { return m_truth; }
    const std::vector<start_record>& starts() const { return m_starts; }
    bool running() const { return m_phase != phase::idle; }

    // The scene frame a frame starting (line 0, column 0 rising edge) at
    // start_tick shows: the profile's nominal frame period slot the start falls
    // in, rounded to the nearest slot, floor((start - scene_origin + P/2) / P),
    // exact rational arithmetic; 0 for a start more than P/2 before the origin.
    // Derived from time, not counted, so sensors in step show the same scene
    // frame whatever their restart history (docs/sensor.md "Scene frames").
    uint64_t scene_slot_of(simtime::ticks start_tick) const;

    // Take effect from the next frame.
    void set_gain_q8(int gain_q8);
    void set_exposure_lines(int lines);

  private:
    enum class phase : uint8_t { idle, starting, gap, frame };
    static constexpr uint64_t never = std::numeric_limits<uint64_t>::max();

    struct pending {
        fault f;
        bool fired = false;
        // A start skew whose idle clocks are running: an OE stop before its
        // frame begins leaves it to the first frame after the restart.
        bool in_gap = false;
    };

    pin_word step_slow(bool oe);
    void advance_clock() {
        m_last_rise = m_cursor.tick();
        m_cursor.advance();
        m_last_fall = m_cursor.tick();
        m_cursor.advance();
    }

    // Segments.
    void settle();
    void advance_segment();
    void enter_const_phase(phase p, uint64_t end_cycle);
    void fill_const_segment();
    uint16_t const_word() const;
    void begin_frame_or_gap();
    void begin_frame();
    frame_truth new_frame_truth();
    void take_frame_faults(frame_truth& t);
    void load_frame_image(const frame_truth& t);
    frame_request image_request(const frame_truth& t) const;
    void begin_line();
    bool take_dropped_line();
    void build_line(int from_col);
    void finish_frame(bool complete);
    void limit_segment();
    void on_oe_edge(bool oe);
    void note_marks();

    // Faults.
    uint64_t onset_cycle(const fault& f) const;
    bool frame_fault_reached(const fault& f, uint64_t frame_index, uint64_t start_cycle) const;
    bool position_reached(const fault_trigger& t, uint64_t frame, int line, int col) const;
    void activate(const fault& f);
    void switch_to_own_oscillator(int32_t drift_ppm);
    uint64_t next_pixel_fault_onset() const;
    bool activate_due_faults();

    simtime::ticks rise_of(uint64_t cycle) const {
        return m_clock.rise(cycle - m_clock_origin_cycle);
    }
    simtime::ticks fall_of(uint64_t cycle) const {
        return m_clock.fall(cycle - m_clock_origin_cycle);
    }
    int draw_startup_latency(int* extra);

    // Configuration.
    sensor_profile m_profile;
    scene::camera_id m_camera;
    frame_source& m_source;
    sensor_config m_config;
    int m_exposure_lines = 0;
    uint64_t m_extra_threshold = 0;  // extra start-up delay if rng < threshold
    pixel_pipeline m_pixels;

    int m_first_active_col = 0;  // in the line
    int m_last_active_col = 0;

    // Clock.
    simtime::tick_clock m_clock;
    simtime::clock_cursor m_cursor;
    uint64_t m_clock_origin_cycle = 0;
    bool m_on_master_clock = true;
    simtime::ticks m_last_rise = 0;
    simtime::ticks m_last_fall = 0;

    // Position.
    uint64_t m_cycle = 0;
    bool m_oe = false;
    phase m_phase = phase::idle;
    uint64_t m_phase_end = never;    // idle/starting/gap: cycle where the phase ends
    uint64_t m_seg_start_cycle = 0;  // cycle of m_words[0]
    int m_col = 0;                   // next word
    int m_seg_end = 0;               // slow path when m_col reaches it
    int m_seg_natural_end = 0;       // end without fault events / marks
    std::vector<uint16_t> m_words;
    bool m_output_since_start = false;  // a frame started since the last OE start

    // Current frame.
    uint64_t m_frames_started = 0;
    uint64_t m_frame_start_cycle = 0;
    int m_line = 0;
    bool m_frame_dropped = false;
    bool m_extra_after = false;
    bool m_next_is_extra = false;
    uint64_t m_frames_since_oe = 0;  // new frames (not repeats) since OE rose
    bool m_fodd = false;             // the current frame's identity pin
    bool m_line_dropped = false;
    uint64_t m_current_scene_frame = 0;
    int m_skew_pending = 0;    // start_skew clocks inserted before the next frame
    int m_line_href_col = -1;  // marks in this line, -1 if none
    int m_line_first_active = -1;
    int m_line_last_active = -1;

    // Faults.
    std::vector<pending> m_pending;
    fault_effects m_effects;
    uint32_t m_persistent_faults = 0;  // fault bits active from now on

    // Randomness and truth.
    splitmix64 m_startup_rng;
    std::vector<frame_truth> m_truth;
    std::vector<start_record> m_starts;
};

}  // namespace sensor
