#include "facet/gpu_stats/package_pairs.h"

#include <algorithm>

namespace facet::gpu_stats {

std::vector<ShaderPair> glslEsPairs(const package::Package& pkg, const std::vector<std::string>& keys) {
  std::vector<ShaderPair> pairs;
  for (const package::Variant& v : pkg.variants) {
    if (!keys.empty() && std::find(keys.begin(), keys.end(), v.key) == keys.end()) continue;
    ShaderPair pair{v.key, "", ""};
    bool vertex = false, fragment = false;
    for (const package::Shader& s : v.shaders) {
      if (s.target != package::Target::GlslEs300) continue;
      std::string text(s.code.begin(), s.code.end());
      if (s.stage == package::Stage::Vertex) {
        pair.vertexGlsl = std::move(text);
        vertex = true;
      } else {
        pair.fragmentGlsl = std::move(text);
        fragment = true;
      }
    }
    if (vertex && fragment) pairs.push_back(std::move(pair));
  }
  return pairs;
}

}  // namespace facet::gpu_stats
