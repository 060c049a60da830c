#include "facet/compiler/minify_glsl.h"

#include <cctype>
#include <map>
#include <set>
#include <string_view>
#include <vector>

namespace facet::compiler {
namespace {

enum class Kind { Word, Punct, Directive };

struct Token {
  Kind kind;
  std::string_view text;
  bool spaced;  // whitespace (or a comment) stood before it in the input
};

bool wordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::vector<Token> tokenize(std::string_view s) {
  std::vector<Token> tokens;
  size_t i = 0;
  bool spaced = false;
  bool lineStart = true;
  while (i < s.size()) {
    char c = s[i];
    if (c == '\n') {
      lineStart = true;
      spaced = true;
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      spaced = true;
      ++i;
    } else if (s.compare(i, 2, "//") == 0) {
      while (i < s.size() && s[i] != '\n') ++i;
    } else if (s.compare(i, 2, "/*") == 0) {
      size_t end = s.find("*/", i + 2);
      i = end == std::string_view::npos ? s.size() : end + 2;
      spaced = true;
    } else if (c == '#' && lineStart) {
      size_t end = s.find('\n', i);
      if (end == std::string_view::npos) end = s.size();
      tokens.push_back({Kind::Directive, s.substr(i, end - i), true});
      i = end;
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      // A number keeps its spelling: 1.0e-4, .5, 0x1Fu. The exponent sign belongs to the number
      // only for decimal floats (0x1e-1 is 0x1e minus 1).
      size_t start = i;
      bool hex = s.compare(i, 2, "0x") == 0 || s.compare(i, 2, "0X") == 0;
      while (i < s.size() && (wordChar(s[i]) || s[i] == '.')) {
        if (!hex && (s[i] == 'e' || s[i] == 'E') && i + 1 < s.size() && (s[i + 1] == '+' || s[i + 1] == '-')) ++i;
        ++i;
      }
      tokens.push_back({Kind::Word, s.substr(start, i - start), spaced});
      spaced = false;
      lineStart = false;
    } else if (wordChar(c)) {
      size_t start = i;
      while (i < s.size() && wordChar(s[i])) ++i;
      tokens.push_back({Kind::Word, s.substr(start, i - start), spaced});
      spaced = false;
      lineStart = false;
    } else {
      tokens.push_back({Kind::Punct, s.substr(i, 1), spaced});
      ++i;
      spaced = false;
      lineStart = false;
    }
  }
  return tokens;
}

// Two operator characters written apart must stay apart: `a - -b` is not `a--b`, `x / *p` not a
// comment opener.
bool operatorChar(char c) { return std::string_view("+-*/%<>=!&|^").find(c) != std::string_view::npos; }

bool needsSpace(const Token& prev, const Token& next) {
  if (!next.spaced) return false;
  if (prev.kind == Kind::Word && next.kind == Kind::Word) return true;
  return prev.kind == Kind::Punct && next.kind == Kind::Punct && operatorChar(prev.text[0]) &&
         operatorChar(next.text[0]);
}

// One top-level declaration: a directive line, a function definition or prototype, or a
// declaration ending in `;` (variables, structs, blocks, precision statements).
struct Item {
  size_t begin = 0, end = 0;  // token range
  std::set<std::string_view> defines;
  bool root = false;  // kept whatever references it
};

const std::set<std::string_view> kInterfaceWords = {"uniform",   "in",     "out",      "inout", "precision", "layout",
                                                    "invariant", "buffer", "centroid", "flat",  "smooth"};

void classify(const std::vector<Token>& t, Item* item) {
  if (t[item->begin].kind == Kind::Directive) {
    item->root = true;
    return;
  }
  size_t firstParen = item->end, firstBrace = item->end, firstAssign = item->end;
  for (size_t i = item->begin; i < item->end; ++i) {
    std::string_view x = t[i].text;
    if (x == "(" && firstParen == item->end) firstParen = i;
    if (x == "{" && firstBrace == item->end) firstBrace = i;
    if (x == "=" && firstAssign == item->end) firstAssign = i;
  }
  for (size_t i = item->begin; i < std::min(firstParen, firstBrace); ++i)
    if (kInterfaceWords.count(t[i].text)) {
      item->root = true;
      return;
    }
  if (firstParen < firstAssign && firstParen < firstBrace) {  // a function definition or prototype
    if (firstParen > item->begin && t[firstParen - 1].kind == Kind::Word) item->defines.insert(t[firstParen - 1].text);
  } else if (t[item->begin].text == "struct" && item->begin + 1 < item->end) {
    // `struct S { ... };` only: a struct that also declares a variable is kept.
    if (item->end >= 2 && t[item->end - 2].text == "}") item->defines.insert(t[item->begin + 1].text);
  } else {
    // Variables: in each declarator (split at top-level commas), the last word before `=` or `[`.
    int depth = 0;
    std::string_view last;
    bool named = false;
    for (size_t i = item->begin; i < item->end; ++i) {
      std::string_view x = t[i].text;
      if (depth == 0 && (x == "=" || x == "[" || x == "," || x == ";") && !named && !last.empty()) {
        item->defines.insert(last);
        named = true;
      }
      if (depth == 0 && x == ",") named = false, last = {};
      if (x == "(" || x == "[" || x == "{")
        ++depth;
      else if (x == ")" || x == "]" || x == "}")
        --depth;
      else if (depth == 0 && !named && t[i].kind == Kind::Word)
        last = x;
    }
  }
  if (item->defines.empty()) item->root = true;
}

std::vector<Item> splitItems(const std::vector<Token>& t) {
  std::vector<Item> items;
  size_t i = 0;
  while (i < t.size()) {
    Item item;
    item.begin = i;
    if (t[i].kind == Kind::Directive) {
      item.end = ++i;
    } else {
      int paren = 0, brace = 0;
      bool sawParenBeforeBrace = false;
      for (; i < t.size(); ++i) {
        std::string_view x = t[i].text;
        if (t[i].kind == Kind::Directive) break;
        if (x == "(" || x == "[")
          ++paren;
        else if (x == ")" || x == "]")
          --paren;
        else if (x == "{") {
          if (brace == 0) sawParenBeforeBrace = i > item.begin && t[i - 1].text == ")";
          ++brace;
        } else if (x == "}") {
          if (--brace == 0 && sawParenBeforeBrace) {  // end of a function body
            ++i;
            break;
          }
        } else if (x == ";" && paren == 0 && brace == 0) {
          ++i;
          break;
        }
      }
      item.end = i;
    }
    classify(t, &item);
    items.push_back(std::move(item));
  }
  return items;
}

}  // namespace

std::string minifyPreprocessedGlsl(const std::string& preprocessed) {
  std::vector<Token> tokens = tokenize(preprocessed);
  std::vector<Item> items = splitItems(tokens);

  std::map<std::string_view, std::vector<size_t>> definedBy;
  for (size_t k = 0; k < items.size(); ++k)
    for (std::string_view name : items[k].defines) definedBy[name].push_back(k);
  std::vector<bool> kept(items.size(), false);
  std::vector<size_t> work;
  auto keep = [&](size_t k) {
    if (!kept[k]) kept[k] = true, work.push_back(k);
  };
  for (size_t k = 0; k < items.size(); ++k)
    if (items[k].root || items[k].defines.count("main")) keep(k);
  while (!work.empty()) {
    size_t k = work.back();
    work.pop_back();
    for (size_t i = items[k].begin; i < items[k].end; ++i) {
      if (tokens[i].kind != Kind::Word) continue;
      auto it = definedBy.find(tokens[i].text);
      if (it != definedBy.end())
        for (size_t other : it->second) keep(other);
    }
  }

  std::string out;
  out.reserve(preprocessed.size() / 4);
  for (size_t k = 0; k < items.size(); ++k) {
    if (!kept[k]) continue;
    const Item& item = items[k];
    if (tokens[item.begin].kind == Kind::Directive) {
      out.append(tokens[item.begin].text);
      out += '\n';
      continue;
    }
    int paren = 0;
    for (size_t i = item.begin; i < item.end; ++i) {
      const Token& tok = tokens[i];
      bool lineStart = out.empty() || out.back() == '\n';
      if (i > item.begin && !lineStart && needsSpace(tokens[i - 1], tok)) out += ' ';
      out.append(tok.text);
      std::string_view x = tok.text;
      if (x == "(") ++paren;
      if (x == ")") --paren;
      // One statement per line keeps driver messages readable at a byte per statement.
      bool endsLine = (x == ";" && paren == 0) || x == "{" ||
                      (x == "}" && (i + 1 >= item.end || (tokens[i + 1].text != ";" && tokens[i + 1].text != "else")));
      if (endsLine) out += '\n';
    }
    if (out.back() != '\n') out += '\n';
  }
  return out;
}

}  // namespace facet::compiler
