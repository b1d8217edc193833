#include "Logging.h"

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

namespace pistondyn::app {

void addLogLevelOption(CLI::App& command, std::string& level) {
  command
      .add_option("--log-level", level,
                  std::string("how much the program logs on stderr: ") + kLogLevels +
                      " (default: warn; info names what it reads and writes, debug adds "
                      "gnuplot's command lines)")
      ->type_name("LEVEL")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}));
}

void setUpLogging(const std::string& level) {
  // A colour sink colours only on a terminal.
  auto logger = spdlog::stderr_color_mt("pistondyn");
  logger->set_pattern("pistondyn [%l] %v");
  logger->set_level(spdlog::level::from_str(level));
  spdlog::set_default_logger(logger);
}

}  // namespace pistondyn::app
