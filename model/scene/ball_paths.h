// The ball paths of the built-in scenarios, their geometry written once:
// scene::default_scenario, the stereosim scenarios (tb/app/cli/scenarios.cpp)
// and the tests' scenarios (tests/support/host/scenarios.h) all take them
// from here, so a test's "circling at 1 m" is the command's `near`.
//
// `speed` is a time scale: 1 the nominal path, 2 twice as fast (the same
// path in half the time), 0 at rest. Motion starts at `start_s`; before it
// the ball rests where the path starts.
#pragma once

#include "model/scene/trajectory.h"

namespace scene {

// When the motion of a scenario with `still_frames` still frames starts:
// frames 0 .. still_frames - 1 all see the start position.
double motion_start_s(int still_frames, double frame_period_s);

// The default throw, towards the rig and bouncing: from (-0.30, 0, depth) m
// at (0.14, -2.0, -0.45) m/s, the floor 0.35 m below the optical axis (the
// centre touches it at 0.35 - radius), restitution 0.8. Time-scaled:
// velocity x speed, gravity x speed^2 (p_v(t) = p(v t)).
trajectory thrown_ball_path(double depth_m, double ball_radius_m, double speed, double start_s);

// Circling in the plane Z = depth around the optical axis, radius 0.15 depth
// (118 px in the image) at 0.41 depth x speed m/s (8 px per frame at any
// depth at speed 1), from its leftmost point.
trajectory circling_path(double depth_m, double speed, double start_s);

// A straight line from (-0.25, -0.05, depth) m at (1.0, 0.1, 0) x speed m/s
// (7 px per frame at 2.6 m).
trajectory line_path(double depth_m, double speed, double start_s);

// A slow pass across the middle of the view, the same in the image at any
// depth: from (-0.08, -0.02, 1) x depth m at (0.26, 0.02, 0) x depth x speed
// m/s, i.e. from 63 px left of and 16 px above the image centre, 5 px per
// frame right and 0.4 px down at speed 1 (f = 789.47 px, 24.5 ms frames).
// Made for objects of any size: a ball up to half the image wide stays
// wholly inside the view for 30 frames.
trajectory pass_path(double depth_m, double speed, double start_s);

// At rest at (-0.30, 0, depth) m, where the throw starts.
trajectory resting_path(double depth_m);

}  // namespace scene
