#include "dsp/motion_detect.h"

#include <algorithm>
#include <cstring>

namespace dsp {
namespace {

// The pixel kernels take a block of pixels per step, as the C64x takes 8 with
// packed instructions on 64-bit words; a fixed-size inner loop into a local
// block is also what the host compiler turns into its own SIMD. The row's
// last width % block pixels take single steps.
constexpr int block = 16;

inline uint8_t abs_diff(uint8_t a, uint8_t b) {
    return static_cast<uint8_t>(std::max(a, b) - std::min(a, b));
}

inline uint8_t binary(bool set) {
    return set ? uint8_t{255} : uint8_t{0};
}

inline uint64_t load8(const uint8_t* p) {
    uint64_t v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// One row of a binary 3x3 erosion (AND of the 9 pixels) or dilation (OR).
// above / below are null outside the image. Eight pixels per step with
// lane-wise AND / OR on 64-bit words; the left and right neighbours come
// from loads one byte earlier and later, never from shifts across lanes, so
// the word's byte order does not matter.
template <bool erode>
void morph_row(const uint8_t* above, const uint8_t* row, const uint8_t* below, int width,
               uint8_t* out) {
    // Background (0) outside: a missing row or column forces 0 under erosion
    // and is neutral under dilation, where the centre row stands in for it.
    if (erode && (above == nullptr || below == nullptr)) {
        std::memset(out, 0, static_cast<size_t>(width));
        return;
    }
    if (above == nullptr) above = row;
    if (below == nullptr) below = row;
    auto combine = [](uint64_t a, uint64_t b) { return erode ? (a & b) : (a | b); };
    auto column8 = [&](int x) {
        return combine(combine(load8(above + x), load8(row + x)), load8(below + x));
    };
    auto single = [&](int x) {
        uint8_t acc = erode ? uint8_t{255} : uint8_t{0};
        for (int xx = x - 1; xx <= x + 1; ++xx) {
            if (xx < 0 || xx >= width) {
                if (erode) return uint8_t{0};
                continue;
            }
            const uint8_t column = erode ? static_cast<uint8_t>(above[xx] & row[xx] & below[xx])
                                         : static_cast<uint8_t>(above[xx] | row[xx] | below[xx]);
            acc = erode ? static_cast<uint8_t>(acc & column) : static_cast<uint8_t>(acc | column);
        }
        return acc;
    };

    if (width <= 0) return;
    out[0] = single(0);
    int x = 1;
    for (; x + 9 <= width; x += 8) {  // reads columns x - 1 .. x + 8
        const uint64_t v = combine(combine(column8(x - 1), column8(x)), column8(x + 1));
        std::memcpy(out + x, &v, sizeof v);
    }
    for (; x < width; ++x) out[x] = single(x);
}

template <bool erode>
void morph_3x3(gray_cplane in, gray_plane out) {
    for (int y = 0; y < in.height; ++y) {
        const uint8_t* above = y > 0 ? in.row(y - 1) : nullptr;
        const uint8_t* below = y + 1 < in.height ? in.row(y + 1) : nullptr;
        morph_row<erode>(above, in.row(y), below, in.width, out.row(y));
    }
}

// Union-find with every link pointing to a smaller label, so a single
// forward pass over the table resolves all roots.
inline int32_t find_root(int32_t* parent, int32_t label) {
    while (parent[label] != label) {
        parent[label] = parent[parent[label]];  // path halving
        label = parent[label];
    }
    return label;
}

// While labelling, a stats entry keeps its box as (x0, y0, x1, y1) with x1,
// y1 inclusive in (x, y, width, height); the final pass converts it.
inline void extend(component& c, int x0, int x1_inclusive, int y, int area) {
    c.bbox.x = std::min(c.bbox.x, x0);
    c.bbox.width = std::max(c.bbox.width, x1_inclusive);
    c.bbox.y = std::min(c.bbox.y, y);
    c.bbox.height = std::max(c.bbox.height, y);
    c.area += area;
}

inline void merge(component& into, const component& from) {
    into.bbox.x = std::min(into.bbox.x, from.bbox.x);
    into.bbox.y = std::min(into.bbox.y, from.bbox.y);
    into.bbox.width = std::max(into.bbox.width, from.bbox.width);
    into.bbox.height = std::max(into.bbox.height, from.bbox.height);
    into.area += from.area;
}

bool larger_first(const component& a, const component& b) {
    if (a.area != b.area) return a.area > b.area;
    if (a.bbox.y != b.bbox.y) return a.bbox.y < b.bbox.y;
    return a.bbox.x < b.bbox.x;
}

}  // namespace

void absdiff(gray_cplane a, gray_cplane b, gray_plane out) {
    for (int y = 0; y < a.height; ++y) {
        const uint8_t* ra = a.row(y);
        const uint8_t* rb = b.row(y);
        uint8_t* ro = out.row(y);
        int x = 0;
        for (; x + block <= a.width; x += block) {
            uint8_t d[block];
            for (int i = 0; i < block; ++i) d[i] = abs_diff(ra[x + i], rb[x + i]);
            std::memcpy(ro + x, d, block);
        }
        for (; x < a.width; ++x) ro[x] = abs_diff(ra[x], rb[x]);
    }
}

void threshold_binary(gray_cplane in, uint8_t threshold, gray_plane out) {
    for (int y = 0; y < in.height; ++y) {
        const uint8_t* ri = in.row(y);
        uint8_t* ro = out.row(y);
        int x = 0;
        for (; x + block <= in.width; x += block) {
            uint8_t d[block];
            for (int i = 0; i < block; ++i) d[i] = binary(ri[x + i] > threshold);
            std::memcpy(ro + x, d, block);
        }
        for (; x < in.width; ++x) ro[x] = binary(ri[x] > threshold);
    }
}

void mask_and(gray_cplane a, gray_cplane b, gray_plane out) {
    for (int y = 0; y < a.height; ++y) {
        const uint8_t* ra = a.row(y);
        const uint8_t* rb = b.row(y);
        uint8_t* ro = out.row(y);
        int x = 0;
        for (; x + block <= a.width; x += block) {
            uint8_t d[block];
            for (int i = 0; i < block; ++i) d[i] = static_cast<uint8_t>(ra[x + i] & rb[x + i]);
            std::memcpy(ro + x, d, block);
        }
        for (; x < a.width; ++x) ro[x] = static_cast<uint8_t>(ra[x] & rb[x]);
    }
}

void three_frame_difference(gray_cplane f_tm2, gray_cplane f_tm1, gray_cplane f_t,
                            uint8_t threshold, gray_plane object_mask) {
    // Both differences above the threshold <=> the smaller one is.
    auto object = [threshold](uint8_t a, uint8_t b, uint8_t c) {
        return binary(std::min(abs_diff(a, b), abs_diff(b, c)) > threshold);
    };
    for (int y = 0; y < f_tm1.height; ++y) {
        const uint8_t* r0 = f_tm2.row(y);
        const uint8_t* r1 = f_tm1.row(y);
        const uint8_t* r2 = f_t.row(y);
        uint8_t* ro = object_mask.row(y);
        int x = 0;
        for (; x + block <= f_tm1.width; x += block) {
            uint8_t d[block];
            for (int i = 0; i < block; ++i) d[i] = object(r0[x + i], r1[x + i], r2[x + i]);
            std::memcpy(ro + x, d, block);
        }
        for (; x < f_tm1.width; ++x) ro[x] = object(r0[x], r1[x], r2[x]);
    }
}

int packed_row_bytes(int width) {
    return width > 0 ? (width + 7) / 8 : 0;
}

size_t packed_mask_bytes(int width, int height) {
    return height > 0 ? static_cast<size_t>(packed_row_bytes(width)) * static_cast<size_t>(height)
                      : 0;
}

void difference_packed(gray_cplane a, gray_cplane b, uint8_t threshold, uint8_t* packed) {
    const int row_bytes = packed_row_bytes(a.width);
    for (int y = 0; y < a.height; ++y) {
        const uint8_t* ra = a.row(y);
        const uint8_t* rb = b.row(y);
        uint8_t* rp = packed + static_cast<size_t>(y) * static_cast<size_t>(row_bytes);
        for (int byte = 0; byte < row_bytes; ++byte) {
            const int x0 = 8 * byte, n = std::min(8, a.width - x0);
            uint8_t bits = 0;
            for (int i = 0; i < n; ++i)
                bits |= static_cast<uint8_t>((abs_diff(ra[x0 + i], rb[x0 + i]) > threshold) << i);
            rp[byte] = bits;
        }
    }
}

void three_frame_difference_packed_row(const uint8_t* f_tm1, const uint8_t* f_t, int width,
                                       uint8_t threshold, uint8_t* packed_row,
                                       uint8_t* object_row) {
    const int row_bytes = packed_row_bytes(width);
    for (int byte = 0; byte < row_bytes; ++byte) {
        const int x0 = 8 * byte, n = std::min(8, width - x0);
        const uint8_t older = packed_row[byte];
        uint8_t newer = 0;
        for (int i = 0; i < n; ++i)
            newer |= static_cast<uint8_t>((abs_diff(f_tm1[x0 + i], f_t[x0 + i]) > threshold) << i);
        const uint8_t object = older & newer;
        for (int i = 0; i < n; ++i) object_row[x0 + i] = binary((object >> i) & 1u);
        packed_row[byte] = newer;
    }
}

void three_frame_difference_packed(gray_cplane f_tm1, gray_cplane f_t, uint8_t threshold,
                                   uint8_t* packed, gray_plane object_mask) {
    const int row_bytes = packed_row_bytes(f_tm1.width);
    for (int y = 0; y < f_tm1.height; ++y)
        three_frame_difference_packed_row(
            f_tm1.row(y), f_t.row(y), f_tm1.width, threshold,
            packed + static_cast<size_t>(y) * static_cast<size_t>(row_bytes), object_mask.row(y));
}

void erode_3x3(gray_cplane in, gray_plane out) {
    morph_3x3<true>(in, out);
}
void dilate_3x3(gray_cplane in, gray_plane out) {
    morph_3x3<false>(in, out);
}

void component_labeller::begin(int width, int32_t* labels, int32_t* parent, component* stats,
                               int max_labels) {
    m_width = width;
    m_above = labels;  // run labels of row y - 1, -1 = background
    m_current = labels + width;
    m_parent = parent;
    m_stats = stats;
    m_max_labels = max_labels;
    m_label_count = 0;
    m_overflow = false;
    for (int x = 0; x < width; ++x) m_above[x] = -1;
}

bool component_labeller::add_row(const uint8_t* row, int y) {
    if (m_overflow) return false;
    const int width = m_width;
    int32_t* above = m_above;
    int32_t* current = m_current;
    int32_t* parent = m_parent;
    int x = 0;
    while (x < width) {
        if (row[x] == 0) {
            current[x++] = -1;
            continue;
        }
        const int run_start = x;
        while (x < width && row[x] != 0) ++x;
        const int run_end = x;  // one past the run

        // 8-connectivity: the run touches labels above from one column
        // left of its start to one column right of its end.
        int32_t label = -1;
        const int look_from = std::max(run_start - 1, 0);
        const int look_to = std::min(run_end + 1, width);
        for (int xa = look_from; xa < look_to; ++xa) {
            if (above[xa] < 0 || (xa > look_from && above[xa] == above[xa - 1])) continue;
            const int32_t root = find_root(parent, above[xa]);
            if (label < 0) {
                label = root;
            } else if (root != label) {
                const int32_t keep = std::min(root, label);
                parent[std::max(root, label)] = keep;
                label = keep;
            }
        }
        if (label < 0) {
            if (m_label_count == m_max_labels) {
                m_overflow = true;
                return false;
            }
            label = m_label_count++;
            parent[label] = label;
            m_stats[label].bbox = box{run_start, y, run_start, y};
            m_stats[label].area = 0;
        }
        extend(m_stats[label], run_start, run_end - 1, y, run_end - run_start);
        for (int xr = run_start; xr < run_end; ++xr) current[xr] = label;
    }
    std::swap(m_above, m_current);
    return true;
}

int component_labeller::finish(component* out, int max_out) {
    if (m_overflow) return -1;
    int32_t* parent = m_parent;
    component* stats = m_stats;
    // Resolve every label to its root (links point to smaller labels, so a
    // forward pass sees each parent resolved first), fold the stats into the
    // roots and pack the roots to the front of the table.
    int count = 0;
    for (int32_t i = 0; i < m_label_count; ++i) {
        if (parent[i] == i) continue;
        parent[i] = parent[parent[i]];
        merge(stats[parent[i]], stats[i]);
    }
    for (int32_t i = 0; i < m_label_count; ++i) {
        if (parent[i] != i) continue;
        component c = stats[i];
        c.bbox.width = c.bbox.width - c.bbox.x + 1;
        c.bbox.height = c.bbox.height - c.bbox.y + 1;
        stats[count++] = c;
    }

    const int written = std::max(0, std::min(count, max_out));
    std::partial_sort(stats, stats + written, stats + count, larger_first);
    for (int i = 0; i < written; ++i) out[i] = stats[i];
    return written;
}

int connected_components(gray_cplane mask, int32_t* labels, int32_t* parent, component* stats,
                         int max_labels, component* out, int max_out) {
    component_labeller labeller;
    labeller.begin(mask.width, labels, parent, stats, max_labels);
    for (int y = 0; y < mask.height; ++y)
        if (!labeller.add_row(mask.row(y), y)) return -1;
    return labeller.finish(out, max_out);
}

motion_detector::~motion_detector() {
    release();
}

void motion_detector::release() {
    delete[] m_mask;
    delete[] m_rings;
    delete[] m_out_row;
    delete[] m_labels;
    delete[] m_components;
    delete[] m_stats;
    delete[] m_parent;
    m_mask = m_rings = m_out_row = nullptr;
    m_labels = m_parent = nullptr;
    m_components = m_stats = nullptr;
}

size_t motion_detector::workspace_bytes(int max_width, int max_height, int max_components,
                                        bool keep_mask) {
    const size_t w = static_cast<size_t>(max_width), comps = static_cast<size_t>(max_components);
    size_t bytes = (3 * max_passes + 1) * w   // rings, output row
                   + 2 * w * sizeof(int32_t)  // run labels
                   + 2 * comps * sizeof(component) + comps * sizeof(int32_t) +
                   motion_blocks::workspace_bytes(max_width, max_height);
    if (keep_mask) bytes += w * static_cast<size_t>(max_height);
    return bytes;
}

void motion_detector::init(int max_width, int max_height, int max_components, bool keep_mask) {
    const size_t w = static_cast<size_t>(max_width);
    release();
    m_max_width = max_width;
    m_max_height = max_height;
    m_max_components = max_components;
    if (keep_mask) m_mask = new uint8_t[w * static_cast<size_t>(max_height)]();
    m_rings = new uint8_t[3 * max_passes * w]();
    m_out_row = new uint8_t[w]();
    m_labels = new int32_t[2 * w];
    m_components = new component[static_cast<size_t>(max_components)];
    m_stats = new component[static_cast<size_t>(max_components)];
    m_parent = new int32_t[static_cast<size_t>(max_components)];
    m_blocks.init(max_width, max_height);
    m_width = m_height = m_last_width = m_last_height = m_last_foreground = m_last_components = 0;
}

uint8_t* motion_detector::ring_row(int pass, int y) const {
    return m_rings + (static_cast<size_t>(pass) * 3 + static_cast<size_t>(y % 3)) *
                         static_cast<size_t>(m_max_width);
}

// Where pass `pass` (or, past the last pass, the labeller) takes row y.
// Input row y of pass p is in ring_row(p, y); when row y is in, output row
// y - 1 (rows y-2, y-1, y) is ready and goes to the next pass's ring slot
// (y - 1) % 3, whose old row (y - 4) that pass no longer needs.
void motion_detector::push_row(int pass, int y) {
    if (pass == m_passes) {  // no passes: the source wrote m_out_row
        emit_row(m_out_row, y);
        return;
    }
    if (y < 1) return;
    const int out_y = y - 1;
    const uint8_t* above = out_y >= 1 ? ring_row(pass, out_y - 1) : nullptr;
    uint8_t* out = pass + 1 < m_passes ? ring_row(pass + 1, out_y) : m_out_row;
    if (m_pass_erodes[pass])
        morph_row<true>(above, ring_row(pass, out_y), ring_row(pass, y), m_width, out);
    else
        morph_row<false>(above, ring_row(pass, out_y), ring_row(pass, y), m_width, out);
    if (pass + 1 < m_passes)
        push_row(pass + 1, out_y);
    else
        emit_row(m_out_row, out_y);
}

// After the last input row: pass `pass` emits its last row (no row below),
// then the next pass does the same.
void motion_detector::flush(int pass) {
    if (pass == m_passes) return;
    const int out_y = m_height - 1;
    const uint8_t* above = out_y >= 1 ? ring_row(pass, out_y - 1) : nullptr;
    uint8_t* out = pass + 1 < m_passes ? ring_row(pass + 1, out_y) : m_out_row;
    if (m_pass_erodes[pass])
        morph_row<true>(above, ring_row(pass, out_y), nullptr, m_width, out);
    else
        morph_row<false>(above, ring_row(pass, out_y), nullptr, m_width, out);
    if (pass + 1 < m_passes)
        push_row(pass + 1, out_y);
    else
        emit_row(m_out_row, out_y);
    flush(pass + 1);
}

void motion_detector::emit_row(const uint8_t* row, int y) {
    if (m_mask) std::memcpy(m_mask + static_cast<size_t>(y) * m_width, row, m_width);
    m_labeller.add_row(row, y);
}

detection motion_detector::run(int width, int height, const detect_params& params,
                               row_source source, void* context) {
    detection result;
    m_passes = 0;
    for (int i = 0; i < params.open_passes; ++i) m_pass_erodes[m_passes++] = true;
    for (int i = 0; i < params.open_passes; ++i) m_pass_erodes[m_passes++] = false;
    for (int i = 0; i < params.close_passes; ++i) m_pass_erodes[m_passes++] = false;
    for (int i = 0; i < params.close_passes; ++i) m_pass_erodes[m_passes++] = true;
    m_width = width;
    m_height = height;
    m_labeller.begin(width, m_labels, m_parent, m_stats, m_max_components);
    m_blocks.begin(width, height);
    for (int y = 0; y < height; ++y) {
        uint8_t* raw = m_passes > 0 ? ring_row(0, y) : m_out_row;
        source(context, y, raw);
        m_blocks.add_row(raw, y);
        push_row(0, y);
    }
    flush(0);
    m_last_width = width;
    m_last_height = height;

    const int count = m_labeller.finish(m_components, m_max_components);
    if (count < 0) {
        result.label_overflow = true;
        return result;
    }
    m_last_components = count;
    for (int i = 0; i < count; ++i) {
        m_last_foreground += m_components[i].area;
        if (m_components[i].area >= params.min_area) ++result.components;
    }
    if (result.components > 0) {
        result.found = true;
        result.bbox = m_components[0].bbox;
        result.area = m_components[0].area;
    }
    const block_group group =
        m_blocks.extent(result.found ? result.bbox : box{}, params.min_group_pixels);
    result.object_found = result.found || group.found;
    result.object_box = result.found ? result.bbox : group.bbox;
    if (result.found && group.found) result.object_box = bounding_union(result.bbox, group.bbox);
    return result;
}

namespace {

bool size_refused(int width, int height, int max_width, int max_height,
                  const detect_params& params) {
    const bool passes_fit =
        params.open_passes >= 0 && params.close_passes >= 0 &&
        2 * (params.open_passes + params.close_passes) <= motion_detector::max_passes;
    return width <= 0 || height <= 0 || width > max_width || height > max_height || !passes_fit;
}

struct three_frames {
    gray_cplane f_tm2, f_tm1, f_t;
    uint8_t threshold;
};

struct packed_frames {
    gray_cplane f_tm1, f_t;
    uint8_t* packed;
    uint8_t threshold;
};

}  // namespace

detection motion_detector::detect(gray_cplane f_tm2, gray_cplane f_tm1, gray_cplane f_t,
                                  const detect_params& params) {
    m_last_width = m_last_height = m_last_foreground = m_last_components = 0;
    if (m_rings == nullptr ||
        size_refused(f_tm1.width, f_tm1.height, m_max_width, m_max_height, params))
        return detection{};
    three_frames frames{f_tm2, f_tm1, f_t, params.threshold};
    auto source = [](void* context, int y, uint8_t* out) {
        const auto& f = *static_cast<const three_frames*>(context);
        three_frame_difference(f.f_tm2.sub(0, y, f.f_tm1.width, 1),
                               f.f_tm1.sub(0, y, f.f_tm1.width, 1),
                               f.f_t.sub(0, y, f.f_tm1.width, 1), f.threshold,
                               gray_plane{out, f.f_tm1.width, 1, f.f_tm1.width});
    };
    return run(f_tm1.width, f_tm1.height, params, source, &frames);
}

detection motion_detector::detect_packed(gray_cplane f_tm1, gray_cplane f_t, uint8_t* packed,
                                         const detect_params& params) {
    m_last_width = m_last_height = m_last_foreground = m_last_components = 0;
    if (m_rings == nullptr || packed == nullptr ||
        size_refused(f_tm1.width, f_tm1.height, m_max_width, m_max_height, params))
        return detection{};
    packed_frames frames{f_tm1, f_t, packed, params.threshold};
    auto source = [](void* context, int y, uint8_t* out) {
        const auto& f = *static_cast<const packed_frames*>(context);
        const size_t row_bytes = static_cast<size_t>(packed_row_bytes(f.f_tm1.width));
        three_frame_difference_packed_row(f.f_tm1.row(y), f.f_t.row(y), f.f_tm1.width, f.threshold,
                                          f.packed + static_cast<size_t>(y) * row_bytes, out);
    };
    return run(f_tm1.width, f_tm1.height, params, source, &frames);
}

detection motion_detector::detect_rows(int width, int height, const detect_params& params,
                                       row_source source, void* context) {
    m_last_width = m_last_height = m_last_foreground = m_last_components = 0;
    if (m_rings == nullptr || size_refused(width, height, m_max_width, m_max_height, params))
        return detection{};
    return run(width, height, params, source, context);
}

gray_cplane motion_detector::last_mask() const {
    if (m_mask == nullptr) return gray_cplane{};
    return gray_cplane{m_mask, m_last_width, m_last_height, m_last_width};
}

}  // namespace dsp
