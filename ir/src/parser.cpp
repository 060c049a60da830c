#include "facet/ir/parser.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace facet::ir {
namespace {

using ast::Expr;
using ast::ExprPtr;

// Thrown inside the parser only, caught at the nearest recovery point.
struct SyntaxError {};

class Parser {
 public:
  Parser(std::vector<Token> tokens, Diagnostics& diags) : tokens_(std::move(tokens)), diags_(diags) {}

  std::optional<ast::Material> material() {
    ast::Material m;
    try {
      expectKeyword("material");
      const Token& name = expect(Tok::Identifier, "a material name");
      m.name = name.text;
      m.loc = name.loc;
      expect(Tok::LBrace, "'{' after the material name");
    } catch (SyntaxError&) {
      return std::nullopt;
    }
    while (!at(Tok::RBrace) && !at(Tok::End) && !diags_.atErrorLimit()) {
      try {
        item(m);
      } catch (SyntaxError&) {
        syncToItem();
      }
    }
    if (diags_.atErrorLimit()) return std::nullopt;
    if (!at(Tok::End)) {
      advance();  // the closing brace
      if (!at(Tok::End)) error(peek().loc, "unexpected " + spell(peek()) + " after the end of the material");
    } else {
      error(peek().loc, "expected '}' to close material '" + m.name + "'");
    }
    if (diags_.hasErrors()) return std::nullopt;
    return m;
  }

 private:
  const Token& peek(size_t ahead = 0) const {
    size_t i = std::min(pos_ + ahead, tokens_.size() - 1);
    return tokens_[i];
  }
  bool at(Tok t) const { return peek().kind == t; }
  bool atKeyword(std::string_view k) const { return at(Tok::Identifier) && peek().text == k; }
  const Token& advance() {
    const Token& t = peek();
    if (pos_ < tokens_.size() - 1) ++pos_;
    return t;
  }
  bool accept(Tok t) {
    if (!at(t)) return false;
    advance();
    return true;
  }

  static std::string spell(const Token& t) {
    if (t.kind == Tok::Identifier) return "'" + t.text + "'";
    if (t.kind == Tok::Number) return "number '" + t.text + "'";
    return describe(t.kind);
  }

  [[noreturn]] void fail(SourceLoc loc, std::string message) {
    error(loc, std::move(message));
    throw SyntaxError{};
  }
  void error(SourceLoc loc, std::string message) { diags_.error(loc, std::move(message), "parse"); }

  const Token& expect(Tok t, std::string_view what) {
    if (!at(t)) fail(peek().loc, "expected " + std::string(what) + ", found " + spell(peek()));
    return advance();
  }
  void expectKeyword(std::string_view k) {
    if (!atKeyword(k)) fail(peek().loc, "expected '" + std::string(k) + "', found " + spell(peek()));
    advance();
  }

  // After an error inside the material body: skip to the next declaration keyword or '}'.
  void syncToItem() {
    int depth = 0;
    while (!at(Tok::End)) {
      if (depth == 0 && (atKeyword("param") || atKeyword("surface") || atKeyword("shading") || atKeyword("blending") ||
                         atKeyword("tier") || atKeyword("doubleSided") || atKeyword("specularAntiAliasing")))
        return;
      if (at(Tok::LBrace)) ++depth;
      if (at(Tok::RBrace)) {
        if (depth == 0) return;
        --depth;
      }
      advance();
    }
  }

  // After an error inside `surface { }`: skip to the next statement start (an identifier
  // followed by '=' or `let`) or the closing brace. The token where the error stopped may itself
  // start the next statement (`alpha = mix(1.0, 2.0` then `reflectance = 0.5`): it is kept.
  // statement() consumes at least one token from any statement start, so this cannot loop.
  bool atStatementStart() const { return atKeyword("let") || (at(Tok::Identifier) && peek(1).kind == Tok::Assign); }

  void syncToStatement(size_t errorPos) {
    if (pos_ > errorPos && atStatementStart()) return;
    while (!at(Tok::End) && !at(Tok::RBrace)) {
      advance();
      if (atStatementStart()) return;
    }
  }

  void item(ast::Material& m) {
    if (atKeyword("shading")) {
      advance();
      const Token& t = expect(Tok::Identifier, "a shading model (lit, unlit or cloth)");
      m.shading = t.text;
      m.shadingLoc = t.loc;
    } else if (atKeyword("blending")) {
      advance();
      const Token& t = expect(Tok::Identifier, "a blending mode");
      m.blending = t.text;
      m.blendingLoc = t.loc;
      if (accept(Tok::LParen)) {
        m.alphaCutoff = expression();
        expect(Tok::RParen, "')' after the alpha cutoff");
      }
    } else if (atKeyword("doubleSided")) {
      advance();
      m.doubleSided = true;
    } else if (atKeyword("specularAntiAliasing")) {
      specularAntiAliasing(m);
      return;
    } else if (atKeyword("param")) {
      m.params.push_back(param());
    } else if (atKeyword("surface")) {
      surface(m);
      return;
    } else if (atKeyword("tier")) {
      tier(m);
      return;
    } else {
      fail(peek().loc,
           "expected 'param', 'surface', 'tier', 'shading', 'blending', 'doubleSided' or 'specularAntiAliasing', "
           "found " +
               spell(peek()));
    }
    accept(Tok::Semicolon);
  }

  ast::ParamDecl param() {
    advance();
    ast::ParamDecl p;
    const Token& name = expect(Tok::Identifier, "a parameter name");
    p.name = name.text;
    p.loc = name.loc;
    expect(Tok::Colon, "':' and a type after the parameter name");
    const Token& type = expect(Tok::Identifier, "a parameter type");
    p.typeName = type.text;
    p.typeLoc = type.loc;
    if (accept(Tok::LParen)) {
      p.typeArgument = expect(Tok::Identifier, "a colour space (srgb or linear)").text;
      expect(Tok::RParen, "')' after the colour space");
    }
    expect(Tok::Assign, "'=' and a default value (every parameter has one)");
    p.defaultValue = expression();
    if (atKeyword("in")) {
      advance();
      expect(Tok::LBracket, "'[' to open the range");
      p.rangeMin = expression();
      expect(Tok::Comma, "',' between the range bounds");
      p.rangeMax = expression();
      expect(Tok::RBracket, "']' to close the range");
    }
    return p;
  }

  void tier(ast::Material& m) {
    advance();
    const Token& name = expect(Tok::Identifier, "a tier name after 'tier'");
    std::string tierName = name.text;
    SourceLoc tierLoc = name.loc;
    expect(Tok::LBrace, "'{' after the tier name");
    while (!at(Tok::RBrace) && !at(Tok::End)) {
      ast::TierOverride o;
      o.tier = tierName;
      o.tierLoc = tierLoc;
      const Token& axis = expect(Tok::Identifier, "a tier choice (specular, diffuse)");
      o.axis = axis.text;
      o.axisLoc = axis.loc;
      expect(Tok::Assign, "'=' after '" + o.axis + "'");
      const Token& option = expect(Tok::Identifier, "an option for '" + o.axis + "'");
      o.option = option.text;
      o.optionLoc = option.loc;
      accept(Tok::Semicolon);
      m.tierOverrides.push_back(std::move(o));
    }
    expect(Tok::RBrace, "'}' to close the tier block");
  }

  // `specularAntiAliasing [{ name value ... }]`: the checker validates names and values.
  void specularAntiAliasing(ast::Material& m) {
    const Token& keyword = advance();
    if (m.hasSpecularAntiAliasing) error(keyword.loc, "the material already enables specular anti-aliasing");
    m.hasSpecularAntiAliasing = true;
    m.specularAntiAliasingLoc = keyword.loc;
    if (!accept(Tok::LBrace)) {
      accept(Tok::Semicolon);
      return;
    }
    while (!at(Tok::RBrace) && !at(Tok::End)) {
      ast::Setting s;
      const Token& name = expect(Tok::Identifier, "a setting of specularAntiAliasing (variance, threshold)");
      s.name = name.text;
      s.loc = name.loc;
      s.value = expression();
      accept(Tok::Semicolon);
      m.specularAntiAliasing.push_back(std::move(s));
    }
    expect(Tok::RBrace, "'}' to close the specularAntiAliasing block");
  }

  void surface(ast::Material& m) {
    advance();
    expect(Tok::LBrace, "'{' after 'surface'");
    while (!at(Tok::RBrace) && !at(Tok::End) && !diags_.atErrorLimit()) {
      size_t start = pos_;
      try {
        m.surface.push_back(statement());
        accept(Tok::Semicolon);
      } catch (SyntaxError&) {
        syncToStatement(start);
      }
    }
    expect(Tok::RBrace, "'}' to close the surface block");
  }

  ast::Statement statement() {
    ast::Statement s;
    if (atKeyword("let")) {
      advance();
      s.isLet = true;
    }
    const Token& name = expect(Tok::Identifier, s.isLet ? "a name after 'let'" : "an output name or 'let'");
    s.name = name.text;
    s.loc = name.loc;
    expect(Tok::Assign, "'=' after '" + s.name + "'");
    s.value = expression();
    return s;
  }

  // --- expressions, by precedence (lowest first) ---

  struct DepthGuard {
    Parser& p;
    explicit DepthGuard(Parser& parser) : p(parser) {
      if (++p.depth_ > kMaxExpressionDepth)
        p.fail(p.peek().loc, "expression nested deeper than " + std::to_string(kMaxExpressionDepth) + " levels");
    }
    ~DepthGuard() { --p.depth_; }
  };

  // Sets e's height from its children; fails when the tree grows past the limit.
  ExprPtr finish(ExprPtr e) {
    for (const ExprPtr& a : e->args) e->height = std::max(e->height, a->height + 1);
    if (e->height > kMaxExpressionDepth)
      fail(e->loc,
           "expression is more than " + std::to_string(kMaxExpressionDepth) + " operations deep; split it with 'let'");
    return e;
  }

  ExprPtr node(Expr::Kind kind, SourceLoc loc) {
    auto e = std::make_unique<Expr>();
    e->kind = kind;
    e->loc = loc;
    return e;
  }

  ExprPtr expression() {
    DepthGuard guard(*this);
    ExprPtr c = binary(0);
    if (!at(Tok::Question)) return c;
    SourceLoc loc = advance().loc;
    ExprPtr a = expression();
    expect(Tok::Colon, "':' in the conditional expression");
    ExprPtr b = expression();
    ExprPtr e = node(Expr::Kind::Ternary, loc);
    e->args.push_back(std::move(c));
    e->args.push_back(std::move(a));
    e->args.push_back(std::move(b));
    return finish(std::move(e));
  }

  static int precedence(Tok t) {
    switch (t) {
      case Tok::OrOr: return 1;
      case Tok::AndAnd: return 2;
      case Tok::EqualEqual:
      case Tok::NotEqual: return 3;
      case Tok::Less:
      case Tok::LessEqual:
      case Tok::Greater:
      case Tok::GreaterEqual: return 4;
      case Tok::Plus:
      case Tok::Minus: return 5;
      case Tok::Star:
      case Tok::Slash: return 6;
      default: return -1;
    }
  }

  // Precedence climbing; all binary operators are left-associative.
  ExprPtr binary(int minPrecedence) {
    ExprPtr lhs = unary();
    for (;;) {
      int p = precedence(peek().kind);
      if (p < 0 || p < minPrecedence) return lhs;
      const Token& op = advance();
      DepthGuard guard(*this);
      ExprPtr rhs = binary(p + 1);
      ExprPtr e = node(Expr::Kind::Binary, op.loc);
      e->op = op.kind;
      e->args.push_back(std::move(lhs));
      e->args.push_back(std::move(rhs));
      lhs = finish(std::move(e));
    }
  }

  ExprPtr unary() {
    if (at(Tok::Minus) || at(Tok::Not) || at(Tok::Plus)) {
      const Token& op = advance();
      DepthGuard guard(*this);
      ExprPtr x = unary();
      if (op.kind == Tok::Plus) return x;
      ExprPtr e = node(Expr::Kind::Unary, op.loc);
      e->op = op.kind;
      e->args.push_back(std::move(x));
      return finish(std::move(e));
    }
    return postfix();
  }

  ExprPtr postfix() {
    ExprPtr e = primary();
    while (at(Tok::Dot)) {
      advance();
      const Token& field = expect(Tok::Identifier, "a field or swizzle after '.'");
      ExprPtr m = node(Expr::Kind::Member, field.loc);
      m->name = field.text;
      m->args.push_back(std::move(e));
      e = finish(std::move(m));
    }
    return e;
  }

  ExprPtr primary() {
    const Token& t = peek();
    switch (t.kind) {
      case Tok::Number: {
        advance();
        ExprPtr e = node(Expr::Kind::Number, t.loc);
        e->spelling = t.text;
        double v = 0.0;
        auto [ptr, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
        if (ec != std::errc() || ptr != t.text.data() + t.text.size() || !std::isfinite(v) || std::fabs(v) > 3.0e38)
          error(t.loc, "number '" + t.text + "' is out of range for a 32-bit float");
        e->number = v;
        return e;
      }
      case Tok::Identifier: {
        advance();
        if (t.text == "true" || t.text == "false") {
          ExprPtr e = node(Expr::Kind::Bool, t.loc);
          e->boolean = t.text == "true";
          return e;
        }
        if (at(Tok::LParen)) return call(t);
        ExprPtr e = node(Expr::Kind::Name, t.loc);
        e->name = t.text;
        return e;
      }
      case Tok::LParen: {
        advance();
        ExprPtr e = expression();
        expect(Tok::RParen, "')'");
        return e;
      }
      default: fail(t.loc, "expected an expression, found " + spell(t));
    }
  }

  ExprPtr call(const Token& callee) {
    ExprPtr e = node(Expr::Kind::Call, callee.loc);
    e->name = callee.text;
    e->loc.length = uint32_t(callee.text.size());
    advance();  // '('
    if (!at(Tok::RParen)) {
      do {
        e->args.push_back(expression());
      } while (accept(Tok::Comma));
    }
    expect(Tok::RParen, "')' or ',' in the argument list of '" + e->name + "'");
    return finish(std::move(e));
  }

  std::vector<Token> tokens_;
  Diagnostics& diags_;
  size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

std::optional<ast::Material> parse(const SourceFile& file, Diagnostics& diags) {
  std::vector<Token> tokens = lex(file, diags);
  if (diags.hasErrors()) return std::nullopt;
  return Parser(std::move(tokens), diags).material();
}

}  // namespace facet::ir
