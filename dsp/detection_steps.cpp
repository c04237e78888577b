#include "dsp/detection_steps.h"

namespace dsp {

namespace {

int edge_of(const box& b, int edge) {
    switch (edge) {
        case 0:
            return b.x;
        case 1:
            return b.right();
        case 2:
            return b.y;
        default:
            return b.bottom();
    }
}

}  // namespace

void detection_steps::push(box detected, uint32_t frame_index) {
    if (m_count > 0 && frame_index != m_last_index + 1) m_count = 0;
    if (m_count == pairs + 1) {
        for (int i = 1; i <= pairs; ++i) m_boxes[i - 1] = m_boxes[i];
        --m_count;
    }
    m_boxes[m_count++] = detected;
    m_last_index = frame_index;
}

bool detection_steps::edge_keeps_stepping(int min_step) const {
    if (m_count < pairs + 1) return false;
    for (int edge = 0; edge < 4; ++edge) {
        int forward = 0, backward = 0;
        for (int i = 1; i <= pairs; ++i) {
            const int step = edge_of(m_boxes[i], edge) - edge_of(m_boxes[i - 1], edge);
            forward += step >= min_step;
            backward += step <= -min_step;
        }
        // The opposite edge must have come along: one edge stepping alone
        // is a detection growing over more of a slow object (a spinning
        // 75 px ball's piece grew 6 px a pair upwards over teddy).
        const int across = edge_of(m_boxes[pairs], edge ^ 1) - edge_of(m_boxes[0], edge ^ 1);
        if ((forward == pairs && across >= pairs) || (backward == pairs && across <= -pairs))
            return true;
    }
    return false;
}

}  // namespace dsp
