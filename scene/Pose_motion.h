// A pose motion (spec: "Motion with rotation (poses)") made ready for the
// pipeline: validated, and when it never rotates, read as the piecewise-
// linear translation it is (spec: "a motion written either way gives the
// same answers").
#ifndef CLASH4D_SCENE_POSE_MOTION_H
#define CLASH4D_SCENE_POSE_MOTION_H

#include "scene/Scene.h"
#include <string>
#include <vector>

namespace clash4d {

// At most this many poses per object (spec; more is exit 3).
constexpr std::size_t CLASH4D_MAX_POSES = 10000;

// Throws Input_error naming place + ".poses[i]..." for the first pose the
// spec refuses: none, too many (exit 3), times not strictly increasing, a
// zero quaternion, or q_{i+1} a negative multiple of q_i (q(t) would pass
// through 0). `place` is the motion's, e.g. "objects[1].motion".
void check_poses(const std::vector<Pose>& poses, const std::string& place);

// Where the shape's origin is at time 0: c(0), c linear between poses and
// constant before the first and after the last.
std::array<Rational, 3> pose_origin_at_zero(const std::vector<Pose>& poses);

// The object moving by the poses (checked, as check_poses): motion.poses as
// written, and times / velocities the translation D(t) = c(t) - c(0) when no
// pose rotates (the shape then put at c(0), a Translate around the written
// shape; none when c(0) = 0), at rest when some pose rotates (the
// translation pipeline refuses it: scene/Rotation_refusal.h).
void set_pose_motion(Scene_object& object, std::vector<Pose> poses, const std::string& place);

// The shape as written: without set_pose_motion's Translate to c(0).
const Solid& written_shape(const Scene_object& object);

} // namespace clash4d

#endif
