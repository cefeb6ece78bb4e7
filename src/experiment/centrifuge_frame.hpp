#pragma once
// The strongbox flying in a centrifuge ([centrifuge], docs/config.md): the rotating frame of the
// engine (rotating_frame.hpp) placed in the model's coordinates (x across the box's width, y from
// the front window to the back plate, z up from the base).
//
// Geometry: a swinging basket swung up, its base normal to the radial direction through the
// box's centre line at the reference level (Taylor 1995, section 2.3; Schofield 1980). The axis is
// a distance `radius` above that level (at x = box.width/2, y = box.depth/2), and normal to the
// box's width when the width lies in the plane of rotation (the axis along -y, the box travelling
// towards +x), or along the width otherwise (the axis along +x, travelling towards +y). So the
// acceleration omega^2 r grows with depth (r from radius - (H - z_ref) at the surface to radius +
// z_ref at the base) and, in the plane of rotation, fans out across the width by atan(dx / r).
// Earth's gravity is left out in flight: normal to the plane of rotation, it would tilt the
// resultant by atan(1/N) (1.1 degrees at 50 g) and raise it by sqrt(1 + 1/N^2) - 1 (2e-4); the
// basket's swing itself (from hanging at 1 g to flying) is not modelled, the model flies from the
// start of the spin-up.
//
// Spin-up: omega grows linearly from sqrt(g / radius) (1 g at the reference level, what the
// pluviation and settling had) to sqrt(N g / radius) over spin_up.ramp_time, with its Euler force
// -alpha k x r; then omega stays constant for the rest of the run (Taylor 1995, eq. 2.1: N g = omega^2 r).
#include "dem/rotating_frame.hpp"
#include "experiment/experiment_config.hpp"

namespace trapdem {

// rad/s, the spin that gives `g_level` g at `radius` (m): omega = sqrt(N g / r).
double centrifuge_angular_velocity(double g_level, double radius);

// The spin-up's angular velocity at time t: a linear ramp from 1 g to spin_up.g_level at the
// reference level, starting at `ramp_start` (s); constant before and after it.
FrameSpin centrifuge_spin(const ExperimentConfig& e, double ramp_start, double t);

// The frame of the configuration's [centrifuge], its spin ramp starting at `ramp_start` (s); with
// `ramped` false, the final spin throughout (the lowering and after).
RotatingFrame centrifuge_frame(const ExperimentConfig& e, double ramp_start, bool ramped);

// m, the distance from the axis of a point of the box's centre line at height z above the base.
double centrifuge_radius_at(const CentrifugeConfig& c, double z);

}  // namespace trapdem
