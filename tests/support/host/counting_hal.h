// The host harness's HAL: no hardware, only counters. It records the
// modelled cycles the firmware charges per stage, per frame and in total,
// and checks the firmware's stage protocol (every charge inside the stage it
// names, stage_begin / stage_end paired, never nested).
#pragma once

#include <cstdint>

#include "dsp/hal.h"
#include "dsp/stage.h"

namespace host {

class counting_hal final : public dsp::hal {
  public:
    // Kernels priced with `model` (default: DSK v1, hand-scheduled).
    explicit counting_hal(const c64x::cost_model& model = {}) : m_model(model) {}

    // Starts a new frame: the per-frame counters go back to zero.
    void begin_frame();

    void charge_cycles(dsp::stage s, uint64_t cycles) override;
    uint64_t kernel_cycles(const c64x::kernel_profile& kernel) override {
        return m_model.cycles(kernel);
    }
    void stage_begin(dsp::stage s) override;
    void stage_end(dsp::stage s) override;

    uint64_t frame_cycles(dsp::stage s) const { return m_frame_cycles[index(s)]; }
    uint64_t total_cycles(dsp::stage s) const { return m_total_cycles[index(s)]; }
    uint64_t frame_cycles_all() const;
    uint64_t total_cycles_all() const;
    // How many times the stage was entered in the current frame.
    int frame_entries(dsp::stage s) const { return m_frame_entries[index(s)]; }
    uint32_t frames() const { return m_frames; }
    // Protocol violations seen so far (charge outside its stage, unpaired or
    // nested stage_begin / stage_end).
    uint32_t protocol_errors() const { return m_protocol_errors; }

  private:
    static int index(dsp::stage s) { return static_cast<int>(s); }

    c64x::cost_model m_model;

    uint64_t m_frame_cycles[dsp::stage_count] = {};
    uint64_t m_total_cycles[dsp::stage_count] = {};
    int m_frame_entries[dsp::stage_count] = {};
    uint32_t m_frames = 0;
    uint32_t m_protocol_errors = 0;
    int m_open_stage = -1;  // the stage between stage_begin and stage_end, -1 none
};

}  // namespace host
