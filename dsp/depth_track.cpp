#include "dsp/depth_track.h"

#include <algorithm>

namespace dsp {

namespace {

constexpr uint64_t depth_scale = uint64_t{1} << 32;  // depth units: 2^32 / Q8 disparity

// The least-squares line and quadratic through depths[0..n) at x = 0..n-1
// (n >= 4, the F test's residuals n - 3 degrees of freedom), by the discrete
// orthogonal polynomials P0 = 1, P1 = 2x - (n-1)
// and P2 = 6x^2 - 6(n-1)x + (n-1)(n-2), whose squares sum to n, n(n^2-1)/3
// and n(n^2-1)(n^2-4)/5: with S_k = sum P_k(x) y, the line at x is
// (S0 (n^2-1)(n^2-4) + 3 S1 P1(x) (n^2-4)) / scale, the quadratic that plus
// 5 S2 P2(x) / scale, scale = n (n^2-1) (n^2-4); exact in integers.
struct depth_fit {
    int64_t s0 = 0, s1 = 0, s2 = 0;
    int64_t n = 0;
    bool curved = false;  // the quadratic stands for the depths, not the line
    int64_t scale() const { return n * (n * n - 1) * (n * n - 4); }
    int64_t p2(int64_t x) const { return 6 * x * x - 6 * (n - 1) * x + (n - 1) * (n - 2); }
    int64_t curvature_at(int64_t x) const { return 5 * s2 * p2(x); }
    int64_t at(int64_t x) const {
        const int64_t line =
            s0 * (n * n - 1) * (n * n - 4) + 3 * s1 * (2 * x - (n - 1)) * (n * n - 4);
        return curved ? line + curvature_at(x) : line;
    }
};

// Residuals are compared in units of 4096 / scale: their squares stay in
// 64 bits for depths within the gate (scale 30240 at 8 pairs).
constexpr int64_t residual_unit = 4096;

// The curvature's F statistic over the quadratic's residuals,
// F = (RSS_line - RSS_quad) / (RSS_quad / (n - 3)), against f_critical:
// the quadratic is taken only where its term stands out of the noise.
void test_curvature(const uint32_t* depths, depth_fit& fit, int f_critical) {
    fit.curved = true;
    int64_t rss_quad = 0, rss_curvature = 0;
    for (int64_t x = 0; x < fit.n; ++x) {
        const int64_t r = (int64_t{depths[x]} * fit.scale() - fit.at(x)) / residual_unit;
        const int64_t c = fit.curvature_at(x) / residual_unit;
        rss_quad += r * r, rss_curvature += c * c;
    }
    fit.curved = rss_curvature * (fit.n - 3) > int64_t{f_critical} * rss_quad;
}

depth_fit fit_depths(const uint32_t* depths, int n, int f_critical) {
    depth_fit f;
    f.n = n;
    for (int64_t x = 0; x < n; ++x) {
        f.s0 += depths[x];
        f.s1 += (2 * x - (n - 1)) * depths[x];
        f.s2 += f.p2(x) * depths[x];
    }
    test_curvature(depths, f, f_critical);
    return f;
}

// |y - fit| more than per_mille of the fit, both in units of 1 / scale.
bool off_line(int64_t y_scaled, int64_t line_scaled, int per_mille) {
    const int64_t off = y_scaled > line_scaled ? y_scaled - line_scaled : line_scaled - y_scaled;
    return off * 1000 > int64_t{per_mille} * line_scaled;
}

// A depth off the fit that a bounce off a wall behind the ball explains:
// its depth speed reversed (restitution at most 1) or stopped somewhere
// between the last pair and this one puts it between the fit's next value
// and one step behind its last, `step` the fit's step a pair; the gate's
// margin widens the far end for the noise. Only a ball going away by more
// than half the gate a pair can turn by more than the gate: a slower
// one's step is noise, and a depth off its fit there a mismatch.
bool turned_back(int64_t y_scaled, int64_t next_scaled, int64_t step_scaled, int per_mille) {
    const int64_t margin = next_scaled * per_mille / 1000;
    return 2 * step_scaled > margin && y_scaled < next_scaled &&
           y_scaled >= next_scaled - 2 * step_scaled - margin;
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
    const int n = std::min(std::max(params.history, 4), capacity);
    if (m_count < n || m_replaced_last) {
        m_replaced_last = false;
        push(depth);
        return r;
    }
    // Gated only where the track's depths lie on their fit: every one of
    // them within the gate of it (a detection's first depth, read on a part
    // of the object, can be 8 % off and would tilt the line).
    const uint32_t* history = m_depth + (m_count - n);
    const depth_fit fit = fit_depths(history, n, params.curvature_f);
    r.fitted = n;
    for (int x = 0; x < n; ++x)
        if (off_line(int64_t{history[x]} * fit.scale(), fit.at(x), params.gate_per_mille)) {
            push(depth);
            return r;
        }
    const int64_t next_scaled = fit.at(n), depth_scaled = int64_t{depth} * fit.scale();
    if (next_scaled <= 0 || !off_line(depth_scaled, next_scaled, params.gate_per_mille)) {
        push(depth);
        return r;
    }
    if (turned_back(depth_scaled, next_scaled, next_scaled - fit.at(n - 1),
                    params.gate_per_mille)) {
        r.turned = true;  // the track's depths start again from this one
        clear();
        push(depth);
        return r;
    }
    const int64_t next = (next_scaled + fit.scale() / 2) / fit.scale();
    r.replaced = m_replaced_last = true;
    push(static_cast<uint32_t>(std::min<int64_t>(next, UINT32_MAX)));
    r.disparity_q8 =
        offset_q8 + static_cast<int64_t>((depth_scale + static_cast<uint64_t>(next) / 2) /
                                         static_cast<uint64_t>(next));
    return r;
}

}  // namespace dsp
