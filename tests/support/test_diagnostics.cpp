#include "test_diagnostics.h"

#include "facet/ir/check.h"

namespace facet::test {

std::string diagnosticsFor(const std::string& text, const std::string& path) {
  ir::SourceFile file{path, text};
  ir::Diagnostics diags(file);
  ir::compileSource(file, diags);
  return diags.format();
}

}  // namespace facet::test
