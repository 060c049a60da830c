// glTF 2.0 meshes (.gltf with its buffers, or .glb) as runtime Meshes, read with Debian's
// tinygltf (libtinygltf-dev). Separate from the core (facet_runtime_gltf): an app that has its
// own asset pipeline does not link it.
#pragma once

#include <optional>
#include <string>

#include "facet/render_backend.h"

namespace facet::runtime {

// Every triangle primitive of every mesh in the file, concatenated into one Mesh in
// shader_abi.h's vertex layout: POSITION (required), NORMAL, TANGENT, TEXCOORD_0, TEXCOORD_1
// and COLOR_0 (float, or normalised unsigned byte/short as the glTF spec allows), indices
// (unsigned byte/short/int, or none). A missing attribute takes runtime::Vertex's default.
// Node transforms are not applied: the scene object's position and radius place the mesh's own
// coordinates. Texture coordinates are as stored (glTF: origin at the image's first row).
//
// Only regular files are read: the file itself and the buffers it names, which must lie in its
// folder or below (data: URIs are decoded). Errors name the file and the glTF field, e.g.
// `m.gltf: error: /meshes/0/primitives/0/attributes/NORMAL: expected VEC3 of float`.
std::optional<Mesh> loadGltfMesh(const std::string& path, std::string* error);

}  // namespace facet::runtime
