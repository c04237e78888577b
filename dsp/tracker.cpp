#include "dsp/tracker.h"

#include <algorithm>
#include <cstring>

namespace dsp {
namespace {

// A new size for one dimension, keeping the centre; then the box is moved
// inside [0, limit).
void resize_keep_centre(int& start, int& size, int new_size, int limit) {
    start += (size - new_size) / 2;
    size = new_size;
    start = std::clamp(start, 0, std::max(limit - size, 0));
}

}  // namespace

sad_tracker::~sad_tracker() {
    delete[] m_pattern;
}

void sad_tracker::init(const track_params& params) {
    m_params = params;
    delete[] m_pattern;
    const size_t side = static_cast<size_t>(std::max(params.max_size, 1));
    m_pattern = new uint8_t[side * side]();
    m_position = box{};
    m_window = box{};
    m_last = sad_result{};
    m_status = track_status::lost;
}

gray_cplane sad_tracker::pattern() const {
    return gray_cplane{m_pattern, m_pattern_box.width, m_pattern_box.height, m_pattern_box.width};
}

box sad_tracker::pattern_box_of(box object) const {
    box p = object;
    resize_keep_centre(p.x, p.width, std::min(object.width, m_params.max_size), object.right());
    resize_keep_centre(p.y, p.height, std::min(object.height, m_params.max_size), object.bottom());
    return p;
}

void sad_tracker::take_pattern(gray_cplane frame) {
    m_pattern_box = pattern_box_of(m_position);
    const box& p = m_pattern_box;
    for (int j = 0; j < p.height; ++j) {
        std::memcpy(m_pattern + static_cast<size_t>(j) * static_cast<size_t>(p.width),
                    frame.row(p.y + j) + p.x, static_cast<size_t>(p.width));
    }
}

void sad_tracker::start(gray_cplane frame, box object) {
    m_last = sad_result{};
    m_window = box{};
    if (m_pattern == nullptr || frame.width < m_params.min_size ||
        frame.height < m_params.min_size) {
        m_status = track_status::lost;
        return;
    }
    box b = object;
    const int w = std::clamp(b.width, m_params.min_size, frame.width);
    const int h = std::clamp(b.height, m_params.min_size, frame.height);
    resize_keep_centre(b.x, b.width, w, frame.width);
    resize_keep_centre(b.y, b.height, h, frame.height);
    m_position = b;
    take_pattern(frame);
    m_status = track_status::tracking;
}

box sad_tracker::refit_size(gray_cplane motion_mask, box matched) const {
    const int grow_x = std::max(2, matched.width / 4);
    const int grow_y = std::max(2, matched.height / 4);
    const int x0 = std::max(matched.x - grow_x, 0);
    const int y0 = std::max(matched.y - grow_y, 0);
    const int x1 = std::min(matched.right() + grow_x, motion_mask.width);
    const int y1 = std::min(matched.bottom() + grow_y, motion_mask.height);

    int count = 0, min_x = x1, max_x = x0 - 1, min_y = y1, max_y = y0 - 1;
    for (int y = y0; y < y1; ++y) {
        const uint8_t* row = motion_mask.row(y);
        for (int x = x0; x < x1; ++x) {
            if (row[x] == 0) continue;
            ++count;
            min_x = std::min(min_x, x);
            max_x = std::max(max_x, x);
            min_y = std::min(min_y, y);
            max_y = std::max(max_y, y);
        }
    }
    if (count * 8 < matched.width * matched.height) return matched;

    auto towards = [&](int size, int fitted, int limit) {
        const int step = std::max(1, size / 8);
        const int moved = std::clamp(fitted, size - step, size + step);
        return std::clamp(moved, std::min(m_params.min_size, limit), limit);
    };
    box b = matched;
    resize_keep_centre(b.x, b.width, towards(b.width, max_x - min_x + 1, motion_mask.width),
                       motion_mask.width);
    resize_keep_centre(b.y, b.height, towards(b.height, max_y - min_y + 1, motion_mask.height),
                       motion_mask.height);
    return b;
}

track_status sad_tracker::update(gray_cplane frame, gray_cplane motion_mask) {
    return search(frame, motion_mask, m_pattern_box);
}

track_status sad_tracker::update_near(gray_cplane frame, box expected) {
    // The pattern keeps its place in the object box.
    box centre = m_pattern_box;
    centre.x += (expected.center_x2() - m_position.center_x2()) / 2;
    centre.y += (expected.center_y2() - m_position.center_y2()) / 2;
    return search(frame, gray_cplane{}, centre);
}

// `centre`: the pattern-sized box the window is centred on.
track_status sad_tracker::search(gray_cplane frame, gray_cplane motion_mask, box centre) {
    if (m_status == track_status::lost) return m_status;

    const int r = m_params.search_radius;
    const box& p = m_pattern_box;
    const box wanted{centre.x - r, centre.y - r, 2 * r + 1, 2 * r + 1};
    m_window = clip_positions(wanted, frame.width, frame.height, p.width, p.height);
    m_last = sad_search(frame, pattern(), m_window);
    if (!m_last.valid) {
        m_status = track_status::lost;
        return m_status;
    }

    const uint64_t area = static_cast<uint64_t>(p.width) * p.height;
    const bool too_different = m_last.sad > static_cast<uint64_t>(m_params.lost_mean_sad) * area;
    const bool at_clipped_edge =
        (m_last.x == m_window.x && wanted.x < m_window.x) ||
        (m_last.x == m_window.right() - 1 && wanted.right() > m_window.right()) ||
        (m_last.y == m_window.y && wanted.y < m_window.y) ||
        (m_last.y == m_window.bottom() - 1 && wanted.bottom() > m_window.bottom());
    if (too_different || at_clipped_edge) {
        m_status = track_status::lost;
        return m_status;
    }

    // The object box moves with its pattern, kept inside the frame.
    box matched = m_position;
    matched.x = std::clamp(matched.x + m_last.x - p.x, 0, frame.width - matched.width);
    matched.y = std::clamp(matched.y + m_last.y - p.y, 0, frame.height - matched.height);
    if (!motion_mask.empty()) matched = refit_size(motion_mask, matched);
    m_position = matched;
    take_pattern(frame);
    return m_status;
}

}  // namespace dsp
