#include "dsp/object_depth.h"

#include <algorithm>

#include "dsp/int_bounds.h"

namespace dsp {

namespace {

constexpr int max_tiles_per_side = 16;
constexpr int max_tiles = max_tiles_per_side * max_tiles_per_side;
constexpr int max_tile_rows = 64;  // a tile's height: under 2 min_tile_side up to 512 rows

// Tiles along one side of `length` px: as many as fit at min_tile_side, at
// most tiles_per_side.
int tiles_along(int length, const object_depth_params& params) {
    const int per_side = std::min(params.tiles_per_side, max_tiles_per_side);
    return std::max(1, std::min(per_side, length / params.min_tile_side));
}

// A tile matched on the object has a SAD near the object's other tiles'; one
// of background in the object's range (its true minimum lies outside it)
// is far above (measured on the 320 px ball: 0.2-1.5 a pixel on the ball
// on the host, 1-2.5 co-simulated with the sensors' noise; 10-55 on the
// background around it). Gate: gate_median_factor x the
// median tile's SAD plus gate_floor_per_pixel a pixel (room for noise).
uint64_t sad_gate(const uint32_t* sads, int n, int area, const object_depth_params& params) {
    uint32_t sorted[max_tiles];
    for (int k = 0; k < n; ++k) {  // insertion sort: n <= 256
        int at = k;
        while (at > 0 && sorted[at - 1] > sads[k]) {
            sorted[at] = sorted[at - 1];
            --at;
        }
        sorted[at] = sads[k];
    }
    return uint64_t{sorted[n / 2]} * static_cast<uint64_t>(params.gate_median_factor) +
           static_cast<uint64_t>(params.gate_floor_per_pixel) * static_cast<uint64_t>(area);
}

// `tile`'s part of the object rows (absolute columns, one per tile row) as
// spans relative to the tile; returns its pixels.
int clip_to_tile(const row_span* object_rows, box tile, row_span* spans) {
    int pixels = 0;
    for (int y = 0; y < tile.height; ++y) {
        spans[y].begin = std::max(0, std::min(tile.width, object_rows[y].begin - tile.x));
        spans[y].end = std::max(spans[y].begin, std::min(tile.width, object_rows[y].end - tile.x));
        pixels += spans[y].end - spans[y].begin;
    }
    return pixels;
}

}  // namespace

int surface_spread_px(int32_t core_q8, int side, const camera_rig& rig) {
    const int64_t true_q8 = core_q8 - rig.principal_offset_q8();
    const int64_t focal_q8 = rig.focal_px_q8();
    if (true_q8 <= 0 || focal_q8 <= 0) return 2;
    return static_cast<int>(true_q8 * side / (2 * focal_q8)) + 2;
}

bool object_is_tiled(box object, const object_depth_params& params) {
    return object.width >= params.min_object_side || object.height >= params.min_object_side;
}

object_depth_result match_object_surface(gray_cplane right, gray_cplane left, box object,
                                         int32_t core_q8, const stereo_params& search,
                                         const camera_rig& rig, const object_depth_params& params,
                                         bool outlined) {
    object_depth_result r;
    if (!object_is_tiled(object, params)) return r;
    r.tiled = true;
    const int spread = surface_spread_px(core_q8, std::max(object.width, object.height), rig);
    stereo_params narrow = search;
    narrow.min_disparity = std::max(search.min_disparity, (core_q8 >> 8) - spread);
    narrow.max_disparity = std::min(search.max_disparity, ((core_q8 + 255) >> 8) + spread);
    narrow.fit = params.tile_fit;

    const int columns = tiles_along(object.width, params);
    const int rows = tiles_along(object.height, params);
    r.columns = columns;
    r.rows = rows;
    r.tile_width = object.width / columns;
    r.tile_height = object.height / rows;
    if (r.tile_height > max_tile_rows) return r;
    // The grid centred on the box (its remainder split between both sides).
    const int x0 = object.x + (object.width - columns * r.tile_width) / 2;
    const int y0 = object.y + (object.height - rows * r.tile_height) / 2;
    const int64_t offset_q8 = rig.principal_offset_q8();
    int32_t tile_q8[max_tiles];
    uint32_t tile_sad[max_tiles];
    uint32_t tile_pixels[max_tiles];
    const int area = r.tile_width * r.tile_height;
    // Outlined: each tile row's part of the box's ellipse (inset), each tile
    // matched on its part of it.
    const int inset = params.outline_inset;
    const box ellipse{object.x + inset, object.y + inset, object.width - 2 * inset,
                      object.height - 2 * inset};
    const bool masked = outlined && !ellipse.empty();
    row_span ellipse_rows[max_tile_rows];
    row_span spans[max_tile_rows];
    for (int j = 0; j < rows; ++j) {
        const int tile_y = y0 + j * r.tile_height;
        if (masked)
            for (int y = 0; y < r.tile_height; ++y)
                ellipse_rows[y] = ellipse_row(ellipse, tile_y + y);
        for (int i = 0; i < columns; ++i) {
            const box tile{x0 + i * r.tile_width, tile_y, r.tile_width, r.tile_height};
            const int pixels = masked ? clip_to_tile(ellipse_rows, tile, spans) : area;
            if (4 * pixels < area) continue;  // a corner's sliver: too few pixels to match
            const stereo_result m = masked
                                        ? stereo_match_sad_masked(right, left, tile, spans, narrow)
                                        : stereo_match_sad(right, left, tile, narrow);
            ++r.tiles;
            r.positions += m.positions;
            // Kept only with its minimum strictly inside the narrow range.
            if (!m.valid ||
                at_range_end(m, tile, narrow.min_disparity, narrow.max_disparity, left.width))
                continue;
            if (m.disparity_q8 - offset_q8 <= 0) continue;
            tile_q8[r.inside] = m.disparity_q8;
            // The SAD a whole tile would have at that rate, for the gate.
            tile_sad[r.inside] =
                pixels == area
                    ? m.sad
                    : static_cast<uint32_t>(uint64_t{m.sad} * static_cast<uint64_t>(area) /
                                            static_cast<uint64_t>(pixels));
            tile_pixels[r.inside] = static_cast<uint32_t>(pixels);
            ++r.inside;
        }
    }
    const uint64_t gate = r.inside > 0 ? sad_gate(tile_sad, r.inside, area, params) : 0;
    uint64_t inverse_sum = 0;  // sum of n_i 2^32 / (d_i - offset), Q8 disparities
    uint64_t pixel_sum = 0;
    for (int k = 0; k < r.inside; ++k) {
        if (tile_sad[k] > gate) continue;
        inverse_sum +=
            tile_pixels[k] * ((uint64_t{1} << 32) / static_cast<uint64_t>(tile_q8[k] - offset_q8));
        pixel_sum += tile_pixels[k];
        ++r.matched;
    }
    if (r.matched < params.min_tiles || inverse_sum == 0) return r;
    const uint64_t mean_q8 = ((pixel_sum << 32) + inverse_sum / 2) / inverse_sum;
    r.valid = true;
    r.disparity_q8 = static_cast<int32_t>(static_cast<int64_t>(mean_q8) + offset_q8);
    return r;
}

}  // namespace dsp
