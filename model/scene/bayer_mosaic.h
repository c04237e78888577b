// Bayer mosaicking: keep, at each pixel, the one colour the sensor's colour
// filter array samples there (the inverse view of dsp/bayer_demosaic.h).
// CFA orders as dsp::cfa_order, the 2x2 cell read row by row from pixel
// (0, 0): rggb = R at (0,0), G at (1,0), G at (0,1), B at (1,1); bggr, grbg
// and gbrg likewise. The cell repeats over the image, so the colour at (x, y)
// is the cell's colour at (x & 1, y & 1).
#pragma once

#include <cstdint>

#include "dsp/bayer_demosaic.h"
#include "dsp/image.h"
#include "model/scene/images.h"

namespace scene {

enum class cfa_colour : uint8_t { red, green, blue };

// The one CFA table of the model (the sensor's pixel pipeline uses it too).
inline cfa_colour cfa_colour_at(dsp::cfa_order order, int x, int y) {
    // [order][y & 1][x & 1]
    constexpr cfa_colour r = cfa_colour::red, g = cfa_colour::green, b = cfa_colour::blue;
    static constexpr cfa_colour cells[4][2][2] = {
        {{r, g}, {g, b}},  // rggb
        {{b, g}, {g, r}},  // bggr
        {{g, r}, {b, g}},  // grbg
        {{g, b}, {r, g}},  // gbrg
    };
    return cells[static_cast<int>(order)][y & 1][x & 1];
}

// The component of px that colour c samples.
inline uint8_t cfa_sample(const dsp::rgb8& px, cfa_colour c) {
    return c == cfa_colour::red ? px.r : (c == cfa_colour::green ? px.g : px.b);
}

// raw must have rgb's size.
void mosaic(dsp::rgb_cplane rgb, dsp::cfa_order order, dsp::gray_plane raw);
gray_image mosaic(const rgb_image& rgb, dsp::cfa_order order);

}  // namespace scene
