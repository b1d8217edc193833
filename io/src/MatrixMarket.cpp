#include "pistondyn/io/MatrixMarket.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

#include "CsvText.h"
#include "pistondyn/io/DeckError.h"

namespace pistondyn::io {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream ss(line);
  std::vector<std::string> out;
  std::string w;
  while (ss >> w)
    out.push_back(w);
  return out;
}

// Reads the lines of one file, numbering them, skipping '%' comments and blank lines.
class LineSource {
 public:
  LineSource(std::ifstream& in, const std::string& path) : in_(in), path_(path) {}

  // The next data line's words; false at the end of the file.
  bool next(std::vector<std::string>& out) {
    std::string line;
    while (std::getline(in_, line)) {
      ++line_;
      const std::string t = detail::trim(line);
      if (t.empty() || t[0] == '%')
        continue;
      out = words(t);
      return true;
    }
    return false;
  }
  std::string where() const { return path_ + ":" + std::to_string(line_); }

 private:
  std::ifstream& in_;
  const std::string& path_;
  int line_ = 1;  // the banner was line 1
};

long long parseIndex(const std::string& text, const std::string& where, const char* what) {
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE) {
    throw DeckError(where + ": " + what + " '" + text + "' is not an integer");
  }
  return v;
}

double parseValue(const std::string& text, const std::string& where) {
  double v = 0.0;
  if (!detail::parseDouble(text, v)) {
    throw DeckError(where + ": entry '" + text + "' is not a finite number");
  }
  return v;
}

}  // namespace

Eigen::MatrixXd readMatrixMarketDense(const std::string& filePath, Eigen::Index expectedSize,
                                      const std::string& sizeReason) {
  std::ifstream in(filePath);
  if (!in) {
    throw DeckError(filePath + ": cannot open the Matrix Market file");
  }
  std::string banner;
  if (!std::getline(in, banner)) {
    throw DeckError(filePath +
                    ":1: empty file, expected a Matrix Market banner "
                    "'%%MatrixMarket matrix coordinate|array real general|symmetric'");
  }
  detail::stripBom(banner);
  const std::vector<std::string> b = words(banner);
  if (b.size() != 5 || lower(b[0]) != "%%matrixmarket" || lower(b[1]) != "matrix") {
    throw DeckError(filePath +
                    ":1: not a Matrix Market file: expected the banner "
                    "'%%MatrixMarket matrix coordinate|array real general|symmetric', "
                    "found '" +
                    detail::trim(banner) + "'");
  }
  const std::string format = lower(b[2]), field = lower(b[3]), symmetry = lower(b[4]);
  if (format != "coordinate" && format != "array") {
    throw DeckError(filePath + ":1: format '" + b[2] + "': expected coordinate or array");
  }
  if (field != "real" && field != "integer" && field != "double") {
    throw DeckError(filePath + ":1: field '" + b[3] +
                    "': expected real (or integer); pattern and complex matrices are not "
                    "compliances");
  }
  if (symmetry != "general" && symmetry != "symmetric") {
    throw DeckError(filePath + ":1: symmetry '" + b[4] + "': expected general or symmetric");
  }
  const bool coordinate = format == "coordinate";
  const bool symmetric = symmetry == "symmetric";

  LineSource src(in, filePath);
  std::vector<std::string> w;
  if (!src.next(w)) {
    throw DeckError(filePath + ": no size line after the banner (expected '" +
                    std::string(coordinate ? "rows columns entries" : "rows columns") + "')");
  }
  if (w.size() != (coordinate ? 3u : 2u)) {
    throw DeckError(src.where() + ": size line: expected " +
                    (coordinate ? "'rows columns entries'" : "'rows columns'") +
                    " (integers), found " + std::to_string(w.size()) + " fields");
  }
  const long long rows = parseIndex(w[0], src.where(), "row count");
  const long long cols = parseIndex(w[1], src.where(), "column count");
  const long long limit = 20000;  // a dense 20000^2 matrix is 3.2 GB: far beyond a coarse grid
  if (rows < 1 || cols < 1 || rows > limit || cols > limit) {
    throw DeckError(src.where() + ": size " + w[0] + " x " + w[1] +
                    ": expected 1 to 20000 rows and columns (dense storage)");
  }
  if (symmetric && rows != cols) {
    throw DeckError(src.where() + ": a symmetric matrix must be square, found " + w[0] + " x " +
                    w[1]);
  }
  // The caller's size, before the matrix (and, for coordinates, its map of entries seen) is
  // allocated from what the header claims.
  if (expectedSize >= 0 && (rows != expectedSize || cols != expectedSize)) {
    const std::string n = std::to_string(expectedSize);
    throw DeckError(filePath + ": " + std::to_string(rows) + " x " + std::to_string(cols) +
                    " matrix, expected " + n + " x " + n + sizeReason);
  }
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(rows, cols);

  if (coordinate) {
    const long long count = parseIndex(w[2], src.where(), "entry count");
    if (count < 0 || count > rows * cols) {
      throw DeckError(src.where() + ": entry count " + w[2] + " out of range 0.." +
                      std::to_string(rows * cols));
    }
    Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic> seen =
        Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic>::Constant(rows, cols, false);
    for (long long e = 0; e < count; ++e) {
      if (!src.next(w)) {
        throw DeckError(filePath + ": ends after " + std::to_string(e) + " of " +
                        std::to_string(count) + " entries");
      }
      if (w.size() != 3) {
        throw DeckError(src.where() + ": expected 'row column value', found " +
                        std::to_string(w.size()) + " fields");
      }
      const long long i = parseIndex(w[0], src.where(), "row index");
      const long long j = parseIndex(w[1], src.where(), "column index");
      if (i < 1 || i > rows || j < 1 || j > cols) {
        throw DeckError(src.where() + ": entry (" + w[0] + ", " + w[1] + ") outside the " +
                        std::to_string(rows) + " x " + std::to_string(cols) +
                        " matrix (indices are 1-based)");
      }
      if (symmetric && i < j) {
        throw DeckError(src.where() + ": entry (" + w[0] + ", " + w[1] +
                        ") above the diagonal: a symmetric Matrix Market file stores the lower "
                        "triangle only (row >= column)");
      }
      if (seen(i - 1, j - 1)) {
        throw DeckError(src.where() + ": entry (" + w[0] + ", " + w[1] + ") given twice");
      }
      seen(i - 1, j - 1) = true;
      const double v = parseValue(w[2], src.where());
      m(i - 1, j - 1) = v;
      if (symmetric)
        m(j - 1, i - 1) = v;
    }
  } else {
    // Values column by column; symmetric: the lower triangle (i >= j) column by column.
    // Values may share lines (the format allows it only one per line, exporters vary).
    std::vector<std::string> pending;
    std::size_t next = 0;
    std::string where;
    auto nextValue = [&](long long done, long long total) {
      while (next >= pending.size()) {
        if (!src.next(pending)) {
          throw DeckError(filePath + ": ends after " + std::to_string(done) + " of " +
                          std::to_string(total) + " values");
        }
        next = 0;
        where = src.where();
      }
      return parseValue(pending[next++], where);
    };
    const long long total = symmetric ? rows * (rows + 1) / 2 : rows * cols;
    long long done = 0;
    for (long long j = 0; j < cols; ++j) {
      for (long long i = symmetric ? j : 0; i < rows; ++i) {
        const double v = nextValue(done, total);
        ++done;
        m(i, j) = v;
        if (symmetric)
          m(j, i) = v;
      }
    }
    if (next < pending.size()) {
      throw DeckError(where + ": more values than the " + std::to_string(total) +
                      " the size line states");
    }
  }
  if (src.next(w)) {
    throw DeckError(src.where() +
                    ": data after the last entry: more entries than the size "
                    "line states");
  }
  return m;
}

}  // namespace pistondyn::io
