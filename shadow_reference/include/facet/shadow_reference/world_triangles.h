// A scene's triangles in world space, in double precision, from the meshes the renderer draws:
// the runtime's built-in meshes (makeSphere, makePlane, makeBox with the renderer's
// tessellation) and glTF files (loadGltfMesh), each placed by the scene's modelMatrix.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "facet/scene/scene.h"

namespace facet::shadow_reference {

struct WorldTriangle {
  glm::dvec3 a, b, c;   // in the mesh's winding
  uint32_t object = 0;  // index into the scene's objects
};

// Every triangle of every object, in scene order. A triangle that the model matrix collapses
// (zero area in double) is kept: it cannot be hit, and indices stay the mesh's. Errors name the
// object: "object 3: <the mesh loader's error>".
std::optional<std::vector<WorldTriangle>> buildWorldTriangles(const runtime::Scene& scene, std::string* error);

}  // namespace facet::shadow_reference
