// The extent of a moving object whose three-frame mask falls apart into
// pieces. Three-frame differencing (paper eq. 2-4) marks object(t-1) only
// where f(t-1) differs from both f(t-2) and f(t): for an object wider than
// its motion per frame that is thin slivers on its silhouette and its
// texture, which the detector's opening erases (a 160 px ball moving 5 px
// per frame: 140 raw pixels, none left after the opening). Their bounding
// box is still the object's: the raw mask of that ball spans exactly its
// 160 x 154 px image.
//
// So, while the detector's row pipeline makes the raw mask, this keeps per
// 16 x 16 block the number of set pixels and their extent; a block with at
// least two counts as moving. Moving blocks one block apart (8-connected
// after one 3x3 dilation of the block grid: gaps up to 16 px bridged) form a
// group; a group's extent is the union of its blocks' extents (blocks of
// another group inside its block box count too: boxes only, no label map).
// extent() takes the largest group that is one object with the seed (the
// detector's largest component), or, with no seed, the largest group of at
// least min_pixels set pixels, and joins every group that is one object with
// it: boxes that overlap, or face each other across a gap no longer than
// the length along which they face (a ball's two silhouette crescents; not a
// speck beside it).
//
// Memory (L2, no allocation after init): 3 bytes per block, one dilated
// block row, two label rows and a 64-entry union-find table
// (workspace_bytes). Costs: dsp::cost::motion_blocks_cycles.
#pragma once

#include <cstddef>
#include <cstdint>

#include "dsp/image.h"

namespace dsp {

struct component;  // dsp/motion_detect.h

struct block_group {
    bool found = false;
    box bbox;        // pixel extent of the group's set pixels
    int pixels = 0;  // set raw pixels in the group's blocks
    int blocks = 0;  // moving blocks in it
};

class motion_blocks {
  public:
    static constexpr int block_side = 16;
    static constexpr int min_block_pixels = 2;  // a block with fewer is noise
    static constexpr int max_groups = 64;

    motion_blocks() = default;
    ~motion_blocks();
    motion_blocks(const motion_blocks&) = delete;
    motion_blocks& operator=(const motion_blocks&) = delete;

    static size_t workspace_bytes(int max_width, int max_height);
    void init(int max_width, int max_height);

    // A new mask of width x height (at most the init size).
    void begin(int width, int height);
    // Raw mask row y (width bytes, non-zero = set), rows in order 0, 1, ...
    void add_row(const uint8_t* row, int y);
    // The group overlapping `seed` (empty seed: the largest group, if it has
    // at least min_pixels set pixels); found = false when there is none.
    block_group extent(box seed, int min_pixels);

    int blocks_x() const { return m_blocks_x; }
    int blocks_y() const { return m_blocks_y; }

  private:
    void release();
    bool moving(int bx, int by) const;
    void dilated_row(int by, uint8_t* out) const;
    block_group group_in(box blocks) const;

    int m_max_blocks_x = 0, m_max_blocks_y = 0;
    int m_width = 0;
    int m_blocks_x = 0, m_blocks_y = 0;
    uint8_t* m_count = nullptr;   // set pixels per block, saturating at 255
    uint8_t* m_x_span = nullptr;  // first | last set column in the block (nibbles)
    uint8_t* m_y_span = nullptr;  // first | last set row
    uint8_t* m_row = nullptr;     // one dilated block row
    int32_t* m_labels = nullptr;  // labeller: 2 block rows
    int32_t* m_parent = nullptr;
    component* m_stats = nullptr;
};

}  // namespace dsp
