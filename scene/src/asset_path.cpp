#include "facet/scene/asset_path.h"

#include <algorithm>
#include <system_error>
#include <vector>

namespace facet::scene {

namespace fs = std::filesystem;

fs::path realPath(const fs::path& path) {
  // Linux's MAXSYMLINKS: a path needing more links than this fails with ELOOP there too.
  constexpr int kMaxLinks = 40;
  std::error_code ec;
  const fs::path absolute = fs::absolute(path.empty() ? fs::path(".") : path, ec);
  if (ec) return {};
  // std::filesystem::weakly_canonical stops at the first component that does not exist, so a
  // dangling link inside the folder would count as inside while its target lies outside: the
  // components are walked one by one here instead, each link replaced by its target.
  std::vector<fs::path> pending(absolute.begin(), absolute.end());
  std::reverse(pending.begin(), pending.end());
  fs::path resolved = absolute.root_path();
  int links = 0;
  while (!pending.empty()) {
    const fs::path part = std::move(pending.back());
    pending.pop_back();
    if (part.empty() || part == "." || part == absolute.root_path() || part == absolute.root_directory()) continue;
    if (part == "..") {
      resolved = resolved.parent_path();
      continue;
    }
    const fs::path next = resolved / part;
    if (!fs::is_symlink(fs::symlink_status(next, ec))) {
      resolved = next;
      continue;
    }
    const fs::path target = fs::read_symlink(next, ec);
    if (ec || ++links > kMaxLinks) return {};
    if (target.is_absolute()) resolved = target.root_path();
    for (auto it = target.end(); it != target.begin();) pending.push_back(*--it);
  }
  return resolved;
}

bool isInside(const fs::path& root, const fs::path& real) {
  if (root.empty() || real.empty()) return false;
  const auto [rootEnd, realEnd] = std::mismatch(root.begin(), root.end(), real.begin(), real.end());
  return rootEnd == root.end();
}

}  // namespace facet::scene
