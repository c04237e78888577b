#include "dsp/bayer_demosaic.h"

namespace dsp {
namespace {

// Which colour sits between the greens of a row, and at which x parity.
struct row_layout {
    bool row_is_red;      // the row carries R (else B) besides G
    int nongreen_parity;  // x parity of its R/B samples
};

row_layout layout_of_row(cfa_order order, int y) {
    row_layout first{true, 0};  // row 0 of rggb
    switch (order) {
        case cfa_order::rggb:
            first = {true, 0};
            break;
        case cfa_order::bggr:
            first = {false, 0};
            break;
        case cfa_order::grbg:
            first = {true, 1};
            break;
        case cfa_order::gbrg:
            first = {false, 1};
            break;
    }
    // The next row of a CFA cell swaps both the colour and the parity.
    if (y & 1) return {!first.row_is_red, first.nongreen_parity ^ 1};
    return first;
}

// row_colour = the row's own R/B colour, other = the colour of the rows above and below.
template <bool kRowIsRed>
inline void store(rgb8& px, unsigned row_colour, unsigned green, unsigned other) {
    const auto rc = static_cast<uint8_t>(row_colour);
    const auto g = static_cast<uint8_t>(green);
    const auto oc = static_cast<uint8_t>(other);
    if (kRowIsRed) {
        px = rgb8{rc, g, oc};
    } else {
        px = rgb8{oc, g, rc};
    }
}

// Pixel x of an R/B site; xl, xr are its left and right columns (mirrored at the edge).
template <bool kRowIsRed>
inline void nongreen_site(const uint8_t* up, const uint8_t* mid, const uint8_t* dn, int x, int xl,
                          int xr, rgb8* out) {
    const unsigned green = (up[x] + dn[x] + mid[xl] + mid[xr] + 2u) >> 2;
    const unsigned other = (up[xl] + up[xr] + dn[xl] + dn[xr] + 2u) >> 2;
    store<kRowIsRed>(out[x], mid[x], green, other);
}

template <bool kRowIsRed>
inline void green_site(const uint8_t* up, const uint8_t* mid, const uint8_t* dn, int x, int xl,
                       int xr, rgb8* out) {
    const unsigned row_colour = (mid[xl] + mid[xr] + 1u) >> 1;
    const unsigned other = (up[x] + dn[x] + 1u) >> 1;
    store<kRowIsRed>(out[x], row_colour, mid[x], other);
}

template <bool kRowIsRed>
void demosaic_row(const uint8_t* up, const uint8_t* mid, const uint8_t* dn, int width,
                  int nongreen_parity, rgb8* out) {
    const int last = width - 1;
    // Column 0 and column width-1 mirror (reflect-101): column -1 is 1, column width is width-2.
    if (nongreen_parity == 0) {
        nongreen_site<kRowIsRed>(up, mid, dn, 0, 1, 1, out);
        for (int x = 1; x < last - 1; x += 2) {
            green_site<kRowIsRed>(up, mid, dn, x, x - 1, x + 1, out);
            nongreen_site<kRowIsRed>(up, mid, dn, x + 1, x, x + 2, out);
        }
        green_site<kRowIsRed>(up, mid, dn, last, last - 1, last - 1, out);
    } else {
        green_site<kRowIsRed>(up, mid, dn, 0, 1, 1, out);
        for (int x = 1; x < last - 1; x += 2) {
            nongreen_site<kRowIsRed>(up, mid, dn, x, x - 1, x + 1, out);
            green_site<kRowIsRed>(up, mid, dn, x + 1, x, x + 2, out);
        }
        nongreen_site<kRowIsRed>(up, mid, dn, last, last - 1, last - 1, out);
    }
}

bool demosaic_size_ok(gray_cplane raw) {
    return !raw.empty() && raw.width >= 4 && raw.height >= 4 && raw.width % 2 == 0 &&
           raw.height % 2 == 0;
}

}  // namespace

const char* cfa_order_name(cfa_order order) {
    switch (order) {
        case cfa_order::rggb:
            return "rggb";
        case cfa_order::bggr:
            return "bggr";
        case cfa_order::grbg:
            return "grbg";
        case cfa_order::gbrg:
            return "gbrg";
    }
    return "?";
}

void demosaic_bilinear_row(gray_cplane raw, cfa_order order, int y, rgb8* out_row) {
    if (!demosaic_size_ok(raw) || y < 0 || y >= raw.height) return;
    // Rows -1 and height mirror to 1 and height-2 (reflect-101).
    const int y_up = y == 0 ? 1 : y - 1;
    const int y_dn = y == raw.height - 1 ? raw.height - 2 : y + 1;
    const row_layout layout = layout_of_row(order, y);
    if (layout.row_is_red) {
        demosaic_row<true>(raw.row(y_up), raw.row(y), raw.row(y_dn), raw.width,
                           layout.nongreen_parity, out_row);
    } else {
        demosaic_row<false>(raw.row(y_up), raw.row(y), raw.row(y_dn), raw.width,
                            layout.nongreen_parity, out_row);
    }
}

void demosaic_bilinear(gray_cplane raw, cfa_order order, rgb_plane out) {
    if (!demosaic_size_ok(raw)) return;
    for (int y = 0; y < raw.height; ++y) demosaic_bilinear_row(raw, order, y, out.row(y));
}

}  // namespace dsp
