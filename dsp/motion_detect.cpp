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

void erode_3x3(gray_cplane in, gray_plane out) {
    morph_3x3<true>(in, out);
}
void dilate_3x3(gray_cplane in, gray_plane out) {
    morph_3x3<false>(in, out);
}

int connected_components(gray_cplane mask, int32_t* labels, int32_t* parent, component* stats,
                         int max_labels, component* out, int max_out) {
    const int width = mask.width;
    int32_t* above = labels;  // run labels of row y - 1, -1 = background
    int32_t* current = labels + width;
    for (int x = 0; x < width; ++x) above[x] = -1;

    int32_t label_count = 0;
    for (int y = 0; y < mask.height; ++y) {
        const uint8_t* row = mask.row(y);
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
                if (label_count == max_labels) return -1;
                label = label_count++;
                parent[label] = label;
                stats[label].bbox = box{run_start, y, run_start, y};
                stats[label].area = 0;
            }
            extend(stats[label], run_start, run_end - 1, y, run_end - run_start);
            for (int xr = run_start; xr < run_end; ++xr) current[xr] = label;
        }
        std::swap(above, current);
    }

    // Resolve every label to its root (links point to smaller labels, so a
    // forward pass sees each parent resolved first), fold the stats into the
    // roots and pack the roots to the front of the table.
    int count = 0;
    for (int32_t i = 0; i < label_count; ++i) {
        if (parent[i] == i) continue;
        parent[i] = parent[parent[i]];
        merge(stats[parent[i]], stats[i]);
    }
    for (int32_t i = 0; i < label_count; ++i) {
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

motion_detector::~motion_detector() {
    delete[] m_mask;
    delete[] m_scratch;
    delete[] m_labels;
    delete[] m_components;
    delete[] m_stats;
    delete[] m_parent;
}

void motion_detector::init(int max_width, int max_height, int max_components) {
    const size_t pixels = static_cast<size_t>(max_width) * static_cast<size_t>(max_height);
    m_max_width = max_width;
    m_max_height = max_height;
    m_max_components = max_components;
    delete[] m_mask;
    delete[] m_scratch;
    delete[] m_labels;
    delete[] m_components;
    delete[] m_stats;
    delete[] m_parent;
    m_mask = new uint8_t[pixels]();
    m_scratch = new uint8_t[pixels]();
    m_labels = new int32_t[2 * static_cast<size_t>(max_width)];
    m_components = new component[static_cast<size_t>(max_components)];
    m_stats = new component[static_cast<size_t>(max_components)];
    m_parent = new int32_t[static_cast<size_t>(max_components)];
    m_result = m_mask;
    m_last_width = m_last_height = m_last_foreground = m_last_components = 0;
}

detection motion_detector::detect(gray_cplane f_tm2, gray_cplane f_tm1, gray_cplane f_t,
                                  const detect_params& params) {
    detection result;
    m_last_width = m_last_height = m_last_foreground = m_last_components = 0;
    const int width = f_tm1.width;
    const int height = f_tm1.height;
    if (m_mask == nullptr || width <= 0 || height <= 0 || width > m_max_width ||
        height > m_max_height)
        return result;

    gray_plane mask{m_mask, width, height, width};
    gray_plane spare{m_scratch, width, height, width};
    three_frame_difference(f_tm2, f_tm1, f_t, params.threshold, mask);

    // Ping-pong between the two buffers; `mask` always holds the latest.
    auto apply = [&](void (*op)(gray_cplane, gray_plane), int passes) {
        for (int i = 0; i < passes; ++i) {
            op(mask.as_const(), spare);
            std::swap(mask, spare);
        }
    };
    apply(erode_3x3, params.open_passes);
    apply(dilate_3x3, params.open_passes);
    apply(dilate_3x3, params.close_passes);
    apply(erode_3x3, params.close_passes);
    m_result = mask.data;
    m_last_width = width;
    m_last_height = height;

    const int count = connected_components(mask.as_const(), m_labels, m_parent, m_stats,
                                           m_max_components, m_components, m_max_components);
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
    return result;
}

gray_cplane motion_detector::last_mask() const {
    return gray_cplane{m_result, m_last_width, m_last_height, m_last_width};
}

}  // namespace dsp
