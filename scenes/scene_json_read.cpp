// Strict reader of the scene JSON format (see scene_json.h and docs/scene-format.md): every object's keys are
// checked against the keys its kind allows, every value against its type and range, before anything is built.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "scenes/json_geometry_read.h"
#include "scenes/json_in.h"
#include "scenes/scene_error.h"
#include "scenes/scene_json.h"

namespace scenes {
namespace {

template <typename T>
T parse_name(const JsonIn& j, std::optional<T> (*parse)(std::string_view), std::span<const NamedEntry> table,
             const char* what) {
  const std::string s = j.string();
  if (auto v = parse(s)) return *v;
  j.fail("unknown " + std::string(what) + " '" + s + "' (known: " + join_names(table) + ")");
}

// Deeper nesting is refused: each level costs a frame here and in the builder, and its key path.
constexpr int kMaxObjectDepth = 256;

ObjectDesc read_object(const JsonIn& j, const std::set<std::string>& materials, const JsonIn& top, int depth = 0) {
  if (depth > kMaxObjectDepth)
    top.fail("children nest deeper than " + std::to_string(kMaxObjectDepth) + " levels");
  j.allow_only({"name", "primitive", "gltf", "mesh", "transform", "material", "casts_shadows", "receives_shadows",
                "children"});
  ObjectDesc o;
  read_opt(j, "name", o.name);
  int sources = 0;
  for (const char* k : {"primitive", "gltf", "mesh"}) sources += j.has(k) ? 1 : 0;
  if (sources > 1) j.fail("give at most one of primitive, gltf and mesh");
  if (auto p = j.optional("primitive")) o.source = read_shape(*p);
  if (auto g = j.optional("gltf")) {
    GltfRef ref;
    if (g->value().is_string()) {
      ref.path = g->nonempty_string();
    } else {
      g->allow_only({"path", "cameras", "lights"}, "gltf reference");
      ref.path = g->member("path").nonempty_string();
      read_opt(*g, "cameras", ref.import_cameras);
      read_opt(*g, "lights", ref.import_lights);
    }
    o.source = ref;
  }
  if (auto m = j.optional("mesh")) o.source = read_mesh(*m);
  if (auto t = j.optional("transform")) o.transform = read_transform(*t);
  if (auto m = j.optional("material")) {
    o.material = m->nonempty_string();
    if (!materials.count(*o.material)) m->fail("unknown material '" + *o.material + "'");
  }
  if (auto c = j.optional("casts_shadows")) o.casts_shadows = c->boolean();
  if (auto r = j.optional("receives_shadows")) o.receives_shadows = r->boolean();
  if (auto c = j.optional("children"))
    for (const JsonIn& child : c->items()) o.children.push_back(read_object(child, materials, top, depth + 1));
  return o;
}

Material read_material(const JsonIn& j) {
  j.allow_only({"name", "base_color", "texture", "specular_color", "specular_strength", "shininess",
                "double_sided", "alpha_mode", "alpha_cutoff"});
  Material m;
  m.name = j.member("name").nonempty_string();
  if (auto c = j.optional("base_color")) {
    if (c->value().is_array() && c->value().size() == 3) m.base_color = glm::vec4(c->vec3(), 1.0f);
    else if (c->value().is_array() && c->value().size() == 4) m.base_color = c->vec4();
    else c->fail("expected an array of 3 or 4 numbers");
  }
  if (auto t = j.optional("texture")) m.texture = t->nonempty_string();
  read_opt(j, "specular_color", m.specular_color);
  read_opt(j, "specular_strength", m.specular_strength);
  read_opt(j, "shininess", m.shininess);
  read_opt(j, "double_sided", m.double_sided);
  if (m.shininess < 0.0f) j.fail_at("shininess", "must not be negative");
  // Reflectances, as glTF's baseColorFactor: each component in [0, 1] (a colour above 1 reflects more light than
  // arrives, below 0 absorbs what no surface can, and both throw the automatic exposure off).
  for (int i = 0; i < 4; ++i)
    if (!(m.base_color[i] >= 0.0f && m.base_color[i] <= 1.0f))
      j.fail_at("base_color", "each component must lie in [0, 1] (linear reflectance and alpha)");
  for (int i = 0; i < 3; ++i)
    if (!(m.specular_color[i] >= 0.0f && m.specular_color[i] <= 1.0f))
      j.fail_at("specular_color", "each component must lie in [0, 1]");
  if (!(m.specular_strength >= 0.0f && m.specular_strength <= 1000.0f))
    j.fail_at("specular_strength", "must lie in [0, 1000]");
  if (!(m.shininess <= 1e6f)) j.fail_at("shininess", "must be at most 10^6");
  if (auto a = j.optional("alpha_mode")) {
    const std::string mode = a->nonempty_string();
    if (mode == "opaque") m.alpha_mode = AlphaMode::opaque;
    else if (mode == "mask") m.alpha_mode = AlphaMode::mask;
    else if (mode == "blend") m.alpha_mode = AlphaMode::blend;
    else a->fail("unknown alpha mode '" + mode + "' (known: opaque, mask, blend)");
  }
  read_opt(j, "alpha_cutoff", m.alpha_cutoff);
  if (!(m.alpha_cutoff >= 0.0f)) j.fail_at("alpha_cutoff", "must not be negative");
  return m;
}

Camera read_camera(const JsonIn& j) {
  j.allow_only({"name", "position", "target", "up", "perspective", "orthographic"});
  Camera c;
  read_opt(j, "name", c.name);
  read_opt(j, "position", c.position);
  read_opt(j, "target", c.target);
  read_opt(j, "up", c.up);
  if (j.has("perspective") && j.has("orthographic")) j.fail("give perspective or orthographic, not both");
  if (auto o = j.optional("orthographic")) {
    o->allow_only({"left", "right", "bottom", "top", "near", "far"});
    Orthographic p;
    for (auto [key, field] : {std::pair{"left", &p.left}, {"right", &p.right}, {"bottom", &p.bottom},
                              {"top", &p.top}, {"near", &p.near}, {"far", &p.far}})
      read_opt(*o, key, *field);
    c.projection = p;
  } else {
    Perspective p;
    if (auto persp = j.optional("perspective")) {
      persp->allow_only({"fovy", "aspect", "near", "far"});
      read_opt(*persp, "fovy", p.fovy_deg);
      if (auto a = persp->optional("aspect")) p.aspect = a->number();
      read_opt(*persp, "near", p.near);
      read_opt(*persp, "far", p.far);
    }
    c.projection = p;
  }
  if (auto problem = camera_problem(c)) j.fail_at(problem->key, problem->message);
  return c;
}

BiasSettings read_bias(const JsonIn& j, BiasSettings b) {
  if (j.value().is_string()) {
    b.mode = parse_name<BiasMode>(j, parse_bias_mode, bias_mode_names(), "bias mode");
    return b;
  }
  j.allow_only({"mode", "constant", "slope", "slope_max", "offset_factor", "offset_units", "normal_offset"});
  if (auto m = j.optional("mode")) b.mode = parse_name<BiasMode>(*m, parse_bias_mode, bias_mode_names(), "bias mode");
  read_opt(j, "constant", b.constant);
  read_opt(j, "slope", b.slope);
  read_opt(j, "slope_max", b.slope_max);
  read_opt(j, "offset_factor", b.offset_factor);
  read_opt(j, "offset_units", b.offset_units);
  read_opt(j, "normal_offset", b.normal_offset);
  return b;
}

ShadowSettings read_shadow(const JsonIn& j, LightType type) {
  j.allow_only({"technique", "filter", "bias", "cull_front", "map_size", "depth_format", "poisson_taps",
                "poisson_spread", "params"});
  ShadowSettings s = default_shadow_settings(type);
  if (auto t = j.optional("technique"))
    s.technique = parse_name<ShadowTechnique>(*t, parse_technique, technique_names(), "technique");
  if (auto f = j.optional("filter")) s.filter = parse_name<ShadowFilter>(*f, parse_filter, filter_names(), "filter");
  if (auto b = j.optional("bias")) s.bias = read_bias(*b, s.bias);
  read_opt(j, "cull_front", s.cull_front);
  // The map's size and format are the technique's defaults unless the file gives them.
  s.map_size = default_map_size(s.technique);
  s.depth_format = default_depth_format(s.technique);
  read_opt(j, "map_size", s.map_size, 1, 16384);
  if (auto d = j.optional("depth_format"))
    s.depth_format = parse_name<DepthFormat>(*d, parse_depth_format, depth_format_names(), "depth format");
  read_opt(j, "poisson_taps", s.poisson_taps, 4, 16);
  read_opt(j, "poisson_spread", s.poisson_spread);
  if (auto params = j.optional("params")) {
    for (const std::string& key : params->keys()) {
      const JsonIn v = params->at(key);
      if (v.value().is_boolean()) s.params[key] = v.boolean();
      else if (v.value().is_number()) s.params[key] = v.value().get<double>();
      else if (v.value().is_string()) s.params[key] = v.string();
      else v.fail("expected a boolean, a number or a string");
    }
  }
  return s;
}

Light read_light(const JsonIn& j) {
  const JsonIn type_key = j.member("type");
  Light l;
  l.type = parse_name<LightType>(type_key, parse_light_type, light_type_names(), "light type");
  const std::string context = std::string(to_string(l.type)) + " light";
  switch (l.type) {
    case LightType::directional:
      j.allow_only({"name", "type", "color", "intensity", "direction", "to_light", "shadow"}, context);
      break;
    case LightType::spot:
      j.allow_only({"name", "type", "color", "intensity", "position", "direction", "inner_cone", "outer_cone",
                    "range", "shadow"}, context);
      break;
    case LightType::point:
      j.allow_only({"name", "type", "color", "intensity", "position", "range", "shadow"}, context);
      break;
    case LightType::hemispherical:
      j.allow_only({"name", "type", "color", "intensity", "position", "direction", "range", "shadow"}, context);
      break;
  }
  read_opt(j, "name", l.name);
  read_opt(j, "color", l.color);
  read_opt(j, "intensity", l.intensity);
  read_opt(j, "position", l.position);
  read_opt(j, "direction", l.direction);
  if (auto t = j.optional("to_light")) {
    if (j.has("direction")) t->fail("cannot be combined with direction");
    l.direction = -t->vec3();
  }
  {  // Scaled by its largest component, so that a huge or tiny (but non-zero) vector normalises without
     // overflowing or underflowing: only its direction counts.
    const float m = std::max({std::fabs(l.direction.x), std::fabs(l.direction.y), std::fabs(l.direction.z)});
    const float d2 = l.direction.x * l.direction.x + l.direction.y * l.direction.y + l.direction.z * l.direction.z;
    if (m > 0.0f && std::isfinite(m) && !(d2 >= 1e-30f && d2 <= 1e30f)) l.direction /= m;
  }
  read_opt(j, "inner_cone", l.inner_cone_deg);
  read_opt(j, "outer_cone", l.outer_cone_deg);
  read_opt(j, "range", l.range);
  l.shadow = j.has("shadow") ? read_shadow(j.at("shadow"), l.type) : default_shadow_settings(l.type);
  if (auto problem = light_problem(l)) {
    const bool via_to_light = problem->key == "direction" && j.has("to_light");
    j.fail_at(via_to_light ? "to_light" : problem->key, problem->message);
  }
  return l;
}

// A colour of the background: three numbers in [0, 1].
glm::vec3 background_color(const JsonIn& j) {
  const glm::vec3 c = j.vec3();
  if (!(glm::all(glm::greaterThanEqual(c, glm::vec3(0.0f))) && glm::all(glm::lessThanEqual(c, glm::vec3(1.0f)))))
    j.fail("expected three numbers in [0, 1] (linear RGB)");
  return c;
}

// `exposure` (EV100 or "auto"), `tonemap` (a name) and `background` (a name, a colour or {"top", "bottom"}).
Look read_look(const JsonIn& root) {
  Look look;
  if (auto e = root.optional("exposure")) {
    if (e->value().is_string()) {
      if (e->string() != "auto") e->fail("expected a number (EV100) or \"auto\"");
    } else {
      const float ev = e->number();
      if (!(ev >= -64.0f && ev <= 64.0f)) e->fail("EV100 must be between -64 and 64");
      look.exposure.ev100 = ev;
    }
  }
  if (auto t = root.optional("tonemap")) {
    const std::string name = t->string();
    if (auto op = shading::parse_tone_map(name)) look.tone_map = *op;
    else {
      std::string known;
      for (const shading::ToneMapName& n : shading::kToneMapNames) known += (known.empty() ? "" : ", ") + std::string(n.name);
      t->fail("unknown tone map '" + name + "' (known: " + known + ")");
    }
  }
  if (auto b = root.optional("background")) {
    if (b->value().is_string()) {
      const std::string name = b->string();
      if (auto named = named_background(name)) look.background = *named;
      else {
        std::string known;
        for (const NamedBackground& n : kBackgrounds) known += (known.empty() ? "" : ", ") + std::string(n.name);
        b->fail("unknown background '" + name + "' (known: " + known + ", or [r, g, b], or {\"top\", \"bottom\"})");
      }
    } else if (b->value().is_array()) {
      look.background.top = look.background.bottom = background_color(*b);
    } else {
      b->allow_only({"top", "bottom"}, "background");
      look.background.top = background_color(b->member("top"));
      look.background.bottom = background_color(b->member("bottom"));
    }
  }
  return look;
}

}  // namespace

SceneDesc parse_scene_json(std::string_view text, const std::string& file) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text.begin(), text.end());
  } catch (const nlohmann::json::exception& e) {
    std::string what = e.what();
    if (const size_t end = what.find("] "); what.rfind("[json.exception.", 0) == 0 && end != std::string::npos)
      what = what.substr(end + 2);
    throw SceneError(file, "", "malformed JSON: " + what);
  }
  const JsonIn root(doc, "", file);
  root.allow_only({"version", "name", "description", "materials", "objects", "cameras", "lights", "exposure",
                   "tonemap", "background"});
  if (auto v = root.optional("version"))
    if (v->integer(0, 1000) != kSceneFormatVersion) v->fail("unsupported version (this reader knows version 1)");
  SceneDesc d;
  read_opt(root, "name", d.name);
  read_opt(root, "description", d.description);
  std::set<std::string> names;
  if (auto m = root.optional("materials"))
    for (const JsonIn& e : m->items()) {
      d.materials.push_back(read_material(e));
      if (!names.insert(d.materials.back().name).second) e.at("name").fail("duplicate material name");
    }
  if (auto o = root.optional("objects"))
    for (const JsonIn& e : o->items()) d.objects.push_back(read_object(e, names, e));
  if (auto c = root.optional("cameras"))
    for (const JsonIn& e : c->items()) d.cameras.push_back(read_camera(e));
  if (auto l = root.optional("lights"))
    for (const JsonIn& e : l->items()) d.lights.push_back(read_light(e));
  d.look = read_look(root);
  return d;
}

SceneDesc load_scene_desc(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path.string(), "", "cannot open file (" + std::string(std::strerror(errno)) + ")");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene_json(text.str(), path.string());
}

}  // namespace scenes
