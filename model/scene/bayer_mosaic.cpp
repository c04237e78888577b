#include "model/scene/bayer_mosaic.h"

namespace scene {

cfa_colour cfa_colour_at(dsp::cfa_order order, int x, int y) {
    // [order][y & 1][x & 1]
    static constexpr cfa_colour r = cfa_colour::red, g = cfa_colour::green, b = cfa_colour::blue;
    static constexpr cfa_colour cells[4][2][2] = {
        {{r, g}, {g, b}},  // rggb
        {{b, g}, {g, r}},  // bggr
        {{g, r}, {b, g}},  // grbg
        {{g, b}, {r, g}},  // gbrg
    };
    return cells[static_cast<int>(order)][y & 1][x & 1];
}

void mosaic(dsp::rgb_cplane rgb, dsp::cfa_order order, dsp::gray_plane raw) {
    for (int y = 0; y < rgb.height; ++y) {
        const dsp::rgb8* in = rgb.row(y);
        uint8_t* out = raw.row(y);
        for (int x = 0; x < rgb.width; ++x) {
            switch (cfa_colour_at(order, x, y)) {
                case cfa_colour::red:
                    out[x] = in[x].r;
                    break;
                case cfa_colour::green:
                    out[x] = in[x].g;
                    break;
                case cfa_colour::blue:
                    out[x] = in[x].b;
                    break;
            }
        }
    }
}

gray_image mosaic(const rgb_image& rgb, dsp::cfa_order order) {
    gray_image raw(rgb.width, rgb.height);
    mosaic(rgb.view(), order, raw.plane());
    return raw;
}

}  // namespace scene
