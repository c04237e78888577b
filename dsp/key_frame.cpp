#include "dsp/key_frame.h"

#include <algorithm>
#include <cstring>

namespace dsp {

key_frame::~key_frame() {
    delete[] m_pixels;
}

size_t key_frame::sdram_bytes(int max_width, int max_height, int max_pattern_side) {
    const size_t side = static_cast<size_t>(std::max(max_pattern_side, 0));
    return static_cast<size_t>(std::max(max_width, 0)) *
               static_cast<size_t>(std::max(max_height, 0)) +
           side * side;
}

void key_frame::init(int max_width, int max_height, int max_pattern_side) {
    delete[] m_pixels;
    m_capacity = sdram_bytes(max_width, max_height, max_pattern_side);
    m_pixels = new uint8_t[m_capacity == 0 ? 1 : m_capacity]();
    m_valid = false;
}

void key_frame::held_span(int y, int* left, int* right) const {
    const int row = m_region.y + y;
    const bool in_hole = !m_hole.empty() && row >= m_hole.y && row < m_hole.bottom();
    *left = in_hole ? m_hole.x - m_region.x : m_region.width;
    *right = in_hole ? m_hole.right() - m_region.x : m_region.width;
}

void key_frame::take(gray_cplane frame, box object, box pattern, int grow) {
    const int x0 = std::max(0, object.x - grow), y0 = std::max(0, object.y - grow);
    const int x1 = std::min(frame.width, object.right() + grow);
    const int y1 = std::min(frame.height, object.bottom() + grow);
    m_region = box{x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
    const int inset = hole_inset;
    m_hole = box{object.x + inset, object.y + inset, std::max(0, object.width - 2 * inset),
                 std::max(0, object.height - 2 * inset)};
    if (m_hole.empty()) m_hole = box{};
    m_ring_bytes = static_cast<size_t>(m_region.width) * static_cast<size_t>(m_region.height) -
                   static_cast<size_t>(m_hole.width) * static_cast<size_t>(m_hole.height);
    const size_t pattern_bytes = static_cast<size_t>(std::max(pattern.width, 0)) *
                                 static_cast<size_t>(std::max(pattern.height, 0));
    m_valid = m_pixels != nullptr && !m_region.empty() &&
              m_ring_bytes + pattern_bytes <= m_capacity && pattern.x >= x0 && pattern.y >= y0 &&
              pattern.right() <= x1 && pattern.bottom() <= y1 && !pattern.empty();
    if (!m_valid) return;
    uint8_t* at = m_pixels;
    for (int y = 0; y < m_region.height; ++y) {
        int left = 0, right = 0;
        held_span(y, &left, &right);
        const uint8_t* src = frame.row(y0 + y) + x0;
        std::memcpy(at, src, static_cast<size_t>(left));
        at += left;
        std::memcpy(at, src + right, static_cast<size_t>(m_region.width - right));
        at += m_region.width - right;
    }
    for (int y = 0; y < pattern.height; ++y, at += pattern.width)
        std::memcpy(at, frame.row(pattern.y + y) + pattern.x, static_cast<size_t>(pattern.width));
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
    std::memcpy(scratch, m_pixels + m_ring_bytes,
                static_cast<size_t>(m_pattern.width) * static_cast<size_t>(m_pattern.height));
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
    m_turned = match_turned(best.sad, area);
    m_dx = best.x - m_pattern.x;
    m_dy = best.y - m_pattern.y;
    return true;
}

block_group key_frame::moved_extent(gray_cplane frame, uint8_t threshold, motion_blocks& blocks,
                                    uint8_t* row) const {
    if (!m_valid) return block_group{};
    blocks.begin(m_region.width, m_region.height);
    const uint8_t* then = m_pixels;
    // Dif of the held pixels [x0, x1) of a row; `then` walks the ring.
    auto differ = [&](const uint8_t* now, int x0, int x1) {
        for (int x = x0; x < x1; ++x, ++then) {
            const int diff = now[x] > *then ? now[x] - *then : *then - now[x];
            row[x] = diff > threshold ? 1 : 0;
        }
    };
    for (int y = 0; y < m_region.height; ++y) {
        const uint8_t* now = frame.row(m_region.y + y) + m_region.x;
        int left = 0, right = 0;
        held_span(y, &left, &right);
        differ(now, 0, left);
        std::memset(row + left, 1, static_cast<size_t>(right - left));  // the hole: the object's
        differ(now, right, m_region.width);
        blocks.add_row(row, y);
    }
    box seed = m_object;
    seed.x += m_dx - m_region.x;
    seed.y += m_dy - m_region.y;
    block_group g = blocks.extent(seed, 0);
    if (!g.found) return g;
    const box& b = g.bbox;
    // The hole alone: nothing the key holds changed.
    if (!m_hole.empty() && b.x >= m_hole.x - m_region.x && b.y >= m_hole.y - m_region.y &&
        b.right() <= m_hole.right() - m_region.x && b.bottom() <= m_hole.bottom() - m_region.y)
        return block_group{};
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
