#include "facet/package/atomic_file.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <new>

namespace facet {
namespace {

// The temporary files a signal handler must remove. Plain arrays and atomics: a handler may
// only touch lock-free state and call async-signal-safe functions (unlink, raise). Enough slots
// for every output of one command staged at once (package::writeFiles): `matc compile
// --emit-source` of 32 variants holds 321 temporary files before it renames them.
constexpr int kSlots = 1024;
constexpr size_t kMaxPath = 4096;
std::atomic<bool> used[kSlots];
// A slot's path buffer is allocated the first time the slot is claimed and never freed, so a
// handler never reads freed memory, and a process that writes one file at a time holds one.
std::atomic<char*> paths[kSlots];

int claim(const std::string& path) {
  if (path.size() >= kMaxPath) return -1;  // still written safely; only an interrupt would leave it
  for (int i = 0; i < kSlots; ++i) {
    bool expected = false;
    if (used[i].compare_exchange_strong(expected, true)) {
      char* buffer = paths[i].load();
      if (buffer == nullptr) {
        buffer = new (std::nothrow) char[kMaxPath];
        if (buffer == nullptr) {
          used[i].store(false);
          return -1;
        }
        buffer[0] = '\0';
        paths[i].store(buffer);
      }
      // Published before the flag is seen set by a handler? The flag is set first, so a handler
      // running now may read a half-written path: write it whole, then mark it ready with a NUL
      // at the start last.
      buffer[0] = '\0';
      std::memcpy(buffer + 1, path.c_str() + 1, path.size());
      std::atomic_signal_fence(std::memory_order_seq_cst);
      buffer[0] = path[0];
      return i;
    }
  }
  return -1;
}

void release(int slot) {
  if (slot < 0) return;
  paths[slot].load()[0] = '\0';
  std::atomic_signal_fence(std::memory_order_seq_cst);
  used[slot].store(false);
}

extern "C" void removeTemporaryFilesAndDie(int sig) {
  for (int i = 0; i < kSlots; ++i) {
    const char* path = paths[i].load();
    if (used[i].load() && path != nullptr && path[0] != '\0') unlink(path);
  }
  signal(sig, SIG_DFL);
  raise(sig);
}

std::string reason(int error) { return std::strerror(error); }

}  // namespace

AtomicFile::~AtomicFile() { discard(); }

void AtomicFile::discard() {
  if (fd_ >= 0) close(fd_);
  fd_ = -1;
  if (!temp_.empty()) unlink(temp_.c_str());
  release(slot_);
  slot_ = -1;
  temp_.clear();
}

bool AtomicFile::open(const std::string& path, std::string* error) {
  discard();
  path_ = path;
  struct stat st {};
  if (stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    *error = "cannot write '" + path + "': it exists and is not a regular file";
    return false;
  }
  // mkstemp: a new name, created with O_EXCL (never an existing file or a planted link).
  // Signals are held off until the name is registered, so no interrupt can leave it behind.
  std::string temp = path + ".tmp.XXXXXX";
  sigset_t all, previous;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, &previous);
  fd_ = mkstemp(temp.data());
  int e = errno;
  if (fd_ >= 0) slot_ = claim(temp);
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  if (fd_ < 0) {
    *error = "cannot write '" + path + "': " + reason(e);
    return false;
  }
  temp_ = temp;
  // mkstemp creates 0600; a package is a plain file, readable as the umask allows.
  mode_t mask = umask(0);
  umask(mask);
  fchmod(fd_, 0666 & ~mask);
  return true;
}

bool AtomicFile::write(std::span<const uint8_t> bytes, std::string* error) {
  const uint8_t* p = bytes.data();
  size_t left = bytes.size();
  while (left > 0) {
    ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      *error = "cannot write '" + path_ + "': " + reason(n < 0 ? errno : EIO);
      discard();
      return false;
    }
    p += n;
    left -= size_t(n);
  }
  return true;
}

bool AtomicFile::finish(std::string* error) {
  if (fd_ < 0) {
    *error = "cannot write '" + path_ + "': not open";
    return false;
  }
  int closed = close(fd_);
  fd_ = -1;
  if (closed != 0) {
    *error = "cannot write '" + path_ + "': " + reason(errno);
    discard();
    return false;
  }
  return true;
}

bool AtomicFile::commit(std::string* error) {
  if (temp_.empty()) {
    *error = "cannot write '" + path_ + "': not open";
    return false;
  }
  if (fd_ >= 0 && !finish(error)) return false;
  if (rename(temp_.c_str(), path_.c_str()) != 0) {
    *error = "cannot write '" + path_ + "': " + reason(errno);
    discard();
    return false;
  }
  temp_.clear();
  release(slot_);
  slot_ = -1;
  return true;
}

void removeTemporaryFilesOnSignals() {
  struct sigaction action {};
  action.sa_handler = removeTemporaryFilesAndDie;
  sigemptyset(&action.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &action, nullptr);
}

}  // namespace facet
