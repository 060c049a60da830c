// Tokens of the material language (docs/material-language.md).
#pragma once

#include <string>
#include <vector>

#include "facet/ir/diagnostics.h"

namespace facet::ir {

enum class Tok {
  End,
  Identifier,
  Number,
  String,
  LBrace,
  RBrace,
  LParen,
  RParen,
  LBracket,
  RBracket,
  Comma,
  Colon,
  Semicolon,
  Dot,
  Assign,
  Plus,
  Minus,
  Star,
  Slash,
  Less,
  LessEqual,
  Greater,
  GreaterEqual,
  EqualEqual,
  NotEqual,
  AndAnd,
  OrOr,
  Not,
  Question,
};

const char* describe(Tok);

struct Token {
  Tok kind = Tok::End;
  std::string text;  // identifier name, number spelling, string contents
  SourceLoc loc;
};

// Hard limits that keep hostile input from exhausting memory or time; exceeding one is an error.
inline constexpr size_t kMaxSourceBytes = 4u << 20;  // 4 MiB of material text
inline constexpr size_t kMaxTokenBytes = 256;        // identifiers, numbers, strings

// Splits source text into tokens, reporting bad characters; always ends with Tok::End.
std::vector<Token> lex(const SourceFile& file, Diagnostics& diags);

}  // namespace facet::ir
