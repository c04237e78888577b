#include "dsp/stereo_edge.h"

namespace dsp {

namespace {

struct q8_range {
    int32_t begin;  // inclusive, Q8 columns
    int32_t end;    // exclusive
    bool contains(int32_t v) const { return v >= begin && v < end; }
};

// Segment boundaries on one row: each run of magnitudes > threshold becomes
// one boundary at its magnitude-weighted centroid (Q8); boundaries outside
// `keep` are dropped. Runs are followed to their ends in the row, so a
// boundary does not depend on where the scan starts or stops. Returns the count.
int find_boundaries(const uint8_t* row, int width, q8_range keep, uint8_t threshold, int32_t* out) {
    // Pixels a kept centroid can lie in: [begin / 256, end / 256] rounded outwards.
    int x = (keep.begin + 128) >> 8;
    int scan_end = ((keep.end + 128) >> 8) + 1;
    if (x < 0) x = 0;
    if (scan_end > width) scan_end = width;
    while (x > 0 && row[x - 1] > threshold) --x;  // start of a run cut by the scan start
    int count = 0;
    while (x < scan_end) {
        if (row[x] <= threshold) {
            ++x;
            continue;
        }
        uint32_t weight = 0;
        uint64_t moment = 0;
        for (; x < width && row[x] > threshold; ++x) {
            weight += row[x];
            moment += static_cast<uint64_t>(row[x]) * static_cast<uint64_t>(x);
        }
        const int32_t centroid = static_cast<int32_t>((moment * 256 + weight / 2) / weight);
        if (keep.contains(centroid) && count < edge_max_boundaries) out[count++] = centroid;
    }
    return count;
}

int32_t absolute(int32_t v) {
    return v < 0 ? -v : v;
}

// Signed distance from q to the nearest entry of the sorted list, found from
// the hint index *cursor, which only moves forward (queries come in order).
int32_t nearest_offset(const int32_t* sorted, int count, int32_t q, int* cursor) {
    int j = *cursor;
    while (j + 1 < count && sorted[j + 1] <= q) ++j;
    *cursor = j;
    int32_t best = sorted[j] - q;
    if (j + 1 < count && absolute(sorted[j + 1] - q) < absolute(best)) best = sorted[j + 1] - q;
    return best;
}

}  // namespace

stereo_result stereo_match_edge(gray_cplane right_edges, gray_cplane left_edges, box pattern,
                                const edge_params& params) {
    stereo_result result;
    if (pattern.empty() || right_edges.empty() || left_edges.empty()) return result;
    if (pattern.x < 0 || pattern.y < 0 || pattern.right() > right_edges.width ||
        pattern.bottom() > right_edges.height)
        return result;

    int d_first = params.min_disparity;
    int d_last = params.max_disparity;
    if (pattern.x + d_first < 0) d_first = -pattern.x;
    if (pattern.right() + d_last > left_edges.width) d_last = left_edges.width - pattern.right();
    if (d_last - d_first + 1 > edge_max_shifts) d_last = d_first + edge_max_shifts - 1;
    if (d_last < d_first) return result;
    const int shifts = d_last - d_first + 1;

    const int32_t cap_q8 = params.edge_cap_px * 256;
    // Pixel x covers Q8 [x * 256 - 128, x * 256 + 128): centroids of the pattern's columns.
    const q8_range pattern_cols{pattern.x * 256 - 128, pattern.right() * 256 - 128};
    // Left boundaries a shifted right boundary could pair with (cap included).
    const q8_range left_keep{pattern_cols.begin + d_first * 256 - cap_q8,
                             pattern_cols.end + d_last * 256 + cap_q8};

    uint32_t score[edge_max_shifts] = {};
    int32_t residual_sum[edge_max_shifts] = {};  // Q8, right boundaries within 1 px
    int32_t residual_count[edge_max_shifts] = {};
    int32_t right_bounds[edge_max_boundaries];
    int32_t left_bounds[edge_max_boundaries];

    const int centre_row = pattern.center_y2() / 2;
    const int half = (params.lines - 1) / 2;
    int spacing = params.line_spacing;
    if (spacing <= 0) spacing = params.lines > 0 ? pattern.height / params.lines : 1;
    if (spacing < 1) spacing = 1;
    int right_total = 0;
    for (int k = 0; k < params.lines; ++k) {
        const int y = centre_row + (k - half) * spacing;
        if (y < pattern.y || y >= pattern.bottom() || y >= left_edges.height) continue;

        const int n_right = find_boundaries(right_edges.row(y), right_edges.width, pattern_cols,
                                            params.edge_threshold, right_bounds);
        const int n_left = find_boundaries(left_edges.row(y), left_edges.width, left_keep,
                                           params.edge_threshold, left_bounds);
        right_total += n_right;
        result.positions += shifts;

        for (int s = 0; s < shifts; ++s) {
            const int32_t shift_q8 = (d_first + s) * 256;
            uint32_t line_score = 0;
            // Right boundaries laid onto the left line.
            int cursor = 0;
            for (int i = 0; i < n_right; ++i) {
                if (n_left == 0) {
                    line_score += static_cast<uint32_t>(cap_q8);
                    continue;
                }
                const int32_t offset =
                    nearest_offset(left_bounds, n_left, right_bounds[i] + shift_q8, &cursor);
                const int32_t distance = absolute(offset);
                line_score += static_cast<uint32_t>(distance < cap_q8 ? distance : cap_q8);
                if (distance < 256) {
                    residual_sum[s] += offset;
                    ++residual_count[s];
                }
            }
            // Left boundaries inside the shifted pattern, back onto the right line.
            const q8_range window{pattern_cols.begin + shift_q8, pattern_cols.end + shift_q8};
            cursor = 0;
            for (int j = 0; j < n_left; ++j) {
                if (!window.contains(left_bounds[j])) continue;
                if (n_right == 0) {
                    line_score += static_cast<uint32_t>(cap_q8);
                    continue;
                }
                const int32_t distance = absolute(
                    nearest_offset(right_bounds, n_right, left_bounds[j] - shift_q8, &cursor));
                line_score += static_cast<uint32_t>(distance < cap_q8 ? distance : cap_q8);
            }
            score[s] += line_score;
        }
    }
    if (right_total < 2) return result;  // no complete segment to match

    int best = 0;
    for (int s = 1; s < shifts; ++s)
        if (score[s] < score[best]) best = s;
    if (residual_count[best] == 0) return result;

    int32_t offset_q8 = residual_sum[best] / residual_count[best];
    if (offset_q8 > 128) offset_q8 = 128;
    if (offset_q8 < -128) offset_q8 = -128;
    result.valid = true;
    result.disparity = d_first + best;
    result.dy = 0;
    result.disparity_q8 = result.disparity * 256 + offset_q8;
    result.sad = score[best];
    return result;
}

}  // namespace dsp
