// Stereo matching by edges (paper step 5b): Sobel edges on both images are
// binarised; a horizontal epipolar line through the pattern cuts the edges
// into segments (runs between edge pixels); the sequence of segment lengths
// seen in the right image across the pattern is matched against the left
// image's segments; the horizontal shift of the matched segments is the
// disparity.
#pragma once

#include <cstdint>

#include "dsp/image.h"
#include "dsp/stereo_sad.h"

namespace dsp {

struct edge_params {
    uint8_t edge_threshold = 60;  // Sobel magnitude above which a pixel is an edge
    int min_disparity = 0;
    int max_disparity = 64;
    int lines = 3;  // epipolar lines used: the pattern's centre row and neighbours
};

// right_edges / left_edges: Sobel magnitudes (dsp/sobel.h) of the two images,
// valid at least on the rows the pattern covers.
stereo_result stereo_match_edge(gray_cplane right_edges, gray_cplane left_edges, box pattern,
                                const edge_params& params);

}  // namespace dsp
