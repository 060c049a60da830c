// The material language front end: diagnostics users read, and facts about the IR.
#include <gtest/gtest.h>

#include "facet/ir/check.h"
#include "facet/ir/emit_glsl.h"
#include "facet/ir/passes.h"
#include "test_diagnostics.h"

using facet::test::diagnosticsFor;

namespace {

std::optional<facet::ir::Material> checkText(const std::string& text, std::string* diagnostics = nullptr) {
  facet::ir::SourceFile file{"test.mat", text};
  facet::ir::Diagnostics diags(file);
  auto m = facet::ir::compileSource(file, diags);
  if (diagnostics) *diagnostics = diags.format();
  return m;
}

const char* kValid = R"(material ok {
    param roughness: float = 0.5 in [0, 1]
    surface {
        roughness = params.roughness
    }
}
)";

}  // namespace

TEST(Language, ValidMaterialHasNoDiagnostics) {
  std::string d;
  ASSERT_TRUE(checkText(kValid, &d).has_value());
  EXPECT_EQ(d, "");
}

TEST(Language, SyntaxErrorReportsFileLineColumnAndCaret) {
  std::string d = diagnosticsFor("material m {\n    param x: float = \n}\n", "bad.mat");
  EXPECT_EQ(d,
            "bad.mat:3:1: error: expected an expression, found '}' [parse]\n"
            "    }\n"
            "    ^\n");
}

TEST(Language, UnknownParameterSuggestsTheClosestName) {
  std::string d = diagnosticsFor(
      "material brick {\n  param roughness: float = 0.5\n  surface {\n    roughness = params.rougness * 0.5\n  }\n}\n",
      "brick.mat");
  EXPECT_NE(d.find("brick.mat:4:24: error: unknown parameter 'rougness'; did you mean 'roughness'? [unknown-name]\n"
                   "        roughness = params.rougness * 0.5\n"
                   "                           ^~~~~~~~\n"),
            std::string::npos)
      << d;
}

TEST(Language, SeveralErrorsAreReportedInOneRun) {
  std::string d = diagnosticsFor(R"(material m {
    param a: flaot = 1.0
    surface {
        baseColor = 1.0
        metalic = 0.0
        roughness = nope
    }
}
)");
  EXPECT_NE(d.find("unknown parameter type 'flaot'; did you mean 'float'?"), std::string::npos) << d;
  EXPECT_NE(d.find("output 'baseColor' is vec3 but the value is float"), std::string::npos) << d;
  EXPECT_NE(d.find("unknown surface output 'metalic'; did you mean 'metallic'?"), std::string::npos) << d;
  EXPECT_NE(d.find("unknown name 'nope'"), std::string::npos) << d;
}

TEST(Language, DefaultOutsideDeclaredRangeIsAnError) {
  std::string d =
      diagnosticsFor("material m {\n  param r: float = 1.5 in [0, 1]\n  surface { roughness = params.r }\n}\n");
  EXPECT_NE(d.find("test.mat:2:20: error: default value 1.5 is outside the declared range [0, 1]"), std::string::npos)
      << d;
}

TEST(Language, UseBeforeDefinitionNamesTheLaterLine) {
  std::string d = diagnosticsFor("material m {\n  surface {\n    roughness = r\n    let r = 0.5\n  }\n}\n");
  EXPECT_NE(d.find("test.mat:3:17: error: 'r' is used before its definition at line 4"), std::string::npos) << d;
}

TEST(Language, UnusedParameterIsAWarningNotAnError) {
  std::string d;
  ASSERT_TRUE(
      checkText("material m {\n  param unused: float = 1.0\n  surface { roughness = 0.5 }\n}\n", &d).has_value());
  EXPECT_NE(d.find("test.mat:2:9: warning: parameter 'unused' is never used [unused-param]"), std::string::npos) << d;
}

TEST(Language, ColourParametersAreStoredLinear) {
  auto m = checkText("material m {\n  param c: color = vec3(0.5, 1.0, 0.0)\n  surface { baseColor = params.c }\n}\n");
  ASSERT_TRUE(m);
  ASSERT_EQ(m->params[0].defaultValue.size(), 3u);
  EXPECT_NEAR(m->params[0].defaultValue[0], 0.21404114, 1e-7);  // sRGB 0.5 -> linear
  EXPECT_DOUBLE_EQ(m->params[0].defaultValue[1], 1.0);
  EXPECT_DOUBLE_EQ(m->params[0].defaultValue[2], 0.0);
}

TEST(Language, IdenticalExpressionsShareOneValue) {
  auto m = checkText(R"(material m {
    param r: float = 0.5
    surface {
        let a = params.r * 2.0
        let b = params.r * 2.0
        roughness = a + b
    }
}
)");
  ASSERT_TRUE(m);
  std::string glsl = facet::ir::emitSurface(*m).body;
  // One multiply, reused: the second let names the same value.
  EXPECT_EQ(glsl.find("params.r * 2.0"), glsl.rfind("params.r * 2.0")) << glsl;
}

TEST(Language, ConstantsAreFoldedAndUnusedLetsEmitNothing) {
  auto m = checkText(R"(material m {
    param r: float = 0.5
    surface {
        let unused = sin(params.r)
        roughness = 0.25 * 2.0
    }
}
)");
  ASSERT_TRUE(m);
  facet::ir::optimize(*m);
  std::string glsl = facet::ir::emitSurface(*m).body;
  EXPECT_EQ(glsl, "    material.roughness = 0.5;\n");
  EXPECT_FALSE(m->params[0].used);
}

TEST(Language, HostileInputGetsErrorsNotCrashes) {
  std::string deepParens = "material m { surface { roughness = " + std::string(100000, '(') + "1" + " } }";
  EXPECT_NE(diagnosticsFor(deepParens).find("error:"), std::string::npos);

  std::string longChain = "material m { surface { roughness = 1";
  for (int i = 0; i < 100000; ++i) longChain += " + 1";
  longChain += " } }";
  EXPECT_NE(diagnosticsFor(longChain).find("operations deep"), std::string::npos);

  std::string binary;
  for (int i = 0; i < 4096; ++i) binary += char((i * 7919) & 0xff);
  EXPECT_NE(diagnosticsFor(binary).find("error:"), std::string::npos);

  EXPECT_NE(diagnosticsFor("").find("error: expected 'material'"), std::string::npos);
  EXPECT_NE(diagnosticsFor(std::string("material m {\0}", 14)).find("byte 0x00"), std::string::npos);
  EXPECT_NE(
      diagnosticsFor("material m { param x: float = 1e999 surface { roughness = params.x } }").find("out of range"),
      std::string::npos);
}

TEST(Language, TexturesAreOnlyReadThroughSample) {
  std::string d = diagnosticsFor(R"(material m {
    param t: texture(srgb) = vec4(1.0)
    param u: texture = vec4(1.0)
    surface {
        baseColor = sample(params.t, 0.5).rgb
        roughness = (params.t * 2.0).x
        metallic = sample(params.t, vertex.uv0).x
    }
}
)");
  EXPECT_NE(d.find("a texture parameter names its colour space: texture(srgb), texture(linear) or texture(normal)"),
            std::string::npos)
      << d;
  EXPECT_NE(d.find("the second argument of 'sample' is a vec2 texture coordinate, not float"), std::string::npos) << d;
  EXPECT_NE(d.find("a texture can only be read with sample(texture, uv)"), std::string::npos) << d;
  EXPECT_EQ(d.find("test.mat:7:"), std::string::npos) << "the valid sample() line must not be reported: " << d;
}

// A normal map is read as a decoded tangent-space vec3, never as colour; lit-only outputs of an
// unlit material are dropped with a warning rather than silently compiled.
TEST(Language, NormalMapsSampleAsVec3AndUnlitIgnoresLightingOutputs) {
  std::string d = diagnosticsFor(R"(material m {
    param n: texture(normal) = vec4(0.5, 0.5, 1.0, 1.0)
    surface {
        alpha = sample(params.n, vertex.uv0).a
        normal = sample(params.n, vertex.uv0)
    }
}
)");
  EXPECT_NE(d.find("test.mat:4:46: error: 'a' is not a swizzle of a vec3"), std::string::npos) << d;
  EXPECT_EQ(d.find("test.mat:5:"), std::string::npos) << "normal = sample(normal map) is valid: " << d;
  d = diagnosticsFor(R"(material m {
    shading unlit
    surface {
        baseColor = vertex.color.rgb
        roughness = 0.5
    }
}
)");
  EXPECT_NE(d.find("test.mat:5:9: warning: output 'roughness' has no effect on an unlit material [unused-output]"),
            std::string::npos)
      << d;
  EXPECT_EQ(d.find("error"), std::string::npos) << d;
}

// The clear coat's roughness and normal count wherever clearCoat is written, before or after them;
// without it they are dropped with a warning at their line, and the coat's tier choice is checked.
TEST(Language, ClearCoatOutputsNeedClearCoat) {
  std::string d;
  auto coated = checkText(R"(material m {
    tier low { clear_coat = none }
    surface {
        clearCoatRoughness = 0.2
        clearCoat = 1.0
    }
}
)",
                          &d);
  ASSERT_TRUE(coated) << d;
  EXPECT_EQ(d, "");
  EXPECT_EQ(coated->surface.outputs.count("clearCoatRoughness"), 1u);
  auto bare = checkText(R"(material m {
    surface {
        clearCoatRoughness = 0.2
    }
}
)",
                        &d);
  ASSERT_TRUE(bare) << d;
  EXPECT_NE(d.find("test.mat:3:9: warning: output 'clearCoatRoughness' has no effect without 'clearCoat' "
                   "[unused-output]"),
            std::string::npos)
      << d;
  EXPECT_EQ(bare->surface.outputs.count("clearCoatRoughness"), 0u);
  d = diagnosticsFor("material m { tier mid { clear_coat = ambiant }\n surface { clearCoat = 1.0 } }");
  EXPECT_NE(d.find("error: unknown clear_coat option 'ambiant'; did you mean 'ambient'?"), std::string::npos) << d;
}

// anisotropyDirection counts wherever anisotropy is written; without it it is dropped with a
// warning at its line, and anisotropy's tier choice is checked.
TEST(Language, AnisotropyDirectionNeedsAnisotropy) {
  std::string d;
  auto brushed = checkText(R"(material m {
    tier mid { anisotropy = none }
    surface {
        anisotropyDirection = vec3(0.0, 1.0, 0.0)
        anisotropy = -0.5
    }
}
)",
                           &d);
  ASSERT_TRUE(brushed) << d;
  EXPECT_EQ(d, "");
  EXPECT_EQ(brushed->surface.outputs.count("anisotropyDirection"), 1u);
  auto bare = checkText(R"(material m {
    surface {
        anisotropyDirection = vec3(0.0, 1.0, 0.0)
    }
}
)",
                        &d);
  ASSERT_TRUE(bare) << d;
  EXPECT_NE(d.find("test.mat:3:9: warning: output 'anisotropyDirection' has no effect without 'anisotropy' "
                   "[unused-output]"),
            std::string::npos)
      << d;
  EXPECT_EQ(bare->surface.outputs.count("anisotropyDirection"), 0u);
  d = diagnosticsFor("material m { tier low { anisotropy = bent_ib }\n surface { anisotropy = 1.0 } }");
  EXPECT_NE(d.find("error: unknown anisotropy option 'bent_ib'; did you mean 'bent_ibl'?"), std::string::npos) << d;
}

TEST(Language, TierOverridesAreCheckedWhereTheyAreWritten) {
  std::string d = diagnosticsFor(R"(material m {
    tier reference { specular = zioma }
    tier hihg { specular = zioma }
    tier mid { speculr = zioma }
    tier mid { diffuse = vertx }
    tier high { specular = lutt }
    tier high { diffuse = vertex; diffuse = pixel }
    tier low { specular = zioma }
    tier mid { specular = lut }
    surface { roughness = 0.5 }
}
)");
  EXPECT_NE(d.find("test.mat:2:10: error: the reference tier is the ground truth"), std::string::npos) << d;
  EXPECT_NE(d.find("test.mat:3:10: error: unknown tier 'hihg'; did you mean 'high'?"), std::string::npos) << d;
  EXPECT_NE(d.find("test.mat:4:16: error: unknown tier choice 'speculr'; did you mean 'specular'?"), std::string::npos)
      << d;
  EXPECT_NE(d.find("test.mat:5:26: error: unknown diffuse option 'vertx'; did you mean 'vertex'?"), std::string::npos)
      << d;
  EXPECT_NE(d.find("test.mat:6:28: error: unknown specular option 'lutt'; did you mean 'lut'?"), std::string::npos)
      << d;
  EXPECT_NE(d.find("test.mat:7:35: error: tier 'high' already sets 'diffuse'"), std::string::npos) << d;
  // Every tier and option is built now: the low tier's override and `lut` are accepted silently.
  EXPECT_EQ(d.find("test.mat:8:"), std::string::npos) << d;
  EXPECT_EQ(d.find("test.mat:9:"), std::string::npos) << d;
}

TEST(Language, AlphaCutoffBelongsToMaskedBlendingAndIsInUnitRange) {
  EXPECT_EQ(diagnosticsFor("material m { blending masked(0.3) surface { alpha = 0.5 } }"), "");
  EXPECT_NE(diagnosticsFor("material m { blending masked(1.5) surface { alpha = 0.5 } }").find("a number in [0, 1]"),
            std::string::npos);
  EXPECT_NE(diagnosticsFor("material m { blending transparent(0.5) surface { alpha = 0.5 } }")
                .find("an alpha cutoff applies to 'masked' blending only"),
            std::string::npos);
}

TEST(Language, OneMistakeIsReportedOnceNotAtEveryUse) {
  std::string d = diagnosticsFor(R"(material m {
    param r: float = 1.5 in [0, 1]
    surface {
        let wave = sin(nope)
        roughness = params.r * wave
        metallic = wave
    }
}
)");
  EXPECT_NE(d.find("default value 1.5 is outside the declared range"), std::string::npos) << d;
  EXPECT_NE(d.find("unknown name 'nope'"), std::string::npos) << d;
  EXPECT_EQ(d.find("unknown parameter 'r'"), std::string::npos) << d;
  EXPECT_EQ(d.find("used before its definition"), std::string::npos) << d;
}

TEST(Language, ErrorsStopAfterTheLimit) {
  std::string text = "material m { surface {\n";
  for (int i = 0; i < 1000; ++i) text += "roughness = nope" + std::to_string(i) + "\n";
  text += "} }";
  std::string d = diagnosticsFor(text);
  size_t errors = 0;
  for (size_t at = d.find(": error: "); at != std::string::npos; at = d.find(": error: ", at + 1)) ++errors;
  EXPECT_EQ(errors, facet::ir::kMaxErrors + 1) << "100 errors and the 'stopped' line";
  EXPECT_NE(d.find("test.mat: error: too many errors; stopped after 100"), std::string::npos);
}

TEST(Language, RecoveryKeepsTheStatementAfterAnUnclosedCall) {
  // The unclosed call stops at 'reflectance'; recovery must parse that statement, not skip it,
  // or its own error (line 4) goes unreported.
  std::string d =
      diagnosticsFor("material m {\n  surface {\n    alpha = mix(1.0, 2.0\n    reflectance = * 2.0\n  }\n}\n");
  EXPECT_NE(d.find("test.mat:4:5: error: expected ')' or ',' in the argument list of 'mix'"), std::string::npos) << d;
  EXPECT_NE(d.find("test.mat:4:19: error: expected an expression, found '*'"), std::string::npos) << d;
}

TEST(Language, NumbersAreCheckedWhereTheyAreWritten) {
  EXPECT_NE(diagnosticsFor("material m { surface { roughness = 2e } }")
                .find("test.mat:1:36: error: number '2e' has an exponent with no digits"),
            std::string::npos);
  EXPECT_NE(diagnosticsFor("material m { param n: int = 1e30\n surface { roughness = float(params.n) } }")
                .find("default value does not fit a 32-bit int"),
            std::string::npos);
}

// Parameter names reach the GLSL as block members and sampler uniforms: a name GLSL reserves is
// the material's error, at its declaration, not an internal error from the shader compiler.
TEST(Language, ParameterNamesGlslReservesAreErrorsAtTheirDeclaration) {
  std::string d = diagnosticsFor(R"(material m {
    param discard: float = 0.5
    param gl_FragColor: float = 0.5
    param sample: float = 0.5
    param a__b: float = 0.5
    param texture: float = 0.5
    param dot: float = 0.5
    surface {
        roughness = params.texture * params.dot
    }
}
)");
  EXPECT_NE(d.find("test.mat:2:11: error: parameter 'discard' cannot be used: 'discard' is a GLSL keyword or reserved "
                   "word [reserved-name]"),
            std::string::npos)
      << d;
  EXPECT_NE(d.find("test.mat:3:11: error: parameter 'gl_FragColor' cannot be used: names starting with 'gl_' are "
                   "reserved by GLSL [reserved-name]"),
            std::string::npos)
      << d;
  EXPECT_NE(
      d.find("test.mat:4:11: error: parameter 'sample' cannot be used: 'sample' is a GLSL keyword or reserved word"),
      std::string::npos)
      << d;
  EXPECT_NE(d.find("test.mat:5:11: error: parameter 'a__b' cannot be used: names containing '__' are reserved by GLSL"),
            std::string::npos)
      << d;
  // Built-in function names are fine: parameters live in the block's member namespace.
  EXPECT_EQ(d.find("'texture'"), std::string::npos) << d;
  EXPECT_EQ(d.find("'dot'"), std::string::npos) << d;
}
