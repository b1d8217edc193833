#include "Gnuplot.h"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "pistondyn/common/Cancellation.h"

extern char** environ;

namespace pistondyn::app {
namespace {

bool isExecutableFile(const std::string& path) {
  struct stat st {};
  return !path.empty() && ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
         ::access(path.c_str(), X_OK) == 0;
}

}  // namespace

std::string findGnuplot() {
  if (const char* given = std::getenv("PISTONDYN_GNUPLOT")) {
    if (isExecutableFile(given))
      return given;
    throw GnuplotMissing(std::string("PISTONDYN_GNUPLOT=") + given +
                         " is not an executable file; unset it to use the gnuplot on PATH");
  }
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/gnuplot";
    if (isExecutableFile(candidate))
      return candidate;
  }
  throw GnuplotMissing(
      "gnuplot was not found on PATH: install it (Debian: apt-get install gnuplot-nox) or set "
      "PISTONDYN_GNUPLOT to its path");
}

void runGnuplot(const std::string& gnuplot, const std::string& scriptPath,
                const std::string& logPath) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, logPath.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::vector<char*> argv{const_cast<char*>(gnuplot.c_str()),
                          const_cast<char*>(scriptPath.c_str()), nullptr};
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, gnuplot.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0)
    throw std::runtime_error(gnuplot + ": cannot start gnuplot");
  // Waited for in short polls, so that SIGINT / SIGTERM (common/Cancellation.h) stop it:
  // gnuplot is ended too, and the caller's cleanup removes what it was drawing.
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid || (done < 0 && errno != EINTR))
      break;
    if (common::isCancellationRequested()) {
      ::kill(pid, SIGTERM);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      common::throwIfCancelled();
    }
    ::usleep(20000);
  }
  common::throwIfCancelled();  // gnuplot ended by the same Ctrl-C (its process group's)
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::ifstream in(logPath);
    std::stringstream ss;
    ss << in.rdbuf();
    throw std::runtime_error("gnuplot failed on " + scriptPath + ":\n" + ss.str());
  }
}

}  // namespace pistondyn::app
