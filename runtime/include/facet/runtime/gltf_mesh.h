// glTF 2.0 meshes (.gltf with its buffers, or .glb) as runtime Meshes, read with Debian's
// tinygltf (libtinygltf-dev). Separate from the core (facet_runtime_gltf): an app that has its
// own asset pipeline does not link it.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "facet/runtime/render_backend.h"

namespace facet::runtime {

// What glTF meshes may cost: one file's on its own, a scene's files together (SceneFrame shares
// one budget across the distinct files a scene names). A few hundred bytes of JSON can declare a
// million vertices and place them from many nodes, and a scene may name 4096 files: each bound
// is checked from sizes and declared counts before the memory is allocated.
struct GltfBudget {
  // Vertices and indices of the built meshes, every node's copy counted. 4 Mi vertices are
  // 288 MiB of runtime vertices (18 floats each), 16 Mi indices 64 MiB: a mobile scene's whole
  // geometry is far below this, and the GPU holds a second copy.
  static constexpr uint64_t kMaxVertices = uint64_t(1) << 22;
  static constexpr uint64_t kMaxIndices = uint64_t(1) << 24;
  // Primitives placed, every node's copy counted: each is looked up, read and transformed on its
  // own, so many tiny ones cost time the vertex count does not show (4 Mi one-vertex copies from
  // a 200 KB file took 45 s of CPU in the fuzzing build). Real files place hundreds to thousands.
  static constexpr uint64_t kMaxPrimitives = uint64_t(1) << 16;
  // Bytes read from files: the .gltf or .glb and the buffer files it names. 256 MiB holds the
  // largest mesh the counts above allow with positions, normals, tangents and one set of texture
  // coordinates (4 Mi × 48 bytes + 16 Mi × 4 bytes); it is also the image file limit
  // (image_texture.h).
  static constexpr uint64_t kMaxFileBytes = uint64_t(256) << 20;

  uint64_t vertices = kMaxVertices;
  uint64_t indices = kMaxIndices;
  uint64_t primitives = kMaxPrimitives;
  uint64_t fileBytes = kMaxFileBytes;
};

struct GltfReadOptions {
  // The folder the file's buffers may be read from (the scene's asset root, SceneReadOptions);
  // "": the glTF file's own folder.
  std::string assetRoot;
  // What is left to spend, reduced by what this file takes; null: a budget of the file's own.
  GltfBudget* budget = nullptr;
};

// Every triangle primitive the file's scene draws (`scene`, else the first; without scenes, every
// mesh as stored), concatenated into one Mesh in shader_abi.h's vertex layout: POSITION
// (required), NORMAL, TANGENT, TEXCOORD_0, TEXCOORD_1 and COLOR_0 (float, or normalised unsigned
// byte/short as the glTF spec allows), indices (unsigned byte/short/int, or none), sparse
// accessors applied. A missing attribute takes runtime::Vertex's default.
// Node transforms are applied (matrix, or T · R · S, parents first): positions by the world
// matrix, normals by its inverse transpose, tangents by its 3×3; a mirroring node flips the
// winding and the tangent's w so triangles stay front-facing. A mesh used by two nodes appears
// twice, counted twice against the budget. Texture coordinates are as stored (glTF: origin at
// the image's first row).
//
// Values: every float Facet reads must be finite; normals and tangents' xyz are normalised (the
// spec asks for unit length; exporters round) but may not be shorter than 1e-6, where there is
// no direction left to keep; a tangent's w is +1 or -1.
//
// What is refused before tinygltf sees the bytes (docs/security.md, "Files"): a file over the
// budget's bytes; JSON nested more than kMaxJsonDepth deep or that tinygltf would expand past
// 256 MiB in memory; a .glb whose header or chunks do not fit the file exactly; asset versions
// other than 2.x (and minVersion above 2.0), extensionsRequired naming any extension but
// KHR_mesh_quantization (whose integer attribute types a file that uses it may have), byteStride outside 4..252 or not
// a multiple of 4, a buffer URI that is not a relative path or a base64 data: URI (NUL, %00, malformed %-escapes, other
// schemes, queries). Only regular files are read: the file itself and its buffers, which must lie in the asset root
// (real paths: symbolic links followed); a path outside gets the same error whether or not it
// exists. Image files the glTF names are never opened.
//
// Errors name the file and the place: `m.gltf:12:7: error: ...` for the JSON's syntax and depth
// (for a .glb, the line and column in its JSON chunk), else `m.gltf: error: <JSON pointer>: ...`,
// e.g. `m.gltf: error: /meshes/0/primitives/0/attributes/NORMAL: /accessors/1 element 7 is not finite`.
std::optional<Mesh> loadGltfMesh(const std::string& path, std::string* error, const GltfReadOptions& options = {});

// The same triangles split by the glTF material their primitive names (the key: its index in
// `materials`, -1 for primitives without one), for drawing each with its own material: one read
// of the file and one budget for all of them. Only materials some placed primitive uses appear.
std::optional<std::map<int, Mesh>> loadGltfMeshesByMaterial(const std::string& path, std::string* error,
                                                            const GltfReadOptions& options = {});

}  // namespace facet::runtime
