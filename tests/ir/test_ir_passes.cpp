// IR passes and value-range analysis.
#include <gtest/gtest.h>

#include <cmath>

#include "facet/ir/check.h"
#include "facet/ir/emit_glsl.h"
#include "facet/ir/passes.h"
#include "facet/ir/ranges.h"

namespace {

using facet::ir::Interval;

facet::ir::Material checked(const std::string& text) {
  facet::ir::SourceFile file{"t.mat", text};
  facet::ir::Diagnostics diags(file);
  auto m = facet::ir::compileSource(file, diags);
  EXPECT_TRUE(m) << diags.format();
  return m ? *m : facet::ir::Material{};
}

// The range of output `name` after optimisation, as one interval over its components.
Interval outputRange(const std::string& params, const std::string& output, const std::string& expr) {
  auto m = checked("material m {\n" + params + "\n surface { " + output + " = " + expr + " }\n}\n");
  facet::ir::optimize(m);
  auto r = facet::ir::analyse_ranges(m).output(output);
  EXPECT_TRUE(r);
  return r ? r->hull() : Interval{};
}

void expectInterval(Interval got, double lo, double hi) {
  EXPECT_NEAR(got.lo, lo, 1e-12);
  EXPECT_NEAR(got.hi, hi, 1e-12);
}

}  // namespace

TEST(Passes, FoldConstantsEvaluatesBuiltinsAndConstructors) {
  auto m = checked("material m { surface { baseColor = vec3(pow(2.0, 3.0), sqrt(16.0), 0.5) * 0.5 } }");
  facet::ir::optimize(m);
  EXPECT_EQ(facet::ir::emitSurface(m).body, "    material.baseColor = vec3(4.0, 2.0, 0.25);\n");
}

TEST(Passes, FoldConstantsLeavesNonFiniteResultsToTheGpu) {
  auto m = checked("material m { surface { roughness = 1.0 / 0.0 } }");
  facet::ir::optimize(m);
  EXPECT_NE(facet::ir::emitSurface(m).body.find("1.0 / 0.0"), std::string::npos);
}

TEST(Passes, ConstantConditionSelectsOneBranch) {
  auto m = checked("material m { param r: float = 0.5\n surface { roughness = 1.0 > 2.0 ? 0.2 : params.r } }");
  facet::ir::optimize(m);
  EXPECT_EQ(facet::ir::emitSurface(m).body, "    material.roughness = params.r;\n");
}

TEST(Passes, FoldingExposesCommonSubexpressions) {
  // (2.0 * 0.5) folds to 1.0, after which both products are params.r * 1.0... one value.
  auto m = checked(R"(material m {
    param r: float = 0.5
    surface { roughness = params.r * (2.0 * 0.5) + params.r * 1.0 }
})");
  facet::ir::optimize(m);
  std::string body = facet::ir::emitSurface(m).body;
  EXPECT_EQ(body.find("params.r * 1.0"), body.rfind("params.r * 1.0")) << body;
}

TEST(Passes, DeadCodeEliminationMarksUnreadParametersUnused) {
  auto m = checked(R"(material m {
    param a: float = 0.5
    param b: float = 0.5
    surface {
        let onlyForNothing = params.b * 3.0
        roughness = params.a
    }
})");
  facet::ir::optimize(m);
  EXPECT_TRUE(m.params[0].used);
  EXPECT_FALSE(m.params[1].used);
  for (facet::ir::ValueId id = 0; id < m.surface.size(); ++id)
    EXPECT_NE(m.surface.value(id).name, "b") << "a value still reads params.b";
}

TEST(Ranges, DeclaredParameterRangesPropagateThroughArithmetic) {
  expectInterval(outputRange("param r: float = 0.5 in [0.2, 0.6]", "roughness", "params.r * 2.0 - 0.1"), 0.3, 1.1);
  expectInterval(outputRange("param c: color = vec3(0.5)", "baseColor", "params.c * 0.5"), 0.0, 0.5);
}

TEST(Ranges, PowUsesTheCornersOfItsArguments) {
  expectInterval(outputRange("param x: float = 0.5 in [0.5, 2]\n param e: float = 2 in [1, 3]", "roughness",
                             "pow(params.x, params.e)"),
                 0.125, 8.0);
  // A negative base has no defined pow in GLSL: unknown.
  EXPECT_FALSE(outputRange("param x: float = 0 in [-1, 1]", "roughness", "pow(params.x, 2.0)").bounded());
}

TEST(Ranges, DivisionByAnIntervalHoldingZeroIsUnbounded) {
  expectInterval(outputRange("param d: float = 2 in [1, 4]", "roughness", "1.0 / params.d"), 0.25, 1.0);
  EXPECT_FALSE(outputRange("param d: float = 0 in [-1, 1]", "roughness", "1.0 / params.d").bounded());
}

TEST(Ranges, NormalizeAndTrigonometryAreWithinUnitBounds) {
  expectInterval(outputRange("param v: vec3 = vec3(1.0)", "baseColor", "normalize(params.v)"), -1.0, 1.0);
  expectInterval(outputRange("", "roughness", "sin(vertex.worldPosition.x) * 0.5 + 0.5"), 0.0, 1.0);
  expectInterval(outputRange("", "roughness", "dot(vertex.normal, vertex.normal)"), 0.0, 3.0);
}

// Vertex inputs and textures carry the ranges of their encodings: unit vectors in [-1, 1], vertex
// colours and colour textures in [0, 1], a normal map's decoded xyz in [-1, 1].
TEST(Ranges, VertexInputsAndTexturesHaveTheirEncodingRanges) {
  expectInterval(outputRange("", "roughness", "vertex.viewDirection.z"), -1.0, 1.0);
  expectInterval(outputRange("", "roughness", "vertex.color.a"), 0.0, 1.0);
  expectInterval(outputRange("param t: texture(linear) = vec4(1.0)", "roughness", "sample(params.t, vertex.uv0).g"),
                 0.0, 1.0);
  expectInterval(outputRange("param n: texture(normal) = vec4(0.5, 0.5, 1.0, 1.0)", "roughness",
                             "sample(params.n, vertex.uv0).x * 0.5"),
                 -64.0 / 127.0, 0.5);
  EXPECT_FALSE(outputRange("", "roughness", "vertex.uv1.x").bounded());
}

TEST(Ranges, MixWithUnitWeightStaysBetweenItsEnds) {
  expectInterval(outputRange("param a: float = 0.2 in [0.1, 0.3]\n param t: float = 0.5 in [0, 1]", "roughness",
                             "mix(params.a, 0.9, params.t)"),
                 0.1, 0.9);
}

TEST(Ranges, UnrangedParametersAndPositionsAreUnbounded) {
  EXPECT_FALSE(outputRange("param s: float = 1.0", "roughness", "params.s").bounded());
  expectInterval(outputRange("param s: float = 1.0", "roughness", "saturate(params.s * vertex.worldPosition.y)"), 0.0,
                 1.0);
}

// The precision policy reads the ranges: a value that can leave fp16's finite range (65504) is
// computed in highp even in a mediump tier; a value proven small, or one with no declared range,
// takes the tier's precision.
TEST(PrecisionPolicy, ValuesRangedBeyondFp16StayHighp) {
  auto m = checked(R"(material m {
    param distance: float = 1000.0 in [0, 100000]
    param scale: float = 0.5 in [0, 1]
    param free: float = 1.0
    surface {
        let far = params.distance * 2.0
        let near = params.scale * 2.0
        let open = params.free * 2.0
        roughness = saturate(far / 200000.0 + near + open)
    }
})");
  facet::ir::optimize(m);
  std::string body = facet::ir::emitSurface(m).body;
  EXPECT_NE(body.find("    highp float m_far = params.distance * 2.0;"), std::string::npos) << body;
  EXPECT_NE(body.find("    float m_near = params.scale * 2.0;"), std::string::npos) << body;
  EXPECT_NE(body.find("    float m_open = params.free * 2.0;"), std::string::npos) << body;
}
