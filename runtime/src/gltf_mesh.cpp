#include "facet/runtime/gltf_mesh.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <span>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "facet/runtime/mesh.h"
#include "gltf_accessor.h"
#include "gltf_source.h"
#include "mikktspace_tangents.h"

namespace facet::runtime {
namespace {

namespace fs = std::filesystem;

using gltf::AccessorReader;

using gltf::ComponentRule;

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE;
constexpr int kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kShort = TINYGLTF_COMPONENT_TYPE_SHORT;
constexpr int kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

// The attributes' component types: glTF 2.0 core (§3.7.2.1), and what KHR_mesh_quantization adds
// when the file uses it (its "Extending Mesh Attributes" table). A non-normalized integer is read
// as the integer: the file's node transforms (positions) or texture transforms scale it.
constexpr ComponentRule kFloats[] = {{kFloat, false}};
constexpr ComponentRule kCoreUvs[] = {{kFloat, false}, {kUByte, true}, {kUShort, true}};
constexpr ComponentRule kCoreColours[] = {{kFloat, false}, {kUByte, true}, {kUShort, true}};
constexpr ComponentRule kQuantizedPositions[] = {{kFloat, false}, {kByte, false},   {kByte, true},
                                                 {kUByte, false}, {kUByte, true},   {kShort, false},
                                                 {kShort, true},  {kUShort, false}, {kUShort, true}};
constexpr ComponentRule kQuantizedDirections[] = {{kFloat, false}, {kByte, true}, {kShort, true}};
constexpr ComponentRule kQuantizedUvs[] = {{kFloat, false}, {kByte, false},   {kByte, true},
                                           {kUByte, false}, {kUByte, true},   {kShort, false},
                                           {kShort, true},  {kUShort, false}, {kUShort, true}};
constexpr ComponentRule kIndices[] = {{kUByte, false}, {kUShort, false}, {kUInt, false}};

bool usesQuantization(const tinygltf::Model& model) {
  return std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), "KHR_mesh_quantization") !=
         model.extensionsUsed.end();
}

// A node's world transform, and what it does to normals and tangents.
struct Placement {
  glm::dmat4 world{1.0};
  glm::dmat3 normalMatrix{1.0};  // inverse transpose of world's upper 3×3
  bool mirrors = false;          // negative determinant: winding and tangent handedness flip
};

Placement placementOf(const glm::dmat4& world) {
  Placement p;
  p.world = world;
  p.normalMatrix = glm::inverseTranspose(glm::dmat3(world));
  p.mirrors = glm::determinant(glm::dmat3(world)) < 0;
  return p;
}

glm::dvec3 normalised(const glm::dvec3& v, const glm::dvec3& fallback) {
  const double length = glm::length(v);
  return length > 0 && std::isfinite(length) ? v / length : fallback;
}

// Normals and tangents must have a direction: the spec asks for unit length, and they are
// normalised here rather than refused when they miss it (exporters round, quantised sources are
// never exactly unit, and other viewers normalise in the shader, so refusing would reject files
// they show), but a vector shorter than this has no direction left to keep (a zero normal
// shaded objects black).
constexpr double kMinDirectionLength = 1e-6;

// One attribute as this primitive reads it: its reader, and where it is named for messages.
struct Attribute {
  std::optional<AccessorReader> reader;
  std::string field;  // ".../attributes/NORMAL"
  int accessor = -1;

  explicit operator bool() const { return reader.has_value(); }

  // The components of element v; false with *error naming the accessor and the element when one
  // is not finite (NaN and infinities turned objects flat grey or black).
  bool read(size_t v, double* out, std::string* error) const {
    for (int c = 0; c < reader->components(); ++c) {
      out[c] = reader->get(v, c);
      if (!std::isfinite(out[c])) {
        *error = where(v) + " is not finite";
        return false;
      }
    }
    return true;
  }

  std::string where(size_t v) const {
    return field + ": /accessors/" + std::to_string(accessor) + " element " + std::to_string(v);
  }
};

bool appendPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& pointer,
                     const Placement& placement, Mesh* mesh, std::string* error) {
  if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != -1) {
    *error = pointer + "/mode: only triangle lists (4) are supported, not " + std::to_string(primitive.mode);
    return false;
  }
  const auto accessorOf = [&](const char* name) {
    auto it = primitive.attributes.find(name);
    return it == primitive.attributes.end() ? -1 : it->second;
  };
  const std::string attributes = pointer + "/attributes/";
  if (accessorOf("POSITION") < 0) {
    *error = attributes + "POSITION: missing (every primitive needs positions)";
    return false;
  }
  Attribute positions, normals, tangents, uv0, uv1, colours;
  struct Use {
    const char* name;
    Attribute* attribute;
    std::initializer_list<int> types;
    std::span<const ComponentRule> components;
  };
  const bool quantized = usesQuantization(model);
  using Rules = std::span<const ComponentRule>;
  const Rules directions = quantized ? Rules(kQuantizedDirections) : Rules(kFloats);
  const Rules uvs = quantized ? Rules(kQuantizedUvs) : Rules(kCoreUvs);
  const Use uses[] = {
      {"POSITION", &positions, {TINYGLTF_TYPE_VEC3}, quantized ? Rules(kQuantizedPositions) : Rules(kFloats)},
      {"NORMAL", &normals, {TINYGLTF_TYPE_VEC3}, directions},
      {"TANGENT", &tangents, {TINYGLTF_TYPE_VEC4}, directions},
      {"TEXCOORD_0", &uv0, {TINYGLTF_TYPE_VEC2}, uvs},
      {"TEXCOORD_1", &uv1, {TINYGLTF_TYPE_VEC2}, uvs},
      {"COLOR_0", &colours, {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, kCoreColours},
  };
  for (const Use& use : uses) {
    Attribute& a = *use.attribute;
    a.accessor = accessorOf(use.name);
    if (a.accessor < 0) continue;
    a.field = attributes + use.name;
    a.reader = AccessorReader::open(model, a.accessor, use.types, use.components, a.field, error);
    if (!a.reader) return false;
    if (a.reader->count() != positions.reader->count()) {
      *error = a.field + ": " + std::to_string(a.reader->count()) + " elements, but POSITION has " +
               std::to_string(positions.reader->count());
      return false;
    }
  }
  const size_t count = positions.reader->count();
  const size_t firstVertex = mesh->vertices.size() / abi::kVertexFloats;
  if (firstVertex + count > UINT32_MAX) {
    *error = attributes + "POSITION: more vertices than 32-bit indices address";
    return false;
  }
  for (size_t v = 0; v < count; ++v) {
    Vertex vertex;
    double p[3], n[3], t[4], c[4];
    if (!positions.read(v, p, error)) return false;
    const glm::dvec4 position = placement.world * glm::dvec4(p[0], p[1], p[2], 1);
    for (int i = 0; i < 3; ++i) vertex.position[i] = float(position[i]);
    for (float f : vertex.position) {
      if (!std::isfinite(f)) {
        *error = positions.where(v) + " is not finite once placed by its node";
        return false;
      }
    }
    if (normals) {
      if (!normals.read(v, n, error)) return false;
      const glm::dvec3 stored(n[0], n[1], n[2]);
      if (glm::length(stored) < kMinDirectionLength) {
        *error = normals.where(v) + " is shorter than 1e-6 (a normal needs a direction)";
        return false;
      }
      const glm::dvec3 placed = normalised(placement.normalMatrix * stored, glm::normalize(stored));
      for (int i = 0; i < 3; ++i) vertex.normal[i] = float(placed[i]);
    }
    if (tangents) {
      if (!tangents.read(v, t, error)) return false;
      const glm::dvec3 stored(t[0], t[1], t[2]);
      if (glm::length(stored) < kMinDirectionLength) {
        *error = tangents.where(v) + ": xyz is shorter than 1e-6 (a tangent needs a direction)";
        return false;
      }
      if (t[3] != 1 && t[3] != -1) {
        *error = tangents.where(v) + ": w is " + std::to_string(t[3]) + ", not +1 or -1 (the bitangent's sign)";
        return false;
      }
      // Tangents move with the surface (world's 3×3); w gives the bitangent's side, which a
      // mirroring transform flips (glTF 2.0 §3.7.2.1: bitangent = cross(normal, tangent.xyz) · w).
      const glm::dvec3 placed = normalised(glm::dmat3(placement.world) * stored, glm::normalize(stored));
      for (int i = 0; i < 3; ++i) vertex.tangent[i] = float(placed[i]);
      vertex.tangent[3] = float(t[3] * (placement.mirrors ? -1.0 : 1.0));
    }
    if (uv0) {
      if (!uv0.read(v, c, error)) return false;
      for (int i = 0; i < 2; ++i) vertex.uv0[i] = float(c[i]);
    }
    if (uv1) {
      if (!uv1.read(v, c, error)) return false;
      for (int i = 0; i < 2; ++i) vertex.uv1[i] = float(c[i]);
    }
    if (colours) {
      if (!colours.read(v, c, error)) return false;
      for (int i = 0; i < colours.reader->components(); ++i) vertex.color[i] = float(c[i]);
    }
    appendVertex(*mesh, vertex);
  }
  // A mirroring transform turns counter-clockwise triangles clockwise: swap two corners back.
  const size_t firstIndex = mesh->indices.size();
  const auto flipWinding = [&] {
    if (!placement.mirrors) return;
    for (size_t i = firstIndex; i + 2 < mesh->indices.size(); i += 3)
      std::swap(mesh->indices[i + 1], mesh->indices[i + 2]);
  };
  if (primitive.indices < 0) {
    if (count % 3 != 0) {
      *error = attributes + "POSITION: " + std::to_string(count) + " vertices without indices are not whole triangles";
      return false;
    }
    for (size_t v = 0; v < count; ++v) mesh->indices.push_back(uint32_t(firstVertex + v));
    flipWinding();
    return true;
  }
  auto indices =
      AccessorReader::open(model, primitive.indices, {TINYGLTF_TYPE_SCALAR}, kIndices, pointer + "/indices", error);
  if (!indices) return false;
  if (indices->count() % 3 != 0) {
    *error = pointer + "/indices: " + std::to_string(indices->count()) + " indices are not whole triangles";
    return false;
  }
  for (size_t i = 0; i < indices->count(); ++i) {
    const double index = indices->get(i, 0);
    if (index >= double(count)) {
      *error = pointer + "/indices: index " + std::to_string(uint64_t(index)) + " is past the " +
               std::to_string(count) + " vertices";
      return false;
    }
    mesh->indices.push_back(uint32_t(firstVertex + size_t(index)));
  }
  flipWinding();
  return true;
}

// A mesh as one node places it.
struct Instance {
  int mesh;
  Placement placement;
  std::string from;  // the JSON pointer naming the mesh, for errors
};

// The UV set to generate a primitive's tangents from: that of its material's normal texture when
// the primitive is normal-mapped but has no TANGENT (and has the normals and UVs to derive them
// from); -1 otherwise.
int tangentUvSet(const tinygltf::Model& model, const tinygltf::Primitive& p) {
  if (p.attributes.count("TANGENT") || !p.attributes.count("NORMAL") || p.material < 0 ||
      size_t(p.material) >= model.materials.size())
    return -1;
  const tinygltf::NormalTextureInfo& normal = model.materials[size_t(p.material)].normalTexture;
  if (normal.index < 0) return -1;
  int set = normal.texCoord;
  // KHR_texture_transform's texCoord, when given, replaces the textureInfo's (gltf_materials.cpp).
  if (auto t = normal.extensions.find("KHR_texture_transform");
      t != normal.extensions.end() && t->second.Has("texCoord") && t->second.Get("texCoord").IsNumber())
    set = t->second.Get("texCoord").GetNumberAsInt();
  return (set == 0 || set == 1) && p.attributes.count("TEXCOORD_" + std::to_string(set)) ? set : -1;
}

// What the instances' primitives will build, from the accessors' declared counts.
struct Totals {
  uint64_t vertices = 0;
  uint64_t indices = 0;
  uint64_t primitives = 0;
};

// A small file can place one large mesh many times (or a sparse accessor without data can
// declare a million vertices): the totals are checked against what is left of the budget
// before any vertex is read or built.
bool checkTotals(const tinygltf::Model& model, const std::vector<Instance>& instances, const GltfBudget& left,
                 Totals* totals, std::string* error) {
  const auto declared = [&](int accessor) {
    return accessor >= 0 && size_t(accessor) < model.accessors.size()
               ? uint64_t(model.accessors[size_t(accessor)].count)
               : 0;
  };
  const auto over = [&](const Instance& instance, uint64_t leftCount, uint64_t limit, const char* what) {
    *error = instance.from + ": the file places more than " +
             (leftCount == limit ? std::to_string(limit) + " " + what
                                 : "the " + std::to_string(leftCount) + " " + what + " left of the " +
                                       std::to_string(limit) + " a scene's glTF meshes may hold") +
             " (counting every node's copy)";
    return false;
  };
  Totals sum;
  for (const Instance& instance : instances) {
    if (instance.mesh < 0 || size_t(instance.mesh) >= model.meshes.size()) continue;  // appendMesh names it
    for (const tinygltf::Primitive& p : model.meshes[size_t(instance.mesh)].primitives) {
      const auto position = p.attributes.find("POSITION");
      uint64_t count = position == p.attributes.end() ? 0 : declared(position->second);
      // Generated tangents may split vertices (mikktspace_tangents.h): at most one per corner.
      if (tangentUvSet(model, p) >= 0) count = std::max(count, p.indices >= 0 ? declared(p.indices) : count);
      // Each term is clamped, so the sums cannot wrap however many primitives there are.
      sum.vertices += std::min(count, left.vertices + 1);
      sum.indices += std::min(p.indices >= 0 ? declared(p.indices) : count, left.indices + 1);
      if (sum.vertices > left.vertices) return over(instance, left.vertices, GltfBudget::kMaxVertices, "vertices");
      if (sum.indices > left.indices) return over(instance, left.indices, GltfBudget::kMaxIndices, "indices");
      if (++sum.primitives > left.primitives)
        return over(instance, left.primitives, GltfBudget::kMaxPrimitives, "primitives");
    }
  }
  *totals = sum;
  return true;
}

// The meshes being built: one for the whole file, or one per glTF material (the key: the
// primitive's `material`, -1 for none) when split.
struct Meshes {
  bool split = false;
  std::map<int, Mesh> byMaterial;

  Mesh& of(const tinygltf::Primitive& p) { return byMaterial[split ? std::max(p.material, -1) : 0]; }
};

bool appendMesh(const tinygltf::Model& model, int index, const std::string& from, const Placement& placement,
                Meshes* meshes, std::string* error) {
  if (index < 0 || size_t(index) >= model.meshes.size()) {
    *error = from + ": mesh " + std::to_string(index) + " does not exist";
    return false;
  }
  const tinygltf::Mesh& m = model.meshes[size_t(index)];
  for (size_t p = 0; p < m.primitives.size(); ++p) {
    const std::string pointer = "/meshes/" + std::to_string(index) + "/primitives/" + std::to_string(p);
    const int material = m.primitives[p].material;
    if (meshes->split && material >= 0 && size_t(material) >= model.materials.size()) {
      *error = pointer + "/material: material " + std::to_string(material) + " does not exist";
      return false;
    }
    Mesh& target = meshes->of(m.primitives[p]);
    const size_t firstVertex = target.vertices.size() / abi::kVertexFloats, firstIndex = target.indices.size();
    if (!appendPrimitive(model, m.primitives[p], pointer, placement, &target, error)) return false;
    const int tangentSet = tangentUvSet(model, m.primitives[p]);
    if (tangentSet >= 0 && !generateMikkTSpaceTangents(&target, firstVertex, firstIndex, tangentSet)) {
      *error = pointer + ": MikkTSpace could not generate its tangents (out of memory)";
      return false;
    }
  }
  return true;
}

// A node's transform relative to its parent: `matrix` (column-major), else T · R · S.
bool localTransform(const tinygltf::Node& node, const std::string& pointer, glm::dmat4* out, std::string* error) {
  glm::dmat4 local(1.0);
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16) {
      *error = pointer + "/matrix: expected 16 numbers";
      return false;
    }
    for (int column = 0; column < 4; ++column)
      for (int row = 0; row < 4; ++row) local[column][row] = node.matrix[size_t(column * 4 + row)];
  } else {
    if ((!node.translation.empty() && node.translation.size() != 3) ||
        (!node.rotation.empty() && node.rotation.size() != 4) || (!node.scale.empty() && node.scale.size() != 3)) {
      *error = pointer + ": translation and scale need 3 numbers, rotation 4";
      return false;
    }
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (!node.translation.empty()) t[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1);
    if (!node.rotation.empty()) {
      // Stored x, y, z, w; glm's constructor takes w first. Unit length by the spec: normalised
      // here so a rounding in the file does not scale the mesh.
      const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
      const double length = glm::length(q);
      if (!(length > 0) || !std::isfinite(length)) {
        *error = pointer + "/rotation: not a rotation quaternion";
        return false;
      }
      r = glm::mat4_cast(q / length);
    }
    if (!node.scale.empty()) s = glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    local = t * r * s;
  }
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row)
      if (!std::isfinite(local[column][row])) {
        *error = pointer + ": transform is not finite";
        return false;
      }
  *out = local;
  return true;
}

// The meshes of the default scene's node trees, each with its node's world transform.
// Iterative (a file may nest thousands of nodes); each node at most once, as glTF requires
// (a node reached twice would be a cycle or a shared child).
bool collectScene(const tinygltf::Model& model, int sceneIndex, std::vector<Instance>* instances, std::string* error) {
  struct Pending {
    int node;
    glm::dmat4 parent;
    std::string from;
  };
  std::vector<bool> visited(model.nodes.size(), false);
  std::vector<Pending> stack;
  const std::vector<int>& roots = model.scenes[size_t(sceneIndex)].nodes;
  const std::string scenePointer = "/scenes/" + std::to_string(sceneIndex) + "/nodes";
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::dmat4(1.0), scenePointer});
  while (!stack.empty()) {
    Pending pending = std::move(stack.back());
    stack.pop_back();
    if (pending.node < 0 || size_t(pending.node) >= model.nodes.size()) {
      *error = pending.from + ": node " + std::to_string(pending.node) + " does not exist";
      return false;
    }
    const std::string pointer = "/nodes/" + std::to_string(pending.node);
    if (visited[size_t(pending.node)]) {
      *error = pointer + ": reached twice (the node hierarchy must be a tree)";
      return false;
    }
    visited[size_t(pending.node)] = true;
    const tinygltf::Node& node = model.nodes[size_t(pending.node)];
    glm::dmat4 local;
    if (!localTransform(node, pointer, &local, error)) return false;
    const glm::dmat4 world = pending.parent * local;
    if (node.mesh >= 0) instances->push_back({node.mesh, placementOf(world), pointer + "/mesh"});
    for (auto it = node.children.rbegin(); it != node.children.rend(); ++it)
      stack.push_back({*it, world, pointer + "/children"});
  }
  return true;
}

// loadGltfMesh, or loadGltfMeshesByMaterial when `split`.
std::optional<std::map<int, Mesh>> loadMeshes(const std::string& path, bool split, std::string* error,
                                              const GltfReadOptions& options) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) {
    *error = path + ": error: cannot open the glTF file: it does not exist";
    return std::nullopt;
  }
  if (!fs::is_regular_file(status)) {
    *error = path + ": error: cannot open the glTF file: not a regular file";
    return std::nullopt;
  }
  const std::string extension = fs::path(path).extension().string();
  if (extension != ".gltf" && extension != ".glb") {
    *error = path + ": error: expected a .gltf or .glb file";
    return std::nullopt;
  }
  GltfBudget own;
  GltfBudget& budget = options.budget ? *options.budget : own;
  uint64_t bytesRead = 0;
  std::optional<tinygltf::Model> model =
      gltf::readSource(path, {options.assetRoot, budget.fileBytes}, &bytesRead, error);
  if (!model) return std::nullopt;
  // The scene the file asks for (glTF: `scene`, else the first); a file without scenes is a
  // library of meshes, each drawn as stored.
  if (model->defaultScene >= 0 && size_t(model->defaultScene) >= model->scenes.size()) {
    *error = path + ": error: /scene: scene " + std::to_string(model->defaultScene) + " does not exist";
    return std::nullopt;
  }
  const int scene = model->defaultScene >= 0 ? model->defaultScene : model->scenes.empty() ? -1 : 0;
  std::vector<Instance> instances;
  std::string why;
  bool ok = true;
  if (scene >= 0) {
    ok = collectScene(*model, scene, &instances, &why);
  } else {
    for (size_t m = 0; m < model->meshes.size(); ++m) instances.push_back({int(m), Placement{}, "/meshes"});
  }
  Totals totals;
  ok = ok && checkTotals(*model, instances, budget, &totals, &why);
  Meshes meshes{split, {}};
  if (ok && !split) {
    Mesh& mesh = meshes.byMaterial[0];
    mesh.vertices.reserve(size_t(totals.vertices) * abi::kVertexFloats);
    mesh.indices.reserve(size_t(totals.indices));
  }
  for (size_t i = 0; ok && i < instances.size(); ++i)
    ok = appendMesh(*model, instances[i].mesh, instances[i].from, instances[i].placement, &meshes, &why);
  if (!ok) {
    *error = path + ": error: " + why;
    return std::nullopt;
  }
  std::erase_if(meshes.byMaterial, [](const auto& entry) { return entry.second.indices.empty(); });
  if (meshes.byMaterial.empty()) {
    *error = path + ": error: " +
             (scene >= 0 ? "/scenes/" + std::to_string(scene) + ": no triangles" : "/meshes: no triangles");
    return std::nullopt;
  }
  budget.vertices -= totals.vertices;
  budget.indices -= totals.indices;
  budget.primitives -= totals.primitives;
  budget.fileBytes -= bytesRead;
  return std::move(meshes.byMaterial);
}

}  // namespace

std::optional<Mesh> loadGltfMesh(const std::string& path, std::string* error, const GltfReadOptions& options) {
  auto meshes = loadMeshes(path, false, error, options);
  if (!meshes) return std::nullopt;
  return std::move(meshes->begin()->second);
}

std::optional<std::map<int, Mesh>> loadGltfMeshesByMaterial(const std::string& path, std::string* error,
                                                            const GltfReadOptions& options) {
  return loadMeshes(path, true, error, options);
}

}  // namespace facet::runtime
