#include "gl_uniform_blocks.h"

namespace facet::runtime::gl {

GLuint UniformBlockCache::resident(const facet::runtime::UniformBlock& block) {
  Entry& entry = blocks_[&block];
  entry.lastUsedFrame = frameNumber_;
  if (entry.buffer.id() && entry.generation == block.generation) return entry.buffer.id();
  if (!entry.buffer.id()) entry.buffer = Buffer::generate();
  // glBufferData gives fresh storage: draws already queued keep reading the old contents.
  glBindBuffer(GL_UNIFORM_BUFFER, entry.buffer.id());
  glBufferData(GL_UNIFORM_BUFFER, static_cast<GLsizeiptr>(block.bytes.size()), block.bytes.data(), GL_STATIC_DRAW);
  entry.generation = block.generation;
  ++uploads_;
  return entry.buffer.id();
}

void UniformBlockCache::endFrame() {
  evictUnusedEntries(blocks_, frameNumber_, [](auto&) {});  // GL objects delete themselves
}

}  // namespace facet::runtime::gl
