#include "dsp/key_frame.h"

#include <algorithm>
#include <cstring>

namespace dsp {

key_frame::~key_frame() {
    delete[] m_pixels;
}

size_t key_frame::sdram_bytes(int max_width, int max_height) {
    return static_cast<size_t>(std::max(max_width, 0)) *
           static_cast<size_t>(std::max(max_height, 0));
}

void key_frame::init(int max_width, int max_height) {
    delete[] m_pixels;
    m_capacity = sdram_bytes(max_width, max_height);
    m_pixels = new uint8_t[m_capacity == 0 ? 1 : m_capacity]();
    m_valid = false;
}

gray_cplane key_frame::region_plane() const {
    return gray_cplane{m_pixels, m_region.width, m_region.height, m_region.width};
}

void key_frame::take(gray_cplane frame, box object, box pattern, int grow) {
    const int x0 = std::max(0, object.x - grow), y0 = std::max(0, object.y - grow);
    const int x1 = std::min(frame.width, object.right() + grow);
    const int y1 = std::min(frame.height, object.bottom() + grow);
    m_region = box{x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
    m_valid =
        m_pixels != nullptr && !m_region.empty() &&
        static_cast<size_t>(m_region.width) * static_cast<size_t>(m_region.height) <= m_capacity &&
        pattern.x >= x0 && pattern.y >= y0 && pattern.right() <= x1 && pattern.bottom() <= y1 &&
        !pattern.empty();
    if (!m_valid) return;
    for (int y = 0; y < m_region.height; ++y)
        std::memcpy(m_pixels + static_cast<size_t>(y) * static_cast<size_t>(m_region.width),
                    frame.row(y0 + y) + x0, static_cast<size_t>(m_region.width));
    m_object = object;
    m_pattern = pattern;
    m_dx = m_dy = 0;
    m_pairs = 0;
    m_turned = false;
    m_outline_only = false;
}

bool key_frame::displacement(gray_cplane frame, uint8_t* scratch, uint32_t lost_mean_sad,
                             int* positions) {
    *positions = 0;
    if (!m_valid) return false;
    ++m_pairs;
    const gray_cplane key = region_plane();
    const int px = m_pattern.x - m_region.x, py = m_pattern.y - m_region.y;
    for (int y = 0; y < m_pattern.height; ++y)
        std::memcpy(scratch + static_cast<size_t>(y) * static_cast<size_t>(m_pattern.width),
                    key.row(py + y) + px, static_cast<size_t>(m_pattern.width));
    const gray_cplane pattern{scratch, m_pattern.width, m_pattern.height, m_pattern.width};
    const int r = max_step + 1;
    const box wanted{m_pattern.x + m_dx - r, m_pattern.y + m_dy - r, 2 * r + 1, 2 * r + 1};
    const sad_result best = sad_search(frame, pattern, wanted);
    *positions = best.positions;
    if (!best.valid) return false;
    const box window =
        clip_positions(wanted, frame.width, frame.height, pattern.width, pattern.height);
    const bool on_edge = best.x == window.x || best.x == window.right() - 1 || best.y == window.y ||
                         best.y == window.bottom() - 1;
    const uint64_t area = static_cast<uint64_t>(pattern.width) * pattern.height;
    if (on_edge || best.sad > static_cast<uint64_t>(lost_mean_sad) * area) return false;
    m_turned = best.sad > static_cast<uint64_t>(turned_mean_sad) * area;
    m_dx = best.x - m_pattern.x;
    m_dy = best.y - m_pattern.y;
    return true;
}

block_group key_frame::moved_extent(gray_cplane frame, uint8_t threshold, motion_blocks& blocks,
                                    uint8_t* row) const {
    if (!m_valid) return block_group{};
    const gray_cplane key = region_plane();
    blocks.begin(m_region.width, m_region.height);
    for (int y = 0; y < m_region.height; ++y) {
        const uint8_t* now = frame.row(m_region.y + y) + m_region.x;
        const uint8_t* then = key.row(y);
        for (int x = 0; x < m_region.width; ++x) {
            const int diff = now[x] > then[x] ? now[x] - then[x] : then[x] - now[x];
            row[x] = diff > threshold ? 1 : 0;
        }
        blocks.add_row(row, y);
    }
    box seed = m_object;
    seed.x += m_dx - m_region.x;
    seed.y += m_dy - m_region.y;
    block_group g = blocks.extent(seed, 0);
    if (!g.found) return g;
    const box& b = g.bbox;
    // Touching the region's edge where the frame goes on: the object may too.
    if ((b.x == 0 && m_region.x > 0) || (b.y == 0 && m_region.y > 0) ||
        (b.right() == m_region.width && m_region.right() < frame.width) ||
        (b.bottom() == m_region.height && m_region.bottom() < frame.height))
        return block_group{};
    g.bbox.x += m_region.x;
    g.bbox.y += m_region.y;
    return g;
}

}  // namespace dsp
