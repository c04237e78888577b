// Detection by three-frame temporal differencing (paper eq. 2-4) and the
// object zone.
//
//   Dif(t-2,t-1) = Binary(|f(t-2) - f(t-1)|)
//   Dif(t-1,t)   = Binary(|f(t-1) - f(t)|)
//   object(t-1)  = Dif(t-2,t-1) AND Dif(t-1,t),  Binary(a) = a > threshold
//
// Masks are 0 / 255 bytes. The object zone: the mask is cleaned (binary
// opening removes specks, closing fills small holes), connected components
// (8-connectivity) are labelled, components smaller than min_area dropped,
// and the largest remaining one is the moving object; its bounding box is
// the reference pattern's zone.
//
// Common assumptions: every plane of one call has the same width and height
// (strides may differ); an output never aliases an input; no alignment or
// multiple-of-8 width is needed (the C64x versions would take 8 pixels per
// step with a scalar tail).
#pragma once

#include <cstdint>

#include "dsp/image.h"
#include "dsp/motion_blocks.h"

namespace dsp {

// out = |a - b| per byte.
// Costs (C64x, estimate; not in the cost model, the detector uses the fused
// kernel): per 8 pixels 2 LDNDW, 2 SUBABS4, 1 STNDW: .D bound, ~0.19
// cycles/pixel.
void absdiff(gray_cplane a, gray_cplane b, gray_plane out);

// out = in > threshold ? 255 : 0.
// Costs (C64x, estimate; not in the cost model): per 8 pixels LDDW, 2
// CMPGTU4, 2 XPND4 (bit mask to 0/255 bytes), STDW: ~0.125 cycles/pixel.
void threshold_binary(gray_cplane in, uint8_t threshold, gray_plane out);

// out = a & b (on 0/255 masks: the intersection).
// Costs (C64x, estimate; not in the cost model): per 8 pixels 2 loads, 2
// AND, 1 store: .D bound, ~0.19 cycles/pixel.
void mask_and(gray_cplane a, gray_cplane b, gray_plane out);

// Eq. 2-4 fused in one pass over the three frames, no intermediate masks:
//   object = (|f0 - f1| > th) & (|f1 - f2| > th) ? 255 : 0.
// Identical to absdiff x2 + threshold_binary x2 + mask_and (tests prove it).
// Computed as min(|f0 - f1|, |f1 - f2|) > th (both above <=> the smaller is).
// Costs (C64x): dsp::cost::three_frame_difference_cycles: per 8 pixels 3
// loads, 4 SUBABS4, 2 MINU4, 2 CMPGTU4, XPND4, 1 store: II 3 (.L bound),
// 0.375 cycles/pixel, against ~0.8 for the five separate passes, which also
// write and re-read four intermediate planes.
void three_frame_difference(gray_cplane f_tm2, gray_cplane f_tm1, gray_cplane f_t,
                            uint8_t threshold, gray_plane object_mask);

// ---- Bit-packed difference masks (the firmware's L2 plan, dsp/controller.h) ----
// The controller keeps Dif(t-2,t-1) of eq. 2 as ONE BIT per pixel instead of
// the third gray frame f(t-2): eq. 4 needs f(t-2) only through that mask.
// Layout: row y starts at byte y * packed_row_bytes(width); pixel x is bit
// (x % 8) of byte x / 8 (LSB first). VGA: 38,400 bytes, an eighth of a frame.
int packed_row_bytes(int width);
size_t packed_mask_bytes(int width, int height);
inline bool packed_bit(const uint8_t* packed, int width, int x, int y) {
    return (packed[static_cast<size_t>(y) * static_cast<size_t>(packed_row_bytes(width)) +
                   static_cast<size_t>(x >> 3)] >>
            (x & 7)) &
           1u;
}

// packed = Dif(a, b): the bit of a pixel is set where |a - b| > threshold.
// Costs (C64x): dsp::cost::difference_packed_cycles: per 8 pixels 2 LDDW, 2
// SUBABS4, 2 CMPGTU4 (4-bit masks), SHL + OR into a byte, STB: II 2, 0.25
// cycles/pixel; reads 2 bytes and writes 1/8 byte per pixel.
void difference_packed(gray_cplane a, gray_cplane b, uint8_t threshold, uint8_t* packed);

// Eq. 2-4 with the older difference stored packed, one row: for every x
//   object_row[x] = (bit x of packed_row) && |f_tm1[x] - f_t[x]| > threshold ? 255 : 0
// and packed_row becomes Dif(t-1,t) of the row (in place: it is the next
// pair's Dif(t-2,t-1)). With packed_row = Dif(f(t-2), f(t-1)) this is exactly
// three_frame_difference(f(t-2), f(t-1), f(t)) (tests prove it on real video).
// Costs (C64x): dsp::cost::three_frame_difference_packed_cycles: per 8 pixels
// 2 LDDW + LDBU + STB + STDW, 2 SUBABS4, 2 CMPGTU4, SHL + OR + AND, 2 XPND4:
// II 3 (.D / .L bound), 0.375 cycles/pixel, as the three-frame kernel, but it
// reads 2 1/8 instead of 3 bytes per pixel.
void three_frame_difference_packed_row(const uint8_t* f_tm1, const uint8_t* f_t, int width,
                                       uint8_t threshold, uint8_t* packed_row, uint8_t* object_row);
// The same over whole frames (object_mask: width x height bytes).
void three_frame_difference_packed(gray_cplane f_tm1, gray_cplane f_t, uint8_t threshold,
                                   uint8_t* packed, gray_plane object_mask);

// Binary 3x3 erosion / dilation of a 0/255 mask with a square structuring
// element: out = AND (erosion) / OR (dilation) of the 3x3 neighbourhood,
// which on 0/255 bytes is its minimum / maximum. Pixels outside the image
// count as background (0): erosion clears the outermost rows and columns,
// dilation is unaffected by the border. Same result as cv::erode /
// cv::dilate with a 3x3 rect kernel and BORDER_CONSTANT 0.
// Assumes: in holds only 0 and 255 (other values are ANDed / ORed bitwise,
// not min / max); out does not alias in (use two buffers and ping-pong).
// Costs (C64x): dsp::cost::morphology_cycles: separable, 8 pixels per
// iteration from LDNDW x-1 / LDDW x / LDNDW x+1 and a 3-row ring, II 4 (.D
// bound), 0.5 cycles/pixel per pass. The host code ANDs / ORs 64-bit words
// reloaded at x - 1, x and x + 1 (lane-wise only, so it does not depend on
// byte order).
void erode_3x3(gray_cplane in, gray_plane out);
void dilate_3x3(gray_cplane in, gray_plane out);

struct component {
    box bbox;
    int area = 0;  // pixels
};

// Connected components, one row at a time (what connected_components and
// the detector's row pipeline run): begin(), add_row() for rows 0, 1, ... in
// order, finish(). Same workspaces, limits and results as
// connected_components below; nothing allocated.
class component_labeller {
  public:
    void begin(int width, int32_t* labels, int32_t* parent, component* stats, int max_labels);
    // Returns false once the rows needed more than max_labels labels (the
    // later rows are then ignored and finish() returns -1).
    bool add_row(const uint8_t* row, int y);
    int finish(component* out, int max_out);

  private:
    int m_width = 0;
    int32_t* m_above = nullptr;
    int32_t* m_current = nullptr;
    int32_t* m_parent = nullptr;
    component* m_stats = nullptr;
    int m_max_labels = 0;
    int32_t m_label_count = 0;
    bool m_overflow = false;
};

// Connected components (8-connectivity) of a mask (any non-zero byte is
// foreground), one raster pass over runs of foreground pixels with
// union-find on run labels, then one pass over the label table.
//
// Workspaces (caller-owned, nothing allocated here):
//   labels: 2 * mask.width entries (the run labels of the previous and the
//           current row; the full label image is never stored, so the
//           kernel needs no width * height int32 buffer in L2);
//   parent, stats: max_labels entries each (the union-find forest and the
//           per-label bounding box and area).
// Returns the number of components written to out (at most max_out), largest
// area first, equal areas by bbox top then left; returns -1 when the mask
// needs more than max_labels provisional labels (one per run that touches no
// labelled run in the row above; at most ceil(w/2) * ceil(h/2)).
// Costs (C64x): dsp::cost::connected_components_cycles: a scan of 8 pixels
// per iteration for the run ends, per run pixel a label look-up above and a
// label store, per run a find / union / stats update (not pipelinable),
// then one pass over the label table and the sort of the components; the
// data-dependent part scales with the foreground (runs), not the image.
int connected_components(gray_cplane mask, int32_t* labels, int32_t* parent, component* stats,
                         int max_labels, component* out, int max_out);

struct detect_params {
    uint8_t threshold = 20;  // Binary(a) = a > threshold
    int open_passes = 1;     // erosions then dilations (specks)
    int close_passes = 2;    // dilations then erosions (holes)
    int min_area = 30;       // pixels; smaller components are noise
    // Raw (unopened) pixels a block group needs when the opening left no
    // component (dsp/motion_blocks.h). A 10 px ball moving half its width per
    // frame leaves fewer than min_area: with min_area here `--scenario small`
    // was not detected in 12 co-simulated frames; with 10, one frame after
    // its first motion.
    int min_group_pixels = 10;
};

struct detection {
    bool found = false;
    box bbox;
    int area = 0;
    int components = 0;           // components at or above min_area
    bool label_overflow = false;  // the mask needed more labels than init's max_components
    // The object's extent from the raw (unopened) mask, dsp/motion_blocks.h:
    // the block group that is one object with bbox, or without a component
    // the largest group of at least min_group_pixels set pixels; object_box
    // is its extent joined with bbox. object_found is set when either is.
    bool object_found = false;
    box object_box;
};

// Owns its work buffers, allocated once in init (never in detect).
//
// detect(): three_frame_difference -> open_passes erosions, open_passes
// dilations (opening) -> close_passes dilations, close_passes erosions
// (closing) -> connected_components -> the largest component with area >=
// min_area. Because the border counts as background, the closing's
// erosions also clear the image's outermost close_passes rows and columns
// (an object cut by the image edge loses that rim).
// The passes run as a ROW PIPELINE: the difference makes one mask row, each
// 3x3 pass keeps a ring of its last 3 input rows and emits its output row as
// soon as the row below it is in, and the labeller takes the last pass's
// rows in order. No full-frame mask is needed (the firmware's L2 plan has no
// room for one); the result equals the whole-frame passes exactly (a pass's
// row y depends on its input rows y-1..y+1 only).
// Memory: 3 rows per pass (at most max_passes passes) + 1 row, 2 * max_width
// labels, 3 tables of max_components entries (parent, stats, sorted
// components), and with keep_mask a max_width * max_height copy of the
// cleaned mask for last_mask() (tests, waveforms; the firmware does not keep
// it). workspace_bytes() gives the total.
class motion_detector {
  public:
    motion_detector() = default;
    ~motion_detector();
    motion_detector(const motion_detector&) = delete;
    motion_detector& operator=(const motion_detector&) = delete;

    // 3x3 passes the row pipeline can hold: 2 * (open_passes + close_passes)
    // must not exceed it (otherwise detect finds nothing).
    static constexpr int max_passes = 8;

    // Size the buffers for images up to max_width x max_height;
    // max_components bounds the provisional labels of one mask; keep_mask
    // keeps a full copy of the cleaned mask for last_mask().
    void init(int max_width, int max_height, int max_components = 4096, bool keep_mask = true);
    // Bytes init allocates for these arguments (the L2 plan counts them).
    static size_t workspace_bytes(int max_width, int max_height, int max_components,
                                  bool keep_mask);

    // The moving object at time t-1 from three consecutive gray frames of the
    // same size (at most the init size; larger frames give found = false).
    detection detect(gray_cplane f_tm2, gray_cplane f_tm1, gray_cplane f_t,
                     const detect_params& params);
    // The same from f(t-1), f(t) and packed = Dif(t-2,t-1) (packed layout
    // above, width of f_tm1): three_frame_difference_packed_row per row, so
    // packed becomes Dif(t-1,t) for the next call. Same result as detect()
    // on f(t-2), f(t-1), f(t). packed is left unchanged if the size is refused.
    detection detect_packed(gray_cplane f_tm1, gray_cplane f_t, uint8_t* packed,
                            const detect_params& params);

    // The same pipeline on object rows made by `source` (row y of the raw
    // object mask, 0/255, into `out`, width bytes), in row order: for a
    // difference kept in another form (dsp/stride_history.h).
    using row_source = void (*)(void* context, int y, uint8_t* out);
    detection detect_rows(int width, int height, const detect_params& params, row_source source,
                          void* context);

    // The cleaned mask of the last detect() call (for tests and waveforms);
    // empty unless init's keep_mask.
    gray_cplane last_mask() const;

    // The components of the last detect() call, largest first (all sizes,
    // also those below min_area).
    const component* last_components() const { return m_components; }
    int last_component_count() const { return m_last_components; }

    // The block statistics' workspace (dsp/motion_blocks.h), free between
    // detect() calls: the controller's track refit uses it in the pairs it
    // does not detect in (one L2 buffer for both).
    motion_blocks& blocks() { return m_blocks; }

    // Statistics of the last call, for the cost model.
    int last_foreground_pixels() const { return m_last_foreground; }

  private:
    // Makes object row y into out (width bytes).
    detection run(int width, int height, const detect_params& params, row_source source,
                  void* context);
    uint8_t* ring_row(int pass, int y) const;
    void push_row(int pass, int y);
    void flush(int pass);
    void emit_row(const uint8_t* row, int y);
    void release();

    int m_max_width = 0, m_max_height = 0, m_max_components = 0;
    uint8_t* m_mask = nullptr;   // kept cleaned mask (keep_mask), else null
    uint8_t* m_rings = nullptr;  // max_passes x 3 rows
    uint8_t* m_out_row = nullptr;
    bool m_pass_erodes[max_passes] = {};
    int m_passes = 0;
    int m_width = 0, m_height = 0;
    component_labeller m_labeller;
    motion_blocks m_blocks;
    int32_t* m_labels = nullptr;
    component* m_components = nullptr;
    component* m_stats = nullptr;
    int32_t* m_parent = nullptr;
    int m_last_width = 0, m_last_height = 0, m_last_foreground = 0, m_last_components = 0;
};

}  // namespace dsp
