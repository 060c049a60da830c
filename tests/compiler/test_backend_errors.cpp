// Errors a backend reports in generated code come back to the user at the material line that
// produced it.
#include <gtest/gtest.h>

#include "facet/compiler/assemble.h"
#include "facet/compiler/backend_errors.h"
#include "facet/compiler/glslang_backend.h"

TEST(BackendErrors, GlslangErrorInSurfaceProgramMapsToMaterialLine) {
  facet::ir::Material material;
  material.name = "m";
  material.shading = "lit";
  material.blending = "opaque";
  // A surface body glslang rejects on its second line: the checker would never emit this, so the
  // test builds it by hand to exercise the real compiler's real error path.
  facet::ir::SurfaceGlsl surface;
  surface.body = "    mediump float a = 0.5;\n    material.roughness = undefined_name * a;\n";
  surface.lineLocs = {{3, 5, 40, 1}, {7, 17, 90, 4}};
  facet::compiler::ParamLayout layout;
  facet::compiler::AssemblyInput input{material, surface, layout, {}, {}, "test"};
  facet::compiler::StageSources sources;
  std::string error;
  ASSERT_TRUE(facet::compiler::assemble(input, facet::compiler::Flavour::GlslEs300, &sources, &error)) << error;

  std::string log;
  ASSERT_FALSE(facet::compiler::checkGlslEs300(sources, &log));
  auto mapped = facet::compiler::mapGlslangErrors(log, sources.fragmentSurfaceLine, surface.lineLocs);
  ASSERT_TRUE(mapped) << log;
  EXPECT_EQ(mapped->loc.line, 7u);
  EXPECT_EQ(mapped->loc.column, 17u);
  EXPECT_NE(mapped->message.find("undefined_name"), std::string::npos) << mapped->message;
}

TEST(BackendErrors, ErrorsOutsideTheSurfaceProgramAreNotBlamedOnTheMaterial) {
  std::vector<facet::ir::SourceLoc> locs = {{3, 5, 40, 1}};
  EXPECT_FALSE(facet::compiler::mapGlslangErrors("ERROR: 0:12: 'x' : undeclared identifier\n", 40, locs));
  EXPECT_FALSE(facet::compiler::mapGlslangErrors("ERROR: 0:41: 'x' : undeclared identifier\n", 40, locs));
  EXPECT_FALSE(facet::compiler::mapGlslangErrors("garbage without a line number\n", 40, locs));
  auto hit = facet::compiler::mapGlslangErrors("WARNING: 0:1: x\nERROR: 0:40: 'x' : undeclared identifier\n", 40, locs);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->loc.line, 3u);
  EXPECT_EQ(hit->message, "'x' : undeclared identifier");
}
