// Bayer CFA bilinear demosaic to RGB (paper step 2).
//
// Computes: each missing colour is the mean of its nearest same-colour
//   neighbours in the 3x3 window, rounded half up:
//     green at an R/B site        (N + S + W + E + 2) >> 2      (cross)
//     B at an R site, R at a B    (NW + NE + SW + SE + 2) >> 2  (diagonals)
//     at a G site, the colour of
//     its row's R/B neighbours    (W + E + 1) >> 1
//     and the other colour        (N + S + 1) >> 1
//   Integer only: sums fit 10 bits, no multiply, no division.
//   On interior pixels this is OpenCV 4.6's cv::demosaicing(...,
//   COLOR_Bayer*2RGB) (bilinear): measured identical (0 differing values) on
//   Kodak mosaics, noise and the openISP raw in all four orders; the tests
//   allow 1 grey level (tests/dsp/test_demosaic.cpp,
//   test_real_images_demosaic.cpp). OpenCV replicates its outermost
//   rows/columns instead of mirroring, so the border differs by design.
// Assumes: width and height even and >= 4 (whole CFA cells, so the order holds
//   for the whole frame); out (or out_row) holds raw.width pixels per row.
//   Calls with a smaller or empty raw image return without writing anything.
// Border: the outermost rows/columns read mirrored neighbours (reflect-101:
//   row -1 is row 1, column width is column width-2). With even sizes the
//   mirror keeps each sample's CFA colour, so every output pixel is defined
//   by the same formulas.
// Cost (this C reference, per output pixel): an R/B site loads 9 samples and
//   does 8 additions and 2 shifts; a G site loads 5 samples and does 4
//   additions and 2 shifts; 3 byte stores. No per-pixel branch: the row loop
//   runs over CFA pairs. A C64x schedule does the 2-sample means with AVGU4
//   (4 pixels per instruction) and the 4-sample means in 16-bit lanes (ADD2);
//   the modelled cycles of the fused demosaic+gray path are
//   cost::demosaic_gray_cycles (dsp/kernel_costs.h).
#pragma once

#include <cstdint>

#include "dsp/image.h"

namespace dsp {

// Colour of the 2x2 CFA cell starting at pixel (0, 0), read row by row:
// rggb = R at (0,0), G at (1,0), G at (0,1), B at (1,1).
// OpenCV names these by the second row's 2nd/3rd pixel: rggb is COLOR_BayerBG,
// bggr is COLOR_BayerRG, grbg is COLOR_BayerGB, gbrg is COLOR_BayerGR
// (checked against cv::demosaicing by tests/dsp/test_demosaic.cpp).
enum class cfa_order : uint8_t { rggb, bggr, grbg, gbrg };

const char* cfa_order_name(cfa_order order);

// Whole-image demosaic.
void demosaic_bilinear(gray_cplane raw, cfa_order order, rgb_plane out);

// One output row y (reads raw rows y-1, y, y+1, mirrored at the frame edge),
// for line-by-line fusion with gray conversion. out_row holds raw.width
// pixels. Gives exactly the row y of demosaic_bilinear.
void demosaic_bilinear_row(gray_cplane raw, cfa_order order, int y, rgb8* out_row);

}  // namespace dsp
