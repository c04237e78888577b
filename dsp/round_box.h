// A ball's box brought back to the shape its image has. A sphere's image is
// an ellipse drawn out along the line from the principal point by 1/cos of
// its angle off the axis; its bounding box is sqrt(f^2 + x^2) wide to
// sqrt(f^2 + y^2) high (x, y its centre's offsets from the principal point,
// f the focal length, all in pixels): square on the axis, 8 % wider than
// high at the left and right ends of a 640 px row behind the default 6 mm
// lens and 7.6 um pixels (22 deg off the axis), 32 % behind a 2.8 mm one.
// Where one side of TRACK's box is shorter than that shape gives it by over
// an eighth, the differences missed the object's rims on that axis and the
// size rules took the short side as the object's (an 88 px ball going away
// over teddy was tracked by a box 48 px high, an eighth lost a pair), so
// that side grows to the shape about the box's centre (docs/firmware.md,
// "A round box").
#pragma once

#include <cstdint>

#include "dsp/image.h"
#include "dsp/triangulate.h"

namespace dsp {

// `b` (a box in the right image, `image_width` x `image_height`) with its
// short side grown to the sphere's shape where it falls short by over an
// eighth (at least 2 px); `b` itself where it is within that, where it
// touches the image's border (a cut object is not round there), or where
// the grown box would leave the image. Only a side that falls short grows:
// a box longer than the shape is not cut back.
box rounded_box(box b, int image_width, int image_height, const camera_rig& rig);

// Whether neither side of `b` falls short of the sphere's shape at b's place
// by over an eighth (at least 2 px): a box a ball's image may fill.
bool is_round(box b, const camera_rig& rig);

// The axis on which `b` is longer than a sphere's image as wide (as high)
// at b's place by over an eighth (at least 2 px): the other side falls
// short of the shape the long one gives it (is_round's test, turned).
enum class drawn_out_axis { neither, width, height };
drawn_out_axis drawn_out(box b, const camera_rig& rig);

}  // namespace dsp
