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

cfa_colour cfa_colour_at(dsp::cfa_order order, int x, int y);

// raw must have rgb's size.
void mosaic(dsp::rgb_cplane rgb, dsp::cfa_order order, dsp::gray_plane raw);
gray_image mosaic(const rgb_image& rgb, dsp::cfa_order order);

}  // namespace scene
