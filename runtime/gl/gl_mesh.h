// A Mesh uploaded into GL buffers with the ABI's vertex layout.
#pragma once

#include <string>

#include "facet/render_backend.h"
#include "gl_objects.h"

namespace facet::runtime::gl {

struct MeshBuffers {
  VertexArray vertexArray;  // records the attribute layout and the index buffer binding
  Buffer vertices;
  Buffer indices;
  GLsizei indexCount = 0;
};

// Checks the mesh (whole vertices, indices in range) and uploads it. Returns false with *error
// set on a malformed mesh: an out-of-range index would read past the buffer in the driver.
bool uploadMesh(const Mesh& mesh, MeshBuffers* buffers, std::string* error);

}  // namespace facet::runtime::gl
