#include "scene/scene_scale.h"

#include <fmt/format.h>

#include "scene/bounds.h"
#include "scene/head_measure.h"

namespace skinsim::scene {
namespace {

bool plausible(float height_mm) {
  return height_mm >= kPlausibleHeadMinMm && height_mm <= kPlausibleHeadMaxMm;
}

// The skin's bounding-box height; 0 without skin.
float box_height(const Scene& scene) {
  Bounds skin;
  for (const Mesh& m : scene.meshes) {
    if (scene.materials[static_cast<std::size_t>(m.material)].kind == MaterialKind::kSkin) {
      skin.grow(mesh_bounds(m));
    }
  }
  return skin.empty() ? 0.0f : skin.extent().y;
}

}  // namespace

std::string describe_scale(const Scene& scene) {
  if (!scene.head) {
    return fmt::format("no head measured; the skin's bounding box is {:.4g} units tall",
                       box_height(scene));
  }
  const HeadLandmarks& h = *scene.head;
  return fmt::format(
      "head {:.4g} units crown to chin (crown y {:.4g}, chin y {:.4g}), {:.4g} mm at {:.4g} "
      "units/mm; a {} mm head would be {:.3g} units/mm",
      h.height(), h.crown.y, h.chin.y, h.height() / scene.units_per_mm, scene.units_per_mm,
      kTypicalHeadMm, h.height() / kTypicalHeadMm);
}

void size_scene(Scene& scene, float given_units_per_mm,
                const std::function<void(const std::string&)>& warn) {
  const HeadMeasure measure = measure_head(scene);
  scene.head = measure.head;
  const float height = scene.head ? scene.head->height() : box_height(scene);
  const std::string what =
      scene.head ? fmt::format("the head is {:.4g} units from crown to chin", height)
                 : fmt::format(
                       "no head found in the skin ({}); its bounding box is {:.4g} units tall, "
                       "more than the head if it is a bust",
                       measure.why_not, height);
  if (given_units_per_mm > 0.0f) {
    scene.units_per_mm = given_units_per_mm;
    scene.units_source = UnitsSource::kGiven;
    const float mm = height / given_units_per_mm;
    if (plausible(mm) || !(height > 0.0f)) return;  // right, or no skin to judge by
    warn(fmt::format(
        "{}: {}, {:.4g} mm at --units-per-mm {:.4g}; a human head is about 200-250 mm, so "
        "diffusion widths will be off. If this is a life-size head, pass --units-per-mm {:.3g} "
        "(= {:.4g} units / {} mm)",
        scene.source, what, mm, given_units_per_mm, height / kTypicalHeadMm, height,
        kTypicalHeadMm));
    return;
  }
  // glTF's metres, when they give a plausible head (or there is no skin to measure).
  if (plausible(height / 0.001f) || !(height > 0.0f)) {
    scene.units_per_mm = 0.001f;
    scene.units_source = UnitsSource::kFile;
    return;
  }
  scene.units_per_mm = height / kTypicalHeadMm;
  scene.units_source = scene.head ? UnitsSource::kHeadHeight : UnitsSource::kBoxHeight;
  warn(fmt::format(
      "{}: {}, {:.4g} mm in glTF's metres; sized as a life-size head instead: {:.3g} units/mm "
      "(= {:.4g} units / {} mm, a typical head). Pass --units-per-mm to set the scale yourself",
      scene.source, what, height / 0.001f, scene.units_per_mm, height, kTypicalHeadMm));
}

}  // namespace skinsim::scene
