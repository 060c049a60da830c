#include "facet/runtime/gltf_mesh.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "facet/runtime/mesh.h"
#include "gltf_accessor.h"

namespace facet::runtime {
namespace {

namespace fs = std::filesystem;

// The folder buffers may be read from, for the file-system callbacks.
struct ReadPolicy {
  fs::path folder;
};

bool isUnder(const fs::path& folder, const fs::path& file) {
  const fs::path relative = file.lexically_normal().lexically_relative(folder.lexically_normal());
  return !relative.empty() && *relative.begin() != ".." && !relative.is_absolute();
}

// Existence only: readWholeFile decides what may be read, with the reason in its error.
bool fileExists(const std::string& path, void*) {
  std::error_code ec;
  return fs::exists(path, ec);
}

std::string expandPath(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  const auto* policy = static_cast<const ReadPolicy*>(user);
  std::error_code ec;
  if (!isUnder(policy->folder, path)) {
    if (err) *err += "'" + path + "' is outside the glTF file's folder\n";
    return false;
  }
  // A FIFO or device would block or never end.
  if (!fs::is_regular_file(path, ec)) {
    if (err) *err += "'" + path + "' is not a regular file\n";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    if (err) *err += "cannot open '" + path + "'\n";
    return false;
  }
  out->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return true;
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "writing is not allowed\n";
  return false;
}

// Images are not part of a mesh: not decoded at all.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

using gltf::AccessorReader;

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
constexpr int kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

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

bool appendPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& pointer,
                     const Placement& placement, Mesh* mesh, std::string* error) {
  if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != -1) {
    *error = pointer + "/mode: only triangle lists (4) are supported, not " + std::to_string(primitive.mode);
    return false;
  }
  const auto attribute = [&](const char* name) {
    auto it = primitive.attributes.find(name);
    return it == primitive.attributes.end() ? -1 : it->second;
  };
  const std::string attributes = pointer + "/attributes/";
  if (attribute("POSITION") < 0) {
    *error = attributes + "POSITION: missing (every primitive needs positions)";
    return false;
  }
  auto positions = AccessorReader::open(model, attribute("POSITION"), {TINYGLTF_TYPE_VEC3}, {kFloat}, false,
                                        attributes + "POSITION", error);
  if (!positions) return false;
  const size_t count = positions->count();
  std::optional<AccessorReader> normals, tangents, uv0, uv1, colours;
  struct Optional {
    const char* name;
    std::optional<AccessorReader>* reader;
    std::initializer_list<int> types;
    std::initializer_list<int> components;
  };
  const Optional optional[] = {
      {"NORMAL", &normals, {TINYGLTF_TYPE_VEC3}, {kFloat}},
      {"TANGENT", &tangents, {TINYGLTF_TYPE_VEC4}, {kFloat}},
      {"TEXCOORD_0", &uv0, {TINYGLTF_TYPE_VEC2}, {kFloat, kUByte, kUShort}},
      {"TEXCOORD_1", &uv1, {TINYGLTF_TYPE_VEC2}, {kFloat, kUByte, kUShort}},
      {"COLOR_0", &colours, {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, {kFloat, kUByte, kUShort}},
  };
  for (const Optional& o : optional) {
    if (attribute(o.name) < 0) continue;
    *o.reader = AccessorReader::open(model, attribute(o.name), o.types, o.components, false, attributes + o.name, error);
    if (!*o.reader) return false;
    if ((*o.reader)->count() != count) {
      *error = attributes + o.name + ": " + std::to_string((*o.reader)->count()) + " elements, but POSITION has " +
               std::to_string(count);
      return false;
    }
  }
  const size_t firstVertex = mesh->vertices.size() / abi::kVertexFloats;
  if (firstVertex + count > UINT32_MAX) {
    *error = attributes + "POSITION: more vertices than 32-bit indices address";
    return false;
  }
  for (size_t v = 0; v < count; ++v) {
    Vertex vertex;
    const glm::dvec4 position = placement.world * glm::dvec4(positions->get(v, 0), positions->get(v, 1), positions->get(v, 2), 1);
    for (int c = 0; c < 3; ++c) vertex.position[c] = float(position[c]);
    if (normals) {
      const glm::dvec3 n(normals->get(v, 0), normals->get(v, 1), normals->get(v, 2));
      const glm::dvec3 placed = normalised(placement.normalMatrix * n, n);
      for (int c = 0; c < 3; ++c) vertex.normal[c] = float(placed[c]);
    }
    if (tangents) {
      // Tangents move with the surface (world's 3×3); w gives the bitangent's side, which a
      // mirroring transform flips (glTF 2.0 §3.7.2.1: bitangent = cross(normal, tangent.xyz) · w).
      const glm::dvec3 t(tangents->get(v, 0), tangents->get(v, 1), tangents->get(v, 2));
      const glm::dvec3 placed = normalised(glm::dmat3(placement.world) * t, t);
      for (int c = 0; c < 3; ++c) vertex.tangent[c] = float(placed[c]);
      vertex.tangent[3] = float(tangents->get(v, 3) * (placement.mirrors ? -1.0 : 1.0));
    }
    if (uv0)
      for (int c = 0; c < 2; ++c) vertex.uv0[c] = float(uv0->get(v, c));
    if (uv1)
      for (int c = 0; c < 2; ++c) vertex.uv1[c] = float(uv1->get(v, c));
    if (colours)
      for (int c = 0; c < colours->components(); ++c) vertex.color[c] = float(colours->get(v, c));
    for (float f : vertex.position) {
      if (!std::isfinite(f)) {
        *error = attributes + "POSITION: element " + std::to_string(v) + " is not finite";
        return false;
      }
    }
    appendVertex(*mesh, vertex);
  }
  // A mirroring transform turns counter-clockwise triangles clockwise: swap two corners back.
  const size_t firstIndex = mesh->indices.size();
  const auto flipWinding = [&] {
    if (!placement.mirrors) return;
    for (size_t i = firstIndex; i + 2 < mesh->indices.size(); i += 3) std::swap(mesh->indices[i + 1], mesh->indices[i + 2]);
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
  auto indices = AccessorReader::open(model, primitive.indices, {TINYGLTF_TYPE_SCALAR}, {kUByte, kUShort, kUInt}, true,
                                      pointer + "/indices", error);
  if (!indices) return false;
  if (indices->count() % 3 != 0) {
    *error = pointer + "/indices: " + std::to_string(indices->count()) + " indices are not whole triangles";
    return false;
  }
  for (size_t i = 0; i < indices->count(); ++i) {
    const double index = indices->get(i, 0, false);
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

// A small file can place one large mesh many times (or a sparse accessor without data can
// declare a million vertices): the totals are checked from the accessors' declared counts before
// anything is read. 4 M vertices are 302 MB of runtime vertices (18 floats each).
constexpr uint64_t kMaxVertices = uint64_t(1) << 22;
constexpr uint64_t kMaxIndices = uint64_t(1) << 24;

bool checkTotals(const tinygltf::Model& model, const std::vector<Instance>& instances, std::string* error) {
  uint64_t vertices = 0, indices = 0;
  const auto declared = [&](int accessor) {
    return accessor >= 0 && size_t(accessor) < model.accessors.size() ? uint64_t(model.accessors[size_t(accessor)].count) : 0;
  };
  for (const Instance& instance : instances) {
    if (instance.mesh < 0 || size_t(instance.mesh) >= model.meshes.size()) continue;  // appendMesh names it
    for (const tinygltf::Primitive& p : model.meshes[size_t(instance.mesh)].primitives) {
      const auto position = p.attributes.find("POSITION");
      const uint64_t count = position == p.attributes.end() ? 0 : declared(position->second);
      vertices += std::min(count, kMaxVertices + 1);
      indices += std::min(p.indices >= 0 ? declared(p.indices) : count, kMaxIndices + 1);
      if (vertices > kMaxVertices || indices > kMaxIndices) {
        *error = instance.from + ": the file places more than " +
                 std::to_string(vertices > kMaxVertices ? kMaxVertices : kMaxIndices) +
                 (vertices > kMaxVertices ? " vertices" : " indices") + " (counting every node's copy)";
        return false;
      }
    }
  }
  return true;
}

bool appendMesh(const tinygltf::Model& model, int index, const std::string& from, const Placement& placement,
                Mesh* mesh, std::string* error) {
  if (index < 0 || size_t(index) >= model.meshes.size()) {
    *error = from + ": mesh " + std::to_string(index) + " does not exist";
    return false;
  }
  const tinygltf::Mesh& m = model.meshes[size_t(index)];
  for (size_t p = 0; p < m.primitives.size(); ++p) {
    const std::string pointer = "/meshes/" + std::to_string(index) + "/primitives/" + std::to_string(p);
    if (!appendPrimitive(model, m.primitives[p], pointer, placement, mesh, error)) return false;
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

}  // namespace

std::optional<Mesh> loadGltfMesh(const std::string& path, std::string* error) {
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
  ReadPolicy policy{fs::absolute(fs::path(path), ec).parent_path()};
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({fileExists, expandPath, readWholeFile, writeWholeFile, &policy});
  loader.SetImageLoader(skipImage, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const std::string absolute = (policy.folder / fs::path(path).filename()).string();
  const bool loaded = extension == ".glb" ? loader.LoadBinaryFromFile(&model, &err, &warn, absolute)
                                          : loader.LoadASCIIFromFile(&model, &err, &warn, absolute);
  if (!loaded) {
    while (!err.empty() && err.back() == '\n') err.pop_back();
    *error = path + ": error: " + (err.empty() ? std::string("not a valid glTF 2.0 file") : err);
    return std::nullopt;
  }
  Mesh mesh;
  std::string why;
  // The scene the file asks for (glTF: `scene`, else the first); a file without scenes is a
  // library of meshes, each drawn as stored.
  if (model.defaultScene >= 0 && size_t(model.defaultScene) >= model.scenes.size()) {
    *error = path + ": error: /scene: scene " + std::to_string(model.defaultScene) + " does not exist";
    return std::nullopt;
  }
  const int scene = model.defaultScene >= 0 ? model.defaultScene : model.scenes.empty() ? -1 : 0;
  std::vector<Instance> instances;
  bool ok = true;
  if (scene >= 0) {
    ok = collectScene(model, scene, &instances, &why);
  } else {
    for (size_t m = 0; m < model.meshes.size(); ++m) instances.push_back({int(m), Placement{}, "/meshes"});
  }
  ok = ok && checkTotals(model, instances, &why);
  for (size_t i = 0; ok && i < instances.size(); ++i)
    ok = appendMesh(model, instances[i].mesh, instances[i].from, instances[i].placement, &mesh, &why);
  if (!ok) {
    *error = path + ": error: " + why;
    return std::nullopt;
  }
  if (mesh.indices.empty()) {
    *error = path + ": error: " + (scene >= 0 ? "/scenes/" + std::to_string(scene) + ": no triangles" : "/meshes: no triangles");
    return std::nullopt;
  }
  return mesh;
}

}  // namespace facet::runtime
