// Tracking by SAD (paper eq. 5): the reference pattern is searched in a
// window around its last position; the minimum SAD is the new position.
// Every frame the reference pattern is replaced by the pixels at the new
// position, its size is re-fitted to the object when a motion mask is given
// (see update()), and the search window is re-centred on it (paper:
// "reference pattern, its size and the search area are updated every
// frame").
//
// The box is the object's, of any size up to the frame; the pattern is its
// centre, at most max_size x max_size (pattern_box()): a ball half the image
// wide is found by its central 96 x 96 px and the box moves with it. (A
// 96 px pattern on a 180 px ball left the box off the ball's centre by 16 px
// on average.)
//
// One update(frame), with (x, y, w, h) the current pattern box and r the radius:
//   1. window = top-left positions [x - r, x + r] x [y - r, y + r], clipped so
//      the pattern stays inside the frame (sad_search; ties -> raster order);
//   2. lost-track rule, checked on the best match:
//      - mean |difference| per pixel above lost_mean_sad, tested exactly in
//        integers as sad > lost_mean_sad * w * h, or
//      - the pattern leaving the image: the best position lies on a window
//        edge that the image border clipped (x == 0 with x - r < 0, x == W - w
//        with x + r > W - w, same for y): the true minimum may lie outside, or
//      - no position fits (pattern larger than the frame);
//      when lost, the box and the pattern stay as they were;
//   3. the object box moves by the pattern's displacement (kept in the frame);
//   4. size update, only when a motion mask is given (see update()); without
//      one the size is kept: SAD alone says where the pattern is, not how
//      big the object has become;
//   5. the pattern is copied from the frame at the new box's centre.
//
// Assumes: frames are 8-bit gray of one size; the mask, if given, has the
// frame's size and marks moving pixels with non-zero bytes.
// Costs: sad_search ((2r+1)^2 positions of w x h, dsp::cost::sad_search_cycles)
// + pattern copy (w * h / 8 cycles, dsp::cost::pattern_copy_cycles) + with a
// mask one scan of the grown box (about its area / 8 cycles).
#pragma once

#include <cstdint>

#include "dsp/image.h"
#include "dsp/sad_search.h"

namespace dsp {

struct track_params {
    int search_radius = 24;       // pixels each way around the last position
    uint32_t lost_mean_sad = 28;  // mean |difference| per pixel above which the track is lost
    int min_size = 8;             // object box width/height, at least
    int max_size = 96;            // pattern width/height, at most (the object box: the frame)
};

enum class track_status : uint8_t { tracking, lost };

class sad_tracker {
  public:
    sad_tracker() = default;
    ~sad_tracker();
    sad_tracker(const sad_tracker&) = delete;
    sad_tracker& operator=(const sad_tracker&) = delete;

    void init(const track_params& params);  // allocates the pattern buffer (max_size^2)

    // Start tracking the object at `object` in `frame`: its width and height
    // are clamped to [min_size, frame size] around its centre, then the box is
    // moved inside the frame. Status becomes tracking (lost if the frame is
    // smaller than min_size).
    void start(gray_cplane frame, box object);

    // Find the pattern in the next frame; updates position, pattern and window.
    //
    // Size rule, applied when motion_mask is not empty (e.g. the detector's
    // three-frame mask of the latest frames): look at the mask inside the new
    // box grown by a quarter of its size (at least 2 px) on every side; if at
    // least 1/8 of the box's area is set, the width and height move towards
    // those of the set pixels' bounding box by at most max(1, size / 8) px per
    // frame, within [min_size, frame size], keeping the box's centre (the SAD
    // position is more precise than the mask; integer sizes move the centre
    // by at most half a pixel per resize). Too few set pixels (the object
    // stopped): size kept.
    // Limits: the rule is only as good as the mask. A three-frame mask marks
    // the moving edges, not a uniform interior: on the vtest walker (dark
    // coat) it shrank the box from 32x84 to 28x57 in 20 frames. Pass a mask
    // that covers the object, or none (the size is then kept).
    // Once lost, update() returns lost until the next start().
    track_status update(gray_cplane frame, gray_cplane motion_mask = gray_cplane{});

    // update() without a mask, the search window centred where the pattern
    // would be if the object box were at `expected` (the object's position
    // measured otherwise, e.g. from its motion) instead of where it was.
    // The lost rule and the box's move are update()'s, relative to the
    // pattern's last position.
    track_status update_near(gray_cplane frame, box expected);

    track_status status() const { return m_status; }
    box position() const { return m_position; }          // the object box
    box pattern_box() const { return m_pattern_box; }    // where pattern() was taken
    box last_search_window() const { return m_window; }  // top-left positions searched
    const sad_result& last_match() const { return m_last; }
    gray_cplane pattern() const;
    const track_params& params() const { return m_params; }

  private:
    track_status search(gray_cplane frame, gray_cplane motion_mask, box centre);
    box pattern_box_of(box object) const;
    void take_pattern(gray_cplane frame);
    box refit_size(gray_cplane motion_mask, box matched) const;

    track_params m_params;
    uint8_t* m_pattern = nullptr;
    box m_position;
    box m_pattern_box;
    box m_window;
    sad_result m_last;
    track_status m_status = track_status::lost;
};

}  // namespace dsp
