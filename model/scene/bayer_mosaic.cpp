#include "model/scene/bayer_mosaic.h"

namespace scene {

void mosaic(dsp::rgb_cplane rgb, dsp::cfa_order order, dsp::gray_plane raw) {
    for (int y = 0; y < rgb.height; ++y) {
        const dsp::rgb8* in = rgb.row(y);
        uint8_t* out = raw.row(y);
        for (int x = 0; x < rgb.width; ++x) {
            out[x] = cfa_sample(in[x], cfa_colour_at(order, x, y));
        }
    }
}

gray_image mosaic(const rgb_image& rgb, dsp::cfa_order order) {
    gray_image raw(rgb.width, rgb.height);
    mosaic(rgb.view(), order, raw.plane());
    return raw;
}

}  // namespace scene
