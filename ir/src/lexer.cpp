#include "facet/ir/lexer.h"

#include <algorithm>
#include <cctype>

namespace facet::ir {

const char* describe(Tok t) {
  switch (t) {
    case Tok::End: return "end of file";
    case Tok::Identifier: return "identifier";
    case Tok::Number: return "number";
    case Tok::String: return "string";
    case Tok::LBrace: return "'{'";
    case Tok::RBrace: return "'}'";
    case Tok::LParen: return "'('";
    case Tok::RParen: return "')'";
    case Tok::LBracket: return "'['";
    case Tok::RBracket: return "']'";
    case Tok::Comma: return "','";
    case Tok::Colon: return "':'";
    case Tok::Semicolon: return "';'";
    case Tok::Dot: return "'.'";
    case Tok::Assign: return "'='";
    case Tok::Plus: return "'+'";
    case Tok::Minus: return "'-'";
    case Tok::Star: return "'*'";
    case Tok::Slash: return "'/'";
    case Tok::Less: return "'<'";
    case Tok::LessEqual: return "'<='";
    case Tok::Greater: return "'>'";
    case Tok::GreaterEqual: return "'>='";
    case Tok::EqualEqual: return "'=='";
    case Tok::NotEqual: return "'!='";
    case Tok::AndAnd: return "'&&'";
    case Tok::OrOr: return "'||'";
    case Tok::Not: return "'!'";
    case Tok::Question: return "'?'";
  }
  return "token";
}

namespace {

class Lexer {
 public:
  Lexer(const SourceFile& file, Diagnostics& diags) : text_(file.text), diags_(diags) {}

  std::vector<Token> run() {
    std::vector<Token> out;
    if (text_.size() > kMaxSourceBytes) {
      diags_.error(here(),
                   "material file is " + std::to_string(text_.size()) + " bytes; the limit is " +
                       std::to_string(kMaxSourceBytes),
                   "limit");
      out.push_back({Tok::End, "", here()});
      return out;
    }
    for (;;) {
      skipSpaceAndComments();
      if (diags_.atErrorLimit()) pos_ = text_.size();  // enough: report what we have
      SourceLoc loc = here();
      if (pos_ >= text_.size()) {
        out.push_back({Tok::End, "", loc});
        return out;
      }
      unsigned char c = static_cast<unsigned char>(text_[pos_]);
      if (std::isalpha(c) || c == '_') {
        out.push_back(word(Tok::Identifier, loc, [](unsigned char ch) { return std::isalnum(ch) || ch == '_'; }));
      } else if (std::isdigit(c) ||
                 (c == '.' && pos_ + 1 < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_ + 1])))) {
        out.push_back(number(loc));
      } else if (c == '"') {
        out.push_back(string(loc));
      } else if (Tok t = punct(); t != Tok::End) {
        loc.length = uint32_t(pos_ - loc.offset);
        out.push_back({t, "", loc});
      } else if (c >= 0x80) {
        nonAscii(loc);
      } else {
        std::string shown = (c >= 0x20 && c < 0x7f) ? std::string("'") + char(c) + "'" : "byte 0x" + hex(c);
        diags_.error(loc, "unexpected character " + shown, "lex");
        advance();
      }
    }
  }

 private:
  static std::string hex(unsigned char c) {
    const char* digits = "0123456789abcdef";
    return {digits[c >> 4], digits[c & 15]};
  }

  SourceLoc here() const { return {line_, column_, uint32_t(pos_), 1}; }

  // Moves past one character: a whole UTF-8 sequence (never containing an ASCII byte, so no
  // caller looking for '\n', '"' or '*' can miss one), or one byte of anything else.
  void advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    pos_ += std::max<size_t>(1, utf8SequenceLength(text_, pos_));
  }

  // Non-ASCII outside comments and strings: one error for the whole run of it (a word in another
  // script is one mistake, not one per byte), quoting it when it is valid UTF-8.
  void nonAscii(SourceLoc loc) {
    bool valid = true;
    std::string bytes;
    while (pos_ < text_.size() && static_cast<unsigned char>(text_[pos_]) >= 0x80) {
      size_t n = utf8SequenceLength(text_, pos_);
      valid = valid && n > 0;
      if (bytes.size() < 24) bytes += text_.substr(pos_, std::max<size_t>(1, n));
      advance();
    }
    loc.length = uint32_t(pos_ - loc.offset);
    if (valid) {
      diags_.error(loc, "unexpected non-ASCII text '" + bytes + "'; outside comments and strings a material is ASCII",
                   "lex");
      return;
    }
    std::string shown;
    for (size_t i = 0; i < bytes.size() && i < 8; ++i) shown += " 0x" + hex(static_cast<unsigned char>(bytes[i]));
    diags_.error(loc,
                 std::string("invalid UTF-8 (") + (loc.length == 1 ? "byte" : "bytes") + shown +
                     (loc.length > 8 ? " ..." : "") + ")",
                 "lex");
  }

  bool at(char c, size_t ahead = 0) const { return pos_ + ahead < text_.size() && text_[pos_ + ahead] == c; }

  void skipSpaceAndComments() {
    while (pos_ < text_.size()) {
      char c = text_[pos_];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
        advance();
      } else if (c == '/' && at('/', 1)) {
        while (pos_ < text_.size() && text_[pos_] != '\n') advance();
      } else if (c == '/' && at('*', 1)) {
        SourceLoc start = here();
        advance();
        advance();
        while (pos_ < text_.size() && !(at('*') && at('/', 1))) advance();
        if (pos_ >= text_.size()) {
          diags_.error(start, "unterminated block comment", "lex");
          return;
        }
        advance();
        advance();
      } else {
        return;
      }
    }
  }

  template <typename Pred>
  Token word(Tok kind, SourceLoc loc, Pred keep) {
    while (pos_ < text_.size() && keep(static_cast<unsigned char>(text_[pos_]))) advance();
    return finish(kind, loc, std::string(text_.substr(loc.offset, pos_ - loc.offset)));
  }

  Token finish(Tok kind, SourceLoc loc, std::string spelling) {
    loc.length = uint32_t(pos_ - loc.offset);
    if (spelling.size() > kMaxTokenBytes) {
      diags_.error(loc,
                   std::string(describe(kind)) + " is " + std::to_string(spelling.size()) +
                       " characters long; the limit is " + std::to_string(kMaxTokenBytes),
                   "limit");
      spelling.resize(kMaxTokenBytes);
    }
    return {kind, std::move(spelling), loc};
  }

  Token number(SourceLoc loc) {
    auto digits = [&] {
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) advance();
    };
    digits();
    if (at('.')) {
      advance();
      digits();
    }
    if (at('e') || at('E')) {
      advance();
      if (at('+') || at('-')) advance();
      if (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) {
        digits();
      } else {  // "2e" or "2e+": an exponent with no digits is a typo, not 2 followed by a name
        SourceLoc at = loc;
        at.length = uint32_t(pos_ - loc.offset);
        diags_.error(
            at,
            "number '" + std::string(text_.substr(loc.offset, pos_ - loc.offset)) + "' has an exponent with no digits",
            "lex");
      }
    }
    return finish(Tok::Number, loc, std::string(text_.substr(loc.offset, pos_ - loc.offset)));
  }

  Token string(SourceLoc loc) {
    advance();
    size_t begin = pos_;
    while (pos_ < text_.size() && text_[pos_] != '"' && text_[pos_] != '\n') advance();
    if (!at('"')) {
      diags_.error(loc, "unterminated string", "lex");
      return finish(Tok::String, loc, std::string(text_.substr(begin, pos_ - begin)));
    }
    std::string contents(text_.substr(begin, pos_ - begin));
    advance();
    return finish(Tok::String, loc, std::move(contents));
  }

  Tok punct() {
    char c = text_[pos_];
    auto two = [&](char next, Tok both, Tok one) {
      advance();
      if (at(next)) {
        advance();
        return both;
      }
      return one;
    };
    switch (c) {
      case '{': advance(); return Tok::LBrace;
      case '}': advance(); return Tok::RBrace;
      case '(': advance(); return Tok::LParen;
      case ')': advance(); return Tok::RParen;
      case '[': advance(); return Tok::LBracket;
      case ']': advance(); return Tok::RBracket;
      case ',': advance(); return Tok::Comma;
      case ':': advance(); return Tok::Colon;
      case ';': advance(); return Tok::Semicolon;
      case '.': advance(); return Tok::Dot;
      case '+': advance(); return Tok::Plus;
      case '-': advance(); return Tok::Minus;
      case '*': advance(); return Tok::Star;
      case '/': advance(); return Tok::Slash;
      case '?': advance(); return Tok::Question;
      case '=': return two('=', Tok::EqualEqual, Tok::Assign);
      case '<': return two('=', Tok::LessEqual, Tok::Less);
      case '>': return two('=', Tok::GreaterEqual, Tok::Greater);
      case '!': return two('=', Tok::NotEqual, Tok::Not);
      case '&':
        if (at('&', 1)) {
          advance();
          advance();
          return Tok::AndAnd;
        }
        return Tok::End;
      case '|':
        if (at('|', 1)) {
          advance();
          advance();
          return Tok::OrOr;
        }
        return Tok::End;
      default: return Tok::End;
    }
  }

  std::string_view text_;
  Diagnostics& diags_;
  size_t pos_ = 0;
  uint32_t line_ = 1;
  uint32_t column_ = 1;
};

}  // namespace

std::vector<Token> lex(const SourceFile& file, Diagnostics& diags) { return Lexer(file, diags).run(); }

}  // namespace facet::ir
