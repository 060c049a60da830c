#include "reserved_names.h"

#include <set>

namespace facet::ir {
namespace {

const std::set<std::string_view>& glslKeywords() {
  // GLSL ES 3.00 §3.7 keywords and reserved words, and the words GLSL ES 3.10 §3.8 added.
  static const std::set<std::string_view> words = {
      // keywords
      "const", "uniform", "layout", "centroid", "flat", "smooth", "break", "continue", "do", "for", "while",
      "switch", "case", "default", "if", "else", "in", "out", "inout", "float", "int", "void", "bool", "true",
      "false", "invariant", "discard", "return", "mat2", "mat3", "mat4", "mat2x2", "mat2x3", "mat2x4", "mat3x2",
      "mat3x3", "mat3x4", "mat4x2", "mat4x3", "mat4x4", "vec2", "vec3", "vec4", "ivec2", "ivec3", "ivec4",
      "bvec2", "bvec3", "bvec4", "uint", "uvec2", "uvec3", "uvec4", "lowp", "mediump", "highp", "precision",
      "sampler2D", "sampler3D", "samplerCube", "sampler2DShadow", "samplerCubeShadow", "sampler2DArray",
      "sampler2DArrayShadow", "isampler2D", "isampler3D", "isamplerCube", "isampler2DArray", "usampler2D",
      "usampler3D", "usamplerCube", "usampler2DArray", "struct",
      // reserved for future use
      "attribute", "varying", "coherent", "volatile", "restrict", "readonly", "writeonly", "resource",
      "atomic_uint", "noperspective", "patch", "sample", "subroutine", "common", "partition", "active", "asm",
      "class", "union", "enum", "typedef", "template", "this", "goto", "inline", "noinline", "public",
      "static", "extern", "external", "interface", "long", "short", "double", "half", "fixed", "unsigned",
      "superp", "input", "output", "hvec2", "hvec3", "hvec4", "dvec2", "dvec3", "dvec4", "fvec2", "fvec3",
      "fvec4", "sampler3DRect", "filter", "image1D", "image2D", "image3D", "imageCube", "iimage1D",
      "iimage2D", "iimage3D", "iimageCube", "uimage1D", "uimage2D", "uimage3D", "uimageCube",
      "image1DArray", "image2DArray", "iimage1DArray", "iimage2DArray", "uimage1DArray", "uimage2DArray",
      "imageBuffer", "iimageBuffer", "uimageBuffer", "sampler1D", "sampler1DShadow", "sampler1DArray",
      "sampler1DArrayShadow", "isampler1D", "isampler1DArray", "usampler1D", "usampler1DArray",
      "sampler2DRect", "sampler2DRectShadow", "isampler2DRect", "usampler2DRect", "samplerBuffer",
      "isamplerBuffer", "usamplerBuffer", "sampler2DMS", "isampler2DMS", "usampler2DMS", "sampler2DMSArray",
      "isampler2DMSArray", "usampler2DMSArray", "sizeof", "cast", "namespace", "using",
      // GLSL ES 3.10 additions
      "buffer", "shared", "readonly", "iimage2DArray", "samplerCubeArray", "samplerCubeArrayShadow",
      "isamplerCubeArray", "usamplerCubeArray", "imageCubeArray", "iimageCubeArray", "uimageCubeArray",
      "samplerExternalOES", "precise",
  };
  return words;
}

}  // namespace

std::string reservedNameReason(std::string_view name) {
  if (glslKeywords().count(name)) return "'" + std::string(name) + "' is a GLSL keyword or reserved word";
  if (name.substr(0, 3) == "gl_") return "names starting with 'gl_' are reserved by GLSL";
  if (name.find("__") != std::string_view::npos) return "names containing '__' are reserved by GLSL";
  // The compiler's own members of the parameter block (the preshader's derived inputs) and
  // samplers are named facet_*: a parameter of that name could collide with them.
  if (name.substr(0, 6) == "facet_") return "names starting with 'facet_' are reserved for the compiler's own uniforms";
  return "";
}

}  // namespace facet::ir
