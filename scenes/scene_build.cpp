// Scene document -> Scene (see scene_build.h): walks the object hierarchy composing transforms and inherited
// flags, generates or imports geometry, then fixes mirrored winding and completes cameras and lights.
#include "scenes/scene_build.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <cctype>
#include <cerrno>
#include <system_error>
#include <map>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_access.hpp>

#include "scenes/camera_math.h"
#include "scenes/gltf_import.h"
#include "scenes/mesh_ops.h"
#include "scenes/primitives.h"
#include "scenes/scene_error.h"
#include "scenes/scene_json.h"
#include "scenes/scene_queries.h"

namespace scenes {
namespace {

// Why a file cannot be opened (worded like strerror), or nothing.
std::optional<std::string> unreadable(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) return std::generic_category().message(ENOENT);
  if (!std::filesystem::is_regular_file(status)) return std::string("not a regular file");
  return std::nullopt;
}

// What a child inherits from its parent.
struct Inherited {
  glm::mat4 transform{1.0f};
  std::optional<uint32_t> material;
  bool casts = true;
  bool receives = true;
};

class Builder {
 public:
  Builder(const SceneDesc& desc, const BuildContext& ctx) : desc_(desc), ctx_(ctx) {}

  Scene run() {
    out_.name = desc_.name;
    out_.description = desc_.description;
    out_.look = desc_.look;
    for (const Material& m : desc_.materials) {
      Material copy = m;
      if (!copy.texture.empty()) copy.texture = resolve(copy.texture).generic_string();
      material_index_[copy.name] = uint32_t(out_.materials.size());
      out_.materials.push_back(copy);
    }
    for (size_t i = 0; i < desc_.objects.size(); ++i) {
      const ObjectDesc& o = desc_.objects[i];
      out_.objects.push_back(o.name.empty() ? "object " + std::to_string(i) : o.name);
      add(o, Inherited{}, uint32_t(i), "objects[" + std::to_string(i) + "]");
    }
    if (out_.instances.empty()) fail("objects", "the scene has no triangles");
    if (!any_triangle_with_area())
      fail("objects", "every triangle of the scene has zero area: nothing would be drawn or cast a shadow");
    check_float_steps();
    flip_mirrored();
    finish_cameras();
    finish_lights();
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw SceneError(ctx_.file, ctx_.wraps_model && key.rfind("objects", 0) == 0 ? std::string() : key, message);
  }

  // Vertices are 32-bit floats, which step by 2^-23 of their magnitude: a scene far from the origin for its size
  // (a 1 m model at 1e30 m, whose steps are 1.2e23 m) collapses, and its camera, a few sizes away, cannot be told
  // from its target, so the frame came out empty with no word. Refused where a step exceeds 1/64 of the scene's
  // size (a 1 m model at 500 km; 6 cm steps on it); a 10 km terrain still fits 100,000 km out.
  void check_float_steps() const {
    const Aabb b = scene_bounds(out_);
    if (b.empty()) return;
    const glm::dvec3 lo(b.min), hi(b.max);
    const double reach = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y),
                                   std::abs(hi.z)});
    const double size = glm::length(hi - lo), step = reach * 0x1p-23;
    if (step > size / 64.0) {
      char line[320];
      std::snprintf(line, sizeof line,
                    "the scene lies %.3g m from the origin, where 32-bit floats step by %.3g m, too coarse for its "
                    "size of %.3g m: move it nearer the origin",
                    reach, step, size);
      fail("objects", line);
    }
  }

  std::filesystem::path resolve(const std::string& path) const {
    const std::filesystem::path p(path);
    return (p.is_absolute() || ctx_.base_dir.empty() ? p : ctx_.base_dir / p).lexically_normal();
  }

  uint32_t default_material() {
    if (!default_material_) {
      default_material_ = uint32_t(out_.materials.size());
      out_.materials.push_back(Material{});
    }
    return *default_material_;
  }

  bool any_triangle_with_area() const {
    for (const Instance& inst : out_.instances)
      if (has_triangle_with_area(out_.meshes[inst.mesh], inst.transform)) return true;
    return false;
  }

  // An object's own transform must keep it a solid (no zero scale, no matrix of rank below 3) and affine, and
  // with its parents' keep finite numbers: a flattened or overflowing object would vanish without a word.
  void check_transform(const ObjectDesc& o, const glm::mat4& own, const glm::mat4& world, const std::string& key) const {
    const std::string at = key + ".transform";
    if (o.transform.matrix) {
      const glm::mat4& m = *o.transform.matrix;
      if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f)
        fail(at + ".matrix", "not an affine transform: its last row must be 0, 0, 0, 1");
    }
    const double det = glm::determinant(glm::dmat3(glm::mat3(own)));
    if (!(std::abs(det) > 0.0) || !std::isfinite(det))
      fail(at, "is singular: it flattens the object to nothing (a zero scale, or a matrix of rank below 3)");
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite(world[c][r])) fail(at, "takes the object beyond the range of 32-bit floats");
  }

  // Where a mesh of a shape or an inline mesh lands, every corner of its bounds must stay a finite number.
  void check_placement(const Mesh& mesh, const glm::mat4& world, const std::string& key) const {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    for (int k = 0; k < 8; ++k) {
      const glm::vec4 corner = world * glm::vec4(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z, 1.0f);
      if (!std::isfinite(corner.x) || !std::isfinite(corner.y) || !std::isfinite(corner.z))
        fail(key + ".transform", ctx_.wraps_model ? "the model's vertices, placed, lie beyond the range of 32-bit floats"
                                                   : "takes the object's vertices beyond the range of 32-bit floats");
    }
  }

  void add(const ObjectDesc& o, const Inherited& parent, uint32_t object, const std::string& key) {
    Inherited here = parent;
    const glm::mat4 own = transform_matrix(o.transform);
    here.transform = parent.transform * own;
    check_transform(o, own, here.transform, key);
    if (o.material) {
      const auto it = material_index_.find(*o.material);
      if (it == material_index_.end()) fail(key + ".material", "unknown material '" + *o.material + "'");
      here.material = it->second;
    }
    here.casts = o.casts_shadows.value_or(parent.casts);
    here.receives = o.receives_shadows.value_or(parent.receives);
    const std::string name = o.name.empty() ? out_.objects[object] : o.name;

    if (const auto* shape = std::get_if<Shape>(&o.source)) {
      if (auto problem = check_shape(*shape)) {
        const size_t colon = problem->find(": ");
        fail(key + ".primitive." + problem->substr(0, colon), problem->substr(colon + 2));
      }
      const uint32_t mesh = shape_mesh(*shape);
      check_placement(out_.meshes[mesh], here.transform, key);
      add_instance(name, mesh, here, object);
    } else if (const auto* mesh = std::get_if<Mesh>(&o.source)) {
      if (auto problem = mesh_problem(*mesh)) fail(key + ".mesh", *problem);
      // Drawn as any other (issue 23: such triangles get a defined answer), but said, since it shows nothing;
      // a scene of nothing else is an error (run()).
      if (!has_triangle_with_area(*mesh))
        out_.warnings.push_back(ctx_.file + ": " + key + ".mesh: every triangle has zero area (its vertices coincide "
                                "or lie on a line): it draws nothing");
      check_placement(*mesh, here.transform, key);
      Mesh m = *mesh;
      if (m.name.empty()) m.name = name;
      if (const size_t fixed = repair_normals(m))
        out_.warnings.push_back(ctx_.file + ": " + key + ".mesh: " + std::to_string(fixed) + " normals replaced");
      out_.meshes.push_back(std::move(m));
      add_instance(name, uint32_t(out_.meshes.size() - 1), here, object);
    } else if (const auto* ref = std::get_if<GltfRef>(&o.source)) {
      add_gltf(*ref, here, object, name, key + ".gltf");
    }
    for (size_t c = 0; c < o.children.size(); ++c)
      add(o.children[c], here, object, key + ".children[" + std::to_string(c) + "]");
  }

  uint32_t shape_mesh(const Shape& shape) {
    for (const auto& [s, index] : shapes_)
      if (s == shape) return index;
    out_.meshes.push_back(make_shape_mesh(shape));
    shapes_.emplace_back(shape, uint32_t(out_.meshes.size() - 1));
    return shapes_.back().second;
  }

  void add_instance(const std::string& name, uint32_t mesh, const Inherited& h, uint32_t object) {
    Instance inst;
    inst.name = name;
    inst.mesh = mesh;
    inst.material = h.material ? *h.material : default_material();
    inst.object = object;
    inst.transform = h.transform;
    inst.casts_shadows = h.casts;
    inst.receives_shadows = h.receives;
    out_.instances.push_back(inst);
  }

  // Appends a glTF file's meshes (once per file), materials and instances, and its cameras and lights if asked.
  void add_gltf(const GltfRef& ref, const Inherited& h, uint32_t object, const std::string& name,
                const std::string& key) {
    const std::filesystem::path path = resolve(ref.path);
    if (auto problem = unreadable(path)) fail(key, "cannot open '" + path.generic_string() + "' (" + *problem + ")");
    const std::string label = path.generic_string();
    auto it = gltf_.find(label);
    if (it == gltf_.end()) {
      Scene file = import_gltf(path, label);
      Imported imp;
      imp.mesh_base = uint32_t(out_.meshes.size());
      imp.material_base = uint32_t(out_.materials.size());
      for (Mesh& m : file.meshes) out_.meshes.push_back(std::move(m));
      for (Material& m : file.materials) out_.materials.push_back(std::move(m));
      for (std::string& w : file.warnings) out_.warnings.push_back(std::move(w));
      file.meshes.clear();
      file.materials.clear();
      imp.scene = std::move(file);
      it = gltf_.emplace(label, std::move(imp)).first;
    }
    const Imported& imp = it->second;
    for (const Instance& src : imp.scene.instances) {
      Inherited inst_h = h;
      inst_h.transform = h.transform * src.transform;
      if (!h.material) inst_h.material = imp.material_base + src.material;
      add_instance(src.name.empty() ? name : name + "/" + src.name, imp.mesh_base + src.mesh, inst_h, object);
    }
    const glm::mat3 linear(h.transform);
    if (ref.import_cameras)
      for (Camera c : imp.scene.cameras) {
        c.position = glm::vec3(h.transform * glm::vec4(c.position, 1.0f));
        c.target = glm::vec3(h.transform * glm::vec4(c.target, 1.0f));
        c.up = glm::normalize(linear * c.up);
        out_.cameras.push_back(c);
      }
    if (ref.import_lights)
      for (Light l : imp.scene.lights) {
        l.position = glm::vec3(h.transform * glm::vec4(l.position, 1.0f));
        l.direction = linear * l.direction;
        out_.lights.push_back(l);
      }
  }

  // Mirroring transforms turn counter-clockwise triangles clockwise: give those instances a flipped mesh.
  void flip_mirrored() {
    std::map<uint32_t, uint32_t> flipped;
    for (Instance& inst : out_.instances) {
      if (glm::determinant(glm::mat3(inst.transform)) >= 0.0f) continue;
      auto it = flipped.find(inst.mesh);
      if (it == flipped.end()) {
        Mesh m = out_.meshes[inst.mesh];
        flip_winding(m);
        m.name += " (mirrored)";
        out_.meshes.push_back(std::move(m));
        it = flipped.emplace(inst.mesh, uint32_t(out_.meshes.size() - 1)).first;
      }
      inst.mesh = it->second;
    }
  }

  void finish_cameras() {
    std::vector<Camera> cameras = desc_.cameras;
    cameras.insert(cameras.end(), out_.cameras.begin(), out_.cameras.end());
    for (size_t i = 0; i < desc_.cameras.size(); ++i)
      if (auto problem = camera_problem(cameras[i]))
        fail("cameras[" + std::to_string(i) + "]" + (problem->key.empty() ? "" : "." + problem->key), problem->message);
    if (cameras.empty() && ctx_.default_camera) cameras.push_back(frame_camera(scene_bounds(out_)));
    out_.cameras = std::move(cameras);
  }

  void finish_lights() {
    std::vector<Light> lights = desc_.lights;
    lights.insert(lights.end(), out_.lights.begin(), out_.lights.end());
    for (size_t i = 0; i < desc_.lights.size(); ++i)
      if (auto problem = light_problem(lights[i]))
        fail("lights[" + std::to_string(i) + "]" + (problem->key.empty() ? "" : "." + problem->key), problem->message);
    if (lights.empty() && ctx_.default_light) {
      Light sun;
      sun.name = "default";
      sun.direction = -glm::vec3(0.5f, 2.0f, 2.0f);
      sun.shadow = default_shadow_settings(LightType::directional);
      lights.push_back(sun);
    }
    const Aabb bounds = scene_bounds(out_);
    for (size_t i = 0; i < lights.size(); ++i) {
      Light& l = lights[i];
      if (glm::dot(l.direction, l.direction) > 0.0f) l.direction = glm::normalize(l.direction);
      if (l.type == LightType::directional) continue;
      const float fit = reach(l.position, bounds);
      if (l.range <= 0.0f) {
        l.range = fit;
      } else if ((l.type == LightType::point || l.type == LightType::hemispherical) && l.range > kFarRange * fit) {
        // The maps of a point-like light store distance / range, and their biases are in those units: a range
        // far beyond the scene leaves its depths a sliver of the map's values and its biases wide, so shadows
        // go coarse or vanish (3e38 draws none). Drawn as given (the lighting's window is the author's), but said.
        const std::string at = i < desc_.lights.size() ? ctx_.file + ": lights[" + std::to_string(i) + "].range"
                                                        : "light '" + l.name + "': range";
        out_.warnings.push_back(at + ": " + number(l.range) + " m is over " + number(kFarRange) +
                                " times the scene's reach from the light (" + number(fit) +
                                " m); its shadow maps store distance / range, so they lose depth resolution and "
                                "shadows may vanish (0 fits the range to the scene)");
      }
    }
    out_.lights = std::move(lights);
  }

  // A point-like light's range beyond this many times the scene's reach gets a warning (finish_lights).
  static constexpr float kFarRange = 100.0f;
  static std::string number(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", double(v));
    return buf;
  }

  // Distance from p to the farthest corner of a box, a little more, at least a millimetre. In double: the
  // squares of a scene 10^20 m across overflow a float, and an infinite range reads as none at all.
  static float reach(const glm::vec3& p, const Aabb& b) {
    const glm::dvec3 far = glm::max(glm::abs(glm::dvec3(p) - glm::dvec3(b.min)), glm::abs(glm::dvec3(p) - glm::dvec3(b.max)));
    return float(std::clamp(1.01 * glm::length(far), 1e-3, double(std::numeric_limits<float>::max())));
  }

  struct Imported {
    Scene scene;  // instances, cameras and lights in the file's space; meshes and materials moved out
    uint32_t mesh_base = 0, material_base = 0;
  };

  const SceneDesc& desc_;
  const BuildContext& ctx_;
  Scene out_;
  std::map<std::string, uint32_t> material_index_;
  std::optional<uint32_t> default_material_;
  std::vector<std::pair<Shape, uint32_t>> shapes_;
  std::map<std::string, Imported> gltf_;
};

bool is_gltf(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".gltf" || ext == ".glb";
}

}  // namespace

Scene build_scene(const SceneDesc& desc, const BuildContext& context) { return Builder(desc, context).run(); }

Scene load_scene(const std::filesystem::path& path) {
  BuildContext context{path.parent_path(), path.string()};
  if (!is_gltf(path)) return build_scene(load_scene_desc(path), context);
  context.wraps_model = true;
  if (auto problem = unreadable(path)) throw SceneError(path.string(), "", "cannot open file (" + *problem + ")");
  SceneDesc desc;
  desc.name = path.stem().string();
  ObjectDesc model;
  model.name = desc.name;
  model.source = GltfRef{path.filename().string()};
  desc.objects.push_back(model);
  return build_scene(desc, context);
}

}  // namespace scenes
