#pragma once
// Finding and running gnuplot (Debian package gnuplot; the pngcairo terminal) for
// `pistondyn plot`, `report` and `run`. Plotting stays at the program's edge.

#include <stdexcept>
#include <string>

namespace pistondyn::app {

// gnuplot is not installed (or PISTONDYN_GNUPLOT names no executable file).
class GnuplotMissing : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The gnuplot to run: $PISTONDYN_GNUPLOT if set (it must be an executable file), else the
// first `gnuplot` on $PATH. Throws GnuplotMissing with a message that says what to install.
std::string findGnuplot();

// Runs `gnuplot scriptPath`, its output going to logPath. Throws std::runtime_error with
// gnuplot's messages if it cannot start or exits with an error, common::Cancelled (after
// ending gnuplot) when SIGINT / SIGTERM asked the program to stop meanwhile.
void runGnuplot(const std::string& gnuplot, const std::string& scriptPath,
                const std::string& logPath);

}  // namespace pistondyn::app
