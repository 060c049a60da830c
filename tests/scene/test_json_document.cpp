// Facet's strict JSON reader and the files read through it (scenes, lint budgets and baselines):
// nesting is bounded before any parser runs, so a small file cannot exhaust the stack or memory.
#include <gtest/gtest.h>

#include <string>

#include "facet/lint/budgets.h"
#include "facet/scene/json_document.h"
#include "facet/scene/scene.h"

namespace {

using facet::scene::jsonTooDeepAt;
using facet::scene::kMaxJsonDepth;

std::string nested(size_t depth, const std::string& inner = "") {
  return std::string(depth, '[') + inner + std::string(depth, ']');
}

}  // namespace

TEST(JsonDocument, NestingIsMeasuredOutsideStrings) {
  EXPECT_FALSE(jsonTooDeepAt(nested(kMaxJsonDepth)));
  EXPECT_EQ(jsonTooDeepAt(nested(kMaxJsonDepth + 1)), kMaxJsonDepth);
  EXPECT_EQ(jsonTooDeepAt("{\"a\": [[{}]]}", 3), 8u);
  // Brackets inside strings, escaped quotes included, open nothing.
  EXPECT_FALSE(jsonTooDeepAt("[\"[[[[\", \"\\\"[[[[\"]", 1));
  EXPECT_EQ(jsonTooDeepAt("[\"\\\\\", [[]]]", 2), 8u) << "an escaped backslash ends before the closing quote";
  // Closing brackets beyond the opening ones are the parser's to report, not a negative depth.
  EXPECT_EQ(jsonTooDeepAt("]]]]][[", 1), 6u);
}

TEST(JsonDocument, TooDeepIsAnErrorAtItsLineAndColumnBeforeParsing) {
  std::string error;
  // 20,000 levels in 40 KB: once a stack overflow in a recursive reader, and quadratic memory in
  // one that keeps the path to every open level.
  const std::string text = "{\"objects\": [],\n \"x\": " + nested(20000) + "}";
  EXPECT_FALSE(facet::scene::parseJsonDocument("deep.json", text, &error));
  EXPECT_EQ(error, "deep.json:2:" + std::to_string(7 + kMaxJsonDepth - 1) +
                       ": error: arrays and objects nest more than 64 deep here (Facet reads JSON at most that deep)");
  // At the bound the document parses.
  EXPECT_TRUE(facet::scene::parseJsonDocument("ok.json", "{\"x\": " + nested(kMaxJsonDepth - 1) + "}", &error))
      << error;
}

TEST(JsonDocument, ScenesAndLintFilesRefuseDeepNesting) {
  const std::string deep = "{\"tiers\": " + nested(100000) + "}";
  std::string error;
  EXPECT_FALSE(facet::runtime::parseScene("s.json", deep, &error));
  EXPECT_NE(error.find("s.json:1:"), std::string::npos) << error;
  EXPECT_NE(error.find("nest more than 64 deep"), std::string::npos) << error;
  error.clear();
  EXPECT_FALSE(facet::lint::parseBudgets("budgets.json", deep, &error));
  EXPECT_NE(error.find("budgets.json:1:"), std::string::npos) << error;
  EXPECT_NE(error.find("nest more than 64 deep"), std::string::npos) << error;
  error.clear();
  EXPECT_FALSE(facet::lint::parseBaseline("baseline.json", deep, &error));
  EXPECT_NE(error.find("baseline.json:1:"), std::string::npos) << error;
  EXPECT_NE(error.find("nest more than 64 deep"), std::string::npos) << error;
}
