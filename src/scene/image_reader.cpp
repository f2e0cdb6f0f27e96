// The scene's `image` (size, quality preset, picture features, motion blur) and an object's
// `finish` (docs/scene-format.md, "image" and "objects").
#include <array>
#include <cmath>
#include <string_view>

#include "scene/element_readers.hpp"

namespace dinam {
namespace {

struct NamedFinish {
  std::string_view name;
  Finish finish;
};

// The finishes an object can name: what each material looks like under the sun and the sky.
constexpr std::array<NamedFinish, 6> kFinishes = {{
    {"plastic", {0.45f, 0.0f, 0.0f}},
    {"metal", {0.28f, 1.0f, 0.0f}},
    {"rope", {0.9f, 0.0f, 0.6f}},
    {"rubber", {0.65f, 0.0f, 0.0f}},
    {"cloth", {0.85f, 0.0f, 0.8f}},
    {"matte", {1.0f, 0.0f, 0.0f}},
}};

std::string finish_names() {
  std::string names;
  for (const NamedFinish& f : kFinishes) {
    names += (names.empty() ? "" : ", ") + std::string(f.name);
  }
  return names;
}

float fraction(YamlMap& map, const std::string& key, float fallback) {
  const double value = map.number(key, fallback);
  if (!(value >= 0.0 && value <= 1.0)) {
    throw_user_error(map.loc(key), "'{}' must be between 0 and 1, got {}", map.path(key), value);
  }
  return static_cast<float>(value);
}

MotionBlurDesc read_motion_blur(const YAML::Node& node, const std::string& file,
                                MotionBlurDesc blur) {
  if (node.IsScalar()) {
    if (!as_bool(node, file, "image.motion_blur")) {
      blur.samples = 1;
      return blur;
    }
    blur.samples = std::max(blur.samples, 8);
    return blur;
  }
  YamlMap map(node, file, "image.motion_blur");
  blur.samples = map.integer("samples", blur.enabled() ? blur.samples : 8);
  blur.shutter = map.number("shutter", blur.shutter);
  map.finish();
  if (blur.samples < 1 || blur.samples > 64) {
    throw_user_error(map.loc("samples"),
                     "'image.motion_blur.samples' must be between 1 (no blur) and 64, got {}",
                     blur.samples);
  }
  if (!(blur.shutter > 0.0 && blur.shutter <= 1.0)) {
    throw_user_error(map.loc("shutter"),
                     "'image.motion_blur.shutter' is the fraction of the frame interval the "
                     "shutter stays open, in (0, 1]; got {} (0.5 is a film camera's 180°)",
                     blur.shutter);
  }
  return blur;
}

}  // namespace

RenderQualityDesc quality_preset(QualityPreset preset) {
  RenderQualityDesc quality;
  quality.preset = preset;
  switch (preset) {
    case QualityPreset::kDraft:
      quality.samples = 1;
      quality.shadow_resolution = 1024;
      quality.look.filtered_shadow_edges = false;
      break;
    case QualityPreset::kStandard:
      break;
    case QualityPreset::kFinal:
      quality.look.soft_shadows = true;
      quality.look.ambient_occlusion = true;
      quality.motion_blur.samples = 8;
      break;
  }
  return quality;
}

Finish read_finish(const YAML::Node& node, const std::string& file, const std::string& what) {
  if (node.IsScalar()) {
    const std::string name = as_string(node, file, what);
    for (const NamedFinish& f : kFinishes) {
      if (f.name == name) {
        return f.finish;
      }
    }
    throw_user_error(loc_of(node, file),
                     "'{}' names no finish: '{}'; use one of {}, or give "
                     "{{roughness, metallic, sheen}}",
                     what, name, finish_names());
  }
  YamlMap map(node, file, what);
  Finish finish;
  if (map.has("like")) {
    finish = read_finish(map.get("like"), file, map.path("like"));
  }
  finish.roughness = fraction(map, "roughness", finish.roughness);
  finish.metallic = fraction(map, "metallic", finish.metallic);
  finish.sheen = fraction(map, "sheen", finish.sheen);
  map.finish();
  return finish;
}

void read_image(YamlMap image, SceneDescription& scene) {
  if (image.has("quality")) {
    const std::string name = image.string("quality", "standard");
    if (name == "draft") {
      scene.quality = quality_preset(QualityPreset::kDraft);
    } else if (name == "standard") {
      scene.quality = quality_preset(QualityPreset::kStandard);
    } else if (name == "final") {
      scene.quality = quality_preset(QualityPreset::kFinal);
    } else {
      throw_user_error(image.loc("quality"),
                       "'image.quality' must be draft, standard or final; got '{}'", name);
    }
  }
  RenderQualityDesc& quality = scene.quality;
  scene.image_width = image.integer("width", scene.image_width);
  scene.image_height = image.integer("height", scene.image_height);
  for (const char* key : {"width", "height"}) {
    const int n = std::string(key) == "width" ? scene.image_width : scene.image_height;
    if (n < 16 || n > 8192) {
      throw_user_error(image.loc(key), "'image.{}' must be between 16 and 8192 pixels, got {}", key,
                       n);
    }
  }
  quality.samples = image.integer("samples", quality.samples);
  if (quality.samples < 1 || quality.samples > 16) {
    throw_user_error(image.loc("samples"), "'image.samples' must be between 1 and 16, got {}",
                     quality.samples);
  }
  quality.shadows = image.boolean("shadows", quality.shadows);
  quality.shadow_resolution = image.integer("shadow_resolution", quality.shadow_resolution);
  if (quality.shadow_resolution < 64 || quality.shadow_resolution > 8192) {
    throw_user_error(image.loc("shadow_resolution"),
                     "'image.shadow_resolution' must be between 64 and 8192, got {}",
                     quality.shadow_resolution);
  }
  LookSettings& look = quality.look;
  look.soft_shadows = image.boolean("soft_shadows", look.soft_shadows);
  look.ambient_occlusion = image.boolean("ambient_occlusion", look.ambient_occlusion);
  look.sky_light = image.boolean("sky_light", look.sky_light);
  const std::string tone = image.string("tone_mapping", look.tone_mapping ? "filmic" : "none");
  if (tone != "filmic" && tone != "none") {
    throw_user_error(image.loc("tone_mapping"),
                     "'image.tone_mapping' must be filmic or none; "
                     "got '{}'",
                     tone);
  }
  look.tone_mapping = tone == "filmic";
  const double exposure = image.number("exposure", look.exposure);
  if (!(std::abs(exposure) <= 10.0)) {
    throw_user_error(image.loc("exposure"),
                     "'image.exposure' is in stops (+1 doubles the light), within ±10; got {}",
                     exposure);
  }
  look.exposure = static_cast<float>(exposure);
  const std::string background = image.string("background", "sky");
  if (background != "sky" && background != "transparent") {
    throw_user_error(image.loc("background"),
                     "'image.background' must be sky or transparent; got '{}'", background);
  }
  look.transparent_background = background == "transparent";
  if (image.has("motion_blur")) {
    quality.motion_blur =
        read_motion_blur(image.get("motion_blur"), image.file(), quality.motion_blur);
  }
  image.finish();
}

}  // namespace dinam
