#include "facet/ir/check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "builtins.h"
#include "evaluate.h"
#include "facet/ir/parser.h"
#include "reserved_names.h"

namespace facet::ir {

double srgbToLinear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

namespace {

using ast::Expr;

class Checker {
 public:
  explicit Checker(Diagnostics& diags) : diags_(diags) {}

  std::optional<Material> run(const ast::Material& src) {
    material_.name = src.name;
    checkHeader(src);
    if (src.hasSpecularAntiAliasing) checkSpecularAntiAliasing(src);
    for (size_t i = 0; i < src.params.size(); ++i) {
      if (i == kMaxParams)
        error(src.params[i].loc, "a material has at most " + std::to_string(kMaxParams) + " parameters", "limit");
      if (i >= kMaxParams)
        rejectedParams_.insert(src.params[i].name);  // known by name: uses of it add no errors
      else
        checkParam(src.params[i]);
    }
    if (src.alphaCutoff) {
      if (src.blending != "masked") {
        error(src.alphaCutoff->loc, "an alpha cutoff applies to 'masked' blending only", "type");
      } else if (auto c = constantOf(*src.alphaCutoff, "the alpha cutoff")) {
        if (c->type != Type::Float || c->constant[0] < 0.0 || c->constant[0] > 1.0)
          error(src.alphaCutoff->loc, "the alpha cutoff is a number in [0, 1]", "range");
        else
          material_.alphaCutoff = c->constant[0];
      }
    }
    checkSurface(src);
    for (const ast::TierOverride& o : src.tierOverrides) checkTierOverride(o);
    for (const Param& p : material_.params)
      if (!usedParams_.count(p.name)) diags_.warning(p.loc, "parameter '" + p.name + "' is never used", "unused-param");
    if (diags_.hasErrors()) return std::nullopt;
    return std::move(material_);
  }

 private:
  using Result = std::optional<ValueId>;

  void error(SourceLoc loc, std::string message, const char* code = "type") {
    diags_.error(loc, std::move(message), code);
  }
  Type typeOf(ValueId id) const { return module().value(id).type; }
  Module& module() { return material_.surface; }
  const Module& module() const { return material_.surface; }

  static std::string suggestion(const std::string& best) {
    return best.empty() ? "" : "; did you mean '" + best + "'?";
  }

  // --- header and parameters ---

  void checkHeader(const ast::Material& src) {
    static const std::vector<std::string> shadings = {"lit", "unlit", "cloth"};
    static const std::vector<std::string> blendings = {"opaque", "masked", "transparent", "additive"};
    // A cloth material is lit (the same lights, environment and variants); only its model differs.
    material_.shading = src.shading == "cloth" ? "lit" : src.shading;
    material_.cloth = src.shading == "cloth";
    material_.blending = src.blending;
    material_.doubleSided = src.doubleSided;
    if (std::find(shadings.begin(), shadings.end(), src.shading) == shadings.end())
      error(src.shadingLoc,
            "unknown shading model '" + src.shading + "' (lit, unlit or cloth)" +
                suggestion(closestMatch(src.shading, shadings)),
            "unknown-name");
    if (std::find(blendings.begin(), blendings.end(), src.blending) == blendings.end())
      error(src.blendingLoc,
            "unknown blending mode '" + src.blending + "'" + suggestion(closestMatch(src.blending, blendings)),
            "unknown-name");
  }

  // `specularAntiAliasing { variance v threshold t }`: both optional (defaults 0.02, the variance
  // measured in docs/material-models.md, and Filament's 0.2), each a constant in [0, 1]:
  // σ² = variance · |∇n|² and the α² it adds is at most threshold, and α² itself is at most 1
  // (chunks/specular_antialiasing.glsl).
  void checkSpecularAntiAliasing(const ast::Material& src) {
    if (material_.shading == "unlit") {
      error(src.specularAntiAliasingLoc,
            "specular anti-aliasing widens the specular lobe, and an unlit material has none; remove it", "shading");
      return;
    }
    static const std::vector<std::string> names = {"variance", "threshold"};
    Material::SpecularAntiAliasing settings;
    settings.loc = src.specularAntiAliasingLoc;
    std::set<std::string> seen;
    bool ok = true;
    for (const ast::Setting& setting : src.specularAntiAliasing) {
      if (std::find(names.begin(), names.end(), setting.name) == names.end()) {
        error(setting.loc,
              "unknown setting '" + setting.name + "' of specularAntiAliasing (variance, threshold)" +
                  suggestion(closestMatch(setting.name, names)),
              "unknown-name");
        ok = false;
        continue;
      }
      if (!seen.insert(setting.name).second) {
        error(setting.loc, "specularAntiAliasing already sets '" + setting.name + "'", "duplicate");
        ok = false;
        continue;
      }
      auto c = constantOf(*setting.value, "a specularAntiAliasing setting");
      if (!c) {
        ok = false;
        continue;
      }
      if (c->type != Type::Float || c->constant[0] < 0.0 || c->constant[0] > 1.0) {
        error(setting.value->loc,
              "'" + setting.name + "' is a number in [0, 1]" +
                  (setting.name == "variance" ? " (default 0.02)" : " (Filament's default 0.2)"),
              "range");
        ok = false;
        continue;
      }
      (setting.name == "variance" ? settings.variance : settings.threshold) = c->constant[0];
    }
    if (ok) material_.specularAntiAliasing = settings;
  }

  void checkTierOverride(const ast::TierOverride& o) {
    const TierChoices& choices = tierChoices();
    if (std::find(choices.tiers.begin(), choices.tiers.end(), o.tier) == choices.tiers.end()) {
      error(o.tierLoc, "unknown tier '" + o.tier + "'" + suggestion(closestMatch(o.tier, choices.tiers)),
            "unknown-name");
      return;
    }
    if (o.tier == "reference") {
      error(o.tierLoc, "the reference tier is the ground truth every tier is measured against; it has no overrides",
            "tier");
      return;
    }
    auto axis = choices.options.find(o.axis);
    if (axis == choices.options.end()) {
      std::vector<std::string> axes;
      for (const auto& [name, options] : choices.options) axes.push_back(name);
      error(o.axisLoc, "unknown tier choice '" + o.axis + "'" + suggestion(closestMatch(o.axis, axes)), "unknown-name");
      return;
    }
    const std::vector<std::string>& options = axis->second;
    if (std::find(options.begin(), options.end(), o.option) == options.end()) {
      error(o.optionLoc,
            "unknown " + o.axis + " option '" + o.option + "'" + suggestion(closestMatch(o.option, options)),
            "unknown-name");
      return;
    }
    for (const TierOverride& earlier : material_.tierOverrides) {
      if (earlier.tier == o.tier && earlier.axis == o.axis) {
        error(o.axisLoc, "tier '" + o.tier + "' already sets '" + o.axis + "'", "duplicate");
        return;
      }
    }
    material_.tierOverrides.push_back({o.tier, o.axis, o.option});
  }

  // Evaluates an expression that must be a compile-time constant (defaults, range bounds).
  std::optional<Value> constantOf(const Expr& e, const char* what) {
    constantOnly_ = true;
    Result r = expr(e);
    constantOnly_ = false;
    if (!r) return std::nullopt;
    auto c = evaluateConstant(module(), *r);
    if (!c) {
      error(e.loc, std::string(what) + " is not a finite constant", "constant");
      return std::nullopt;
    }
    Value v;
    v.op = Op::Constant;
    v.type = typeOf(*r);
    v.constant = *c;
    return v;
  }

  // A parameter whose declaration has an error is still known by name, so its uses do not add
  // "unknown parameter" errors on top of the real one.
  void checkParam(const ast::ParamDecl& decl) {
    size_t before = material_.params.size();
    checkParamDecl(decl);
    if (material_.params.size() == before) rejectedParams_.insert(decl.name);
  }

  void checkParamDecl(const ast::ParamDecl& decl) {
    if (std::string why = reservedNameReason(decl.name); !why.empty()) {
      error(decl.loc, "parameter '" + decl.name + "' cannot be used: " + why, "reserved-name");
      return;
    }
    for (const Param& p : material_.params) {
      if (p.name == decl.name) {
        error(decl.loc, "parameter '" + decl.name + "' is already declared at line " + std::to_string(p.loc.line),
              "duplicate");
        return;
      }
    }
    auto parsed = parseTypeName(decl.typeName, decl.typeArgument);
    if (!parsed && decl.typeName == "texture") {
      error(decl.typeLoc,
            "a texture parameter names its colour space: texture(srgb), texture(linear) or texture(normal)", "type");
      return;
    }
    if (!parsed) {
      static const std::vector<std::string> types = {"float", "vec2", "vec3",  "vec4",
                                                     "int",   "bool", "color", "texture"};
      error(decl.typeLoc,
            "unknown parameter type '" + decl.typeName + "'" + suggestion(closestMatch(decl.typeName, types)),
            "unknown-name");
      return;
    }
    Param p;
    p.name = decl.name;
    p.type = parsed->type;
    p.isColor = parsed->isColor;
    p.textureSpace = parsed->textureSpace;
    p.loc = decl.loc;
    if (p.type == Type::Texture2D) {
      checkTextureParam(decl, std::move(p));
      return;
    }
    auto def = constantOf(*decl.defaultValue, "a default value");
    if (!def) return;
    bool integralFloat = def->type == Type::Float && std::floor(def->constant[0]) == def->constant[0];
    if (def->type != p.type && !(p.type == Type::Int && integralFloat)) {
      error(decl.defaultValue->loc,
            "default value is " + std::string(typeName(def->type)) + " but parameter '" + p.name + "' is " +
                decl.typeName,
            "type");
      return;
    }
    if (p.type == Type::Int && (def->constant[0] < -2147483648.0 || def->constant[0] > 2147483647.0)) {
      error(decl.defaultValue->loc, "default value does not fit a 32-bit int", "range");
      return;
    }
    for (int i = 0; i < componentCount(p.type); ++i) p.defaultValue.push_back(def->constant[size_t(i)]);

    if (decl.rangeMin) {
      auto lo = constantOf(*decl.rangeMin, "a range bound");
      auto hi = constantOf(*decl.rangeMax, "a range bound");
      if (!lo || !hi) return;
      if (p.type == Type::Bool || lo->type != Type::Float || hi->type != Type::Float) {
        error(decl.rangeMin->loc, "a range is two numbers and applies to numeric parameters", "type");
        return;
      }
      p.rangeMin = lo->constant[0];
      p.rangeMax = hi->constant[0];
      if (*p.rangeMin > *p.rangeMax) {
        error(decl.rangeMin->loc, "range is empty: minimum is greater than maximum", "range");
        return;
      }
      for (double c : p.defaultValue) {
        if (c < *p.rangeMin || c > *p.rangeMax) {
          error(decl.defaultValue->loc,
                "default value " + formatNumber(c) + " is outside the declared range [" + formatNumber(*p.rangeMin) +
                    ", " + formatNumber(*p.rangeMax) + "]",
                "range");
          return;
        }
      }
    }
    if (p.isColor) {
      for (double& c : p.defaultValue) {
        if (c < 0.0 || c > 1.0) {
          error(decl.defaultValue->loc, "colour components are sRGB values in [0, 1]", "range");
          return;
        }
        c = srgbToLinear(c);
      }
    }
    material_.params.push_back(std::move(p));
  }

  // A texture's default is the RGBA value (as encoded in its colour space) a missing image
  // samples as; the runtime makes a 1×1 texture of it.
  void checkTextureParam(const ast::ParamDecl& decl, Param p) {
    size_t textures = 0;
    for (const Param& q : material_.params) textures += q.type == Type::Texture2D;
    if (textures >= kMaxTextureParams) {
      error(decl.loc, "a material has at most " + std::to_string(kMaxTextureParams) + " texture parameters", "limit");
      return;
    }
    if (decl.rangeMin) {
      error(decl.rangeMin->loc, "a texture parameter has no range", "type");
      return;
    }
    auto def = constantOf(*decl.defaultValue, "a default value");
    if (!def) return;
    if (def->type != Type::Vec4) {
      error(decl.defaultValue->loc, "the default of a texture is the vec4 a missing image samples as", "type");
      return;
    }
    for (int i = 0; i < 4; ++i) {
      if (def->constant[size_t(i)] < 0.0 || def->constant[size_t(i)] > 1.0) {
        error(decl.defaultValue->loc, "texture default components are in [0, 1]", "range");
        return;
      }
      p.defaultValue.push_back(def->constant[size_t(i)]);
    }
    material_.params.push_back(std::move(p));
  }

  static std::string formatNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
  }

  // --- surface program ---

  void checkSurface(const ast::Material& src) {
    std::map<std::string, SourceLoc> letsAhead;
    for (const ast::Statement& s : src.surface)
      if (s.isLet) letsAhead.emplace(s.name, s.loc);

    std::map<std::string, SourceLoc> written;
    for (const ast::Statement& s : src.surface) {
      letsAhead_ = &letsAhead;
      Result value = expr(*s.value);
      if (s.isLet) {
        if (lets_.count(s.name)) {
          error(s.loc, "'" + s.name + "' is already defined at line " + std::to_string(lets_[s.name].loc.line),
                "duplicate");
        } else if (findOutput(s.name)) {
          error(s.loc, "'" + s.name + "' is a surface output; choose another name for the let", "duplicate");
        } else if (s.name == "params" || s.name == "vertex") {
          error(s.loc, "'" + s.name + "' is reserved", "duplicate");
        } else if (value) {
          lets_[s.name] = {*value, s.loc};
          module().nameValue(*value, s.name);
        } else {
          failedLets_.insert(s.name);  // its error is reported; uses of it stay quiet
        }
        continue;
      }
      const OutputInfo* out = findOutput(s.name);
      if (!out) {
        std::vector<std::string> names;
        for (const OutputInfo& o : outputs()) names.push_back(o.name);
        std::string hint = suggestion(closestMatch(s.name, names));
        if (hint.empty() && lets_.count(s.name)) hint = "; use 'let' only once per name";
        error(s.loc, "unknown surface output '" + s.name + "'" + hint, "unknown-name");
        continue;
      }
      if (auto [it, fresh] = written.emplace(s.name, s.loc); !fresh) {
        error(s.loc, "output '" + s.name + "' is already written at line " + std::to_string(it->second.line),
              "duplicate");
        continue;
      }
      if (!value) continue;
      if (typeOf(*value) != out->type) {
        error(s.value->loc,
              "output '" + s.name + "' is " + typeName(out->type) + " but the value is " + typeName(typeOf(*value)),
              "type");
        continue;
      }
      if (out->litOnly && material_.shading == "unlit") {
        diags_.warning(s.loc, "output '" + s.name + "' has no effect on an unlit material", "unused-output");
        continue;
      }
      if (out->model == OutputModel::Standard && material_.cloth) {
        diags_.warning(s.loc, "output '" + s.name + "' has no effect on a cloth material (the standard model's)",
                       "unused-output");
        continue;
      }
      if (out->model == OutputModel::Cloth && material_.shading == "lit" && !material_.cloth) {
        diags_.warning(s.loc,
                       "output '" + s.name + "' has no effect on a lit material (the cloth model's: 'shading cloth')",
                       "unused-output");
        continue;
      }
      module().outputs[s.name] = *value;
    }
    letsAhead_ = nullptr;
    // Outputs that exist only with another (OutputInfo::presentWith): without it nothing reads them.
    for (const OutputInfo& o : outputs()) {
      if (!o.presentWith || !module().outputs.count(o.name) || module().outputs.count(o.presentWith)) continue;
      diags_.warning(written.at(o.name),
                     "output '" + std::string(o.name) + "' has no effect without '" + o.presentWith + "'",
                     "unused-output");
      module().outputs.erase(o.name);
    }
  }

  // --- expressions ---

  // Checks one expression and records where its value was written.
  Result expr(const Expr& e) {
    Result r = exprKind(e);
    if (r) module().setLoc(*r, e.loc);
    return r;
  }

  Result exprKind(const Expr& e) {
    switch (e.kind) {
      case Expr::Kind::Number: return module().constant(Type::Float, {e.number});
      case Expr::Kind::Bool: return module().constant(Type::Bool, {e.boolean ? 1.0 : 0.0});
      case Expr::Kind::Name: return name(e);
      case Expr::Kind::Member: return member(e);
      case Expr::Kind::Call: return call(e);
      case Expr::Kind::Unary: return unary(e);
      case Expr::Kind::Binary: return binary(e);
      case Expr::Kind::Ternary: return ternary(e);
    }
    return std::nullopt;
  }

  Result name(const Expr& e) {
    if (e.name == "params" || e.name == "vertex") {
      error(e.loc, "'" + e.name + "' is a namespace; write " + e.name + ".<name>", "unknown-name");
      return std::nullopt;
    }
    if (failedLets_.count(e.name)) return std::nullopt;
    if (auto it = lets_.find(e.name); it != lets_.end()) {
      if (constantOnly_) {
        error(e.loc, "'" + e.name + "' cannot be used in a constant expression", "constant");
        return std::nullopt;
      }
      return it->second.value;
    }
    if (letsAhead_) {
      if (auto it = letsAhead_->find(e.name); it != letsAhead_->end()) {
        error(e.loc, "'" + e.name + "' is used before its definition at line " + std::to_string(it->second.line),
              "use-before-def");
        return std::nullopt;
      }
    }
    std::string hint;
    for (const Param& p : material_.params)
      if (p.name == e.name) hint = "; did you mean 'params." + p.name + "'?";
    if (hint.empty()) {
      std::vector<std::string> names;
      for (const auto& [n, l] : lets_) names.push_back(n);
      hint = suggestion(closestMatch(e.name, names));
    }
    error(e.loc, "unknown name '" + e.name + "'" + hint, "unknown-name");
    return std::nullopt;
  }

  Result member(const Expr& e) {
    const Expr& object = *e.args[0];
    if (object.kind == Expr::Kind::Name && object.name == "params") return paramRead(e);
    if (object.kind == Expr::Kind::Name && object.name == "vertex") return attributeRead(e);
    Result base = expr(object);
    if (!base) return std::nullopt;
    return swizzle(e, *base);
  }

  Result paramRead(const Expr& e) {
    if (constantOnly_) {
      error(e.loc, "parameters cannot be used in a constant expression", "constant");
      return std::nullopt;
    }
    for (const Param& p : material_.params) {
      if (p.name == e.name) {
        usedParams_.insert(p.name);
        Value v;
        v.op = Op::Param;
        v.type = p.type;
        v.name = p.name;
        return module().add(std::move(v));
      }
    }
    if (rejectedParams_.count(e.name)) return std::nullopt;  // its declaration's error is reported
    std::vector<std::string> names;
    for (const Param& p : material_.params) names.push_back(p.name);
    error(e.loc, "unknown parameter '" + e.name + "'" + suggestion(closestMatch(e.name, names)), "unknown-name");
    return std::nullopt;
  }

  Result attributeRead(const Expr& e) {
    if (constantOnly_) {
      error(e.loc, "vertex attributes cannot be used in a constant expression", "constant");
      return std::nullopt;
    }
    const AttributeInfo* a = findAttribute(e.name);
    if (!a) {
      std::vector<std::string> names;
      for (const AttributeInfo& i : attributes()) names.push_back(i.name);
      error(e.loc, "unknown vertex attribute '" + e.name + "'" + suggestion(closestMatch(e.name, names)),
            "unknown-name");
      return std::nullopt;
    }
    Value v;
    v.op = Op::Attribute;
    v.type = a->type;
    v.name = a->name;
    return module().add(std::move(v));
  }

  Result swizzle(const Expr& e, ValueId base) {
    Type t = typeOf(base);
    int n = componentCount(t);
    if (!isFloatType(t) || t == Type::Float) {
      error(e.loc, "'." + e.name + "' needs a vector, but the value is " + typeName(t), "type");
      return std::nullopt;
    }
    static const std::string xyzw = "xyzw", rgba = "rgba";
    const std::string& set = xyzw.find(e.name[0]) != std::string::npos ? xyzw : rgba;
    if (e.name.size() > 4) {
      error(e.loc, "a swizzle has at most 4 components", "type");
      return std::nullopt;
    }
    std::string normalized;
    for (char c : e.name) {
      size_t i = set.find(c);
      if (i == std::string::npos || int(i) >= n) {
        error(e.loc, "'" + e.name + "' is not a swizzle of a " + typeName(t), "type");
        return std::nullopt;
      }
      normalized += xyzw[i];
    }
    Value v;
    v.op = Op::Swizzle;
    v.type = floatVector(int(normalized.size()));
    v.name = normalized;
    v.args = {base};
    return module().add(std::move(v));
  }

  // Checks each argument; all are reported even if an early one fails.
  std::optional<std::vector<ValueId>> arguments(const Expr& e) {
    std::vector<ValueId> out;
    bool ok = true;
    for (const auto& a : e.args) {
      Result r = expr(*a);
      if (r) out.push_back(*r);
      ok = ok && r.has_value();
    }
    if (!ok) return std::nullopt;
    return out;
  }

  Result call(const Expr& e) {
    // An unknown name is reported even when an argument has errors of its own: both are mistakes
    // the author has to fix, and the name is usually the first one they look at.
    std::vector<std::string> names = builtinNames();
    names.insert(names.end(), {"vec2", "vec3", "vec4", "float", "sample"});
    const bool known = std::find(names.begin(), names.end(), e.name) != names.end();
    if (!known)
      error(e.loc, "unknown function '" + e.name + "'" + suggestion(closestMatch(e.name, names)), "unknown-name");
    auto args = arguments(e);
    if (!args || !known) return std::nullopt;
    std::vector<Type> types;
    for (ValueId a : *args) types.push_back(typeOf(a));

    if (e.name == "vec2" || e.name == "vec3" || e.name == "vec4" || e.name == "float")
      return construct(e, *args, types);
    if (e.name == "sample") return sample(e, *args, types);
    for (size_t i = 0; i < types.size(); ++i) {
      if (types[i] == Type::Texture2D) {
        error(e.args[i]->loc, "a texture can only be read with sample(texture, uv)", "type");
        return std::nullopt;
      }
    }

    std::string why;
    auto b = resolveBuiltin(e.name, types, &why);
    if (!b) {
      error(e.loc, why, "type");
      return std::nullopt;
    }
    Value v;
    v.op = Op::Builtin;
    v.type = b->result;
    v.name = b->glsl;
    v.args = *args;
    return module().add(std::move(v));
  }

  // sample(texture, uv) -> vec4: the texture's filtered RGBA at uv (colour textures decoded to
  // linear by the sampler). On a texture(normal) it is `sample_normal` -> vec3: the tangent-space
  // normal decoded from RGB (not renormalized: the shading normal is normalized once, after the
  // tangent frame is applied).
  Result sample(const Expr& e, const std::vector<ValueId>& args, const std::vector<Type>& types) {
    if (args.size() != 2) {
      error(e.loc, "'sample' takes 2 arguments, not " + std::to_string(args.size()), "type");
      return std::nullopt;
    }
    if (types[0] != Type::Texture2D || module().value(args[0]).op != Op::Param) {
      error(e.args[0]->loc,
            "the first argument of 'sample' is a texture parameter, not " + std::string(typeName(types[0])), "type");
      return std::nullopt;
    }
    if (types[1] != Type::Vec2) {
      error(e.args[1]->loc,
            "the second argument of 'sample' is a vec2 texture coordinate, not " + std::string(typeName(types[1])),
            "type");
      return std::nullopt;
    }
    if (constantOnly_) {
      error(e.loc, "textures cannot be sampled in a constant expression", "constant");
      return std::nullopt;
    }
    bool normalMap = false;
    for (const Param& p : material_.params)
      if (p.name == module().value(args[0]).name) normalMap = p.textureSpace == TextureSpace::Normal;
    Value v;
    v.op = Op::Builtin;
    v.type = normalMap ? Type::Vec3 : Type::Vec4;
    v.name = normalMap ? "sample_normal" : "sample";
    v.args = args;
    return module().add(std::move(v));
  }

  Result construct(const Expr& e, const std::vector<ValueId>& args, const std::vector<Type>& types) {
    int n = e.name == "float" ? 1 : e.name[3] - '0';
    Type result = floatVector(n);
    if (n == 1) {
      if (args.size() != 1 || componentCount(types[0]) != 1) {
        error(e.loc, "'float' takes one scalar argument", "type");
        return std::nullopt;
      }
      if (types[0] == Type::Float) return args[0];
    } else {
      int total = 0;
      for (Type t : types) {
        if (!isFloatType(t)) {
          error(e.loc,
                "'" + e.name + "' takes float or vector arguments, not " + typeName(t) + "; convert with float()",
                "type");
          return std::nullopt;
        }
        total += componentCount(t);
      }
      bool splat = args.size() == 1 && types[0] == Type::Float;
      if (!splat && total != n) {
        error(e.loc,
              "'" + e.name + "' needs " + std::to_string(n) + " components, but the arguments have " +
                  std::to_string(total),
              "type");
        return std::nullopt;
      }
    }
    Value v;
    v.op = Op::Construct;
    v.type = result;
    v.args = args;
    return module().add(std::move(v));
  }

  Result unary(const Expr& e) {
    Result x = expr(*e.args[0]);
    if (!x) return std::nullopt;
    Type t = typeOf(*x);
    if (e.op == Tok::Minus) {
      if (t == Type::Bool || t == Type::Texture2D) {
        error(e.loc, "'-' needs a number, but the operand is " + std::string(typeName(t)), "type");
        return std::nullopt;
      }
      return module().add(Value{Op::Neg, t, {*x}, {}, ""});
    }
    if (t != Type::Bool) {
      error(e.loc, "'!' needs a bool, but the operand is " + std::string(typeName(t)), "type");
      return std::nullopt;
    }
    return module().add(Value{Op::Not, Type::Bool, {*x}, {}, ""});
  }

  static Op binaryOp(Tok t) {
    switch (t) {
      case Tok::Plus: return Op::Add;
      case Tok::Minus: return Op::Sub;
      case Tok::Star: return Op::Mul;
      case Tok::Slash: return Op::Div;
      case Tok::Less: return Op::Less;
      case Tok::LessEqual: return Op::LessEqual;
      case Tok::Greater: return Op::Greater;
      case Tok::GreaterEqual: return Op::GreaterEqual;
      case Tok::EqualEqual: return Op::Equal;
      case Tok::NotEqual: return Op::NotEqual;
      case Tok::AndAnd: return Op::And;
      default: return Op::Or;
    }
  }

  Result binary(const Expr& e) {
    Result a = expr(*e.args[0]);
    Result b = expr(*e.args[1]);
    if (!a || !b) return std::nullopt;
    Type ta = typeOf(*a), tb = typeOf(*b);
    Op op = binaryOp(e.op);
    auto mismatch = [&] {
      error(e.loc, std::string("operands of ") + describe(e.op) + " are " + typeName(ta) + " and " + typeName(tb),
            "type");
      return std::nullopt;
    };
    if (ta == Type::Texture2D || tb == Type::Texture2D) {
      error(e.loc, "a texture can only be read with sample(texture, uv)", "type");
      return std::nullopt;
    }
    if (op == Op::And || op == Op::Or) {
      if (ta != Type::Bool || tb != Type::Bool) return mismatch();
      return module().add(Value{op, Type::Bool, {*a, *b}, {}, ""});
    }
    if (op >= Op::Less && op <= Op::NotEqual) {
      bool scalar = componentCount(ta) == 1 && ta == tb;
      bool ordered = op <= Op::GreaterEqual;
      if (!scalar || (ordered && ta == Type::Bool)) return mismatch();
      return module().add(Value{op, Type::Bool, {*a, *b}, {}, ""});
    }
    // Arithmetic: same type, or a float scalar with a float vector (GLSL broadcasting).
    Type result;
    if (ta == tb && ta != Type::Bool)
      result = ta;
    else if (ta == Type::Float && isFloatType(tb))
      result = tb;
    else if (tb == Type::Float && isFloatType(ta))
      result = ta;
    else
      return mismatch();
    return module().add(Value{op, result, {*a, *b}, {}, ""});
  }

  Result ternary(const Expr& e) {
    Result c = expr(*e.args[0]);
    Result a = expr(*e.args[1]);
    Result b = expr(*e.args[2]);
    if (!c || !a || !b) return std::nullopt;
    if (typeOf(*c) != Type::Bool) {
      error(e.args[0]->loc, "the condition is " + std::string(typeName(typeOf(*c))) + ", not bool", "type");
      return std::nullopt;
    }
    if (typeOf(*a) != typeOf(*b)) {
      error(e.loc, std::string("the branches are ") + typeName(typeOf(*a)) + " and " + typeName(typeOf(*b)), "type");
      return std::nullopt;
    }
    return module().add(Value{Op::Select, typeOf(*a), {*c, *a, *b}, {}, ""});
  }

  struct Let {
    ValueId value;
    SourceLoc loc;
  };

  Diagnostics& diags_;
  Material material_;
  std::map<std::string, Let> lets_;
  const std::map<std::string, SourceLoc>* letsAhead_ = nullptr;
  std::set<std::string> usedParams_;
  std::set<std::string> failedLets_;      // lets whose value had an error
  std::set<std::string> rejectedParams_;  // parameters whose declaration had an error
  bool constantOnly_ = false;
};

}  // namespace

std::optional<Material> check(const ast::Material& material, Diagnostics& diags) {
  return Checker(diags).run(material);
}

std::optional<Material> compileSource(const SourceFile& file, Diagnostics& diags) {
  auto parsed = parse(file, diags);
  if (!parsed) return std::nullopt;
  return check(*parsed, diags);
}

}  // namespace facet::ir
