// The scale of a loaded scan (Scene::units_per_mm), decided from the head in it: diffusion
// profiles are in millimetres, so a head at the wrong scale is blurred too much or too little.
#pragma once

#include <functional>
#include <string>

#include "scene/scene.h"

namespace skinsim::scene {

// Crown to chin (vertex to menton), adults: about 215-235 mm between the sexes' averages; a
// head outside 100-400 mm at the given units is almost surely in other units.
inline constexpr float kPlausibleHeadMinMm = 100.0f;
inline constexpr float kPlausibleHeadMaxMm = 400.0f;
inline constexpr float kTypicalHeadMm = 225.0f;

// Measures the head (head_measure.h; scene.head) and sets scene.units_per_mm and
// scene.units_source:
//  - `given_units_per_mm` > 0 (--units-per-mm) wins; warns when it makes the head implausible,
//    suggesting the value that makes it kTypicalHeadMm;
//  - else glTF's metres when they give a plausible head, or when nothing is skin;
//  - else the value that makes the measured head kTypicalHeadMm tall, or, when no head was
//    found, the skin's bounding-box height (which overstates a bust's head); either way it
//    warns, saying what was measured.
// "Head" heights are the measured crown-to-chin height, else the skin's bounding-box height.
void size_scene(Scene& scene, float given_units_per_mm,
                const std::function<void(const std::string&)>& warn);

// One line for the user: what the head measures and the units per mm it gives, e.g. "head
// 4.38 units crown to chin (crown y 3.973, chin y -0.4072), 225 mm at 0.01947 units/mm; a 225
// mm head would be 0.0195 units/mm".
std::string describe_scale(const Scene& scene);

}  // namespace skinsim::scene
