#include "dsp/gray_convert.h"

namespace dsp {

void rgb_row_to_gray(const rgb8* in, int width, uint8_t* out) {
    for (int x = 0; x < width; ++x) out[x] = gray_of(in[x]);
}

void rgb_to_gray(rgb_cplane in, gray_plane out) {
    for (int y = 0; y < in.height; ++y) rgb_row_to_gray(in.row(y), in.width, out.row(y));
}

}  // namespace dsp
