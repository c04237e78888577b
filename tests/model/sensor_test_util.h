// Helpers shared by the sensor tests: a small profile, a deterministic frame
// source and pin-stream recording / edge finding.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "model/scene/images.h"
#include "model/sensor/frame_source.h"
#include "model/sensor/profile.h"
#include "model/sensor/sensor_core.h"

namespace sensor_test {

// A small profile with every layout feature (dark and border on all sides,
// HREF not at column 0, a VSYNC that ends mid-line), so a frame is 1200 clocks.
inline sensor::sensor_profile small_profile() {
    sensor::sensor_profile p;
    p.name = "small";
    p.line_pclks = 40;
    p.href_start = 3;
    p.dark_cols_left = 2;
    p.border_cols_before = 1;
    p.active_cols = 16;
    p.border_cols_after = 1;
    p.dark_cols_right = 2;  // readout 22 columns: HREF on columns 3..24
    p.frame_lines = 30;
    p.vsync_pclks = 75;  // 1 line and 35 clocks
    p.first_row_line = 4;
    p.dark_rows_top = 1;
    p.border_rows_before = 1;
    p.active_rows = 12;
    p.border_rows_after = 1;
    p.dark_rows_bottom = 1;  // readout 16 rows: lines 4..19
    p.cfa = dsp::cfa_order::bggr;
    p.mclk_period = {simtime::pclk_default_period, 1};
    p.mclk_per_pclk = 1;
    p.startup_latency_pclks = 7;
    p.extra_delay_probability = 0.0;
    p.extra_delay_max_pclks = 80;
    p.black_level = 16;
    p.exposure_lines = 20;
    return p;
}

// Deterministic RGB per (camera, scene frame, x, y); remembers the requests.
class pattern_source : public sensor::frame_source {
  public:
    static dsp::rgb8 pixel(int camera, uint64_t frame, int x, int y) {
        const int f = static_cast<int>(frame % 97);
        return {static_cast<uint8_t>((x * 3 + y * 5 + f * 7 + camera * 11) & 255),
                static_cast<uint8_t>((x * 13 + y * 7 + f * 3 + 40) & 255),
                static_cast<uint8_t>((x * 5 + y * 11 + f * 17 + camera * 29 + 90) & 255)};
    }

    pattern_source(int width, int height) : m_width(width), m_height(height) {}

    dsp::rgb_cplane frame(const sensor::frame_request& request) override {
        requests.push_back(request);
        const int cam = request.camera == scene::camera_id::left ? 0 : 1;
        scene::rgb_image& img = m_images[cam];
        img.resize(m_width, m_height);
        for (int y = 0; y < m_height; ++y)
            for (int x = 0; x < m_width; ++x) img.at(x, y) = pixel(cam, request.scene_frame, x, y);
        return img.view();
    }

    std::vector<sensor::frame_request> requests;

  private:
    int m_width, m_height;
    scene::rgb_image m_images[2];
};

// One fixed image for every request (cheap: no per-frame work).
class still_source : public sensor::frame_source {
  public:
    explicit still_source(scene::rgb_image image) : m_image(std::move(image)) {}
    still_source(int width, int height, dsp::rgb8 colour) : m_image(width, height) {
        for (auto& px : m_image.pixels) px = colour;
    }
    dsp::rgb_cplane frame(const sensor::frame_request&) override { return m_image.view(); }

  private:
    scene::rgb_image m_image;
};

// One pixel clock of a recorded run.
struct cycle_record {
    sensor::pin_word pins;
    simtime::ticks rise = 0;
    simtime::ticks fall = 0;
};

// Runs `cycles` clocks; oe(n) gives OE as sampled at cycle n's rising edge.
inline std::vector<cycle_record> run(sensor::sensor_core& core, uint64_t cycles,
                                     const std::function<bool(uint64_t)>& oe) {
    std::vector<cycle_record> out;
    out.reserve(cycles);
    for (uint64_t i = 0; i < cycles; ++i) {
        const uint64_t n = core.cycle();
        const sensor::pin_word w = core.step(oe(n));
        out.push_back({w, core.last_rise_tick(), core.last_fall_tick()});
    }
    return out;
}

inline std::function<bool(uint64_t)> oe_from(uint64_t rise_cycle) {
    return [rise_cycle](uint64_t n) { return n >= rise_cycle; };
}

// Cycles where a pin (selected by mask) goes from 0 to 1 / 1 to 0 (the first
// cycle counts as a rise if the pin starts high).
inline std::vector<uint64_t> rises(const std::vector<cycle_record>& rec, uint16_t mask) {
    std::vector<uint64_t> out;
    bool prev = false;
    for (uint64_t n = 0; n < rec.size(); ++n) {
        const bool v = (rec[n].pins.bits & mask) != 0;
        if (v && !prev) out.push_back(n);
        prev = v;
    }
    return out;
}

inline std::vector<uint64_t> falls(const std::vector<cycle_record>& rec, uint16_t mask) {
    std::vector<uint64_t> out;
    bool prev = false;
    for (uint64_t n = 0; n < rec.size(); ++n) {
        const bool v = (rec[n].pins.bits & mask) != 0;
        if (!v && prev) out.push_back(n);
        prev = v;
    }
    return out;
}

}  // namespace sensor_test

namespace sensor_test {

// The data of each frame as a receiver sees it: a new frame at each VSYNC
// rise, one row per HREF pulse, one value per HREF-high clock.
using readout = std::vector<std::vector<uint8_t>>;

inline std::vector<readout> frames_from_pins(const std::vector<cycle_record>& rec) {
    std::vector<readout> frames;
    bool prev_vsync = false, prev_href = false;
    for (const cycle_record& c : rec) {
        if (c.pins.vsync() && !prev_vsync) frames.emplace_back();
        if (!frames.empty() && c.pins.href()) {
            if (!prev_href) frames.back().emplace_back();
            frames.back().back().push_back(c.pins.data());
        }
        prev_vsync = c.pins.vsync();
        prev_href = c.pins.href();
    }
    return frames;
}

}  // namespace sensor_test
