#include "pistondyn/io/ResultWriters.h"

#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace pistondyn::io {

std::string formatNumber(double v) {
  if (!std::isfinite(v))
    return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  std::array<char, 32> buf{};
  const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), res.ptr);
}

void writeCsv(std::ostream& out, const plugin::ResultTable& table,
              const std::vector<std::string>& commentLines) {
  for (const auto& c : commentLines)
    out << "# " << c << '\n';
  for (std::size_t j = 0; j < table.columns.size(); ++j) {
    out << (j ? "," : "") << table.columns[j];
  }
  out << '\n';
  for (const auto& row : table.rows) {
    for (std::size_t j = 0; j < row.size(); ++j)
      out << (j ? "," : "") << formatNumber(row[j]);
    out << '\n';
  }
}

std::string JsonWriter::quote(const std::string& s) {
  std::string q = "\"";
  for (const char c : s) {
    switch (c) {
      case '"':
        q += "\\\"";
        break;
      case '\\':
        q += "\\\\";
        break;
      case '\n':
        q += "\\n";
        break;
      case '\t':
        q += "\\t";
        break;
      case '\r':
        q += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          q += buf;
        } else {
          q += c;
        }
    }
  }
  return q + "\"";
}

void JsonWriter::prefix(const std::string& key) {
  if (!first_.empty()) {
    if (!first_.back())
      out_ << ",";
    first_.back() = false;
    out_ << "\n" << std::string(2 * first_.size(), ' ');
  }
  if (!key.empty())
    out_ << quote(key) << ": ";
}

JsonWriter& JsonWriter::beginObject(const std::string& key) {
  prefix(key);
  out_ << "{";
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::endObject() {
  first_.pop_back();
  out_ << "\n" << std::string(2 * first_.size(), ' ') << "}";
  if (first_.empty())
    out_ << "\n";
  return *this;
}

JsonWriter& JsonWriter::beginArray(const std::string& key) {
  prefix(key);
  out_ << "[";
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::endArray() {
  first_.pop_back();
  out_ << "\n" << std::string(2 * first_.size(), ' ') << "]";
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& key, double v) {
  prefix(key);
  // JSON has no NaN/Inf; write null rather than an unreadable file.
  out_ << (std::isfinite(v) ? formatNumber(v) : "null");
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& key, long v) {
  prefix(key);
  out_ << v;
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& key, bool v) {
  prefix(key);
  out_ << (v ? "true" : "false");
  return *this;
}

JsonWriter& JsonWriter::value(const std::string& key, const std::string& v) {
  prefix(key);
  out_ << quote(v);
  return *this;
}

JsonWriter& JsonWriter::arrayValue(const std::string& v) {
  return value(std::string(), v);
}
JsonWriter& JsonWriter::arrayValue(double v) {
  return value(std::string(), v);
}

void writeFilesAtomically(const std::string& dir,
                          const std::vector<std::pair<std::string, std::string>>& files) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw std::runtime_error(dir + ": cannot create the output folder: " + ec.message());
  const fs::path folder(dir);
  auto target = [&](std::size_t i) { return folder / files[i].first; };
  auto temporary = [&](std::size_t i) { return folder / ("." + files[i].first + ".partial"); };
  auto backup = [&](std::size_t i) { return folder / ("." + files[i].first + ".previous"); };
  auto removeQuietly = [](const fs::path& p) {
    std::error_code ignored;
    fs::remove(p, ignored);
  };

  // 1. Every file complete under a temporary name.
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::ofstream out(temporary(i), std::ios::binary);
    out << files[i].second;
    out.close();
    if (!out) {
      for (std::size_t k = 0; k <= i; ++k) removeQuietly(temporary(k));
      throw std::runtime_error(target(i).string() + ": write failed");
    }
  }
  // 2. Existing results moved aside, 3. new ones moved in; any failure restores the
  // folder as it was (old results back, no new or temporary files).
  std::vector<bool> backedUp(files.size(), false), placed(files.size(), false);
  auto rollBack = [&](const std::string& why) {
    for (std::size_t k = 0; k < files.size(); ++k) {
      if (placed[k]) removeQuietly(target(k));
      if (backedUp[k]) {
        std::error_code ignored;
        fs::rename(backup(k), target(k), ignored);
      }
      removeQuietly(temporary(k));
    }
    throw std::runtime_error(why);
  };
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (fs::exists(target(i), ec)) {
      if (fs::is_directory(target(i), ec)) {
        rollBack(target(i).string() + ": is a folder, cannot write the result there");
      }
      fs::rename(target(i), backup(i), ec);
      if (ec) rollBack(target(i).string() + ": cannot replace the old result: " + ec.message());
      backedUp[i] = true;
    }
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    fs::rename(temporary(i), target(i), ec);
    if (ec) rollBack(target(i).string() + ": cannot move the result into place: " + ec.message());
    placed[i] = true;
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (backedUp[i]) removeQuietly(backup(i));
  }
}

}  // namespace pistondyn::io
