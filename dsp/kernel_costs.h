// Modelled C64x cycles of each firmware kernel call, from the C64x cost
// model (model/c64x/cost_model.h): every function describes the operations a
// hand-scheduled C64x implementation of the kernel issues per functional
// unit (packed 8-bit SIMD such as SUBABS4 and DOTPU4, 64-bit loads) and
// where its data lives, and lets the model turn that into cycles.
//
// The op profile of each kernel (ops per iteration per unit, pixels per
// iteration) is documented in kernel_costs.cpp; *_profile() returns it. The
// firmware prices a profile through dsp::hal::kernel_cycles, i.e. under the
// run's cost model (the DSK v2/v3 clocks change the SDRAM stalls, a
// compiled-C factor every figure); the *_cycles() functions below give the
// default model's figures (DSK v1, hand-scheduled) for tests and docs.
#pragma once

#include <cstdint>

#include "dsp/hal.h"
#include "model/c64x/cost_model.h"

namespace dsp::cost {

// Where a kernel's image data lives (docs/design-brief.md, "DSP memory").
enum class memory : uint8_t { l2, sdram };

// The model the *_cycles() functions use: DSK v1 clocks, fitted values.
const c64x::cost_model& default_model();

// Fused Bayer bilinear demosaic + gray + brightness mean, one frame; `where`
// places both the raw input and the gray output, the four-argument form each
// on its own (the firmware's plan: raw in SDRAM, gray in L2).
uint64_t demosaic_gray_cycles(int width, int height, memory where = memory::l2);
uint64_t demosaic_gray_cycles(int width, int height, memory gray_where, memory raw_where);
// Brightness gain lookup table build + apply, one frame.
uint64_t brightness_cycles(int width, int height, memory where = memory::l2);
// Three-frame difference (two absdiff + threshold + and), fused, one frame.
uint64_t three_frame_difference_cycles(int width, int height, memory where = memory::l2);
// The same from f(t-1), f(t) and the packed Dif(t-2,t-1), which it replaces
// by Dif(t-1,t) (dsp/motion_detect.h three_frame_difference_packed_row).
uint64_t three_frame_difference_packed_cycles(int width, int height, memory where = memory::l2);
// Dif(a, b) into a packed mask (dsp/motion_detect.h difference_packed).
uint64_t difference_packed_cycles(int width, int height, memory where = memory::l2);
// Binary 3x3 erosion or dilation, `passes` passes over width x height.
uint64_t morphology_cycles(int width, int height, int passes);
// Connected components with `foreground` set pixels in width x height.
uint64_t connected_components_cycles(int width, int height, int foreground);
// Block statistics of the raw motion mask and their grouping, one frame
// (dsp/motion_blocks.h).
uint64_t motion_blocks_cycles(int width, int height);
// Exhaustive SAD search: `positions` placements of a pattern_w x pattern_h
// pattern.
uint64_t sad_search_cycles(int pattern_w, int pattern_h, int positions);
// Copy of a pattern (reference update).
uint64_t pattern_copy_cycles(int pattern_w, int pattern_h);
// Parabola sub-pixel refinement (one division).
uint64_t subpixel_cycles();
// One axis of a fast object's box fitted to `extents` frame differences'
// extents (dsp/extent_window.h).
uint64_t window_fit_cycles(int extents);
// One axis's motion read from `extents` extents (dsp/extent_window.h,
// window_step2): the size check and the median of their edges' steps.
uint64_t window_step_cycles(int extents);
uint64_t size_at_depth_cycles(int divides);
// The gate and mean depth of a large object's tiles (dsp/object_depth.h):
// the sort of `inside` SADs, one 64-bit division per `matched` tile and one
// for the mean.
uint64_t surface_mean_cycles(int inside, int matched);
// The outline's mask over a large object's tiles (dsp/object_depth.h): an
// ellipse span for each of `rows` rows, clipped to `columns` tiles, and each
// `inside` tile's SAD scaled to a whole tile's.
uint64_t surface_outline_cycles(int rows, int columns, int inside);
// Sobel 3x3 over `rows` rows of `width` pixels.
uint64_t sobel_cycles(int width, int rows);
// Edge segment extraction and matching over `lines` epipolar lines of
// `width` pixels scanned per line and image, shifts
// min_disparity..max_disparity.
uint64_t edge_match_cycles(int width, int lines, int max_disparity, int min_disparity = 0);
// Triangulation: depth and X, Y (64-bit divisions in software).
uint64_t triangulate_cycles();

// SDRAM traffic of a kernel call: the bytes of its streams that live in
// SDRAM (dsp::hal::charge_with_traffic). The memory stall cycles of the
// figures above already include the CPU's wait for exactly these bytes
// (cost_model::memory_cycles); the platform replays them on the EMIF bus.
sdram_traffic sdram_traffic_of(const c64x::kernel_profile& kernel);
sdram_traffic demosaic_gray_traffic(int width, int height, memory where = memory::l2);
sdram_traffic demosaic_gray_traffic(int width, int height, memory gray_where, memory raw_where);
sdram_traffic brightness_traffic(int width, int height, memory where = memory::l2);
sdram_traffic three_frame_difference_traffic(int width, int height, memory where = memory::l2);
sdram_traffic three_frame_difference_packed_traffic(int width, int height,
                                                    memory where = memory::l2);
sdram_traffic difference_packed_traffic(int width, int height, memory where = memory::l2);

// The op profiles behind the figures above (same arguments).
c64x::kernel_profile demosaic_gray_profile(int width, int height, memory where = memory::l2);
c64x::kernel_profile demosaic_gray_profile(int width, int height, memory gray_where,
                                           memory raw_where);
c64x::kernel_profile brightness_profile(int width, int height, memory where = memory::l2);
c64x::kernel_profile three_frame_difference_profile(int width, int height,
                                                    memory where = memory::l2);
c64x::kernel_profile three_frame_difference_packed_profile(int width, int height,
                                                           memory where = memory::l2);
c64x::kernel_profile difference_packed_profile(int width, int height, memory where = memory::l2);
// Dif(key, t) over a key region less its hole (dsp/key_frame.h): the key in
// SDRAM, f(t) in L2, no mask written.
c64x::kernel_profile key_difference_profile(int width, int height, int hole_width = 0,
                                            int hole_height = 0);
c64x::kernel_profile morphology_profile(int width, int height, int passes);
c64x::kernel_profile motion_blocks_profile(int width, int height);
c64x::kernel_profile connected_components_profile(int width, int height, int foreground);
c64x::kernel_profile sad_search_profile(int pattern_w, int pattern_h, int positions);
c64x::kernel_profile pattern_copy_profile(int pattern_w, int pattern_h);
c64x::kernel_profile subpixel_profile();
// The half-pixel step's two SADs over the pattern (dsp/stereo_sad.h, half_pel).
c64x::kernel_profile half_pel_profile(int pattern_w, int pattern_h);
c64x::kernel_profile surface_mean_profile(int inside, int matched);
c64x::kernel_profile surface_outline_profile(int rows, int columns, int inside);
c64x::kernel_profile sobel_profile(int width, int rows);
c64x::kernel_profile edge_match_profile(int width, int lines, int max_disparity,
                                        int min_disparity = 0);
c64x::kernel_profile window_fit_profile(int extents);
c64x::kernel_profile window_step_profile(int extents);
c64x::kernel_profile detection_steps_profile();
c64x::kernel_profile size_at_depth_profile(int divides);
c64x::kernel_profile round_box_profile();
c64x::kernel_profile extent_end_profile();
c64x::kernel_profile size_depth_profile();
c64x::kernel_profile depth_line_profile(bool replaced);
c64x::kernel_profile triangulate_profile();

}  // namespace dsp::cost
