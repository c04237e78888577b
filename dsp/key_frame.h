// A slow object's outline measured against an older frame, the key.
//
// Two frames one pair apart differ, around an object moving v px per frame,
// by about v times the contrast times |cos| of the angle between the motion
// and the outline's normal: where the outline runs along the motion (the
// top and bottom of a ball passing sideways) the difference stays under the
// threshold unless v is several pixels. At 1 px per frame the difference's
// extent across the motion was 45-51 px for a 60 px ball and 92-108 px for a
// 110 px one, varying from pair to pair, and a box fitted to it jumped by
// up to 9 px (docs/firmware.md, "Slow objects: a key frame"). Against a
// frame the object left 4 px ago the same extents were 58-61 px and
// 110-111 px.
//
// So, while the object moves slowly, one frame is kept as the key: the
// region around the object, copied when the key is taken. Each pair the
// key's pattern (the object box's centre, at most the tracker's max_size,
// as in dsp/tracker.h) is searched in the new frame within max_step px of
// where it was last: the displacement since the key, with no rounding
// carried from pair to pair. It is the object's while the pattern still
// matches closely; a slowly turning texture's pattern can still match
// within the lost rule, at the texture's displacement, and its match then
// differs by over turned_mean_sad per pixel (turned(): the controller then
// reads the displacement from Dif(key, t), dsp/box_refit.h
// difference_shift). Once the object has moved
// min_shift px, Dif(key, t) spans object(key) and object(t) with the whole
// outline; object(t) is that extent less the displacement, on the side the
// object moved to (dsp/box_refit.h, keyed_axis).
//
// Memory: the key in SDRAM, its pattern copied for each search into a
// scratch the caller gives (L2). Of the region only a ring is kept: its
// rows outside the object box shrunk by hole_inset px each side (the hole),
// stored back to back, then the pattern. Dif(key, t) is an extent, made at
// the outline: within max_shift px of the key's box it moves, margin px
// more for that box's error, and inside that band the object's own pixels
// only change with its texture. The hole counts as changed (it is the
// object's, and joins the outline's crescents into one group, as a
// textured interior did), so an extent that is the hole alone is none.
// Every byte of the key crosses the EMIF when it is taken and each pair it
// is read, and capture alone keeps the EMIF busy 23.5-23.7 ms of the
// 24.5 ms period: the whole region of a ball half the image wide
// (370 x 367 px) read each pair, and written at each new key, dropped
// pairs (docs/firmware.md, "the key's ring").
// Costs: dsp::cost kernels, charged by the controller (stage track).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "dsp/image.h"
#include "dsp/motion_blocks.h"
#include "dsp/sad_search.h"

namespace dsp {

class key_frame {
  public:
    static constexpr int min_shift = 4;   // px moved since the key before its difference is used
    static constexpr int max_shift = 16;  // px moved since the key: a new key is taken
    static constexpr int max_step = 2;    // px per pair, at most, for an object to count as slow
    static constexpr int margin = 8;      // px of the region beyond max_shift around the object
    static constexpr uint32_t turned_mean_sad = 8;  // mean |difference| per pixel: a turned pattern
    static constexpr int hole_inset = max_shift + margin;  // px of the object's edge kept inside it

    key_frame() = default;
    ~key_frame();
    key_frame(const key_frame&) = delete;
    key_frame& operator=(const key_frame&) = delete;

    // `max_pattern_side`: the largest pattern's side (the tracker's max_size).
    static size_t sdram_bytes(int max_width, int max_height, int max_pattern_side);
    void init(int max_width, int max_height, int max_pattern_side);

    bool valid() const { return m_valid; }
    void drop() { m_valid = false; }

    // The key: `frame`'s region around `object` grown by `grow` each side
    // (max_shift + margin for a tracked object; more for a detection that
    // may be a part of its object), clipped to the frame; `pattern` is the
    // object's pattern box in it.
    void take(gray_cplane frame, box object, box pattern, int grow = max_shift + margin);

    // The displacement since the key (dx, dy): its pattern, copied into
    // `scratch` (at least pattern width x height bytes), searched in `frame`
    // within max_step + 1 px of the last displacement. False (the key is
    // then of no use) when the best match lies on that window's edge (the
    // object moved more than max_step) or is more different than
    // lost_mean_sad per pixel. `positions`: the positions searched.
    bool displacement(gray_cplane frame, uint8_t* scratch, uint32_t lost_mean_sad, int* positions);

    // The extent of Dif(key, frame) at `threshold` over the key region: the
    // block group one object with the key's object box moved by the
    // displacement; not found when it reaches the region's edge (the
    // object may go on past it). `row`: one row of the region's width.
    block_group moved_extent(gray_cplane frame, uint8_t threshold, motion_blocks& blocks,
                             uint8_t* row) const;

    int shift() const {  // px moved since the key, on the axis it moved most
        return std::max(std::max(m_dx, -m_dx), std::max(m_dy, -m_dy));
    }
    int pairs() const { return m_pairs; }  // pairs searched since the key was taken
    // The last match differed by more than turned_mean_sad per pixel on
    // average: the pattern's texture turned.
    bool turned() const { return m_turned; }
    // A match of `sad` for a pattern of `area` pixels differs by over
    // turned_mean_sad per pixel: the texture turned (also read on a
    // detection's pattern, dsp/controller_detect.cpp).
    static bool match_turned(uint32_t sad, uint64_t area) {
        return sad > static_cast<uint64_t>(turned_mean_sad) * area;
    }
    // A key of the outline only: its pattern is not searched (its texture
    // outruns its object); the controller reads Dif(key, t) alone.
    bool outline_only() const { return m_outline_only; }
    void set_outline_only() { m_outline_only = true; }
    int dx() const { return m_dx; }
    int dy() const { return m_dy; }
    box object() const { return m_object; }             // the object box when the key was taken
    box region() const { return m_region; }             // the frame's pixels around the object
    box hole() const { return m_hole; }                 // of them, the ones not held (may be empty)
    size_t ring_bytes() const { return m_ring_bytes; }  // the region less the hole
    size_t stored_bytes() const {  // the ring and the pattern: written when taken
        return m_ring_bytes + static_cast<size_t>(m_pattern.width) * m_pattern.height;
    }
    box pattern() const { return m_pattern; }  // where the key's pattern was taken

  private:
    // Region row y's held pixels: [0, left) and [right, width) of the row
    // (both width outside the hole's rows: the whole row).
    void held_span(int y, int* left, int* right) const;

    uint8_t* m_pixels = nullptr;  // the ring, row after row, then the pattern
    size_t m_capacity = 0;
    bool m_valid = false;
    box m_region;
    box m_object;
    box m_pattern;
    box m_hole;
    size_t m_ring_bytes = 0;
    int m_dx = 0, m_dy = 0;
    int m_pairs = 0;
    bool m_turned = false;
    bool m_outline_only = false;
};

}  // namespace dsp
