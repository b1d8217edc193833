// Compares a run's cycle.csv and summary.json with those of another build (a refactoring
// check, not a physics reference):
//   compare_results REFERENCE_DIR NEW_DIR
// cycle.csv: identical text except its first line (program name and version);
// summary.json: the same keys in the same order, strings equal, every number the same
// double bit for bit, except wall_time_s (a measurement). Prints what differs; exit 1 if
// anything does.

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

namespace {

using Json = nlohmann::ordered_json;

long numbers = 0;

bool compare(const Json& a, const Json& b, const std::string& path) {
  if (path == "/wall_time_s")
    return true;
  if (a.is_number() && b.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    ++numbers;
    if (std::memcmp(&x, &y, sizeof x) != 0) {
      std::cout << path << ": " << a.dump() << " vs " << b.dump() << "\n";
      return false;
    }
    return true;
  }
  if (a.type() != b.type()) {
    std::cout << path << ": " << a.dump() << " vs " << b.dump() << "\n";
    return false;
  }
  if (a.is_object()) {
    bool same = a.size() == b.size();
    auto ia = a.items().begin(), ib = b.items().begin();
    for (; ia != a.items().end() && ib != b.items().end(); ++ia, ++ib) {
      if (ia.key() != ib.key()) {
        std::cout << path << ": key " << ia.key() << " vs " << ib.key() << "\n";
        return false;
      }
      same = compare(ia.value(), ib.value(), path + "/" + ia.key()) && same;
    }
    if (a.size() != b.size())
      std::cout << path << ": " << a.size() << " vs " << b.size() << " keys\n";
    return same;
  }
  if (a.is_array()) {
    bool same = a.size() == b.size();
    for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
      same = compare(a[i], b[i], path + "/" + std::to_string(i)) && same;
    return same;
  }
  if (a != b) {
    std::cout << path << ": " << a.dump() << " vs " << b.dump() << "\n";
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: compare_results REFERENCE_DIR NEW_DIR\n";
    return 2;
  }
  const std::string ref = argv[1], now = argv[2];
  bool same = true;
  std::ifstream ca(ref + "/cycle.csv"), cb(now + "/cycle.csv");
  if (!ca || !cb) {
    std::cerr << "compare_results: cannot open both cycle.csv\n";
    return 2;
  }
  std::string la, lb;
  long line = 0, differing = 0;
  while (true) {
    const bool ga = static_cast<bool>(std::getline(ca, la));
    const bool gb = static_cast<bool>(std::getline(cb, lb));
    if (!ga && !gb)
      break;
    ++line;
    if (ga != gb || (line > 1 && la != lb)) {
      if (++differing <= 5)
        std::cout << "cycle.csv:" << line << ": '" << la << "' vs '" << lb << "'\n";
    }
  }
  same = same && differing == 0;
  std::cout << "cycle.csv: " << line << " lines, " << differing
            << " differ (line 1 not compared)\n";

  std::ifstream ja(ref + "/summary.json"), jb(now + "/summary.json");
  const Json a = Json::parse(ja), b = Json::parse(jb);
  same = compare(a, b, "") && same;
  std::cout << "summary.json: " << numbers << " numbers compared bit for bit (wall_time_s not)\n";
  return same ? 0 : 1;
}
