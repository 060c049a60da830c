// Syntax tree of a material file, as written (names unresolved, types unchecked).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "facet/ir/diagnostics.h"
#include "facet/ir/lexer.h"

namespace facet::ir::ast {

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

struct Expr {
  enum class Kind { Number, Bool, Name, Member, Call, Unary, Binary, Ternary };
  Kind kind = Kind::Number;
  SourceLoc loc;
  std::string name;      // Name: identifier; Member: field; Call: callee
  std::string spelling;  // Number: as written
  double number = 0.0;
  bool boolean = false;
  Tok op = Tok::End;          // Unary / Binary operator
  int height = 1;             // longest path to a leaf; bounded by the parser
  std::vector<ExprPtr> args;  // Member: {object}; Call: arguments; Unary: {x}; Binary: {a, b}; Ternary: {c, a, b}
};

struct ParamDecl {
  std::string name;
  SourceLoc loc;
  std::string typeName;
  std::string typeArgument;  // texture(srgb): "srgb"
  SourceLoc typeLoc;
  ExprPtr defaultValue;
  ExprPtr rangeMin;  // both set when the declaration has `in [min, max]`
  ExprPtr rangeMax;
};

struct Statement {
  bool isLet = false;  // `let name = value` binds; `name = value` writes a surface output
  std::string name;
  SourceLoc loc;
  ExprPtr value;
};

// `tier high { specular = ggx_fastv }`: one choice of a tier's preset, replaced.
struct TierOverride {
  std::string tier;
  SourceLoc tierLoc;
  std::string axis;
  SourceLoc axisLoc;
  std::string option;
  SourceLoc optionLoc;
};

// One setting of a header block, `name value` (`variance 0.02` in `specularAntiAliasing { }`).
struct Setting {
  std::string name;
  SourceLoc loc;
  ExprPtr value;
};

struct Material {
  std::string name;
  SourceLoc loc;
  std::string shading = "lit";
  SourceLoc shadingLoc;
  std::string blending = "opaque";
  SourceLoc blendingLoc;
  ExprPtr alphaCutoff;  // blending masked(cutoff)
  bool doubleSided = false;
  // `specularAntiAliasing { variance v threshold t }`.
  bool hasSpecularAntiAliasing = false;
  SourceLoc specularAntiAliasingLoc;
  std::vector<Setting> specularAntiAliasing;
  std::vector<ParamDecl> params;
  std::vector<Statement> surface;
  std::vector<TierOverride> tierOverrides;
};

}  // namespace facet::ir::ast
