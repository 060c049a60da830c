#include "facet/ir/emit_glsl.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "facet/abi/shader_abi.h"
#include "facet/ir/precision.h"
#include "facet/ir/ranges.h"

namespace facet::ir {

namespace {

std::string floatLiteral(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  std::string s = buf;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string scalarLiteral(Type t, double v) {
  if (t == Type::Bool) return v != 0.0 ? "true" : "false";
  if (t == Type::Int) return std::to_string(static_cast<long long>(v));
  return floatLiteral(v);
}

const char* infix(Op op) {
  switch (op) {
    case Op::Add: return " + ";
    case Op::Sub: return " - ";
    case Op::Mul: return " * ";
    case Op::Div: return " / ";
    case Op::Less: return " < ";
    case Op::LessEqual: return " <= ";
    case Op::Greater: return " > ";
    case Op::GreaterEqual: return " >= ";
    case Op::Equal: return " == ";
    case Op::NotEqual: return " != ";
    case Op::And: return " && ";
    case Op::Or: return " || ";
    default: return nullptr;
  }
}

class Emitter {
 public:
  explicit Emitter(const Material& m) : module_(m.surface), precision_(analyse_precision(m, analyse_ranges(m))) {}

  SurfaceGlsl run() {
    for (const OutputInfo& o : outputs()) {
      auto it = module_.outputs.find(o.name);
      if (it == module_.outputs.end()) continue;
      std::string value = use(it->second);
      line("    material." + std::string(o.name) + " = " + value + ";\n", it->second);
    }
    return std::move(out_);
  }

 private:
  // The GLSL expression that refers to value `id`, emitting its definition first if needed.
  // Operands are emitted depth first, left to right, with an explicit stack: a chain of lets
  // makes the value graph as deep as the file is long, too deep for the call stack.
  std::string use(ValueId id) {
    struct Pending {
      ValueId id;
      size_t next = 0;             // index of the next operand to visit
      std::vector<std::string> a;  // GLSL of the operands visited so far
    };
    std::vector<Pending> stack;
    std::string result;
    if (refer(id, &result)) return result;
    stack.push_back({id});
    while (!stack.empty()) {
      const Value& v = module_.value(stack.back().id);
      if (stack.back().next < v.args.size()) {
        ValueId arg = v.args[stack.back().next++];
        if (refer(arg, &result))
          stack.back().a.push_back(result);
        else
          stack.push_back({arg});
        continue;
      }
      result = emitDefinition(stack.back().id, stack.back().a);
      stack.pop_back();
      if (!stack.empty()) stack.back().a.push_back(result);
    }
    return result;
  }

  // The GLSL for a value that needs no new statement (a constant, parameter, attribute or an
  // already emitted temporary); false if `id` must be defined first.
  bool refer(ValueId id, std::string* glsl) {
    const Value& v = module_.value(id);
    switch (v.op) {
      case Op::Constant: *glsl = glslConstant(v.type, v.constant); return true;
      case Op::Param:
        out_.params.insert(v.name);
        // Samplers cannot live in a uniform block: each texture is its own uniform, named in the
        // interface's `facet_` namespace (shader_abi.h kMaterialSamplerPrefix) so that no
        // parameter name can collide with a chunk's function.
        *glsl = (v.type == Type::Texture2D ? std::string(abi::kMaterialSamplerPrefix) : "params.") + v.name;
        return true;
      case Op::Attribute:
        out_.attributes.insert(v.name);
        *glsl = findAttribute(v.name)->glsl;
        return true;
      default: break;
    }
    if (auto it = temps_.find(id); it != temps_.end()) {
      *glsl = it->second;
      return true;
    }
    return false;
  }

  // Emits the statement defining value `id` from its operands' GLSL; returns the temporary's name.
  std::string emitDefinition(ValueId id, const std::vector<std::string>& a) {
    const Value& v = module_.value(id);
    std::string rhs = define(v, a);
    std::string name = tempName(id);
    // Unqualified values take the tier's default precision; analyse_precision says which keep highp.
    std::string precision = v.type != Type::Bool && precision_.highp(id) ? "highp " : "";
    line("    " + precision + glslName(v.type) + " " + name + " = " + rhs + ";\n", id);
    temps_.emplace(id, name);
    return name;
  }

  // Appends one line of GLSL, remembering which material source produced it.
  void line(const std::string& text, ValueId source) {
    out_.body += text;
    const SourceLoc* loc = module_.locOf(source);
    out_.lineLocs.push_back(loc ? *loc : SourceLoc{});
  }

  std::string define(const Value& v, const std::vector<std::string>& a) {
    if (const char* op = infix(v.op)) return a[0] + op + a[1];
    switch (v.op) {
      case Op::Swizzle: return a[0] + "." + v.name;
      case Op::Neg: return "-" + a[0];
      case Op::Not: return "!" + a[0];
      case Op::Select: return a[0] + " ? " + a[1] + " : " + a[2];
      case Op::Construct: return std::string(glslName(v.type)) + "(" + join(a) + ")";
      case Op::Builtin:
        if (v.name == "saturate") return "clamp(" + a[0] + ", 0.0, 1.0)";
        if (v.name == "sample") return "texture(" + a[0] + ", " + a[1] + ")";
        // 8-bit UNORM has no 127.5: decoding with 255/127 and 128/127 puts a flat texel (128)
        // at exactly 0, full scale (255) at exactly 1; 0 lands at −1.008, outside any unit normal.
        if (v.name == "sample_normal")
          return "texture(" + a[0] + ", " + a[1] + ").xyz * (255.0 / 127.0) - (128.0 / 127.0)";
        return v.name + "(" + join(a) + ")";
      default: return "";
    }
  }

  static std::string join(const std::vector<std::string>& a) {
    std::string s;
    for (size_t i = 0; i < a.size(); ++i) s += (i ? ", " : "") + a[i];
    return s;
  }

  std::string tempName(ValueId id) {
    if (const std::string* let = module_.nameOf(id)) return "m_" + *let;
    return "t" + std::to_string(counter_++);
  }

  const Module& module_;
  PrecisionMap precision_;
  SurfaceGlsl out_;
  std::map<ValueId, std::string> temps_;
  int counter_ = 0;
};

}  // namespace

std::string glslConstant(Type type, const std::array<double, 4>& c) {
  int n = componentCount(type);
  if (n == 1) {
    std::string s = scalarLiteral(type, c[0]);
    return c[0] < 0.0 ? "(" + s + ")" : s;
  }
  bool same = true;
  for (int i = 1; i < n; ++i) same = same && c[size_t(i)] == c[0];
  std::string s = std::string(glslName(type)) + "(";
  for (int i = 0; i < (same ? 1 : n); ++i) s += (i ? ", " : "") + floatLiteral(c[size_t(i)]);
  return s + ")";
}

SurfaceGlsl emitSurface(const Material& material) { return Emitter(material).run(); }

}  // namespace facet::ir
