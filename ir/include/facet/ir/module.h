// The typed IR of a material: parameters, and the surface program as a value graph (a DAG in
// SSA form: every value is defined once, by an operation on earlier values).
//
// Values are interned on creation: building the same operation on the same operands twice
// returns the first value, so common subexpressions are shared by construction.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "facet/ir/diagnostics.h"
#include "facet/ir/types.h"

namespace facet::ir {

using ValueId = uint32_t;

enum class Op {
  Constant,   // constant[0..n)
  Param,      // material parameter `name`
  Attribute,  // interpolated vertex attribute `name` (see attributes below)
  Swizzle,    // name = component letters, args = {vector}
  Construct,  // vecN(args...) / float(x)
  Neg,
  Not,
  Add,
  Sub,
  Mul,
  Div,
  Less,
  LessEqual,
  Greater,
  GreaterEqual,
  Equal,
  NotEqual,
  And,
  Or,
  Select,   // args = {condition, ifTrue, ifFalse}
  Builtin,  // name = GLSL built-in function
};

struct Value {
  Op op = Op::Constant;
  Type type = Type::Float;
  std::vector<ValueId> args;
  std::array<double, 4> constant{};
  std::string name;
  bool operator==(const Value&) const = default;
};

// Surface attributes a material may read, and the GLSL the templates provide for each.
struct AttributeInfo {
  const char* name;  // as written after `vertex.`
  Type type;
  const char* glsl;  // expression in the fragment stage
  bool highp;        // positions and UVs need highp (DESIGN: precision policy)
};
const std::vector<AttributeInfo>& attributes();
const AttributeInfo* findAttribute(std::string_view name);

// Which lit model reads an output: both, the standard (metallic-roughness) one only, or the cloth
// model only (`shading cloth`, docs/material-models.md). Written where its model is not the
// material's, it is dropped with an `unused-output` warning. Sheen: both, the cloth model always and
// the standard one as a sheen layer over its base where the material writes it.
enum class OutputModel { Any, Standard, Cloth, Sheen };

// Surface outputs, their types and the values they take when the program does not write them.
struct OutputInfo {
  const char* name;
  Type type;
  std::array<double, 4> defaultValue;
  bool litOnly;  // read by lighting only: an unlit material drops it (with a warning)
  // An output that only exists with another: MaterialInputs holds it only in variants of
  // materials that write `presentWith` (the clear coat's outputs, with `clearCoat`), so a material
  // without that output compiles the shaders it compiled before the output existed. Written
  // without it, it is dropped with a warning. nullptr: always a member.
  const char* presentWith;
  // A Cloth output is a MaterialInputs member only in cloth materials' variants; a Sheen output in
  // cloth materials' and in those of lit materials that write it.
  OutputModel model;
};
const std::vector<OutputInfo>& outputs();
const OutputInfo* findOutput(std::string_view name);

struct Param {
  std::string name;
  Type type = Type::Float;
  bool isColor = false;                            // authored in sRGB; defaultValue holds the linear value
  TextureSpace textureSpace = TextureSpace::None;  // textures: how the image is encoded; defaultValue
                                                   // is the RGBA (as encoded) a missing image samples as
  std::vector<double> defaultValue;                // componentCount(type) values
  std::optional<double> rangeMin, rangeMax;
  SourceLoc loc;
  bool used = true;  // false once opt_eliminate_dead_code finds no output depends on it
};

class Module {
 public:
  // Adds a value, or returns the existing identical one.
  ValueId add(Value v);
  ValueId constant(Type t, std::array<double, 4> c);

  const Value& value(ValueId id) const { return values_[id]; }
  size_t size() const { return values_.size(); }

  // Where in the material source a value was first written (for mapping backend errors back).
  void setLoc(ValueId id, SourceLoc loc) { locs_.emplace(id, loc); }
  const SourceLoc* locOf(ValueId id) const {
    auto it = locs_.find(id);
    return it == locs_.end() ? nullptr : &it->second;
  }

  // A readable name for a value, from the `let` that bound it (first binding wins).
  void nameValue(ValueId id, const std::string& name) { names_.emplace(id, name); }
  const std::string* nameOf(ValueId id) const {
    auto it = names_.find(id);
    return it == names_.end() ? nullptr : &it->second;
  }

  std::map<std::string, ValueId> outputs;  // outputs the surface program writes

 private:
  struct Hash {
    size_t operator()(const Value& v) const;
  };
  std::vector<Value> values_;
  std::unordered_map<Value, ValueId, Hash> interned_;
  std::map<ValueId, std::string> names_;
  std::map<ValueId, SourceLoc> locs_;
};

// A checked per-tier override of the tier presets (names validated against tierChoices()).
struct TierOverride {
  std::string tier;    // reference | high | mid | low
  std::string axis;    // specular | diffuse
  std::string option;  // e.g. ggx_fastv
  bool operator==(const TierOverride&) const = default;
};

// The language's vocabulary of tier choices: the tiers, and per axis the options it accepts.
// permutations/src/tiers.cpp turns a checked choice into shading maths.
struct TierChoices {
  std::vector<std::string> tiers;
  std::map<std::string, std::vector<std::string>> options;
};
const TierChoices& tierChoices();

// A checked material: what every later stage reads.
struct Material {
  std::string name;
  std::string shading;       // "lit" | "unlit" (a cloth material is lit: lights and environment as any other)
  bool cloth = false;        // `shading cloth`: lit by the cloth model instead of the standard one
  std::string blending;      // opaque | masked | transparent | additive
  double alphaCutoff = 0.5;  // masked: fragments with alpha below it are discarded
  bool doubleSided = false;  // false: back faces are culled
  // `specularAntiAliasing { }` (docs/material-models.md, "Specular anti-aliasing"): the lobe's α²
  // widened by the screen-space variance of the shading normal (chunks/specular_antialiasing.glsl).
  struct SpecularAntiAliasing {
    double variance = 0.02;  // σ² per unit of |∂n/∂x|² + |∂n/∂y|², in [0, 1]
    double threshold = 0.2;  // the largest α² the kernel adds, in [0, 1]
    SourceLoc loc;           // of the header item
  };
  std::optional<SpecularAntiAliasing> specularAntiAliasing;
  std::vector<Param> params;
  std::vector<TierOverride> tierOverrides;
  Module surface;
};

}  // namespace facet::ir
