// The static background: a fronto-parallel plane Z = depth_m (world frame),
// seen by both cameras with the parallax of that depth, f * baseline / depth.
// Its surface is a uniform colour, the seeded procedural texture or a real
// image (texture_image) of a given texel size.
//
// Each camera's background is rendered once per renderer as the exact (or,
// for images, supersampled) mean radiance over every pixel's footprint on
// the plane; frames then only add the balls and the lighting gain.
#pragma once

#include <memory>
#include <vector>

#include "model/scene/camera.h"
#include "model/scene/geometry.h"
#include "model/scene/texture.h"

namespace scene {

struct background_desc {
    enum class kind { uniform, procedural, image };

    kind type = kind::procedural;
    double depth_m = 5.0;
    vec3 uniform_radiance{110.0, 110.0, 110.0};  // levels, kind::uniform
    procedural_texture_params procedural;        // kind::procedural
    std::shared_ptr<const texture_image> image;  // kind::image
    double texel_size_m = 0.005;                 // plane metres per image texel
    vec2 image_centre_m{-0.06, 0.0};             // plane (X, Y) under the image's centre

    static background_desc uniform(vec3 radiance, double depth_m = 5.0);
    static background_desc procedural_plane(const procedural_texture_params& params,
                                            double depth_m = 5.0);
    // The image scaled (aspect kept) and centred so it just covers what both
    // cameras of the rig see of the plane.
    static background_desc image_plane(std::shared_ptr<const texture_image> image,
                                       const stereo_rig& rig, double depth_m = 5.0);
};

// Mean radiance (levels, before the lighting gain) of the background over
// each pixel of the camera: width x height RGB float triples, row-major.
// Procedural: exact box mean; image: supersampling x supersampling bilinear
// samples per pixel; uniform: the colour. The plane must be in front of the
// camera.
void render_background(const background_desc& background, const pinhole_camera& camera,
                       int supersampling, std::vector<float>* rgb);

}  // namespace scene
