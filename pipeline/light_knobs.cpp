// The knob rows for light and framing, shadows and transmission: every technique uses them
// (appended to common_knobs()).
#include "pipeline/light_knobs.h"

#include "pipeline/knob_types.h"

namespace skinsim::pipeline {

namespace {

bool has_shadows(const PipelineConfig& c) {
  return c.shadows;
}

KnobSpec shadow_knob(KnobSpec k) {
  k.applies = has_shadows;
  return k;
}

}  // namespace

std::vector<KnobSpec> light_knobs() {
  KnobSpec shadows =
      switch_knob("shadows", "--shadows", "Key-light shadows from a depth-only shadow-map pass",
                  &PipelineConfig::shadows);
  shadows.decides = true;
  KnobSpec taps =
      integer_knob("shadow_taps", "--shadow-taps",
                   "Shadow-map fetches per pixel (PCF), on a square grid one texel apart",
                   &PipelineConfig::shadow_taps, 1, 16);
  taps.values = "1, 4, 9 or 16";
  taps.invalid = [](const PipelineConfig& c) -> std::string {
    for (const int n : {1, 4, 9, 16}) {
      if (c.shadow_taps == n) return "";
    }
    return "shadow_taps must be 1, 4, 9 or 16 (a square grid), got " +
           std::to_string(c.shadow_taps);
  };
  return {
      shapes_reference(
          optional_real_knob("light_azimuth_deg", "--light-azimuth",
                             "Key light direction around the up axis in degrees, 0 = from the "
                             "camera's side of the face, 90 = from the picture's right (auto: the "
                             "scene's)",
                             &PipelineConfig::light_azimuth_deg, {-180.0, 180.0})),
      shapes_reference(
          optional_real_knob("light_elevation_deg", "--light-elevation",
                             "Key light elevation above the horizon in degrees (auto: the scene's)",
                             &PipelineConfig::light_elevation_deg, {-89.0, 89.0})),
      shapes_reference(
          optional_real_knob("back_light", "--back-light",
                             "Back (rim) light strength: 1 = the studio rim light behind the head, "
                             "0 = none (auto: the scene's)",
                             &PipelineConfig::back_light, {0.0, 10.0})),
      shapes_reference(
          optional_real_knob("camera_distance_m", "--camera-distance",
                             "Camera distance to the head's centre (a scan's measured head, else "
                             "the skin's) in metres (auto: the scene's)",
                             &PipelineConfig::camera_distance_m, {0.05, 1000.0, true, false})),
      shapes_reference(real_knob("camera_yaw_deg", "--camera-yaw",
                                 "Camera orbit around the head's centre about the up axis, degrees",
                                 &PipelineConfig::camera_yaw_deg, {-180.0, 180.0})),
      std::move(shadows),
      shadow_knob(integer_knob("shadow_map_size", "--shadow-map-size",
                               "Shadow map size per axis (texels)",
                               &PipelineConfig::shadow_map_size, 64, 4096, true)),
      shadow_knob(choice_knob("shadow_filter", "--shadow-filter",
                              "Shadow-map fetch: one texel compared, or the 2x2 hardware-filtered "
                              "comparison of iOS shadow samplers",
                              "nearest or pcf2x2", &PipelineConfig::shadow_filter,
                              parse_shadow_filter, shadow_filter_name)),
      shadow_knob(std::move(taps)),
      shadow_knob(choice_knob("shadow_depth", "--shadow-depth",
                              "Shadow-map depth format (OES_depth_texture: 16 or 24 bits)",
                              "depth16 or depth24", &PipelineConfig::shadow_depth,
                              parse_shadow_depth, shadow_depth_name)),
      shadow_knob(optional_rgb_knob("shadow_tint", "--shadow-tint",
                                    "Light left in full shadow per channel, a dark skin colour "
                                    "(URP skin shadow tint; auto: none, black shadows)",
                                    &PipelineConfig::shadow_tint, {0.0, 1.0})),
      switch_knob("transmission", "--transmission",
                  "Light through thin parts (ears, nostrils) from behind, from the baked "
                  "thickness and the profile's transmittance",
                  &PipelineConfig::transmission),
  };
}

}  // namespace skinsim::pipeline
