#include "facet/runtime/gltf_mesh.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "facet/runtime/mesh.h"

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

// One accessor's elements as floats, bounds-checked against its buffer.
class AccessorReader {
 public:
  // `allowed`: component types accepted (float, or normalised unsigned integers).
  static std::optional<AccessorReader> open(const tinygltf::Model& model, int index, std::initializer_list<int> types,
                                            std::initializer_list<int> components, bool integers,
                                            const std::string& field, std::string* error) {
    if (index < 0 || size_t(index) >= model.accessors.size()) {
      *error = field + ": accessor " + std::to_string(index) + " does not exist";
      return std::nullopt;
    }
    const tinygltf::Accessor& a = model.accessors[size_t(index)];
    if (std::find(types.begin(), types.end(), a.type) == types.end() ||
        std::find(components.begin(), components.end(), a.componentType) == components.end() ||
        (!integers && a.normalized != (a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT))) {
      *error = field + ": accessor " + std::to_string(index) + " has a type or component type this attribute cannot have";
      return std::nullopt;
    }
    if (a.sparse.isSparse) {
      *error = field + ": sparse accessors are not supported";
      return std::nullopt;
    }
    if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size()) {
      *error = field + ": accessor " + std::to_string(index) + " has no buffer view";
      return std::nullopt;
    }
    const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) {
      *error = field + ": buffer view " + std::to_string(a.bufferView) + " names no buffer";
      return std::nullopt;
    }
    const std::vector<unsigned char>& data = model.buffers[size_t(view.buffer)].data;
    AccessorReader r;
    r.count_ = a.count;
    r.components_ = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    r.componentType_ = a.componentType;
    r.componentSize_ = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType)));
    const int stride = a.ByteStride(view);
    // Everything in size_t: a declared offset or count near 2^32 must not wrap the check.
    const size_t elementSize = r.componentSize_ * size_t(r.components_);
    const size_t start = view.byteOffset + a.byteOffset;
    const size_t viewEnd = view.byteOffset + view.byteLength;
    if (stride <= 0 || size_t(stride) < elementSize || viewEnd > data.size() ||
        (a.count > 0 && start + size_t(stride) * (a.count - 1) + elementSize > viewEnd)) {
      *error = field + ": accessor " + std::to_string(index) + " reaches past its buffer view or buffer";
      return std::nullopt;
    }
    r.base_ = data.data() + start;
    r.stride_ = size_t(stride);
    return r;
  }

  size_t count() const { return count_; }
  int components() const { return components_; }

  // Component c of element e: floats as stored, unsigned integers normalised to [0, 1] (or, for
  // indices, as integers when normalise is false).
  double get(size_t e, int c, bool normalise = true) const {
    const unsigned char* p = base_ + e * stride_ + size_t(c) * componentSize_;
    switch (componentType_) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p, 4);
        return f;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalise ? p[0] / 255.0 : p[0];
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return normalise ? v / 65535.0 : v;
      }
      default: {  // UNSIGNED_INT, indices only
        uint32_t v;
        std::memcpy(&v, p, 4);
        return v;
      }
    }
  }

 private:
  const unsigned char* base_ = nullptr;
  size_t stride_ = 0;
  size_t count_ = 0;
  int components_ = 0;
  int componentType_ = 0;
  size_t componentSize_ = 0;
};

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
constexpr int kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

bool appendPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& pointer,
                     Mesh* mesh, std::string* error) {
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
    for (int c = 0; c < 3; ++c) vertex.position[c] = float(positions->get(v, c));
    if (normals)
      for (int c = 0; c < 3; ++c) vertex.normal[c] = float(normals->get(v, c));
    if (tangents)
      for (int c = 0; c < 4; ++c) vertex.tangent[c] = float(tangents->get(v, c));
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
  if (primitive.indices < 0) {
    if (count % 3 != 0) {
      *error = attributes + "POSITION: " + std::to_string(count) + " vertices without indices are not whole triangles";
      return false;
    }
    for (size_t v = 0; v < count; ++v) mesh->indices.push_back(uint32_t(firstVertex + v));
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
  for (size_t m = 0; m < model.meshes.size(); ++m) {
    for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
      const std::string pointer = "/meshes/" + std::to_string(m) + "/primitives/" + std::to_string(p);
      std::string why;
      if (!appendPrimitive(model, model.meshes[m].primitives[p], pointer, &mesh, &why)) {
        *error = path + ": error: " + why;
        return std::nullopt;
      }
    }
  }
  if (mesh.indices.empty()) {
    *error = path + ": error: /meshes: no triangles";
    return std::nullopt;
  }
  return mesh;
}

}  // namespace facet::runtime
