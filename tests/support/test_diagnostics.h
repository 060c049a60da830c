// The diagnostics of material text, for tests of the language front end (links facet_ir only).
#pragma once

#include <string>

namespace facet::test {

// Parses and checks material text; returns the diagnostics as formatted text.
std::string diagnosticsFor(const std::string& text, const std::string& path = "test.mat");

}  // namespace facet::test
