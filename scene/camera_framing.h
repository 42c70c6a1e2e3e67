// Automatic camera placement for scenes that bring no camera of their own.
#pragma once

#include "scene/bounds.h"
#include "scene/scene.h"

namespace skinsim::scene {

// A perspective camera on the +Z side of `bounds`, looking along -Z at the box centre
// (glTF assets face +Z, so this shows the front of a head scan), placed so that the whole
// box fits a frame of the given aspect (width / height) with `margin` (0.05 = 5%) to spare.
// znear/zfar bracket the box. Requires a non-empty box.
Camera frame_front(const Bounds& bounds, float yfov_radians, float aspect, float margin);

// frame_front() of the head's crown-to-chin box (head_measure.h) with a 10% margin: the
// camera aims at the middle of the face and the head fills the frame, whatever else the scan
// holds (a bust's neck and shoulders).
Camera frame_face(const HeadLandmarks& head, float yfov_radians, float aspect);

}  // namespace skinsim::scene
