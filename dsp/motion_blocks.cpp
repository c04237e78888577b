#include "dsp/motion_blocks.h"

#include <algorithm>

#include "dsp/motion_detect.h"

namespace dsp {
namespace {

int blocks_for(int pixels) {
    return (pixels + motion_blocks::block_side - 1) / motion_blocks::block_side;
}

uint8_t first_of(uint8_t span) {
    return static_cast<uint8_t>(span >> 4);
}
uint8_t last_of(uint8_t span) {
    return static_cast<uint8_t>(span & 0x0f);
}
uint8_t span_of(int first, int last) {
    return static_cast<uint8_t>((first << 4) | last);
}

}  // namespace

motion_blocks::~motion_blocks() {
    release();
}

void motion_blocks::release() {
    delete[] m_count;
    delete[] m_x_span;
    delete[] m_y_span;
    delete[] m_row;
    delete[] m_labels;
    delete[] m_parent;
    delete[] m_stats;
    m_count = m_x_span = m_y_span = m_row = nullptr;
    m_labels = m_parent = nullptr;
    m_stats = nullptr;
}

size_t motion_blocks::workspace_bytes(int max_width, int max_height) {
    const size_t bx = static_cast<size_t>(blocks_for(max_width));
    const size_t blocks = bx * static_cast<size_t>(blocks_for(max_height));
    return 3 * blocks + bx + 2 * bx * sizeof(int32_t) +
           static_cast<size_t>(max_groups) * (sizeof(int32_t) + sizeof(component));
}

void motion_blocks::init(int max_width, int max_height) {
    release();
    m_max_blocks_x = blocks_for(max_width);
    m_max_blocks_y = blocks_for(max_height);
    const size_t blocks = static_cast<size_t>(m_max_blocks_x) * m_max_blocks_y;
    m_count = new uint8_t[blocks]();
    m_x_span = new uint8_t[blocks]();
    m_y_span = new uint8_t[blocks]();
    m_row = new uint8_t[static_cast<size_t>(m_max_blocks_x)]();
    m_labels = new int32_t[2 * static_cast<size_t>(m_max_blocks_x)];
    m_parent = new int32_t[max_groups];
    m_stats = new component[max_groups];
    m_blocks_x = m_blocks_y = 0;
}

void motion_blocks::begin(int width, int height) {
    m_width = width;
    m_blocks_x = std::min(blocks_for(width), m_max_blocks_x);
    m_blocks_y = std::min(blocks_for(height), m_max_blocks_y);
    std::fill(m_count, m_count + static_cast<size_t>(m_blocks_x) * m_blocks_y, uint8_t{0});
}

void motion_blocks::add_row(const uint8_t* row, int y) {
    const int by = y / block_side, oy = y % block_side;
    if (by >= m_blocks_y) return;
    for (int bx = 0; bx < m_blocks_x; ++bx) {
        const uint8_t* pixels = row + bx * block_side;
        const int columns = std::min(block_side, m_width - bx * block_side);  // the last may be cut
        int set = 0, first = -1, last = -1;
        for (int o = 0; o < columns; ++o) {
            if (pixels[o] == 0) continue;
            ++set;
            if (first < 0) first = o;
            last = o;
        }
        if (set == 0) continue;
        const size_t b = static_cast<size_t>(by) * m_blocks_x + bx;
        if (m_count[b] == 0) {
            m_x_span[b] = span_of(first, last);
            m_y_span[b] = span_of(oy, oy);
        } else {
            m_x_span[b] = span_of(std::min<int>(first, first_of(m_x_span[b])),
                                  std::max<int>(last, last_of(m_x_span[b])));
            m_y_span[b] = span_of(first_of(m_y_span[b]), oy);  // rows come in order
        }
        m_count[b] = static_cast<uint8_t>(std::min(255, m_count[b] + set));
    }
}

bool motion_blocks::moving(int bx, int by) const {
    if (bx < 0 || by < 0 || bx >= m_blocks_x || by >= m_blocks_y) return false;
    return m_count[static_cast<size_t>(by) * m_blocks_x + bx] >= min_block_pixels;
}

void motion_blocks::dilated_row(int by, uint8_t* out) const {
    for (int bx = 0; bx < m_blocks_x; ++bx) {
        bool any = false;
        for (int dy = -1; dy <= 1 && !any; ++dy)
            for (int dx = -1; dx <= 1 && !any; ++dx) any = moving(bx + dx, by + dy);
        out[bx] = any ? 1 : 0;
    }
}

// The moving blocks inside a box of blocks: their pixels and pixel extent.
block_group motion_blocks::group_in(box blocks) const {
    block_group g;
    int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    for (int by = blocks.y; by < blocks.bottom(); ++by) {
        for (int bx = blocks.x; bx < blocks.right(); ++bx) {
            if (!moving(bx, by)) continue;
            const size_t b = static_cast<size_t>(by) * m_blocks_x + bx;
            const int left = bx * block_side + first_of(m_x_span[b]);
            const int right = bx * block_side + last_of(m_x_span[b]);
            const int top = by * block_side + first_of(m_y_span[b]);
            const int bottom = by * block_side + last_of(m_y_span[b]);
            if (g.blocks == 0) {
                x0 = left, x1 = right, y0 = top, y1 = bottom;
            } else {
                x0 = std::min(x0, left), x1 = std::max(x1, right);
                y0 = std::min(y0, top), y1 = std::max(y1, bottom);
            }
            ++g.blocks;
            g.pixels += m_count[b];
        }
    }
    g.found = g.blocks > 0;
    if (g.found) g.bbox = box{x0, y0, x1 - x0 + 1, y1 - y0 + 1};
    return g;
}

namespace {

// Two pieces of one object: their boxes overlap, or they face each other
// (overlap along one axis) across a gap no longer than that overlap. The
// two silhouette crescents of a ball 160 px wide face each other along
// 150 px across a 140 px gap; a speck beside it faces it along a few px only.
bool one_object(box a, box b) {
    const int overlap_x = std::min(a.right(), b.right()) - std::max(a.x, b.x);
    const int overlap_y = std::min(a.bottom(), b.bottom()) - std::max(a.y, b.y);
    if (overlap_x > 0 && overlap_y > 0) return true;
    if (overlap_y > 0) return -overlap_x <= overlap_y;  // side by side
    if (overlap_x > 0) return -overlap_y <= overlap_x;  // one above the other
    return false;
}

block_group joined(const block_group& a, const block_group& b) {
    block_group j = a;
    j.bbox = bounding_union(a.bbox, b.bbox);
    j.pixels += b.pixels;
    j.blocks += b.blocks;
    return j;
}

}  // namespace

block_group motion_blocks::extent(box seed, int min_pixels) {
    component_labeller labeller;
    labeller.begin(m_blocks_x, m_labels, m_parent, m_stats, max_groups);
    for (int by = 0; by < m_blocks_y; ++by) {
        dilated_row(by, m_row);
        if (!labeller.add_row(m_row, by)) return block_group{};  // too many groups
    }
    const int count = labeller.finish(m_stats, max_groups);
    block_group groups[max_groups];
    int best = -1;
    for (int i = 0; i < count; ++i) {
        groups[i] = group_in(m_stats[i].bbox);
        const block_group& g = groups[i];
        if (!g.found || (best >= 0 && g.pixels <= groups[best].pixels)) continue;
        if (seed.empty() ? g.pixels >= min_pixels : one_object(g.bbox, seed)) best = i;
    }
    if (best < 0) return block_group{};
    // Grow the chosen group by every group that is one object with it.
    block_group object = groups[best];
    bool taken[max_groups] = {};
    taken[best] = true;
    for (bool grown = true; grown;) {
        grown = false;
        for (int i = 0; i < count; ++i) {
            if (taken[i] || !groups[i].found || !one_object(object.bbox, groups[i].bbox)) continue;
            object = joined(object, groups[i]);
            taken[i] = grown = true;
        }
    }
    return object;
}

}  // namespace dsp
