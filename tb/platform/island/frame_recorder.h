// The sensor frames as driven on the sensors' pins (docs/platform.md, "Data
// path integrity"): the active pixels of the last few frames of each sensor
// in a ring, and a checksum of every frame, for the scoreboard to compare
// with what the EDMA put in the DSP's memory.
#pragma once

#include <cstdint>
#include <vector>

#include "model/sensor/sensor_core.h"
#include "tb/platform/island/island_config.h"
#include "tb/platform/island/timeline.h"

namespace platform {

class frame_recorder {
  public:
    // `ring` frames kept per sensor (at least 2); each frame's start goes to
    // the timeline as a sensor_frame event.
    frame_recorder(const sensor::sensor_profile& profile, int ring, timeline& events);

    // The sensor whose truth (frame starts) names the frames.
    void attach(int camera, const sensor::sensor_core& core) { m_core[camera] = &core; }
    const sensor::sensor_core& sensor(int camera) const { return *m_core[camera]; }

    // A sensor's word of one pixel clock.
    void record(int camera, uint16_t bits);
    // Closes the frames in progress (end of run).
    void finish();

    // Active pixels of the sensor's frame `truth_index` as driven on its
    // pins (nullptr once evicted from the ring or never recorded).
    const uint8_t* pixels(int camera, uint64_t truth_index) const;
    // Checksum of that frame (computed now if still in the ring); false if unknown.
    bool checksum(int camera, uint64_t truth_index, uint64_t* checksum);
    const std::vector<frame_info>& frames(int camera) const { return m_frames[camera]; }

  private:
    struct recorder {
        bool href = false;
        bool vsync = false;
        int col = 0;
        int row = 0;
        uint8_t* frame = nullptr;  // active pixels of the frame being recorded
        uint64_t truth_index = UINT64_MAX;
        uint64_t pixels = 0;
    };
    void start_frame(int camera);
    void finalize(int camera, uint64_t truth_index);

    sensor::sensor_profile m_profile;
    timeline& m_events;
    const sensor::sensor_core* m_core[2] = {};
    recorder m_rec[2];
    std::vector<std::vector<uint8_t>> m_ring[2];
    std::vector<uint64_t> m_ring_owner[2];
    std::vector<frame_info> m_frames[2];
};

}  // namespace platform
