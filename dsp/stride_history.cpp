#include "dsp/stride_history.h"

#include <algorithm>

namespace dsp {

namespace {

constexpr uint8_t level_bits = 0xFE;  // the kept frame's 7 bits; bit 0 is the difference

bool differs(uint8_t kept, uint8_t now, uint8_t threshold) {
    const int a = kept & level_bits;
    return (a > now ? a - now : now - a) > threshold;
}

}  // namespace

void stride_history::init(uint8_t* storage, size_t capacity) {
    m_storage = storage;
    m_capacity = storage == nullptr ? 0 : capacity;
    reset();
}

void stride_history::reset() {
    m_kept = 0;
    m_pairs = 0;
}

bool stride_history::due() {
    if (m_kept == 0) return true;
    return ++m_pairs >= stride;
}

void stride_history::three_frame_row(const uint8_t* f_t_row, int y, uint8_t threshold,
                                     uint8_t* object_row) const {
    const uint8_t* kept_row = m_storage + static_cast<size_t>(y) * static_cast<size_t>(m_width);
    for (int x = 0; x < m_width; ++x)
        object_row[x] = (kept_row[x] & 1u) && differs(kept_row[x], f_t_row[x], threshold) ? 255 : 0;
}

gray_cplane stride_history::kept() const {
    return gray_cplane{m_storage, m_width, m_height, m_width};
}

void stride_history::keep(gray_cplane frame, uint8_t threshold) {
    if (static_cast<size_t>(frame.width) * static_cast<size_t>(frame.height) > m_capacity) {
        reset();
        return;
    }
    if (frame.width != m_width || frame.height != m_height) m_kept = 0;
    m_width = frame.width;
    m_height = frame.height;
    for (int y = 0; y < frame.height; ++y) {
        uint8_t* kept_row = m_storage + static_cast<size_t>(y) * static_cast<size_t>(m_width);
        const uint8_t* row = frame.row(y);
        for (int x = 0; x < m_width; ++x) {
            const bool moved = m_kept > 0 && differs(kept_row[x], row[x], threshold);
            kept_row[x] = static_cast<uint8_t>((row[x] & level_bits) | (moved ? 1u : 0u));
        }
    }
    m_kept = std::min(m_kept + 1, 2);
    m_pairs = 0;
}

}  // namespace dsp
