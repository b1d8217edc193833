#include "pistondyn/io/OutputFolderLock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace pistondyn::io {

namespace fs = std::filesystem;

OutputFolderLock::OutputFolderLock(std::string dir) : dir_(std::move(dir)) {
  std::error_code ec;
  // The folders that do not exist yet, deepest first, to remove them again.
  for (fs::path p = dir_; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    created_.push_back(p.string());
    if (p == p.parent_path())
      break;
  }
  lockPath_ = (fs::path(dir_) / kFileName).string();
  try {
    fs::create_directories(dir_, ec);
    if (ec || !fs::is_directory(dir_))
      throw std::runtime_error(dir_ + ": cannot create the output folder" +
                               (ec ? ": " + ec.message() : std::string()));
    // Lock, then check that the file locked is still the folder's lock file: a holder
    // that released it meanwhile removed it (release()), and a lock on the removed file
    // locks nothing.
    for (int attempt = 0; attempt < 100; ++attempt) {
      fd_ = ::open(lockPath_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
      if (fd_ < 0) {
        throw std::runtime_error(
            lockPath_ + ": cannot create the output folder's lock file: " + std::strerror(errno));
      }
      if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const int err = errno;
        ::close(fd_);
        fd_ = -1;
        if (err == EWOULDBLOCK) {
          throw OutputFolderBusy(dir_ +
                                 " is in use by another pistondyn process writing results there "
                                 "now (it holds " +
                                 lockPath_ + "); wait for it to end, or use another folder");
        }
        ::unlink(lockPath_.c_str());
        return;  // no flock() on this file system: unlocked, as documented
      }
      struct stat held {
      }, named{};
      if (::fstat(fd_, &held) == 0 && ::stat(lockPath_.c_str(), &named) == 0 &&
          held.st_dev == named.st_dev && held.st_ino == named.st_ino)
        return;
      ::close(fd_);
      fd_ = -1;
    }
    throw std::runtime_error(lockPath_ + ": the lock file keeps changing under this process");
  } catch (...) {
    release();
    throw;
  }
}

OutputFolderLock::~OutputFolderLock() {
  release();
}

void OutputFolderLock::release() noexcept {
  std::error_code ignored;
  if (fd_ >= 0) {
    // Removed while still held: nobody can lock the file being removed in between.
    ::unlink(lockPath_.c_str());
    ::close(fd_);
    fd_ = -1;
  }
  for (const auto& folder : created_)
    fs::remove(folder, ignored);  // only removes empty folders
  created_.clear();
}

}  // namespace pistondyn::io
