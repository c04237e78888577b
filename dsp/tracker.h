// Tracking by SAD (paper eq. 5): the reference pattern is searched in a
// window around its last position; the minimum SAD is the new position.
// Every frame the reference pattern is replaced by the pixels at the new
// position, its size is re-fitted to the object, and the search window is
// re-centred on it (paper: "reference pattern, its size and the search area
// are updated every frame").
//
// Lost-track rule: the track is lost when the best mean absolute difference
// per pixel exceeds lost_mean_sad, or when the pattern would leave the image.
#pragma once

#include <cstdint>

#include "dsp/image.h"
#include "dsp/sad_search.h"

namespace dsp {

struct track_params {
    int search_radius = 24;       // pixels each way around the last position
    uint32_t lost_mean_sad = 28;  // mean |difference| per pixel above which the track is lost
    int min_size = 8;             // pattern width/height limits
    int max_size = 96;
};

enum class track_status : uint8_t { tracking, lost };

class sad_tracker {
public:
    sad_tracker() = default;
    ~sad_tracker();
    sad_tracker(const sad_tracker&) = delete;
    sad_tracker& operator=(const sad_tracker&) = delete;

    void init(const track_params& params);  // allocates the pattern buffer (max_size^2)

    // Start tracking the object at `object` in `frame` (box clamped to max_size).
    void start(gray_cplane frame, box object);

    // Find the pattern in the next frame; updates position, pattern and window.
    track_status update(gray_cplane frame);

    box position() const { return m_position; }
    box last_search_window() const { return m_window; }  // top-left positions searched
    const sad_result& last_match() const { return m_last; }
    gray_cplane pattern() const;
    const track_params& params() const { return m_params; }

private:
    track_params m_params;
    uint8_t* m_pattern = nullptr;
    box m_position;
    box m_window;
    sad_result m_last;
};

}  // namespace dsp
