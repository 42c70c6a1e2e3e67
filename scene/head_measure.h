// Finds a head in the skin's geometry and measures it from crown to chin, so that a scan in
// unknown units is sized from the head itself and not from its bounding box (a bust's box
// holds the neck and shoulders: LeePerrySmith.glb's is 7.95 units tall, its head about 4.4).
//
// Orientation as glTF and the loader's auto camera assume: +Y up, the face looking along +Z.
// The method reads the front profile, the silhouette a side view would show:
//  1. The skin's triangles are cut by horizontal planes every 1/400 of its height; each cut
//     gives the point furthest forward (max z), and the cut's width and depth.
//  2. Crown: the highest vertex. Nose tip: the most forward profile point in the upper two
//     thirds of the skin (a bust's chest lies lower; on a face the nose sticks out most).
//  3. Chin (menton): the profile point furthest along the direction halfway between forward
//     and down (max z - y), where the chin's front turns into its underside. Looked for from
//     0.3 crown-to-nose lengths below the nose tip (past the nose's own underside and the
//     lips; adults' chins are about 0.5-0.6 below) down to where the profile has fallen back
//     a tenth of that length behind the best point so far (under the chin towards the neck),
//     at most 0.9 below; a profile that never falls back there shows no chin (e.g. a scan
//     lying down or facing -Z).
#pragma once

#include <optional>
#include <string>

#include "scene/scene.h"

namespace skinsim::scene {

struct HeadMeasure {
  std::optional<HeadLandmarks> head;
  std::string why_not;  // when `head` is empty: what was missing, for the user
};

// Measures the skin meshes.
HeadMeasure measure_head(const Scene& scene);

}  // namespace skinsim::scene
