#include "tb/platform/island/frame_recorder.h"

#include <algorithm>
#include <cstring>

namespace platform {

frame_recorder::frame_recorder(const sensor::sensor_profile& profile, int ring, timeline& events)
    : m_profile(profile), m_events(events) {
    const size_t bytes =
        static_cast<size_t>(profile.active_cols) * static_cast<size_t>(profile.active_rows);
    for (int c = 0; c < 2; ++c) {
        m_ring[c].assign(static_cast<size_t>(std::max(2, ring)), std::vector<uint8_t>(bytes, 0));
        m_ring_owner[c].assign(m_ring[c].size(), UINT64_MAX);
    }
}

void frame_recorder::record(int c, uint16_t bits) {
    recorder& r = m_rec[c];
    const sensor::pin_word word{bits};
    const bool vsync = word.vsync();
    if (vsync && !r.vsync) start_frame(c);
    r.vsync = vsync;
    const bool href = word.href() && word.valid();
    if (href) {
        const sensor::sensor_profile& p = m_profile;
        const int x = r.col - p.active_col0();
        const int y = r.row - p.active_row0();
        if (r.frame && static_cast<unsigned>(x) < static_cast<unsigned>(p.active_cols) &&
            static_cast<unsigned>(y) < static_cast<unsigned>(p.active_rows)) {
            r.frame[static_cast<size_t>(y) * p.active_cols + x] = word.data();
            ++r.pixels;
        }
        ++r.col;
    } else if (r.href) {
        ++r.row;
        r.col = 0;
    }
    r.href = href;
}

void frame_recorder::start_frame(int c) {
    recorder& r = m_rec[c];
    const sensor::sensor_core& s = *m_core[c];
    if (s.truth().empty()) return;
    const uint64_t index = s.truth().size() - 1;
    if (index == r.truth_index) return;  // a VSYNC glitch inside the frame
    if (r.truth_index != UINT64_MAX) m_frames[c][r.truth_index].pixels = r.pixels;
    const size_t slot = static_cast<size_t>(index % m_ring[c].size());
    if (m_ring_owner[c][slot] != UINT64_MAX) {
        finalize(c, m_ring_owner[c][slot]);
        m_frames[c][m_ring_owner[c][slot]].slot = -1;
    }
    std::vector<uint8_t>& buffer = m_ring[c][slot];
    std::memset(buffer.data(), 0, buffer.size());
    m_ring_owner[c][slot] = index;
    if (m_frames[c].size() <= index) m_frames[c].resize(index + 1);
    m_frames[c][index].slot = static_cast<int>(slot);
    r.truth_index = index;
    r.frame = buffer.data();
    r.pixels = 0;
    r.row = 0;
    r.col = 0;
    m_events.add_pin_event(s.truth()[index].start_tick, event_kind::sensor_frame,
                           static_cast<uint8_t>(c), static_cast<uint32_t>(index));
}

void frame_recorder::finalize(int c, uint64_t index) {
    frame_info& f = m_frames[c][index];
    if (f.have_checksum || f.slot < 0) return;
    if (m_rec[c].truth_index == index) f.pixels = m_rec[c].pixels;
    const std::vector<uint8_t>& buffer = m_ring[c][static_cast<size_t>(f.slot)];
    f.checksum = fnv1a(buffer.data(), buffer.size());
    f.have_checksum = true;
}

void frame_recorder::finish() {
    for (int c = 0; c < 2; ++c) {
        if (m_rec[c].truth_index != UINT64_MAX)
            m_frames[c][m_rec[c].truth_index].pixels = m_rec[c].pixels;
    }
}

const uint8_t* frame_recorder::pixels(int c, uint64_t index) const {
    if (index >= m_frames[c].size() || m_frames[c][index].slot < 0) return nullptr;
    return m_ring[c][static_cast<size_t>(m_frames[c][index].slot)].data();
}

bool frame_recorder::checksum(int c, uint64_t index, uint64_t* checksum) {
    if (index >= m_frames[c].size()) return false;
    finalize(c, index);
    if (!m_frames[c][index].have_checksum) return false;
    *checksum = m_frames[c][index].checksum;
    return true;
}

}  // namespace platform
