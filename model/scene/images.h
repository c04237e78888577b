// Owning 8-bit images for the scene (not firmware: std::vector storage), with
// views in the firmware's plane types so dsp kernels can read them directly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dsp/image.h"

namespace scene {

template <typename T>
struct image {
    int width = 0;
    int height = 0;
    std::vector<T> pixels;  // row-major, stride = width

    image() = default;
    image(int w, int h) { resize(w, h); }
    void resize(int w, int h) {
        width = w;
        height = h;
        pixels.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), T{});
    }
    T& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
    const T& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
    dsp::plane<T> plane() { return dsp::plane<T>{pixels.data(), width, height, width}; }
    dsp::plane<const T> view() const {
        return dsp::plane<const T>{pixels.data(), width, height, width};
    }
};

using rgb_image = image<dsp::rgb8>;
using gray_image = image<uint8_t>;

}  // namespace scene
