#!/usr/bin/env python3
"""Writes the generated part of the seed corpora (tests/fuzz/corpus/<target>/): small glTF files, text and
binary, including every malformed glTF and JSON case of issue 23, and light-matrix files. The EXR and PNG seeds
come from make_image_seeds.sh; docs/examples/*.json is copied in by run.sh. Run from anywhere; deterministic."""
import base64, json, os, struct

here = os.path.dirname(os.path.abspath(__file__))
corpus = os.path.join(here, "corpus")

def put(target, name, data):
    d = os.path.join(corpus, target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())

def tri_bin():
    pos = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    idx = struct.pack("<3H", 0, 1, 2) + b"\0\0"
    return pos, idx

def gltf_doc(bin_bytes, uri=None, extra_nodes=None, count=3, mode=4):
    pos, idx = tri_bin()
    doc = {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": len(bin_bytes)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": mode, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.2, 1], "roughnessFactor": 0.5},
                       "doubleSided": True}],
        "nodes": [{"mesh": 0, "translation": [0, 0, -2]},
                  {"camera": 0, "translation": [0, 0, 3]},
                  {"extensions": {"KHR_lights_punctual": {"light": 0}}, "rotation": [-0.38, 0, 0, 0.92]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100}}],
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "spot", "intensity": 2,
                                                           "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}}]}},
        "scenes": [{"nodes": [0, 1, 2]}],
        "scene": 0,
    }
    if uri is not None:
        doc["buffers"][0]["uri"] = uri
    if extra_nodes:
        extra_nodes(doc)
    return doc

def glb(doc, bin_bytes):
    js = json.dumps(doc, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    bin_bytes += b"\0" * (-len(bin_bytes) % 4)
    chunks = struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(bin_bytes), b"BIN\0") + bin_bytes
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks

pos, idx = tri_bin()
data = pos + idx + b"\0\0"
uri = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
put("fuzz_gltf", "triangle.gltf", json.dumps(gltf_doc(data, uri), indent=1))
put("fuzz_gltf", "triangle.glb", glb(gltf_doc(data), data))
put("fuzz_gltf", "strip.gltf", json.dumps(gltf_doc(data, uri, mode=5)))
# Issue 23's reproducers, small: a cycle, a DAG (node i lists i+1 twice), a long chain, count 0, a huge count,
# a GLB whose buffer says byteLength 0, NaN positions.
def cycle(d): d["nodes"][0]["children"] = [3]; d["nodes"].append({"children": [0]})
put("fuzz_gltf", "cycle.gltf", json.dumps(gltf_doc(data, uri, cycle)))
def dag(d):
    base = len(d["nodes"])
    d["nodes"][0]["children"] = [base]
    for i in range(20):
        d["nodes"].append({"children": [base + i + 1, base + i + 1], "mesh": 0})
    d["nodes"].append({"mesh": 0})
put("fuzz_gltf", "dag.gltf", json.dumps(gltf_doc(data, uri, dag)))
def chain(d):
    base = len(d["nodes"])
    d["nodes"][0]["children"] = [base]
    for i in range(300):
        d["nodes"].append({"children": [base + i + 1], "translation": [0.01, 0, 0]})
    d["nodes"].append({"mesh": 0})
put("fuzz_gltf", "chain.gltf", json.dumps(gltf_doc(data, uri, chain)))
put("fuzz_gltf", "count0.gltf", json.dumps(gltf_doc(data, uri, count=0)))
put("fuzz_gltf", "count_huge.gltf", json.dumps(gltf_doc(data, uri, count=1 << 28)))
# The campaign's find: the same count on an accessor without a bufferView (all zeros) allocated 3 GiB.
zeros = gltf_doc(data, uri, count=1 << 28); del zeros["accessors"][0]["bufferView"]
put("fuzz_gltf", "zeros_count_huge.gltf", json.dumps(zeros))
zero = gltf_doc(data); zero["buffers"][0]["byteLength"] = 0
put("fuzz_gltf", "zero_buffer.glb", glb(zero, data))
nan = struct.pack("<9f", float("nan"), 0, 0, float("inf"), 0, 0, 0, -1e38, 0) + idx + b"\0\0"
put("fuzz_gltf", "nan.glb", glb(gltf_doc(nan), nan))

# A skinned, morphed triangle (two joints, inverse bind matrices, one morph target at weight 0.5) and a
# quantized one (normalized SHORT positions under KHR_mesh_quantization): the pose code of gltf_pose.cpp.
joints = struct.pack("<12B", 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0)
weights = struct.pack("<12f", 1, 0, 0, 0, 1, 0, 0, 0, 0.5, 0.5, 0, 0)
ident16 = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
ibm = struct.pack("<16f", *ident16) + struct.pack("<16f", *(ident16[:12] + [0, -1, 0, 1]))
morph = struct.pack("<9f", 0, 0, 1, 0, 0, 1, 0, 0, 1)
skin_data = data + joints + weights + ibm + morph
def skinned(d):
    d["buffers"][0]["byteLength"] = len(skin_data)
    off = len(data)
    for length, comp, typ in ((12, 5121, "VEC4"), (48, 5126, "VEC4"), (128, 5126, "MAT4"), (36, 5126, "VEC3")):
        d["bufferViews"].append({"buffer": 0, "byteOffset": off, "byteLength": length})
        count = 2 if typ == "MAT4" else 3
        d["accessors"].append({"bufferView": len(d["bufferViews"]) - 1, "componentType": comp, "count": count, "type": typ})
        off += length
    prim = d["meshes"][0]["primitives"][0]
    prim["attributes"].update({"JOINTS_0": 2, "WEIGHTS_0": 3})
    prim["targets"] = [{"POSITION": 5}]
    d["meshes"][0]["weights"] = [0.5]
    d["nodes"][0]["skin"] = 0
    d["nodes"] += [{"translation": [1, 0, 0], "children": [4]}, {"rotation": [0, 0, 0.7071, 0.7071], "translation": [0, 1, 0]}]
    d["scenes"][0]["nodes"].append(3)
    d["skins"] = [{"joints": [3, 4], "inverseBindMatrices": 4}]
put("fuzz_gltf", "skinned.gltf", json.dumps(gltf_doc(skin_data, "data:application/octet-stream;base64," +
                                                     base64.b64encode(skin_data).decode(), skinned)))
put("fuzz_gltf", "skinned.glb", glb(gltf_doc(skin_data, None, skinned), skin_data))
qpos = struct.pack("<12h", 0, 0, 0, 0, 32767, 0, 0, 0, 0, 32767, 0, 0)
qdata = qpos + idx + b"\0\0"
def quantized(d):
    d["buffers"][0]["byteLength"] = len(qdata)
    d["bufferViews"][0].update({"byteLength": 24, "byteStride": 8})
    d["bufferViews"][1]["byteOffset"] = 24
    d["accessors"][0].update({"componentType": 5122, "normalized": True})
    d["extensionsUsed"].append("KHR_mesh_quantization")
    d["extensionsRequired"] = ["KHR_mesh_quantization"]
put("fuzz_gltf", "quantized.glb", glb(gltf_doc(qdata, None, quantized), qdata))

# JSON scenes beyond docs/examples: the deep-nesting reproducer (cut to what the reader refuses quickly),
# degenerate and huge geometry, every technique on a small scene.
def nest(depth):
    leaf = {"name": "box", "primitive": {"type": "box", "size": [1, 1, 1]}}
    for _ in range(depth):
        leaf = {"children": [leaf]}
    return leaf
put("fuzz_scene_json", "deep.json", json.dumps({"objects": [nest(300)]}))
seed_lights = {
    "shadowmap": [("directional", {"direction": [0.3, -1, 0.2]}), ("spot", {"position": [0, 4, 0], "direction": [0, -1, 0]})],
    "cube": [("point", {"position": [0, 3, 0]})],
    "paraboloid": [("point", {"position": [0, 3, 0]}), ("hemispherical", {"position": [0, 3, 0], "direction": [0, -1, 0]})],
    "pyramid": [("hemispherical", {"position": [0, 3, 0], "direction": [0, -1, 0]})],
    "projective": [("directional", {"to_light": [0.5, 2, 2]}), ("point", {"position": [0, 3, 0]})],
    "cascades": [("directional", {"to_light": [0.5, 2, 2]})],
    "lispsm": [("directional", {"to_light": [0.5, 2, 2]})],
    "frustum-faces": [("directional", {"to_light": [0.5, 2, 2]})],
    "none": [("spot", {"position": [0, 4, 0]})],
}
for t, lights in seed_lights.items():
    put("fuzz_scene_json", "technique-" + t + ".json", json.dumps({
        "objects": [{"name": "ground", "primitive": {"type": "plane", "size": [10, 10]}},
                    {"name": "box", "primitive": {"type": "box", "size": [1e30, 1, 1]},
                     "transform": {"translate": [0, 0.5, 0]}}],
        "lights": [dict(type=k, **v, shadow={"technique": t, "map_size": 64}) for k, v in lights]}))

# Light matrices.
ident = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
put("fuzz_light_matrix", "view_proj.json", json.dumps({"view_proj": ident}))
put("fuzz_light_matrix", "view_and_proj.json", json.dumps({"view": ident, "proj": ident}))
put("fuzz_light_matrix", "overflow.json", '{"view_proj": [1e999, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}')
put("fuzz_light_matrix", "unknown.json", json.dumps({"view": ident, "projection": ident}))
