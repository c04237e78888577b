// Bayer CFA bilinear demosaic to RGB (paper step 2).
//
// Computes: each missing colour is the mean of its nearest same-colour
//   neighbours: 2 (horizontal or vertical) or 4 (cross or diagonal)
//   samples, rounded half up: (a + b + 1) >> 1, (a + b + c + d + 2) >> 2.
//   This is what OpenCV's cv::demosaicing(..., COLOR_Bayer*2RGB) computes on
//   interior pixels.
// Assumes: width and height even and >= 4; out has raw's size.
// Border: the outermost row/column is computed with mirrored neighbours
//   (reflect-101), so every output pixel is defined.
// Cost: see dsp/kernel_costs.h (demosaic_gray_cycles covers the fused path).
#pragma once

#include <cstdint>

#include "dsp/image.h"

namespace dsp {

// Colour of the 2x2 CFA cell starting at pixel (0, 0), read row by row:
// rggb = R at (0,0), G at (1,0), G at (0,1), B at (1,1).
// OpenCV names these by the second row's 2nd/3rd pixel: rggb is COLOR_BayerBG,
// bggr is COLOR_BayerRG, grbg is COLOR_BayerGB, gbrg is COLOR_BayerGR.
enum class cfa_order : uint8_t { rggb, bggr, grbg, gbrg };

const char* cfa_order_name(cfa_order order);

// Whole-image demosaic.
void demosaic_bilinear(gray_cplane raw, cfa_order order, rgb_plane out);

// One output row y (reads raw rows y-1, y, y+1), for line-by-line fusion
// with gray conversion. out_row holds raw.width pixels.
void demosaic_bilinear_row(gray_cplane raw, cfa_order order, int y, rgb8* out_row);

}  // namespace dsp
