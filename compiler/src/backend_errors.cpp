#include "facet/compiler/backend_errors.h"

#include <charconv>
#include <sstream>

namespace facet::compiler {

std::optional<MappedError> mapGlslangErrors(const std::string& log, uint32_t surfaceFirstLine,
                                            const std::vector<ir::SourceLoc>& lineLocs) {
  if (surfaceFirstLine == 0) return std::nullopt;
  std::istringstream lines(log);
  std::string line;
  const std::string prefix = "ERROR: 0:";
  while (std::getline(lines, line)) {
    if (line.rfind(prefix, 0) != 0) continue;
    const char* begin = line.data() + prefix.size();
    const char* end = line.data() + line.size();
    uint32_t number = 0;
    auto [rest, ec] = std::from_chars(begin, end, number);
    if (ec != std::errc() || rest == end || *rest != ':' || number < surfaceFirstLine) continue;
    size_t index = number - surfaceFirstLine;
    if (index >= lineLocs.size() || lineLocs[index].line == 0) continue;
    std::string message(rest + 1, end);
    while (!message.empty() && message.front() == ' ') message.erase(0, 1);
    return MappedError{message, lineLocs[index]};
  }
  return std::nullopt;
}

}  // namespace facet::compiler
