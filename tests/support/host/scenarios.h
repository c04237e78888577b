// Stereo scenarios for the firmware's end-to-end tests and benchmarks, beside
// scene::default_scenario (a thrown, bouncing ball at 2.6 m -> 1.6 m). All use
// the default rig and the procedural background at 5 m; one ball, 5 cm except
// in pass_scenario. Frame n is taken at n * 24.5 ms.
#pragma once

#include "model/scene/sequence.h"

namespace host {

// The radius of a ball at depth_m whose image is diameter_px wide at the image
// centre: the tangent cone's width 2 f r / sqrt(Z^2 - r^2) (model/scene/camera.h).
double ball_radius_for_width(double diameter_px, double depth_m, double focal_px);

// The ball rests at (-0.3, 0, 2.6) m (scene::resting_path) for every frame:
// nothing moves.
scene::scenario static_scenario(int frames = 40);

// The ball still for still_frames frames, then on scene::circling_path
// (model/scene/ball_paths.h, also `stereosim run --scenario near / far`): in
// the plane Z = depth_m around the optical axis, radius 0.15 * depth_m (118 px
// in the image) at 0.41 * depth_m m/s (8 px per frame at any depth). With
// depth_m at 1 and 3 it puts the ball at both ends of docs/design-brief.md's 1-3 m
// accuracy range.
scene::scenario circling_scenario(double depth_m, int still_frames = 4, int frames = 40);

// A ball of radius ball_radius_m still for still_frames frames, then on
// scene::pass_path (model/scene/ball_paths.h, also `--set scenario.path=pass`):
// a slow pass across the middle of the view at depth_m, 5 px per frame.
scene::scenario pass_scenario(double depth_m, double ball_radius_m, int still_frames = 3,
                              int frames = 30);

// The ball circles in the plane Z = 2.5 m, centre (0.7, 0, 2.5) m, radius
// 0.5 m, at 1.2 m/s (~9 px per frame), starting at its leftmost point after
// still_frames frames and going up. Its image leaves the right edge of the
// view and comes back: see exit_return_timing() for when.
scene::scenario exit_return_scenario(int still_frames = 4);

// A slow ball that leaves the view and comes back at another depth:
// carried round a horizontal circle 0.5 m in radius at 0.25 m/s (a toy on a
// turntable, 2 px a frame or less in the image), it leaves the right edge on
// the circle's near side, 2.5 m from the rig, and comes back on its far
// side, 3.35 m away (51 px wide, then 38). A slow ball: its tracks are
// keyed (dsp/key_frame.h). exit_return_timing() applies to it too.
scene::scenario turntable_return_scenario();

// One ball's track ends and another object is tracked at another depth: a
// ball 12 cm wide crosses to the right at 4.5 m, 1.2 m/s (5 px a frame),
// and leaves the right edge by frame 56; a second one, still at 2.4 m on
// the left since frame 0, starts to the right at 0.25 m/s (2 px a frame:
// keyed, dsp/key_frame.h) at frame second_object_start_frame().
scene::scenario exit_then_new_object_scenario();
// The same second ball; the first goes away from 3.2 m at 1.5 m/s, near
// the middle of the view, until it is behind the background plane (5 m)
// from frame 55: it leaves no border behind.
scene::scenario vanish_then_new_object_scenario();
// The same second ball; the first, 12 cm wide at 3 m, is dropped from rest
// at frame 3, bounces on a floor 0.45 m below (restitution 0.3) and lies
// still from about frame 26. With second_moves false the second ball stays
// still: nothing moves after the first comes to rest.
scene::scenario dropped_then_new_object_scenario(bool second_moves);
// The same dropped ball; the second ball is a speck 8 mm wide (3 px), whose
// differences are under the detector's min_area.
scene::scenario dropped_then_speck_scenario();
// The same second ball; the first, 12 cm wide, goes right at 0.07 m/s 3 m
// away (0.45 px a frame, just over the slowest DETECT starts: 0.4), still
// moving while the second starts.
scene::scenario slow_then_new_object_scenario();
// The same second ball; the first, 12 cm wide at 3 m, stays where it is
// and spins at 2 rev/s about y: its texture moves, its outline does not.
scene::scenario spinning_then_new_object_scenario();
constexpr int second_object_start_frame() {
    return 90;
}

// Frame indices of exit_return_scenario(still_frames), from the scene's
// closed-form ellipse: the last frame fully inside the image before the
// exit, the first frame with no pixel in the image, the last such frame,
// and the first frame fully inside again.
struct exit_return_frames {
    int last_inside = -1;
    int first_outside = -1;
    int last_outside = -1;
    int first_inside_again = -1;
};
exit_return_frames exit_return_timing(const scene::sequence& sequence, int frames);

// The ball still (no motion at all) while the global light changes at
// change_frame: a step of the gain to `gain`, or, with ramp_frames > 0, a
// linear ramp to `gain` over ramp_frames frame periods (a lamp dimming).
scene::scenario lighting_change_scenario(int change_frame, double gain, int ramp_frames,
                                         int frames = 24);

}  // namespace host
