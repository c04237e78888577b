// PNG files <-> scene images, and JPEG files -> scene images (stb_image /
// stb_image_write from Debian's libstb-dev; no OpenCV in the libraries). Errors throw
// std::runtime_error naming the file and what is wrong.
#pragma once

#include <string>

#include "model/scene/images.h"

namespace scene {

struct png_info {
    int width = 0;
    int height = 0;
    int channels = 0;  // in the file: 1 gray, 2 gray+alpha, 3 RGB, 4 RGBA
};

// Header only (size and channels), without decoding the pixels. Throws if the
// file is missing, not a PNG, or 16-bit.
png_info read_png_info(const std::string& path);

// 8-bit PNG as RGB: gray is replicated to R = G = B, alpha is dropped, palettes
// are expanded (as OpenCV's imread does). 16-bit PNGs are refused rather than
// silently reduced to 8 bits.
rgb_image read_png_rgb(const std::string& path);

// 8-bit PNG as gray: only 1-channel (or gray+alpha) files; an RGB file is an
// error, not converted (the conversion would be a choice of weights).
gray_image read_png_gray(const std::string& path);

// A replay's frame: a PNG (as read_png_rgb) or a JPEG (8-bit, baseline or
// progressive, gray replicated to RGB), told apart by the file's signature.
png_info read_image_info(const std::string& path);
rgb_image read_image_rgb(const std::string& path);

void write_png(const std::string& path, const rgb_image& image);
void write_png(const std::string& path, const gray_image& image);

}  // namespace scene
