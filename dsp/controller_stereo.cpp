// Stereo on the object box (the core's SAD match, its tiles, the edge
// match), the disparity chosen, and the 3D point.
#include "dsp/controller_impl.h"
#include "dsp/object_core.h"
#include "dsp/object_depth.h"
#include "dsp/round_box.h"
#include "dsp/stereo_reach.h"

namespace dsp {

using namespace controller_parts;

// Stage stereo_sad: the object's core (the right pattern) along the same rows
// (+-row_slack) of the left image over the depth range; a large
// object's disparity is then its tiles' mean depth around the core's
// (dsp/object_depth.h), the core's when too few tiles matched; on a
// tracked box, the tiles of the box moved in where the object stops short
// of it, and a smaller object's core matched again on that box. The
// reported box is then widened where the object's disparity reaches past a
// side, else moved in (dsp/stereo_reach.h).
void controller::impl::stereo_sad(box object, bool outlined, frame_output& out) {
    stage_scope scope(*hardware, stage::stereo_sad, out);
    int core_pixels = 0;
    scope.charge(match_core(object, out, &core_pixels));
    if (!out.sad_match.valid || out.sad_at_range_end) return;
    // Where the object stops short of the box, read at the core's
    // disparity, the tiled depth (under its size, the core) is read again
    // on the box moved in: the background its sides took in pulled the
    // depth far (held-out round 25's 140 px ball going away, its box 4-7 px
    // too large, 1.04 %; round 80's 45 px ball, its box 6 px past its left
    // rim, 1.80 %).
    stereo_reach short_sides, short_ends;
    box surface = object;
    if (outlined) {
        scope.charge(read_short_of(core_pixels, out, &short_sides, &short_ends));
        surface = moved_box(object, stereo_reach{}, stereo_reach{}, short_sides, short_ends);
    }
    if (object_is_tiled(surface, config.surface)) {
        scope.charge(match_surface(surface, outlined, out));
    } else if (!same_box(surface, object)) {
        scope.charge(rematch_core(surface, out, &core_pixels));
    }
    if (outlined) scope.charge(widen_to_stereo_reach(core_pixels, short_sides, short_ends, out));
}

// The core's SAD match on `object` into `out`, its pixels; its cycles.
uint64_t controller::impl::match_core(box object, frame_output& out, int* core_pixels) {
    row_span spans[max_round_core_rows];
    const object_core_pattern pattern = object_core(object, config.surface, spans);
    const box core = pattern.core;
    *core_pixels = pattern.pixels;
    out.sad_match = pattern.round
                        ? stereo_match_sad_masked(history(0), left(), core, spans, config.stereo)
                        : stereo_match_sad(history(0), left(), core, config.stereo);
    out.sad_at_range_end = at_range_end(out.sad_match, core, config.stereo.min_disparity,
                                        config.stereo.max_disparity, width);
    uint64_t cycles =
        cycles_of(cost::sad_search_profile(core.width, core.height, out.sad_match.positions));
    // The round core's rows: an ellipse's half width a row, as the tiles' outline.
    if (pattern.round) cycles += cycles_of(cost::surface_outline_profile(core.height, 1, 0));
    if (config.stereo.subpixel && out.sad_match.valid) {
        cycles += cycles_of(cost::subpixel_profile());
        if (config.stereo.fit == subpixel_fit::half_pel)
            cycles += cycles_of(cost::half_pel_profile(core.width, core.height));
    }
    return cycles;
}

// The core matched again on the box moved in; the first match stands where
// the second is no measurement.
uint64_t controller::impl::rematch_core(box moved_in, frame_output& out, int* core_pixels) {
    const stereo_result first = out.sad_match;
    const int first_pixels = *core_pixels;
    const uint64_t cycles = match_core(moved_in, out, core_pixels);
    if (!out.sad_match.valid || out.sad_at_range_end) {
        out.sad_match = first;
        out.sad_at_range_end = false;
        *core_pixels = first_pixels;
    }
    return cycles;
}

// The tiled disparity of a large object (dsp/object_depth.h), its cycles.
uint64_t controller::impl::match_surface(box object, bool outlined, frame_output& out) {
    const object_depth_result& r = out.surface =
        match_object_surface(history(0), left(), object, out.sad_match.disparity_q8, config.stereo,
                             config.rig, config.surface, outlined);
    uint64_t cycles = 0;
    // Each tile a search of its own (the mean of their positions: they
    // differ only where the left image's border clips one).
    if (r.tiles > 0)
        cycles += r.tiles * cycles_of(cost::sad_search_profile(r.tile_width, r.tile_height,
                                                               r.positions / r.tiles));
    if (config.stereo.subpixel) cycles += r.tiles * cycles_of(cost::subpixel_profile());
    if (outlined)
        cycles +=
            cycles_of(cost::surface_outline_profile(r.rows * r.tile_height, r.columns, r.inside));
    cycles += cycles_of(cost::surface_mean_profile(r.inside, r.matched));
    if (r.valid) out.sad_match.disparity_q8 = r.disparity_q8;
    return cycles;
}

namespace {

// The object's match as the stereo reach reads it (dsp/stereo_reach.h),
// from its core's `pixels`.
object_match match_of(const stereo_result& sad, int pixels, box b, const camera_rig& rig) {
    object_match match;
    match.disparity = (sad.disparity_q8 + 128) >> 8;
    match.spread = surface_spread_px(sad.disparity_q8, max_int(b.width, b.height), rig);
    match.sad_per_pixel_q8 =
        static_cast<uint32_t>((uint64_t{sad.sad} << 8) / static_cast<uint64_t>(max_int(1, pixels)));
    return match;
}

}  // namespace

// The cycles of a reach's tiles (each a SAD search) and of its splits'
// lines read at two disparities (a line a column of band_height px past a
// side, a row past an end).
uint64_t controller::impl::reach_cycles(const stereo_reach& reach, bool rows) const {
    const stereo_reach_params params;
    const int along = params.tile_width, across = params.band_height;
    uint64_t c = 0;
    if (reach.tiles > 0)
        c += reach.tiles *
             cycles_of(cost::sad_search_profile(rows ? across : along, rows ? along : across,
                                                reach.positions / reach.tiles));
    if (reach.split_columns > 0)
        c += cycles_of(cost::sad_search_profile(rows ? across : reach.split_columns,
                                                rows ? reach.split_columns : across, 2));
    return c;
}

// The box moved out where the object reaches past a side, else in where it
// stops short of it.
box controller::impl::moved_box(box b, const stereo_reach& sides, const stereo_reach& ends,
                                const stereo_reach& short_sides,
                                const stereo_reach& short_ends) const {
    auto moved = [](int reach, int short_by) { return reach > 0 ? reach : -short_by; };
    const int out_left = moved(sides.left, short_sides.left);
    const int out_right = moved(sides.right, short_sides.right);
    const int out_up = moved(ends.up, short_ends.up), out_down = moved(ends.down, short_ends.down);
    const int x = max_int(0, b.x - out_left), y = max_int(0, b.y - out_up);
    return box{x, y, min_int(width, b.right() + out_right) - x,
               min_int(height, b.bottom() + out_down) - y};
}

// How far the object stops short of the box's sides and ends, at most a
// quarter of its size a side, read at the core's disparity; its cycles.
uint64_t controller::impl::read_short_of(int core_pixels, const frame_output& out,
                                         stereo_reach* short_sides, stereo_reach* short_ends) {
    const box b = out.box_right;
    const stereo_reach_params params;
    const object_match match = match_of(out.sad_match, core_pixels, b, config.rig);
    *short_sides = short_of_sides(history(0), left(), b, match, b.width / 4, config.stereo, params);
    *short_ends = short_of_ends(history(0), left(), b, match, b.height / 4, config.stereo, params);
    return reach_cycles(*short_sides, false) + reach_cycles(*short_ends, true);
}

// A side no difference outlines (it does not move, or fades into what it
// passes) is still where the object's disparity ends: the reported box is
// widened there, at most half its size a side, else moved in where the
// object stops short of it. The tracker's box is not: handed to it, the
// wider box was placed by the difference rules from its other edge, and
// walked off the object (docs/firmware.md).
// A widening that draws the box out on one axis past a sphere's image
// (dsp/round_box.h, drawn_out) read what is behind as the object: a ball a
// few tenths of a metre before the background stands within its own
// disparity span of it (a 120 px ball going away over teddy, 0.6 m before
// it: widened 42 px down, its tracker's box 74 x 84 px on a ball of 83).
// That axis's reach is not taken. Each axis is judged against the other's
// larger size, the tracker's or the reported one: a side moved in too far
// makes the box oblong too, and is no sign of a wrong reach (a 140 px ball
// going away, its tracker's box held 29 px too large, trimmed 9 px too far
// on y). A reach refused is no size to judge the other axis against: a
// 129 px ball going away over teddy, 88 px wide by then, had a 37 px reach
// of its width refused, and against that width a 16 px reach of its height
// passed (its box 18 px too tall); the other axis is judged again without
// it. Away from the image's border only: a cut object is not round.
uint64_t controller::impl::widen_to_stereo_reach(int core_pixels, const stereo_reach& short_sides,
                                                 const stereo_reach& short_ends,
                                                 frame_output& out) {
    const box b = out.box_right;
    const stereo_reach_params params;
    const object_match match = match_of(out.sad_match, core_pixels, b, config.rig);
    stereo_reach r =
        reach_past_sides(history(0), left(), b, match, b.width / 2, config.stereo, params);
    stereo_reach v =
        reach_past_ends(history(0), left(), b, match, b.height / 2, config.stereo, params);
    uint64_t cycles = reach_cycles(r, false) + reach_cycles(v, true);
    const box widened = moved_box(b, r, v, short_sides, short_ends);
    if (!at_border(b) && !at_border(widened)) {
        const box against_width{widened.x, widened.y, widened.width,
                                max_int(widened.height, b.height)};
        const box against_height{widened.x, widened.y, max_int(widened.width, b.width),
                                 widened.height};
        bool refuse_x = drawn_out(against_width, config.rig) == drawn_out_axis::width;
        bool refuse_y = drawn_out(against_height, config.rig) == drawn_out_axis::height;
        cycles += 2 * cycles_of(cost::round_box_profile());  // a sphere's shape, twice
        if (refuse_x != refuse_y) {  // the other axis judged again without the refused reach
            const box kept = moved_box(b, refuse_x ? stereo_reach{} : r,
                                       refuse_y ? stereo_reach{} : v, short_sides, short_ends);
            const box against =
                refuse_x ? box{kept.x, kept.y, max_int(kept.width, b.width), kept.height}
                         : box{kept.x, kept.y, kept.width, max_int(kept.height, b.height)};
            const drawn_out_axis axis = drawn_out(against, config.rig);
            refuse_x = refuse_x || axis == drawn_out_axis::width;
            refuse_y = refuse_y || axis == drawn_out_axis::height;
            cycles += cycles_of(cost::round_box_profile());
        }
        if (refuse_x) r = stereo_reach{};
        if (refuse_y) v = stereo_reach{};
    }
    out.box_right = moved_box(b, r, v, short_sides, short_ends);
    return cycles;
}

// Stage stereo_edge: Sobel on a band of the pattern's rows of both images
// (one extra input row each side for the 3x3), then segment matching. The
// band planes have their own row numbering, so the pattern's rows are shifted
// by the band's first row; columns, and so disparities, are unchanged.
void controller::impl::stereo_edge(box object, frame_output& out) {
    stage_scope scope(*hardware, stage::stereo_edge, out);
    box pattern = object;
    if (pattern.height > band_rows) {  // keep the central rows
        pattern.y += (pattern.height - band_rows) / 2;
        pattern.height = band_rows;
    }
    const int in_y0 = max_int(0, pattern.y - 1);
    const int in_rows = min_int(height, pattern.bottom() + 1) - in_y0;
    // The bands live in f(t-1)'s buffer (memory plan), dead by now: the next
    // pair's Dif(t-1,t) is already in the packed mask.
    uint8_t* band_base = edge_band_storage ? edge_band_storage : right_gray[1 - newest];
    const size_t band_bytes = static_cast<size_t>(width) * static_cast<size_t>(in_rows);
    const gray_plane right_band{band_base, width, in_rows, width};
    const gray_plane left_band{band_base + band_bytes, width, in_rows, width};
    const int out_y0 = pattern.y - in_y0, out_y1 = out_y0 + pattern.height;
    // At the image's top or bottom row the band's edge is the image's edge,
    // where sobel_3x3 also writes 0: the band equals the whole-image Sobel.
    sobel_3x3_rows(history(0).sub(0, in_y0, width, in_rows), out_y0, out_y1, right_band);
    sobel_3x3_rows(left().sub(0, in_y0, width, in_rows), out_y0, out_y1, left_band);
    box band_pattern = pattern;
    band_pattern.y = out_y0;
    out.edge_match =
        stereo_match_edge(right_band.as_const(), left_band.as_const(), band_pattern, config.edge);
    out.edge_at_range_end = at_range_end(out.edge_match, object, config.edge.min_disparity,
                                         config.edge.max_disparity, width);
    scope.charge(
        2 * cycles_of(cost::sobel_profile(width, pattern.height)) +
        cycles_of(cost::edge_match_profile(width, config.edge.lines, config.edge.max_disparity,
                                           config.edge.min_disparity)));
}

namespace {

// The left image's zone matched: the right box at the chosen disparity.
void place_left_box(stereo_method method, frame_output& out) {
    out.box_left = out.box_right;
    out.box_left.x += (out.disparity_q8 + 128) >> 8;
    if (method == stereo_method::sad) out.box_left.y += out.sad_match.dy;
}

}  // namespace

bool controller::impl::choose_disparity(frame_output& out) const {
    const bool sad_ok = out.sad_match.valid && !out.sad_at_range_end;
    const bool edge_ok = out.edge_match.valid && !out.edge_at_range_end;
    bool ok = false;
    switch (config.method) {
        case stereo_method::sad:
            ok = sad_ok;
            out.disparity_q8 = out.sad_match.disparity_q8;
            break;
        case stereo_method::edge:
            ok = edge_ok;
            out.disparity_q8 = out.edge_match.disparity_q8;
            break;
        case stereo_method::both:
            ok = sad_ok || edge_ok;
            if (sad_ok && edge_ok) {
                out.disparity_q8 = (out.sad_match.disparity_q8 + out.edge_match.disparity_q8) / 2;
            } else {
                out.disparity_q8 =
                    sad_ok ? out.sad_match.disparity_q8 : out.edge_match.disparity_q8;
            }
            break;
    }
    // A disparity outside the depth range's (in the search margin) is no
    // measurement of an object inside it: withheld. Measured: a ball that
    // the left image's border still cut matched the background at 13.8 px
    // (6.9 m, beyond the 6 m range) against its true 38 px.
    if (!ok || out.disparity_q8 < far_disparity_q8 || out.disparity_q8 > near_disparity_q8)
        return false;
    place_left_box(config.method, out);
    return true;
}

// Stage xyz: the box centre (Q8, from the exact Q1 centre) triangulated at
// the chosen disparity; a depth no motion of the ball reaches
// (dsp/depth_line.h) is reported at the line of the track's last ones, its
// point triangulated again at that depth's disparity. A depth gated against
// the track's fitted depths passed fewer fresh box cases (docs/firmware.md,
// "The measured depth").
void controller::impl::xyz(box object, frame_output& out) {
    stage_scope scope(*hardware, stage::xyz, out);
    const int32_t x_q8 = object.center_x2() * 128, y_q8 = object.center_y2() * 128;
    out.has_point = triangulate(config.rig, x_q8, y_q8, out.disparity_q8, &out.point);
    scope.charge(cycles_of(cost::triangulate_profile()));
    const int32_t depth_um =
        reported_depth.reported(out.has_point ? out.point.z : 0, &out.depth_from_line);
    scope.charge(cycles_of(cost::depth_line_profile(out.depth_from_line)));
    if (!out.depth_from_line) return;
    out.disparity_q8 = static_cast<int32_t>(disparity_q8_at_depth(config.rig, depth_um));
    out.has_point = triangulate(config.rig, x_q8, y_q8, out.disparity_q8, &out.point);
    scope.charge(cycles_of(cost::triangulate_profile()));
}

}  // namespace dsp
