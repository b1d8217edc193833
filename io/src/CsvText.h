#pragma once
// Text helpers shared by the CSV readers (not installed).

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace pistondyn::io::detail {

inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos)
    return {};
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

inline std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string f;
  while (std::getline(ss, f, ','))
    out.push_back(trim(f));
  if (!line.empty() && line.back() == ',')
    out.emplace_back();
  return out;
}

// A finite number filling the whole field. Underflow (e.g. 1e-400) reads as 0 or a
// subnormal and is accepted as that value; overflow, "nan" and "inf" are rejected.
inline bool parseDouble(const std::string& text, double& value) {
  if (text.empty())
    return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value))
    return false;
  return errno != ERANGE || std::abs(value) < 1.0;  // ERANGE with |value| < 1 = underflow
}

// True if `path` is a folder: std::ifstream opens one without complaint and the first
// read fails, which would read as an empty table.
inline bool isFolder(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_directory(path, ec);
}

// A CSV field as the writers put it (sweep.csv, comparison.csv): quoted when it holds a
// comma, a quote, a line break or surrounding blanks, quotes doubled.
inline std::string csvField(const std::string& text) {
  const bool quote = text.find_first_of(",\"\n\r") != std::string::npos ||
                     (!text.empty() && (text.front() == ' ' || text.back() == ' '));
  if (!quote)
    return text;
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"')
      out += '"';
    out += c;
  }
  return out + "\"";
}

// Removes a UTF-8 byte-order mark at the start of the first line.
inline void stripBom(std::string& line) {
  if (line.rfind("\xEF\xBB\xBF", 0) == 0)
    line.erase(0, 3);
}

}  // namespace pistondyn::io::detail
