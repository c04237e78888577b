// Image planes as the firmware sees them: a pointer, a size and a row stride
// into a buffer the firmware allocated at init. No ownership, no allocation.
#pragma once

#include <cstddef>
#include <cstdint>

namespace dsp {

template <typename T>
struct plane {
    T* data = nullptr;
    int width = 0;
    int height = 0;
    int stride = 0;  // elements (not bytes) from one row to the next

    T* row(int y) const { return data + static_cast<std::ptrdiff_t>(y) * stride; }
    T& at(int x, int y) const { return row(y)[x]; }
    bool empty() const { return data == nullptr || width <= 0 || height <= 0; }
    // A read-only view of the same pixels.
    plane<const T> as_const() const { return plane<const T>{data, width, height, stride}; }
    // The sub-rectangle (x, y, w, h); the caller keeps it inside the plane.
    plane sub(int x, int y, int w, int h) const { return plane{&at(x, y), w, h, stride}; }
};

struct rgb8 {
    uint8_t r, g, b;
};

using gray_plane = plane<uint8_t>;
using gray_cplane = plane<const uint8_t>;
using rgb_plane = plane<rgb8>;
using rgb_cplane = plane<const rgb8>;

// An axis-aligned box in pixel coordinates: x, y of the top-left pixel.
struct box {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;

    bool empty() const { return width <= 0 || height <= 0; }
    int right() const { return x + width; }    // one past the last column
    int bottom() const { return y + height; }  // one past the last row
    // Centre in Q1 (twice the coordinate), exact for any size.
    int center_x2() const { return 2 * x + width - 1; }
    int center_y2() const { return 2 * y + height - 1; }
};

// The smallest box holding both.
inline box bounding_union(box a, box b) {
    const int x0 = a.x < b.x ? a.x : b.x, y0 = a.y < b.y ? a.y : b.y;
    const int x1 = a.right() > b.right() ? a.right() : b.right();
    const int y1 = a.bottom() > b.bottom() ? a.bottom() : b.bottom();
    return box{x0, y0, x1 - x0, y1 - y0};
}

}  // namespace dsp
