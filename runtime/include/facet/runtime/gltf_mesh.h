// glTF 2.0 meshes (.gltf with its buffers, or .glb) as runtime Meshes, read with Debian's
// tinygltf (libtinygltf-dev). Separate from the core (facet_runtime_gltf): an app that has its
// own asset pipeline does not link it.
#pragma once

#include <optional>
#include <string>

#include "facet/render_backend.h"

namespace facet::runtime {

// Every triangle primitive the file's scene draws (`scene`, else the first; without scenes, every
// mesh as stored), concatenated into one Mesh in shader_abi.h's vertex layout: POSITION
// (required), NORMAL, TANGENT, TEXCOORD_0, TEXCOORD_1 and COLOR_0 (float, or normalised unsigned
// byte/short as the glTF spec allows), indices (unsigned byte/short/int, or none), sparse
// accessors applied. A missing attribute takes runtime::Vertex's default.
// Node transforms are applied (matrix, or T · R · S, parents first): positions by the world
// matrix, normals by its inverse transpose, tangents by its 3×3; a mirroring node flips the
// winding and the tangent's w so triangles stay front-facing. A mesh used by two nodes appears
// twice; all copies together hold at most 4 Mi vertices and 16 Mi indices, checked from the
// declared counts before reading. Texture coordinates are as stored (glTF: origin at the image's
// first row).
//
// Only regular files are read: the file itself and the buffers it names, which must lie in its
// folder or below (data: URIs are decoded). Errors name the file and the glTF field, e.g.
// `m.gltf: error: /meshes/0/primitives/0/attributes/NORMAL: expected VEC3 of float`.
std::optional<Mesh> loadGltfMesh(const std::string& path, std::string* error);

}  // namespace facet::runtime
