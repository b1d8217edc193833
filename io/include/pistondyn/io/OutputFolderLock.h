#pragma once
/// @file
/// One pistondyn process at a time writes a result folder. `pistondyn run`, `plot` and
/// `report` hold an exclusive lock on DIR/.pistondyn.lock while they write DIR: a second
/// process started into the same folder is refused at once (OutputFolderBusy), before it
/// simulates or writes anything, so two runs never mix their rows or their files.
///
/// ~~~
///   io::OutputFolderLock lock(outDir);   // creates outDir if needed; throws if it is busy
///   io::runDeck(deck, outDir);           // all-or-nothing inside the locked folder
///                                        // ~OutputFolderLock: lock file removed, and
///                                        // outDir too if this lock created it and it is empty
/// ~~~
///
/// The lock is flock(2) on the lock file, taken without waiting, released when the object
/// goes (or the process ends, however it ends: the kernel drops the lock with the file
/// descriptor). The lock file is removed on release; a process that opened it before the
/// removal notices that the file it locked is no longer the folder's and tries again, so
/// two processes never both hold "the" lock. A file system without flock() (some network
/// file systems) runs unlocked. Within one process the lock is taken once: a second
/// OutputFolderLock on the same folder is refused too.

#include <stdexcept>
#include <string>
#include <vector>

namespace pistondyn::io {

/// Another process (or another OutputFolderLock of this one) holds the folder's lock.
class OutputFolderBusy : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An exclusive lock on a result folder (DIR/.pistondyn.lock, flock(2), taken without
/// waiting) held while one process writes it; see this file's comment for the protocol.
/// Not copyable.
class OutputFolderLock {
 public:
  /// The lock file's name inside the folder.
  static constexpr const char* kFileName = ".pistondyn.lock";

  /// Creates `dir` and missing parents, and locks it. Throws OutputFolderBusy when the lock
  /// is held, std::runtime_error naming the path when the folder or the lock file cannot be
  /// created; in both cases the folders this call created are removed again.
  explicit OutputFolderLock(std::string dir);
  /// Releases the lock and removes the lock file, then every folder this lock created that
  /// is empty (a run that wrote nothing leaves nothing behind). Never throws.
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock&) = delete;
  OutputFolderLock& operator=(const OutputFolderLock&) = delete;

  /// The locked folder, as given to the constructor.
  const std::string& getDirectory() const { return dir_; }

 private:
  void release() noexcept;
  std::string dir_, lockPath_;
  std::vector<std::string> created_;  ///< folders this lock created, deepest first
  int fd_ = -1;
};

}  // namespace pistondyn::io
