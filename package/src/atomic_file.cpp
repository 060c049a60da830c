#include "facet/atomic_file.h"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

namespace facet {
namespace {

// The temporary files a signal handler must remove. Plain arrays and atomics: a handler may
// only touch lock-free state and call async-signal-safe functions (unlink, raise).
constexpr int kSlots = 16;
constexpr size_t kMaxPath = 4096;
std::atomic<bool> used[kSlots];
char paths[kSlots][kMaxPath];

int claim(const std::string& path) {
  if (path.size() >= kMaxPath) return -1;  // still written safely; only an interrupt would leave it
  for (int i = 0; i < kSlots; ++i) {
    bool expected = false;
    if (used[i].compare_exchange_strong(expected, true)) {
      // Published before the flag is seen set by a handler? The flag is set first, so a handler
      // running now may read a half-written path: write it whole, then mark it ready with a NUL
      // at the start last.
      paths[i][0] = '\0';
      std::memcpy(paths[i] + 1, path.c_str() + 1, path.size());
      std::atomic_signal_fence(std::memory_order_seq_cst);
      paths[i][0] = path[0];
      return i;
    }
  }
  return -1;
}

void release(int slot) {
  if (slot < 0) return;
  paths[slot][0] = '\0';
  std::atomic_signal_fence(std::memory_order_seq_cst);
  used[slot].store(false);
}

extern "C" void removeTemporaryFilesAndDie(int sig) {
  for (int i = 0; i < kSlots; ++i)
    if (used[i].load() && paths[i][0] != '\0') unlink(paths[i]);
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

bool AtomicFile::commit(std::string* error) {
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
