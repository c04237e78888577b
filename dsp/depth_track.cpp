#include "dsp/depth_track.h"

#include <algorithm>

namespace dsp {

namespace {

constexpr uint64_t depth_scale = uint64_t{1} << 32;  // depth units: 2^32 / Q8 disparity

// The least-squares line through depths[0..n) at x = 0..n-1, in units of
// 1 / scale: with S0 = sum y and S1 = sum (2x - (n-1)) y, the line at x is
// (2 (n^2 - 1) S0 + 6 S1 (2x - (n-1))) / scale, scale = 2 n (n^2 - 1).
struct depth_line_fit {
    int64_t s0 = 0, s1 = 0;
    int n = 0;
    int64_t scale() const { return int64_t{2} * n * (int64_t{n} * n - 1); }
    int64_t at(int x) const {
        return 2 * (int64_t{n} * n - 1) * s0 + 6 * s1 * (2 * int64_t{x} - (n - 1));
    }
};

depth_line_fit fit_line(const uint32_t* depths, int n) {
    depth_line_fit f;
    f.n = n;
    for (int x = 0; x < n; ++x) {
        f.s0 += depths[x];
        f.s1 += static_cast<int64_t>(2 * x - (n - 1)) * depths[x];
    }
    return f;
}

// |y - line| more than per_mille of the line, both in units of 1 / scale.
bool off_line(int64_t y_scaled, int64_t line_scaled, int per_mille) {
    const int64_t off = y_scaled > line_scaled ? y_scaled - line_scaled : line_scaled - y_scaled;
    return off * 1000 > int64_t{per_mille} * line_scaled;
}

}  // namespace

void depth_track::push(uint32_t depth) {
    if (m_count == capacity) {
        std::copy(m_depth + 1, m_depth + capacity, m_depth);
        --m_count;
    }
    m_depth[m_count++] = depth;
}

depth_gate_result depth_track::gate(int64_t disparity_q8, int64_t offset_q8,
                                    const depth_track_params& params) {
    depth_gate_result r;
    r.disparity_q8 = disparity_q8;
    const int64_t true_q8 = disparity_q8 - offset_q8;
    if (true_q8 <= 0) {  // no depth in front of the rig: the line starts again
        clear();
        return r;
    }
    const uint32_t depth = static_cast<uint32_t>(depth_scale / static_cast<uint64_t>(true_q8));
    const int n = std::min(std::max(params.history, 2), capacity);
    if (m_count < n || m_replaced_last) {
        m_replaced_last = false;
        push(depth);
        return r;
    }
    // Gated only where the track's depths are a line: every one of them
    // within the gate of it (a detection's first depth, read on a part of
    // the object, can be 8 % off and would tilt the line).
    const uint32_t* history = m_depth + (m_count - n);
    const depth_line_fit line = fit_line(history, n);
    r.fitted = n;
    for (int x = 0; x < n; ++x)
        if (off_line(int64_t{history[x]} * line.scale(), line.at(x), params.gate_per_mille)) {
            push(depth);
            return r;
        }
    const int64_t next_scaled = line.at(n);
    if (next_scaled <= 0 ||
        !off_line(int64_t{depth} * line.scale(), next_scaled, params.gate_per_mille)) {
        push(depth);
        return r;
    }
    const int64_t next = (next_scaled + line.scale() / 2) / line.scale();
    r.replaced = m_replaced_last = true;
    push(static_cast<uint32_t>(std::min<int64_t>(next, UINT32_MAX)));
    r.disparity_q8 =
        offset_q8 + static_cast<int64_t>((depth_scale + static_cast<uint64_t>(next) / 2) /
                                         static_cast<uint64_t>(next));
    return r;
}

}  // namespace dsp
