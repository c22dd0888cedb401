#include "membra/io/gltf.hpp"

#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <utility>

#include "membra/core/input_error.hpp"
#include "membra/core/units.hpp"
#include "membra/geometry/triangulation.hpp"
#include "membra/version.hpp"

namespace membra {
namespace {

tinygltf::Value to_value(const nlohmann::json& j) {
  if (j.is_boolean()) return tinygltf::Value(j.get<bool>());
  if (j.is_number_integer() && j.get<std::int64_t>() == static_cast<int>(j.get<std::int64_t>()))
    return tinygltf::Value(j.get<int>());
  if (j.is_number()) return tinygltf::Value(j.get<double>());
  if (j.is_string()) return tinygltf::Value(j.get<std::string>());
  if (j.is_array()) {
    tinygltf::Value::Array a;
    for (const auto& e : j) a.push_back(to_value(e));
    return tinygltf::Value(std::move(a));
  }
  if (j.is_object()) {
    tinygltf::Value::Object o;
    for (const auto& [k, v] : j.items()) o[k] = to_value(v);
    return tinygltf::Value(std::move(o));
  }
  return {};
}

nlohmann::json to_json(const tinygltf::Value& v) {
  if (v.IsBool()) return v.Get<bool>();
  if (v.IsInt()) return v.Get<int>();
  if (v.IsNumber()) return v.GetNumberAsDouble();
  if (v.IsString()) return v.Get<std::string>();
  if (v.IsArray()) {
    nlohmann::json a = nlohmann::json::array();
    for (size_t i = 0; i < v.ArrayLen(); ++i) a.push_back(to_json(v.Get(static_cast<int>(i))));
    return a;
  }
  if (v.IsObject()) {
    nlohmann::json o = nlohmann::json::object();
    for (const auto& k : v.Keys()) o[k] = to_json(v.Get(k));
    return o;
  }
  return nullptr;
}

// Appends `data` to the buffer as a view and an accessor of `count` elements; returns the
// accessor's index.
template <class T>
int add_accessor(tinygltf::Model& m, const std::vector<T>& data, int component, int type,
                 size_t count, int target) {
  auto& bytes = m.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = bytes.size();
  view.byteLength = data.size() * sizeof(T);
  view.target = target;
  bytes.resize(bytes.size() + view.byteLength);
  std::memcpy(bytes.data() + view.byteOffset, data.data(), view.byteLength);
  m.bufferViews.push_back(view);
  tinygltf::Accessor a;
  a.bufferView = static_cast<int>(m.bufferViews.size()) - 1;
  a.componentType = component;
  a.type = type;
  a.count = count;
  m.accessors.push_back(a);
  return static_cast<int>(m.accessors.size()) - 1;
}

std::vector<float> linear_colors(const std::vector<Rgb>& colors) {
  std::vector<float> out;
  out.reserve(colors.size() * 3);
  for (const Rgb& c : colors)
    for (int k = 0; k < 3; ++k) out.push_back(srgb_to_linear(c[k]));
  return out;
}

// membra's z-up (x, y, z) in glTF's y-up axes: (x, z, -y), a turn of -90 degrees about x, so
// that importers (Blender, three.js) show the form upright.
Vec3 to_y_up(const Vec3& v) {
  return {v.x(), v.z(), -v.y()};
}
Vec3 from_y_up(const Vec3& v) {
  return {v.x(), -v.z(), v.y()};
}

// Positions in metres (glTF's unit) and smooth (area-weighted) normals, as float triples in
// glTF's axes.
void vertex_arrays(const GlbSheet& s, std::vector<float>& pos, std::vector<float>& nrm) {
  const Points normals = vertex_normals(s.x, s.triangles);
  for (Eigen::Index p = 0; p < s.x.cols(); ++p) {
    const Vec3 q = to_y_up(s.x.col(p)), m = to_y_up(normals.col(p));
    for (int k = 0; k < 3; ++k) {
      pos.push_back(static_cast<float>(q[k]));
      nrm.push_back(static_cast<float>(m[k]));
    }
  }
}

}  // namespace

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
float linear_to_srgb(float c) {
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

namespace {

// The sheet's vertex attributes, appended to m's buffer, as a primitive without indices.
tinygltf::Primitive sheet_attributes(tinygltf::Model& m, const GlbSheet& s) {
  const auto n = static_cast<size_t>(s.x.cols());
  std::vector<float> pos, nrm;
  vertex_arrays(s, pos, nrm);
  tinygltf::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  const int vec3 = TINYGLTF_TYPE_VEC3, f32 = TINYGLTF_COMPONENT_TYPE_FLOAT;
  const int array = TINYGLTF_TARGET_ARRAY_BUFFER;
  prim.attributes["POSITION"] = add_accessor(m, pos, f32, vec3, n, array);
  auto& p_acc = m.accessors.back();
  p_acc.minValues = {1e300, 1e300, 1e300};
  p_acc.maxValues = {-1e300, -1e300, -1e300};
  for (size_t i = 0; i < pos.size(); ++i) {
    p_acc.minValues[i % 3] = std::min(p_acc.minValues[i % 3], double(pos[i]));
    p_acc.maxValues[i % 3] = std::max(p_acc.maxValues[i % 3], double(pos[i]));
  }
  prim.attributes["NORMAL"] = add_accessor(m, nrm, f32, vec3, n, array);
  if (!s.uv.empty()) {
    std::vector<float> uv;
    for (const Vec2& t : s.uv) {
      uv.push_back(static_cast<float>(t.x()));
      uv.push_back(static_cast<float>(1.0 - t.y()));  // glTF counts v from the top
    }
    prim.attributes["TEXCOORD_0"] = add_accessor(m, uv, f32, TINYGLTF_TYPE_VEC2, n, array);
  }
  prim.attributes["COLOR_0"] =
      add_accessor(m, linear_colors(s.curvature_colors), f32, vec3, n, array);
  prim.attributes["COLOR_1"] = add_accessor(m, linear_colors(s.stress_colors), f32, vec3, n, array);
  const std::vector<float> k(s.curvature.begin(), s.curvature.end()),
      st(s.stress.begin(), s.stress.end());
  prim.attributes["_CURVATURE"] = add_accessor(m, k, f32, TINYGLTF_TYPE_SCALAR, n, array);
  prim.attributes["_STRESS"] = add_accessor(m, st, f32, TINYGLTF_TYPE_SCALAR, n, array);
  return prim;
}

// The two materials: white (the vertex colours show as they are), the latex matte, the resin
// glossy, so that an importer can tell and re-dress them by name.
void add_materials(tinygltf::Model& m) {
  for (const auto& [name, roughness] : {std::pair{"latex", 0.8}, std::pair{"resin", 0.3}}) {
    tinygltf::Material mat;
    mat.name = name;
    mat.doubleSided = true;  // a sheet: both faces are seen
    mat.pbrMetallicRoughness.metallicFactor = 0.0;
    mat.pbrMetallicRoughness.roughnessFactor = roughness;
    m.materials.push_back(mat);
  }
}

// One primitive per material that has triangles (material 0 latex, 1 resin), sharing `base`'s
// attributes.
std::vector<tinygltf::Primitive> material_primitives(tinygltf::Model& m, const GlbSheet& s,
                                                     const tinygltf::Primitive& base) {
  std::vector<tinygltf::Primitive> out;
  for (int material = 0; material < 2; ++material) {
    std::vector<std::uint32_t> idx;
    for (size_t t = 0; t < s.triangles.size(); ++t) {
      const bool resin = !s.resin.empty() && s.resin[t];
      if (resin != (material == 1)) continue;
      for (int c : s.triangles[t]) idx.push_back(static_cast<std::uint32_t>(c));
    }
    if (idx.empty()) continue;
    tinygltf::Primitive prim = base;
    prim.indices = add_accessor(m, idx, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                idx.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    prim.material = material;
    out.push_back(prim);
  }
  return out;
}

}  // namespace

void write_glb(std::ostream& out, const GlbSheet& s) {
  const auto n = static_cast<size_t>(s.x.cols());
  if (s.curvature_colors.size() != n || s.stress_colors.size() != n || s.curvature.size() != n ||
      s.stress.size() != n || (!s.uv.empty() && s.uv.size() != n) ||
      (!s.resin.empty() && s.resin.size() != s.triangles.size()))
    throw InputError("final.glb", "colours, values or materials do not match the mesh");
  tinygltf::Model m;
  m.buffers.resize(1);
  const tinygltf::Primitive base = sheet_attributes(m, s);
  add_materials(m);
  tinygltf::Mesh mesh;
  mesh.name = "membrane";
  mesh.primitives = material_primitives(m, s, base);
  m.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  node.name = "membrane";
  m.nodes.push_back(node);
  m.scenes.push_back({});
  m.scenes[0].nodes.push_back(0);
  m.defaultScene = 0;
  m.asset.version = "2.0";
  m.asset.generator = std::string("membra ") + kVersion;
  nlohmann::json extras = s.extras;
  extras["unit"] = "m";
  extras["up"] = "membra's z is glTF's y: positions are (x, z, -y) of membra's";
  extras["attributes"] = {
      {"TEXCOORD_0", "the flat (natural) sheet, its larger side 0 to 1"},
      {"COLOR_0", "Gaussian curvature colours"},
      {"COLOR_1", "stress colours"},
      {"_CURVATURE", "Gaussian curvature, 1/m^2"},
      {"_STRESS", "mean stress of the springs at the vertex (tension > 0), MPa"}};
  m.asset.extras = to_value(extras);
  tinygltf::TinyGLTF gltf;
  if (!gltf.WriteGltfSceneToStream(&m, out, false, true))
    throw InputError("final.glb", "tinygltf could not write the model");
}

namespace {

// The floats of an accessor written by write_glb (tightly packed, no sparse storage).
std::vector<float> read_floats(const tinygltf::Model& m, const tinygltf::Primitive& prim,
                               const std::string& name, int components, const std::string& where) {
  const auto it = prim.attributes.find(name);
  if (it == prim.attributes.end()) throw InputError(where, "no " + name + " attribute");
  const auto bad = [&] { return InputError(where, name + " has no valid accessor or buffer"); };
  if (it->second < 0 || static_cast<size_t>(it->second) >= m.accessors.size()) throw bad();
  const tinygltf::Accessor& a = m.accessors[static_cast<size_t>(it->second)];
  if (a.bufferView < 0 || static_cast<size_t>(a.bufferView) >= m.bufferViews.size()) throw bad();
  const tinygltf::BufferView& v = m.bufferViews[static_cast<size_t>(a.bufferView)];
  if (v.buffer < 0 || static_cast<size_t>(v.buffer) >= m.buffers.size()) throw bad();
  if (tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)) != components)
    throw bad();
  const auto& bytes = m.buffers[static_cast<size_t>(v.buffer)].data;
  const size_t count = a.count * static_cast<size_t>(components);
  const size_t offset = v.byteOffset + a.byteOffset;
  if (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || offset + count * 4 > bytes.size())
    throw InputError(where, name + " is not a float array inside the buffer");
  std::vector<float> out(count);
  std::memcpy(out.data(), bytes.data() + offset, count * 4);
  return out;
}

std::vector<std::uint32_t> read_indices(const tinygltf::Model& m, const tinygltf::Primitive& prim,
                                        const std::string& where) {
  if (prim.indices < 0 || static_cast<size_t>(prim.indices) >= m.accessors.size())
    throw InputError(where, "the mesh has no indices");
  const tinygltf::Accessor& ia = m.accessors[static_cast<size_t>(prim.indices)];
  if (ia.bufferView < 0 || static_cast<size_t>(ia.bufferView) >= m.bufferViews.size())
    throw InputError(where, "the indices have no buffer view");
  const tinygltf::BufferView& iv = m.bufferViews[static_cast<size_t>(ia.bufferView)];
  if (iv.buffer < 0 || static_cast<size_t>(iv.buffer) >= m.buffers.size())
    throw InputError(where, "the indices have no buffer");
  const auto& bytes = m.buffers[static_cast<size_t>(iv.buffer)].data;
  if (ia.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT ||
      iv.byteOffset + ia.byteOffset + ia.count * 4 > bytes.size())
    throw InputError(where, "indices are not 32-bit inside the buffer");
  std::vector<std::uint32_t> idx(ia.count);
  std::memcpy(idx.data(), bytes.data() + iv.byteOffset + ia.byteOffset, ia.count * 4);
  return idx;
}

std::vector<Rgb> srgb_colors(const std::vector<float>& linear) {
  std::vector<Rgb> out;
  for (size_t i = 0; i + 2 < linear.size(); i += 3)
    out.emplace_back(linear_to_srgb(linear[i]), linear_to_srgb(linear[i + 1]),
                     linear_to_srgb(linear[i + 2]));
  return out;
}

}  // namespace

GlbSheet read_glb(const std::filesystem::path& file) {
  tinygltf::Model m;
  tinygltf::TinyGLTF gltf;
  std::string err, warn;
  const std::string where = file.string();
  if (!gltf.LoadBinaryFromFile(&m, &err, &warn, where))
    throw InputError(where, "not a readable glTF binary: " + err);
  if (m.meshes.empty() || m.meshes[0].primitives.empty()) throw InputError(where, "no mesh");
  const tinygltf::Primitive& prim = m.meshes[0].primitives[0];
  GlbSheet s;
  const auto pos = read_floats(m, prim, "POSITION", 3, where);
  s.x.resize(3, static_cast<Eigen::Index>(pos.size() / 3));
  for (size_t i = 0; i + 2 < pos.size(); i += 3)
    s.x.col(static_cast<Eigen::Index>(i / 3)) = from_y_up(Vec3(pos[i], pos[i + 1], pos[i + 2]));
  s.curvature_colors = srgb_colors(read_floats(m, prim, "COLOR_0", 3, where));
  s.stress_colors = srgb_colors(read_floats(m, prim, "COLOR_1", 3, where));
  for (float v : read_floats(m, prim, "_CURVATURE", 1, where)) s.curvature.push_back(v);
  for (float v : read_floats(m, prim, "_STRESS", 1, where)) s.stress.push_back(v);
  if (prim.attributes.count("TEXCOORD_0")) {
    const auto uv = read_floats(m, prim, "TEXCOORD_0", 2, where);
    for (size_t i = 0; i + 1 < uv.size(); i += 2) s.uv.emplace_back(uv[i], 1.0 - uv[i + 1]);
  }
  for (const tinygltf::Primitive& part : m.meshes[0].primitives) {
    const bool resin = part.material >= 0 &&
                       static_cast<size_t>(part.material) < m.materials.size() &&
                       m.materials[static_cast<size_t>(part.material)].name == "resin";
    const std::vector<std::uint32_t> idx = read_indices(m, part, where);
    for (std::uint32_t i : idx)
      if (i >= static_cast<std::uint32_t>(s.x.cols()))
        throw InputError(where, "an index is out of range");
    for (size_t i = 0; i + 2 < idx.size(); i += 3) {
      s.triangles.emplace_back(static_cast<int>(idx[i]), static_cast<int>(idx[i + 1]),
                               static_cast<int>(idx[i + 2]));
      s.resin.push_back(resin);
    }
  }
  s.extras = to_json(m.asset.extras);
  return s;
}

}  // namespace membra
