#include "facet/shadow_reference/world_triangles.h"

#include <map>

#include "facet/abi/shader_abi.h"
#include "facet/runtime/gltf_mesh.h"
#include "facet/runtime/mesh.h"

namespace facet::shadow_reference {

std::optional<std::vector<WorldTriangle>> buildWorldTriangles(const runtime::Scene& scene, std::string* error) {
  std::vector<WorldTriangle> out;
  // One mesh per built-in name or file, as SceneFrame builds them (one glTF budget shared by the
  // scene's files); the vertex-cache reordering the renderer applies after moves no vertex.
  std::map<std::string, runtime::Mesh> meshes;
  runtime::GltfBudget budget;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const runtime::SceneObject& o = scene.objects[i];
    auto found = meshes.find(o.mesh);
    if (found == meshes.end()) {
      std::optional<runtime::Mesh> made = o.mesh == "sphere"  ? runtime::makeSphere()
                                          : o.mesh == "plane" ? runtime::makePlane()
                                          : o.mesh == "box"
                                              ? runtime::makeBox()
                                              : runtime::loadGltfMesh(o.mesh, error, {scene.assetRoot, &budget});
      if (!made) {
        *error = "object " + std::to_string(i) + ": " + *error;
        return std::nullopt;
      }
      found = meshes.emplace(o.mesh, std::move(*made)).first;
    }
    const runtime::Mesh& mesh = found->second;
    const glm::dmat4 model = runtime::modelMatrix(o);
    auto vertex = [&](uint32_t index) {
      const float* p = &mesh.vertices[size_t(index) * abi::kVertexFloats];
      return glm::dvec3(model * glm::dvec4(p[0], p[1], p[2], 1.0));
    };
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
      out.push_back({vertex(mesh.indices[t]), vertex(mesh.indices[t + 1]), vertex(mesh.indices[t + 2]), uint32_t(i)});
  }
  return out;
}

}  // namespace facet::shadow_reference
