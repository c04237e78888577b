// Illumination: one directional light plus ambient for the balls (the
// background plane carries its own radiance), and an optional global gain
// that changes over time (a lamp switched or dimmed), applied to everything
// before quantization to 8 bits.
#pragma once

#include "model/scene/geometry.h"

namespace scene {

struct lighting {
    enum class change { none, step, ramp };

    vec3 direction_to_light{-0.39, -0.69, -0.61};  // unit, from up-left-front (Y is down)
    double light_level = 255.0;  // radiance of a white Lambertian surface facing the light
    double ambient = 0.3;        // fraction of light_level reaching every surface

    change gain_change = change::none;
    double change_start_s = 0.0;  // step: the time of the step; ramp: its start
    double change_end_s = 0.0;    // ramp: its end
    double gain_before = 1.0;
    double gain_after = 1.0;

    // A step from 1 to gain at time t_s.
    static lighting with_step(double t_s, double gain);
    // A linear ramp from 1 (at start_s) to gain (at end_s).
    static lighting with_ramp(double start_s, double end_s, double gain);

    double gain_at(double t_s) const;
};

}  // namespace scene
