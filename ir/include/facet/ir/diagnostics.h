// Compiler diagnostics: `file:line:col: error: message [code]`, the source line and a caret.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace facet::ir {

// A material source file held in memory; diagnostics quote its lines.
struct SourceFile {
  std::string path;
  std::string text;
};

// A span in a source file. Lines and columns count from 1; columns count characters (a valid
// UTF-8 sequence is one character, each byte of invalid UTF-8 is one), as editors do.
struct SourceLoc {
  uint32_t line = 0;
  uint32_t column = 0;
  uint32_t offset = 0;  // byte offset of the first character
  uint32_t length = 1;  // bytes underlined by the caret
};

// The length in bytes of the well-formed UTF-8 sequence starting at text[i] (1 for ASCII), or 0
// if none starts there (a stray continuation byte, an overlong form, a surrogate, > U+10FFFF, or
// a sequence cut short). Follows the Unicode standard's table of well-formed byte sequences.
size_t utf8SequenceLength(std::string_view text, size_t i);

enum class Severity { Error, Warning };

struct Diagnostic {
  Severity severity = Severity::Error;
  SourceLoc loc;
  std::string message;
  std::string code;  // short stable id, e.g. "parse", "type", "unknown-name"
};

// Collects the diagnostics of one source file. Stages report here; they never print or exit.
// Errors past this many are counted but not kept: one mistake can cascade, and hostile input
// must not turn into millions of messages. The lexer and parser stop at the limit.
inline constexpr size_t kMaxErrors = 100;

class Diagnostics {
 public:
  explicit Diagnostics(const SourceFile& file) : file_(file) {}

  void error(SourceLoc loc, std::string message, std::string code);
  void warning(SourceLoc loc, std::string message, std::string code);

  bool hasErrors() const { return errorCount_ > 0; }
  bool atErrorLimit() const { return errorCount_ >= kMaxErrors; }
  size_t errorCount() const { return errorCount_; }
  const std::vector<Diagnostic>& all() const { return list_; }
  const SourceFile& file() const { return file_; }

  // Every diagnostic, compiler style, each followed by its source line and a caret line.
  std::string format() const;

 private:
  const SourceFile& file_;
  std::vector<Diagnostic> list_;
  size_t errorCount_ = 0;
};

std::string formatDiagnostic(const SourceFile& file, const Diagnostic& d);

// The candidate closest to `name` by edit distance, or "" if none is close enough to suggest.
std::string closestMatch(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace facet::ir
