#pragma once
// How a frame is lit and finished, beside what is drawn (render/draw_list.hpp): the finish of
// each surface, and the picture-wide features that each cost time and can be switched off. In
// core/ because the scene states them and the renderer uses them.
#include <optional>
#include <string_view>

namespace dinam {

// A surface's finish, for a microfacet (GGX) highlight over a diffuse base.
struct Finish {
  float roughness = 0.45f;  // 0 mirror-like … 1 chalky
  float metallic = 0.0f;    // 1: the highlight takes the base colour and there is no diffuse
  float sheen = 0.0f;       // a soft glow at grazing angles, as the fibres of cloth give

  bool operator==(const Finish&) const = default;
};

// How a drawn surface takes the light across its edges (`shading`): smooth everywhere (normals
// shared by the faces at each node, and the surface subdivided), flat (each face its own normal,
// drawn as modelled), or smooth but for the edges whose faces meet at more than `sharp_angle`
// (a cylinder's rim: Blender's Auto Smooth), drawn as modelled.
enum class Shading { kSmooth, kFlat, kAuto };
inline constexpr double kDefaultSharpAngle = 30.0;  // degrees, Blender's Auto Smooth default

// The word a scene and a cache's manifest write for each shading, and back (none for another
// word).
inline const char* shading_name(Shading shading) {
  switch (shading) {
    case Shading::kFlat:
      return "flat";
    case Shading::kAuto:
      return "auto";
    case Shading::kSmooth:
      break;
  }
  return "smooth";
}
inline std::optional<Shading> shading_named(std::string_view name) {
  for (const Shading shading : {Shading::kSmooth, Shading::kFlat, Shading::kAuto}) {
    if (name == shading_name(shading)) {
      return shading;
    }
  }
  return std::nullopt;
}

// Picture-wide features, each off or on.
struct LookSettings {
  // Percentage-closer soft shadows: a penumbra that widens with the distance from the occluder,
  // for a sun of DrawList::light_size. Off: a 3×3 filtered edge of constant width.
  bool soft_shadows = false;
  // Off, a hard shadow's edge is filtered over one texel of the map instead of three (draft).
  bool filtered_shadow_edges = true;
  // Screen-space ambient occlusion: ambient light is dimmed where other surfaces are near, so
  // that a wire on the ground or on another wire reads as touching it.
  bool ambient_occlusion = false;
  // Light from the sky and bounced off the ground by the direction a surface faces, with the
  // sky's reflection in glossy and metallic finishes. Off: a flat, colourless ambient.
  bool sky_light = true;
  // Filmic tone mapping (the ACES fit of Narkowicz): highlights roll off instead of clipping.
  // Off: linear colour clipped at white.
  bool tone_mapping = true;
  float exposure = 0.0f;  // stops; +1 doubles the light
  // No sky: where nothing is drawn the frame is transparent, and its alpha is how much of each
  // pixel what is drawn covers, with colours not darkened by it (straight alpha), for compositing
  // over another picture. Off: opaque everywhere.
  bool transparent_background = false;
};

}  // namespace dinam
