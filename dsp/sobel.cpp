#include "dsp/sobel.h"

#include <cstring>

namespace dsp {
namespace {

// One interior output row from input rows above (a), at (b) and below (c).
// Column terms are computed once and slid along the row: per column x,
// smooth = a + 2b + c and diff = c - a; then V = smooth[x+1] - smooth[x-1]
// and H = diff[x-1] + 2 diff[x] + diff[x+1] (the IMG_sobel sums regrouped).
void sobel_row(const uint8_t* a, const uint8_t* b, const uint8_t* c, int width, uint8_t* out) {
    int smooth_left = a[0] + 2 * b[0] + c[0];
    int diff_left = c[0] - a[0];
    int smooth_mid = a[1] + 2 * b[1] + c[1];
    int diff_mid = c[1] - a[1];
    out[0] = 0;
    for (int x = 1; x < width - 1; ++x) {
        const int smooth_right = a[x + 1] + 2 * b[x + 1] + c[x + 1];
        const int diff_right = c[x + 1] - a[x + 1];
        const int h = diff_left + 2 * diff_mid + diff_right;
        const int v = smooth_right - smooth_left;
        const int magnitude = (h < 0 ? -h : h) + (v < 0 ? -v : v);
        out[x] = static_cast<uint8_t>(magnitude > 255 ? 255 : magnitude);
        smooth_left = smooth_mid;
        diff_left = diff_mid;
        smooth_mid = smooth_right;
        diff_mid = diff_right;
    }
    out[width - 1] = 0;
}

}  // namespace

void sobel_3x3_rows(gray_cplane in, int y0, int y1, gray_plane out) {
    if (in.empty() || in.width < 3 || in.height < 3 || out.width != in.width ||
        out.height != in.height) {
        return;
    }
    if (y0 < 0) y0 = 0;
    if (y1 > in.height) y1 = in.height;
    for (int y = y0; y < y1; ++y) {
        if (y == 0 || y == in.height - 1) {
            std::memset(out.row(y), 0, static_cast<size_t>(in.width));
        } else {
            sobel_row(in.row(y - 1), in.row(y), in.row(y + 1), in.width, out.row(y));
        }
    }
}

void sobel_3x3(gray_cplane in, gray_plane out) {
    sobel_3x3_rows(in, 0, in.height, out);
}

}  // namespace dsp
