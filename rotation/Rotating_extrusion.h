// `clash4d extrude` on a scene where something turns: every object's
// half-space tree per time sub-span, each half-space a.p + d <= 0 of the
// shape written as n(t).x + e(t) <= 0 with polynomial coefficients
// (rotation/Moving_planes.h: the half-space times |q(t)|^2 > 0, fact 9 of
// regularised-semantics.md), so a person can check them by hand. The JSON
// has the translation report's shape (model/Extrusion_report.h) with
// "pose" in place of "velocity" and "offset", and each coefficient a
// polynomial: its rationals from the constant term up.
#ifndef CLASH4D_ROTATION_ROTATING_EXTRUSION_H
#define CLASH4D_ROTATION_ROTATING_EXTRUSION_H

#include "rotation/Pose_segments.h"
#include "scene/Scene.h"
#include <nlohmann/json.hpp>
#include <string>

namespace clash4d {

nlohmann::ordered_json rotating_extrusion(const Scene& scene);

// "3/2*t^2 - t + 1": the polynomial in t, highest power first ("0" for 0).
std::string time_poly_text(const Time_poly& p);

} // namespace clash4d

#endif
