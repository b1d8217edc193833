#pragma once
// Output formats. Numbers are written in the shortest form that reads back to the
// identical double (std::to_chars), so a position in metres keeps every bit.

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "pistondyn/plugin/CycleSimulation.h"

namespace pistondyn::io {

std::string formatNumber(double value);

// '#'-prefixed comment lines, then a header of column names (with units), then rows.
void writeCsv(std::ostream& out, const plugin::ResultTable& table,
              const std::vector<std::string>& commentLines);

// Small streaming JSON writer: objects, arrays, strings, numbers, booleans.
class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}
  JsonWriter& beginObject(const std::string& key = {});
  JsonWriter& endObject();
  JsonWriter& beginArray(const std::string& key = {});
  JsonWriter& endArray();
  JsonWriter& value(const std::string& key, double v);
  JsonWriter& value(const std::string& key, long v);
  JsonWriter& value(const std::string& key, bool v);
  JsonWriter& value(const std::string& key, const std::string& v);
  JsonWriter& value(const std::string& key, const char* v) { return value(key, std::string(v)); }
  JsonWriter& arrayValue(const std::string& v);
  JsonWriter& arrayValue(double v);

 private:
  void prefix(const std::string& key);
  static std::string quote(const std::string& s);
  std::ostream& out_;
  std::vector<bool> first_;  // per open container: no element written yet
};

// Writes files into `dir` all-or-nothing: each is written to a temporary name and
// renamed only after every file is complete. Creates `dir` (and parents) if needed.
// Throws std::runtime_error on I/O failure, leaving no partial result files.
void writeFilesAtomically(const std::string& dir,
                          const std::vector<std::pair<std::string, std::string>>& nameAndContent);

}  // namespace pistondyn::io
