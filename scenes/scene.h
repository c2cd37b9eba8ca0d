// The scene model the renderer draws: triangle meshes, instances placing them in the world, materials,
// cameras and lights with their shadow settings. Plain structs with no behaviour; built by the JSON loader,
// the glTF importer and the built-in scenes (scene_build.h), queried through scene_queries.h.
// Units are metres; the world is right-handed with +Y up (CONVENTIONS.md).
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/look.h"
#include "scenes/shadow_settings.h"

namespace scenes {

// A triangle list in model space. Front faces are counter-clockwise. `normals` always has one entry per
// position once a scene is built; `texcoords` is empty or has one entry per position, in GL's (s, t)
// orientation: t = 0 is the bottom row of the picture as a viewer shows it (the glTF importer turns v into
// 1 − v).
struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> texcoords;
  std::vector<uint32_t> indices;  // three per triangle
  size_t triangle_count() const { return indices.size() / 3; }
  bool operator==(const Mesh&) const = default;
};

// How a material's alpha (base-colour factor alpha × texture alpha) decides coverage, as glTF's alphaMode:
// opaque ignores it; mask keeps a fragment where alpha >= alpha_cutoff and discards it elsewhere, in the camera
// pass and in every shadow depth pass; blend is drawn as mask with a cutoff of 0.5 everywhere (the renderer has
// no sorted transparency, and a shadow map stores one depth per texel).
enum class AlphaMode : uint8_t { opaque, mask, blend };

// GL wrap modes a glTF sampler can name for a material texture.
enum class TextureWrap : uint8_t { repeat, clamp_to_edge, mirrored_repeat };

// Blinn-Phong style surface description. `texture` is a path (empty: none); the scenes module never opens it
// (scenes/io/scene_textures.h loads every material's texture once per scene).
// A texture image that a glTF file carries inside itself (a buffer view of a GLB's binary chunk, or a data:
// URI), kept encoded as stored (PNG or JPEG) until scenes/io decodes it with the other textures.
struct EmbeddedImage {
  std::string file;            // the glTF file holding it, as errors name that file
  std::string where;           // its place in that file: "images[3]"
  std::vector<uint8_t> bytes;  // the encoded image
  bool operator==(const EmbeddedImage&) const = default;
};

// One embedded image shared by every material (and every copy of a scene) that uses it; equal when the
// images are, so that scenes compare by content.
struct EmbeddedImageRef {
  std::shared_ptr<const EmbeddedImage> image;
  explicit operator bool() const { return image != nullptr; }
  bool operator==(const EmbeddedImageRef& o) const {
    return image == o.image || (image && o.image && *image == *o.image);
  }
};

struct Material {
  std::string name = "default";
  glm::vec4 base_color{1.0f};       // linear RGBA factor (multiplies the texture when there is one)
  // Base-colour texture: a path, resolved against the file that named it; or, for an image embedded in a glTF
  // file, "FILE#images[N]", with the image itself in `embedded_texture`.
  std::string texture;
  EmbeddedImageRef embedded_texture;
  // Applied to the mesh's texture coordinates (s, t, 1) before the texture is sampled: glTF's
  // KHR_texture_transform, taken into the GL orientation of Mesh::texcoords.
  glm::mat3 texture_transform{1.0f};
  TextureWrap wrap_s = TextureWrap::repeat, wrap_t = TextureWrap::repeat;
  AlphaMode alpha_mode = AlphaMode::opaque;
  float alpha_cutoff = 0.5f;        // mask: the least alpha kept
  glm::vec3 specular_color{1.0f};
  float specular_strength = 0.3f;   // specular = specular_color * specular_strength * pow(cos, shininess)
  float shininess = 5.0f;
  bool double_sided = false;        // glTF doubleSided: do not back-face cull when drawing the colour pass
  bool operator==(const Material&) const = default;
};

// One mesh placed in the world. A mesh's winding is already flipped where the transform mirrors
// (determinant < 0), so world-space front faces are counter-clockwise for every instance.
struct Instance {
  std::string name;
  uint32_t mesh = 0;        // index into Scene::meshes
  uint32_t material = 0;    // index into Scene::materials
  uint32_t object = 0;      // the top-level scene object it belongs to (Scene::objects): one caster each
  glm::mat4 transform{1.0f};
  bool casts_shadows = true;
  bool receives_shadows = true;
  bool operator==(const Instance&) const = default;
};

struct Perspective {
  float fovy_deg = 45.0f;         // full vertical field of view, degrees
  std::optional<float> aspect;    // width / height; none: the viewport's
  float near = 0.1f;
  float far = 100.0f;
  bool operator==(const Perspective&) const = default;
};

struct Orthographic {
  float left = -1.0f, right = 1.0f, bottom = -1.0f, top = 1.0f;
  float near = 0.1f, far = 100.0f;
  bool operator==(const Orthographic&) const = default;
};

// A camera looking from `position` at `target`; view = glm::lookAt(position, target, up).
struct Camera {
  std::string name;
  glm::vec3 position{0.0f, 0.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  std::variant<Perspective, Orthographic> projection;
  bool operator==(const Camera&) const = default;
};

// A light. `direction` is always the direction the light TRAVELS (from the light into the scene), as in glTF
// and for the axis of a spot: the tutorial's "light towards (0.5, 2, 2)" is direction = -normalize(0.5, 2, 2).
// to_light() gives the opposite. In a built scene `direction` is unit length and `range` is positive.
struct Light {
  std::string name;
  LightType type = LightType::directional;
  glm::vec3 color{1.0f};
  float intensity = 1.0f;                     // glTF KHR_lights_punctual units: candela (spot, point,
                                              // hemispherical) or lux (directional)
  glm::vec3 position{0.0f};                   // spot, point, hemispherical
  glm::vec3 direction{0.0f, -1.0f, 0.0f};     // directional, spot, hemispherical (the way it faces)
  float inner_cone_deg = 20.0f;               // spot: half-angles from the axis, degrees
  float outer_cone_deg = 25.0f;
  float range = 0.0f;                         // spot, point, hemispherical: metres; 0 in a file: scene extent
  ShadowSettings shadow;
  bool operator==(const Light&) const = default;
};

inline glm::vec3 to_light(const Light& light) { return -light.direction; }

// A whole scene. `objects` names the top-level objects (a JSON object, a glTF file, a built-in figure);
// instances refer to them so per-caster techniques can treat each as one caster.
struct Scene {
  std::string name;
  std::string description;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Instance> instances;
  std::vector<std::string> objects;
  std::vector<Camera> cameras;   // the first is the default view
  std::vector<Light> lights;
  Look look;                     // exposure, tone map and background
  std::vector<std::string> warnings;  // repairs made while loading (e.g. non-finite normals replaced)
  // The top-level object staging added as the ground under a bare model (scenes/stage.h): a camera framing the
  // model leaves it out.
  std::optional<uint32_t> staged_ground;
  bool operator==(const Scene&) const = default;
};

}  // namespace scenes
