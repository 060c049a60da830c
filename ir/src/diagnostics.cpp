#include "facet/ir/diagnostics.h"

#include <algorithm>
#include <optional>

namespace facet::ir {

void Diagnostics::error(SourceLoc loc, std::string message, std::string code) {
  if (errorCount_++ < kMaxErrors) list_.push_back({Severity::Error, loc, std::move(message), std::move(code)});
}

void Diagnostics::warning(SourceLoc loc, std::string message, std::string code) {
  list_.push_back({Severity::Warning, loc, std::move(message), std::move(code)});
}

size_t utf8SequenceLength(std::string_view text, size_t i) {
  auto byte = [&](size_t k) { return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0u; };
  const unsigned b0 = byte(0);
  if (i >= text.size()) return 0;
  if (b0 < 0x80) return 1;
  auto continuation = [&](size_t k, unsigned lo = 0x80, unsigned hi = 0xbf) { return byte(k) >= lo && byte(k) <= hi; };
  if (b0 >= 0xc2 && b0 <= 0xdf) return continuation(1) ? 2 : 0;
  if (b0 >= 0xe0 && b0 <= 0xef) {
    unsigned lo = b0 == 0xe0 ? 0xa0 : 0x80, hi = b0 == 0xed ? 0x9f : 0xbf;  // no overlongs, no surrogates
    return continuation(1, lo, hi) && continuation(2) ? 3 : 0;
  }
  if (b0 >= 0xf0 && b0 <= 0xf4) {
    unsigned lo = b0 == 0xf0 ? 0x90 : 0x80, hi = b0 == 0xf4 ? 0x8f : 0xbf;  // no overlongs, ≤ U+10FFFF
    return continuation(1, lo, hi) && continuation(2) && continuation(3) ? 4 : 0;
  }
  return 0;
}

namespace {

// Longer lines are not quoted: a minified or binary "line", where the position says enough.
constexpr size_t kMaxQuotedLine = 200;

// The text of the line holding `offset`, without its newline, or nullopt if that line is longer
// than kMaxQuotedLine. Looks at no more than that many bytes either side of `offset`, so that
// formatting N diagnostics on one huge line costs O(N), not O(N * line length).
std::optional<std::string_view> lineAt(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  size_t begin = offset;
  while (begin > 0 && text[begin - 1] != '\n') {
    if (offset - begin >= kMaxQuotedLine) return std::nullopt;
    --begin;
  }
  size_t end = offset;
  while (end < text.size() && text[end] != '\n') {
    if (end - begin >= kMaxQuotedLine) return std::nullopt;
    ++end;
  }
  return text.substr(begin, end - begin);
}

// Control characters and invalid UTF-8 bytes are shown as '?', so hostile input prints safely;
// valid UTF-8 text is kept, so a caret under it lines up character for character.
std::string printable(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size();) {
    size_t n = utf8SequenceLength(s, i);
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (n > 1) {
      out.append(s.substr(i, n));
    } else {
      out += (c == '\t' || (c >= 0x20 && c < 0x7f)) ? char(c) : '?';
      n = 1;
    }
    i += n;
  }
  return out;
}

// Characters (as SourceLoc counts them) in s[0, bytes).
size_t characters(std::string_view s, size_t bytes) {
  size_t count = 0;
  for (size_t i = 0; i < std::min(bytes, s.size()); ++count) i += std::max<size_t>(1, utf8SequenceLength(s, i));
  return count;
}

}  // namespace

std::string formatDiagnostic(const SourceFile& file, const Diagnostic& d) {
  // Line 0: a finding about the whole file (a lint figure of a compiled variant), not a place in it.
  std::string where =
      d.loc.line == 0 ? file.path : file.path + ":" + std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column);
  std::string out = where + ": " + (d.severity == Severity::Error ? "error" : "warning") + ": " + d.message;
  if (!d.code.empty()) out += " [" + d.code + "]";
  out += "\n";
  if (d.loc.line == 0) return out;
  std::optional<std::string_view> quoted = lineAt(file.text, d.loc.offset);
  if (!quoted) return out;
  std::string_view line = *quoted;
  out += "    " + printable(line) + "\n    ";
  // One space per character before the caret (tabs kept, so the caret lines up in a terminal).
  const size_t lineStart = size_t(line.data() - file.text.data());
  const size_t caretByte = std::min<size_t>(d.loc.offset - lineStart, line.size());
  for (size_t i = 0; i < caretByte;) {
    out += line[i] == '\t' ? '\t' : ' ';
    i += std::max<size_t>(1, utf8SequenceLength(line, i));
  }
  out += '^';
  size_t tail = characters(line.substr(caretByte), d.loc.length);
  for (size_t i = 1; i < tail; ++i) out += '~';
  out += "\n";
  return out;
}

std::string Diagnostics::format() const {
  std::string out;
  for (const Diagnostic& d : list_) out += formatDiagnostic(file_, d);
  if (errorCount_ >= kMaxErrors)
    out += file_.path + ": error: too many errors; stopped after " + std::to_string(kMaxErrors) + "\n";
  return out;
}

std::string closestMatch(std::string_view name, const std::vector<std::string>& candidates) {
  // Optimal string alignment distance: Levenshtein plus adjacent transpositions, so "flaot" is
  // one edit from "float". Suggest only when at most a third of the name differs.
  auto distance = [](std::string_view a, std::string_view b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
      for (size_t j = 1; j <= b.size(); ++j) {
        size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
        d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
        if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
          d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
    return d[a.size()][b.size()];
  };
  std::string best;
  size_t bestDistance = name.size() / 3 + 1;
  for (const std::string& c : candidates) {
    size_t d = distance(name, c);
    if (d < bestDistance) {
      bestDistance = d;
      best = c;
    }
  }
  return best;
}

}  // namespace facet::ir
