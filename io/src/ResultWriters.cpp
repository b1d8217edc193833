#include "pistondyn/io/ResultWriters.h"

#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <stdexcept>

namespace pistondyn::io {

namespace fs = std::filesystem;

std::string formatNumber(double v) {
  if (!std::isfinite(v))
    return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  std::array<char, 32> buf{};
  const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), res.ptr);
}

std::string escapeForCommentLine(const std::string& text) {
  static const char* const kHex = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    switch (c) {
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (c < 0x20 || c == 0x7f) {
          out += "\\x";
          out += kHex[c >> 4];
          out += kHex[c & 0xf];
        } else {
          out += ch;
        }
    }
  }
  return out;
}

void writeCsvHeader(std::ostream& out, const std::vector<std::string>& columns,
                    const std::vector<std::string>& commentLines) {
  for (const auto& c : commentLines)
    out << "# " << escapeForCommentLine(c) << '\n';
  for (std::size_t j = 0; j < columns.size(); ++j) {
    out << (j ? "," : "") << columns[j];
  }
  out << '\n';
}

void writeCsvRow(std::ostream& out, const std::vector<double>& values) {
  for (std::size_t j = 0; j < values.size(); ++j)
    out << (j ? "," : "") << formatNumber(values[j]);
  out << '\n';
}

void writeCsv(std::ostream& out, const plugin::ResultTable& table,
              const std::vector<std::string>& commentLines) {
  writeCsvHeader(out, table.columns, commentLines);
  for (const auto& row : table.rows)
    writeCsvRow(out, row);
}

// ---- CsvRowSink ----------------------------------------------------------------------

CsvRowSink::CsvRowSink(std::string filePath, std::vector<std::string> commentLines)
    : filePath_(std::move(filePath)), comments_(std::move(commentLines)) {}

void CsvRowSink::fail(const std::string& what) const {
  throw std::runtime_error(filePath_ + ": " + what);
}

void CsvRowSink::beginRun(const std::vector<std::string>& columns) {
  columns_ = columns;
  discardRows();
}

void CsvRowSink::discardRows() {
  // The file again from its start: comments and header, no rows.
  out_.close();
  out_.clear();
  out_.open(filePath_, std::ios::binary | std::ios::trunc);
  if (!out_)
    fail("cannot create the file");
  rows_ = 0;
  writeCsvHeader(out_, columns_, comments_);
}

void CsvRowSink::consumeRow(const SimTK::State&, const std::vector<double>& values) {
  writeCsvRow(out_, values);
  ++rows_;
  if (!out_)
    fail("write failed (disk full?)");
}

void CsvRowSink::endRun() {
  out_.close();
  if (!out_)
    fail("write failed");
}

// ---- ResultFileSet -------------------------------------------------------------------

namespace {

void removeQuietly(const fs::path& p) {
  std::error_code ignored;
  fs::remove(p, ignored);
}

fs::path temporaryOf(const fs::path& folder, const std::string& name) {
  return folder / ("." + name + ".partial");
}

fs::path backupOf(const fs::path& folder, const std::string& name) {
  return folder / ("." + name + ".previous");
}

}  // namespace

ResultFileSet::ResultFileSet(std::string dir) : dir_(std::move(dir)) {
  std::error_code ec;
  // The folders that do not exist yet, deepest first, to remove them again on failure.
  for (fs::path p = dir_; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    created_.push_back(p.string());
    if (p == p.parent_path())
      break;
  }
  fs::create_directories(dir_, ec);
  if (ec)
    throw std::runtime_error(dir_ + ": cannot create the output folder: " + ec.message());
}

ResultFileSet::~ResultFileSet() {
  if (committed_)
    return;
  for (const auto& name : names_)
    removeQuietly(temporaryOf(dir_, name));
  for (const auto& folder : created_)
    removeQuietly(folder);  // only removes empty folders
}

std::string ResultFileSet::stage(const std::string& name) {
  if (committed_)
    throw std::logic_error("ResultFileSet::stage: already committed");
  names_.push_back(name);
  return temporaryOf(dir_, name).string();
}

void ResultFileSet::stageText(const std::string& name, const std::string& text) {
  std::ofstream out(stage(name), std::ios::binary);
  out << text;
  out.close();
  if (!out)
    throw std::runtime_error((fs::path(dir_) / name).string() + ": write failed");
}

void ResultFileSet::commit() {
  const fs::path folder(dir_);
  const std::size_t n = names_.size();
  auto target = [&](std::size_t i) { return folder / names_[i]; };
  std::error_code ec;
  // 1. Existing results moved aside, 2. new ones moved in; any failure restores the
  // folder as it was (old results back, no new or temporary files).
  std::vector<bool> backedUp(n, false), placed(n, false);
  auto rollBack = [&](const std::string& why) {
    for (std::size_t k = 0; k < n; ++k) {
      if (placed[k])
        removeQuietly(target(k));
      if (backedUp[k]) {
        std::error_code ignored;
        fs::rename(backupOf(folder, names_[k]), target(k), ignored);
      }
      removeQuietly(temporaryOf(folder, names_[k]));
    }
    throw std::runtime_error(why);
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!fs::exists(temporaryOf(folder, names_[i]), ec))
      rollBack(target(i).string() + ": the result was never written");
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (fs::exists(target(i), ec)) {
      if (fs::is_directory(target(i), ec)) {
        rollBack(target(i).string() + ": is a folder, cannot write the result there");
      }
      fs::rename(target(i), backupOf(folder, names_[i]), ec);
      if (ec)
        rollBack(target(i).string() + ": cannot replace the old result: " + ec.message());
      backedUp[i] = true;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    fs::rename(temporaryOf(folder, names_[i]), target(i), ec);
    if (ec)
      rollBack(target(i).string() + ": cannot move the result into place: " + ec.message());
    placed[i] = true;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (backedUp[i])
      removeQuietly(backupOf(folder, names_[i]));
  }
  committed_ = true;
}

void writeFilesAtomically(const std::string& dir,
                          const std::vector<std::pair<std::string, std::string>>& files) {
  ResultFileSet set(dir);
  for (const auto& [name, content] : files)
    set.stageText(name, content);
  set.commit();
}

}  // namespace pistondyn::io
