#include "facet/runtime/background.h"

#include <algorithm>
#include <cstring>
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "facet/runtime/mesh.h"

namespace facet::runtime {
namespace {

// GL normalized device coordinates of one triangle covering [-1, 1]²; the shader takes them as
// they are (templates/post_background.vert.glsl).
const Mesh& fullScreenTriangle() {
  static const Mesh mesh = [] {
    Mesh m;
    const float corners[3][2] = {{-1, -1}, {3, -1}, {-1, 3}};
    for (const auto& c : corners) {
      Vertex v;
      v.position[0] = c[0];
      v.position[1] = c[1];
      appendVertex(m, v);
    }
    m.indices = {0, 1, 2};
    return m;
  }();
  return mesh;
}

}  // namespace

abi::BackgroundParams backgroundParams(const float viewProjection[16], const BackgroundSettings& settings) {
  // M maps GL clip to world (homogeneous). The eye E = M · (0, 0, 1, 0): the one point every
  // pixel's ray passes through (at infinity, the view direction, for an orthographic camera). The
  // ray of NDC (x, y) joins E and the far-plane point F = M · (x, y, 1, 1), so its direction
  // F.xyz · E.w − E.xyz · F.w is linear in (x, y): D = [E.w · I | −E.xyz] · M. Its sign is that of
  // F.w · E.w, the same over the whole frustum; it is fixed by the centre ray's, which must point
  // from the near plane to the far one. In double: M comes from a float matrix with a near plane
  // thousands of times closer than the far one.
  const glm::dmat4 m = glm::inverse(glm::dmat4(glm::make_mat4(viewProjection)));
  const glm::dvec4 eye = m * glm::dvec4(0, 0, 1, 0);
  glm::dmat4 join(0.0);
  for (int i = 0; i < 3; ++i) {
    join[i][i] = eye.w;
    join[3][i] = -eye[i];
  }
  glm::dmat4 d = join * m;
  const glm::dvec4 nearCentre = m * glm::dvec4(0, 0, -1, 1), farCentre = m * glm::dvec4(0, 0, 1, 1);
  const glm::dvec3 forward = glm::dvec3(farCentre) / farCentre.w - glm::dvec3(nearCentre) / nearCentre.w;
  if (glm::dot(glm::dvec3(d * glm::dvec4(0, 0, 1, 1)), forward) < 0) d = -d;
  abi::BackgroundParams params{};
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row) params.clipToDirection[column * 4 + row] = float(d[column][row]);
  params.lodIntensity[0] = settings.lod;
  params.lodIntensity[1] = settings.intensity;
  return params;
}

void backgroundDirection(const abi::BackgroundParams& params, float x, float y, float direction[3]) {
  const float* d = params.clipToDirection;
  for (int row = 0; row < 3; ++row) direction[row] = d[row] * x + d[4 + row] * y + d[8 + row] + d[12 + row];
}

DrawItem backgroundDraw(const float viewProjection[16], const BackgroundSettings& settings) {
  DrawItem draw;
  draw.mesh = &fullScreenTriangle();
  draw.program = &backgroundProgram();
  draw.instances = {kIdentityInstance};
  const abi::BackgroundParams params = backgroundParams(viewProjection, settings);
  draw.materialParams.resize(sizeof params);
  std::memcpy(draw.materialParams.data(), &params, sizeof params);
  draw.atFarPlane = true;
  return draw;
}

void addBackground(FrameDesc* frame, const BackgroundSettings& settings) {
  auto firstBlended = std::find_if(frame->draws.begin(), frame->draws.end(),
                                   [](const DrawItem& d) { return d.blending != Blending::Opaque; });
  frame->draws.insert(firstBlended, backgroundDraw(frame->frame.viewProjection, settings));
}

}  // namespace facet::runtime
