// Three-frame differencing over a stride of pairs, for an object too slow
// for one pair's.
//
// Two frames one pair apart differ, around an object moving v px per
// frame, by about v times its texture's or its outline's contrast per
// pixel: under the threshold for most of an object moving 1 px per frame
// or less, and the opening then removes what is left (an 80 px ball at 0.5
// px per frame over kodim19: no detection in 30 pairs; an 80 px ball
// circling over teddy at 1 px per frame: none in pairs 3-21,
// docs/firmware.md "Slow detection"). Frames `stride` pairs apart differ as
// much as one pair's at stride times the speed. So, while DETECT finds
// nothing, every stride pairs one frame is kept with the difference of the
// last two kept, and eq. 2-4 on f(t-2s), f(t-s), f(t) give object(t-s), in
// the kept frame, as one pair's give object(t-1).
//
// Memory: one frame, in L2, in a buffer the caller lends (the controller's
// left gray frame, which a DETECT pair that finds nothing does not need).
// The difference is kept in each pixel's low bit: the frame is kept at 7
// bits (its differences within 1 grey level of the 8-bit ones), so no
// mask buffer is needed.
// Costs: dsp::cost kernels, charged by the controller (stage detect).
#pragma once

#include <cstddef>
#include <cstdint>

#include "dsp/image.h"

namespace dsp {

class stride_history {
  public:
    // Pairs between the kept frames: an object at 0.5 px per frame moves 2 px
    // (docs/firmware.md, "Slow detection").
    static constexpr int stride = 4;

    // The frame buffer lent (at least width x height bytes of the frames).
    void init(uint8_t* storage, size_t capacity);

    // Forgets the kept frames (a track or a candidate started, the lent
    // buffer was written by its owner, a new size).
    void reset();
    // One more DETECT pair without a detection: whether this pair's frame is
    // to be kept (the first, then every stride pairs).
    bool due();
    bool has_frame() const { return m_kept >= 1; }
    // The frame kept before and the difference of the two kept before it:
    // three_frame_row may run.
    bool ready() const { return m_kept >= 2; }

    // Row y of eq. 4 on f(t-2s), f(t-s) (the kept frame) and f(t): 255 where
    // the kept bit (Dif(t-2s, t-s)) is set and |f(t-s) - f(t)| > threshold.
    // Reads only: the kept frame is still f(t-s) after it.
    void three_frame_row(const uint8_t* f_t_row, int y, uint8_t threshold,
                         uint8_t* object_row) const;
    // The kept frame, f(t-s) while ready (its low bits are the difference):
    // where a detection's pattern is taken.
    gray_cplane kept() const;
    // Keeps `frame` over the last kept one, each pixel's low bit
    // Dif(last kept, frame) at `threshold` (0 when none was kept).
    void keep(gray_cplane frame, uint8_t threshold);

  private:
    uint8_t* m_storage = nullptr;
    size_t m_capacity = 0;
    int m_width = 0, m_height = 0;
    int m_kept = 0;   // frames kept since the reset, at most 2 counted
    int m_pairs = 0;  // pairs since the last kept frame
};

}  // namespace dsp
