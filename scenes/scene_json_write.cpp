// Writer of the scene JSON format (see scene_json.h): the inverse of the reader, so that reading what it writes
// gives an equal document. Floats are written in their shortest form that reads back to the same float.
#include <charconv>
#include <cstdlib>

#include <nlohmann/json.hpp>

#include "scenes/scene_error.h"
#include "scenes/scene_json.h"

namespace scenes {
namespace {

using Json = nlohmann::ordered_json;

// The double whose shortest decimal form is the float's shortest form: prints as "0.3", reads back as 0.3f.
double exact(float f) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, f);
  *r.ptr = '\0';
  return std::strtod(buf, nullptr);
}

Json vec(const float* v, int n) {
  Json a = Json::array();
  for (int i = 0; i < n; ++i) a.push_back(exact(v[i]));
  return a;
}
Json vec(const glm::vec2& v) { return vec(&v.x, 2); }
Json vec(const glm::vec3& v) { return vec(&v.x, 3); }
Json vec(const glm::vec4& v) { return vec(&v.x, 4); }

Json transform_json(const TransformDesc& t) {
  Json j = Json::object();
  if (t.matrix) {
    Json m = Json::array();
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m.push_back(exact((*t.matrix)[c][r]));
    j["matrix"] = m;
    return j;
  }
  if (t.translate != glm::vec3(0.0f)) j["translate"] = vec(t.translate);
  if (t.quaternion) {
    const glm::quat& q = *t.quaternion;
    j["quaternion"] = vec(glm::vec4(q.x, q.y, q.z, q.w));  // glTF order
  }
  else if (t.rotate_deg != glm::vec3(0.0f)) j["rotate"] = vec(t.rotate_deg);
  if (t.scale != glm::vec3(1.0f)) j["scale"] = vec(t.scale);
  return j;
}

Json shape_json(const Shape& shape) {
  Json j;
  j["type"] = std::string(shape_name(shape));
  std::visit(
      [&](const auto& s) {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, PlaneShape>) {
          j["size"] = vec(s.size);
          j["segments"] = s.segments;
        } else if constexpr (std::is_same_v<S, BoxShape>) {
          j["size"] = vec(s.size);
        } else if constexpr (std::is_same_v<S, SphereShape>) {
          j["radius"] = exact(s.radius);
          j["segments"] = s.segments;
          j["rings"] = s.rings;
        } else if constexpr (std::is_same_v<S, CylinderShape>) {
          j["radius"] = exact(s.radius);
          j["height"] = exact(s.height);
          j["segments"] = s.segments;
          j["caps"] = s.caps;
        } else if constexpr (std::is_same_v<S, ConeShape>) {
          j["radius"] = exact(s.radius);
          j["height"] = exact(s.height);
          j["segments"] = s.segments;
          j["cap"] = s.cap;
        } else if constexpr (std::is_same_v<S, RoomShape>) {
          j["size"] = vec(s.size);
          j["wall"] = exact(s.wall);
          Json sides = Json::array();
          const auto names = room_side_names();
          for (size_t i = 0; i < names.size(); ++i)
            if (s.sides & (1u << i)) sides.push_back(std::string(names[i].name));
          j["sides"] = sides;
        } else {
          j["size"] = vec(s.size);
          j["resolution"] = s.resolution;
          j["amplitude"] = exact(s.amplitude);
          j["wavelength"] = exact(s.wavelength);
          j["seed"] = s.seed;
        }
      },
      shape);
  return j;
}

Json mesh_json(const Mesh& m) {
  Json j;
  if (!m.name.empty()) j["name"] = m.name;
  auto flat = [](const auto& vs, int n) {
    Json a = Json::array();
    for (const auto& v : vs)
      for (int c = 0; c < n; ++c) a.push_back(exact((&v.x)[c]));
    return a;
  };
  j["positions"] = flat(m.positions, 3);
  if (!m.normals.empty()) j["normals"] = flat(m.normals, 3);
  if (!m.texcoords.empty()) j["texcoords"] = flat(m.texcoords, 2);
  j["indices"] = m.indices;
  return j;
}

Json object_json(const ObjectDesc& o) {
  Json j;
  if (!o.name.empty()) j["name"] = o.name;
  if (const auto* shape = std::get_if<Shape>(&o.source)) j["primitive"] = shape_json(*shape);
  if (const auto* ref = std::get_if<GltfRef>(&o.source)) {
    if (ref->import_cameras && ref->import_lights) j["gltf"] = ref->path;
    else j["gltf"] = Json{{"path", ref->path}, {"cameras", ref->import_cameras}, {"lights", ref->import_lights}};
  }
  if (const auto* mesh = std::get_if<Mesh>(&o.source)) j["mesh"] = mesh_json(*mesh);
  if (Json t = transform_json(o.transform); !t.empty()) j["transform"] = t;
  if (o.material) j["material"] = *o.material;
  if (o.casts_shadows) j["casts_shadows"] = *o.casts_shadows;
  if (o.receives_shadows) j["receives_shadows"] = *o.receives_shadows;
  if (!o.children.empty()) {
    Json children = Json::array();
    for (const ObjectDesc& c : o.children) children.push_back(object_json(c));
    j["children"] = children;
  }
  return j;
}

Json material_json(const Material& m) {
  Json j;
  j["name"] = m.name;
  j["base_color"] = vec(m.base_color);
  if (!m.texture.empty()) j["texture"] = m.texture;
  j["specular_color"] = vec(m.specular_color);
  j["specular_strength"] = exact(m.specular_strength);
  j["shininess"] = exact(m.shininess);
  j["double_sided"] = m.double_sided;
  if (m.alpha_mode != AlphaMode::opaque) {
    j["alpha_mode"] = m.alpha_mode == AlphaMode::mask ? "mask" : "blend";
    j["alpha_cutoff"] = exact(m.alpha_cutoff);
  }
  return j;
}

Json camera_json(const Camera& c) {
  Json j;
  if (!c.name.empty()) j["name"] = c.name;
  j["position"] = vec(c.position);
  j["target"] = vec(c.target);
  j["up"] = vec(c.up);
  if (const auto* p = std::get_if<Perspective>(&c.projection)) {
    Json pj;
    pj["fovy"] = exact(p->fovy_deg);
    if (p->aspect) pj["aspect"] = exact(*p->aspect);
    pj["near"] = exact(p->near);
    pj["far"] = exact(p->far);
    j["perspective"] = pj;
  } else {
    const auto& o = std::get<Orthographic>(c.projection);
    j["orthographic"] = Json{{"left", exact(o.left)}, {"right", exact(o.right)}, {"bottom", exact(o.bottom)},
                             {"top", exact(o.top)},   {"near", exact(o.near)},   {"far", exact(o.far)}};
  }
  return j;
}

Json shadow_json(const ShadowSettings& s) {
  Json j;
  j["technique"] = std::string(to_string(s.technique));
  j["filter"] = std::string(to_string(s.filter));
  const BiasSettings& b = s.bias;
  j["bias"] = Json{{"mode", std::string(to_string(b.mode))},   {"constant", exact(b.constant)},
                   {"slope", exact(b.slope)},                  {"slope_max", exact(b.slope_max)},
                   {"offset_factor", exact(b.offset_factor)},  {"offset_units", exact(b.offset_units)},
                   {"normal_offset", exact(b.normal_offset)}};
  j["cull_front"] = s.cull_front;
  j["map_size"] = s.map_size;
  j["depth_format"] = std::string(raster::to_string(s.depth_format));
  j["poisson_taps"] = s.poisson_taps;
  j["poisson_spread"] = exact(s.poisson_spread);
  if (!s.params.empty()) {
    Json p = Json::object();
    for (const auto& param : s.params)  // not a structured binding: clang 14 cannot capture one in a lambda
      std::visit([&](const auto& v) { p[param.first] = v; }, param.second);
    j["params"] = p;
  }
  return j;
}

Json light_json(const Light& l) {
  Json j;
  if (!l.name.empty()) j["name"] = l.name;
  j["type"] = std::string(to_string(l.type));
  j["color"] = vec(l.color);
  j["intensity"] = exact(l.intensity);
  if (l.type != LightType::directional) j["position"] = vec(l.position);
  if (l.type != LightType::point) j["direction"] = vec(l.direction);
  if (l.type == LightType::spot) {
    j["inner_cone"] = exact(l.inner_cone_deg);
    j["outer_cone"] = exact(l.outer_cone_deg);
  }
  if (l.type != LightType::directional) j["range"] = exact(l.range);
  j["shadow"] = shadow_json(l.shadow);
  return j;
}

Json background_json(const Background& b) {
  for (const NamedBackground& n : kBackgrounds)
    if (n.background == b) return std::string(n.name);
  if (b.top == b.bottom) return vec(b.top);
  return Json{{"top", vec(b.top)}, {"bottom", vec(b.bottom)}};
}

// Two-space indented JSON with arrays of numbers and strings kept on one line (twelve items per line when long),
// so vectors and matrices read as they are meant.
void pretty(const Json& v, int indent, std::string& out) {
  const std::string pad(size_t(indent), ' ');
  if (v.is_object() && !v.empty()) {
    out += "{\n";
    size_t i = 0;
    for (const auto& [key, value] : v.items()) {
      out += pad + "  " + Json(key).dump() + ": ";
      pretty(value, indent + 2, out);
      out += ++i < v.size() ? ",\n" : "\n";
    }
    out += pad + "}";
  } else if (v.is_array() && !v.empty()) {
    bool flat = true;
    for (const Json& e : v) flat = flat && !e.is_structured();
    out += flat && v.size() > 12 ? "[\n" + pad + "  " : (flat ? "[" : "[\n");
    for (size_t i = 0; i < v.size(); ++i) {
      if (!flat) out += pad + "  ";
      if (flat) out += v[i].dump();
      else pretty(v[i], indent + 2, out);
      if (i + 1 < v.size()) out += !flat ? ",\n" : (v.size() > 12 && (i + 1) % 12 == 0 ? ",\n" + pad + "  " : ", ");
    }
    out += flat ? (v.size() > 12 ? "\n" + pad + "]" : "]") : "\n" + pad + "]";
  } else {
    out += v.dump();
  }
}

template <typename T, typename F>
Json array_of(const std::vector<T>& items, F&& f) {
  Json a = Json::array();
  for (const T& item : items) a.push_back(f(item));
  return a;
}

}  // namespace

std::string scene_json_text(const SceneDesc& d) {
  Json j;
  j["version"] = kSceneFormatVersion;
  if (!d.name.empty()) j["name"] = d.name;
  if (!d.description.empty()) j["description"] = d.description;
  if (!d.materials.empty()) j["materials"] = array_of(d.materials, material_json);
  j["objects"] = array_of(d.objects, object_json);
  if (!d.cameras.empty()) j["cameras"] = array_of(d.cameras, camera_json);
  if (!d.lights.empty()) j["lights"] = array_of(d.lights, light_json);
  j["exposure"] = d.look.exposure.ev100 ? Json(exact(*d.look.exposure.ev100)) : Json("auto");
  j["tonemap"] = std::string(shading::tone_map_name(d.look.tone_map));
  j["background"] = background_json(d.look.background);
  std::string out;
  pretty(j, 0, out);
  return out + "\n";
}

}  // namespace scenes
