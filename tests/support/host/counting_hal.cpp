#include "tests/support/host/counting_hal.h"

namespace host {

void counting_hal::begin_frame() {
    for (int i = 0; i < dsp::stage_count; ++i) {
        m_frame_cycles[i] = 0;
        m_frame_entries[i] = 0;
    }
    if (m_open_stage >= 0) ++m_protocol_errors;  // a stage left open across frames
    m_open_stage = -1;
    ++m_frames;
}

void counting_hal::charge_cycles(dsp::stage s, uint64_t cycles) {
    if (m_open_stage != index(s)) ++m_protocol_errors;
    m_frame_cycles[index(s)] += cycles;
    m_total_cycles[index(s)] += cycles;
}

void counting_hal::stage_begin(dsp::stage s) {
    if (m_open_stage >= 0) ++m_protocol_errors;
    m_open_stage = index(s);
    ++m_frame_entries[index(s)];
}

void counting_hal::stage_end(dsp::stage s) {
    if (m_open_stage != index(s)) ++m_protocol_errors;
    m_open_stage = -1;
}

uint64_t counting_hal::frame_cycles_all() const {
    uint64_t sum = 0;
    for (uint64_t c : m_frame_cycles) sum += c;
    return sum;
}

uint64_t counting_hal::total_cycles_all() const {
    uint64_t sum = 0;
    for (uint64_t c : m_total_cycles) sum += c;
    return sum;
}

}  // namespace host
