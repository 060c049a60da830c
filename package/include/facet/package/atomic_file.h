// Files that appear whole or not at all. Every output Facet's tools write (packages, reports,
// images, baselines) goes through here, so that neither a failure nor an interrupt leaves a
// partial file, and no tool writes through a device node, a FIFO or a directory.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace facet {

// Bytes go to a fresh temporary file beside the destination (created exclusively: never an
// existing file or a link someone planted), which commit() renames over the destination.
// Until then the temporary file is removed by the destructor, and, in a process that called
// removeTemporaryFilesOnSignals(), when SIGINT, SIGTERM or SIGHUP ends the process.
class AtomicFile {
 public:
  AtomicFile() = default;
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Refuses a destination that exists and is not a regular file (after links): replacing
  // /dev/null or a FIFO with a package is never what the user meant.
  bool open(const std::string& path, std::string* error);
  bool write(std::span<const uint8_t> bytes, std::string* error);
  // Closes the temporary file, every byte written: what can fail before the rename. commit()
  // then only renames, so several files can all be finished before any replaces its destination.
  bool finish(std::string* error);
  bool commit(std::string* error);

  const std::string& temporaryPath() const { return temp_; }

 private:
  void discard();
  std::string path_, temp_;
  int fd_ = -1;
  int slot_ = -1;  // place in the signal handler's list of files to remove
};

// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove the temporary files of open
// AtomicFiles, then end the process with the same signal (so the exit status still says which).
// For command-line tools; a library never installs signal handlers behind an app's back.
void removeTemporaryFilesOnSignals();

}  // namespace facet
