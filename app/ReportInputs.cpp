#include "ReportInputs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "DisplayUnits.h"
#include "pistondyn/io/DeckKeys.h"
#include "pistondyn/io/EngineDeck.h"
#include "pistondyn/io/LubricatedSkirtDeck.h"

namespace pistondyn::app {
namespace {

using Json = nlohmann::ordered_json;

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos)
    return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

// Splits a line into its content and its comment: '#' outside quotes, at the start or after
// a blank.
std::pair<std::string, std::string> splitComment(const std::string& line) {
  char quote = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (c == quote)
        quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '#' && (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t')) {
      return {line.substr(0, i), trim(line.substr(i + 1))};
    }
  }
  return {line, ""};
}

// The key of "key: value" (or "key:"), and the rest; nullopt if the line is not one.
std::optional<std::pair<std::string, std::string>> splitKey(const std::string& content) {
  for (std::size_t i = 0; i < content.size(); ++i) {
    const char c = content[i];
    if (c == '"' || c == '\'' || c == '{' || c == '[')
      return std::nullopt;
    if (c == ':' && (i + 1 == content.size() || content[i + 1] == ' ')) {
      const std::string key = trim(content.substr(0, i));
      if (key.empty())
        return std::nullopt;
      return std::make_pair(key, trim(content.substr(i + 1)));
    }
  }
  return std::nullopt;
}

int depthChange(const std::string& s) {
  int d = 0;
  for (char c : s)
    d += (c == '{' || c == '[') - (c == '}' || c == ']');
  return d;
}

// The keys of a flow mapping "{a: 1, b: {c: 2}}" under `prefix`.
void readFlowMapping(const std::string& text, const std::string& prefix,
                     const std::string& comment, std::map<std::string, std::string>& out) {
  const std::size_t open = text.find('{'), close = text.rfind('}');
  if (open == std::string::npos || close == std::string::npos || close < open)
    return;
  const std::string inner = text.substr(open + 1, close - open - 1);
  std::vector<std::string> items;
  int depth = 0;
  std::string item;
  for (char c : inner) {
    depth += (c == '{' || c == '[') - (c == '}' || c == ']');
    if (c == ',' && depth == 0) {
      items.push_back(item);
      item.clear();
    } else {
      item += c;
    }
  }
  items.push_back(item);
  for (const std::string& i : items) {
    const auto kv = splitKey(trim(i));
    if (!kv)
      continue;
    const std::string path = prefix + kv->first;
    if (!kv->second.empty() && kv->second.front() == '{')
      readFlowMapping(kv->second, path + ".", comment, out);
    else
      out[path] = comment;
  }
}

// The deck keys whose SI form (or own name) a summary input has: SI path -> key.
struct DeckKeyMatch {
  const io::DeckKey* key;
  bool converted;  // the summary holds the value in SI, the key another unit
};
std::map<std::string, DeckKeyMatch> indexDeckKeys() {
  std::map<std::string, DeckKeyMatch> index;
  for (const io::DeckKeyTable* table : {&io::getEngineDeckKeys(), &io::getLubricatedSkirtDeckKeys()}) {
    for (const io::DeckKey& k : table->getKeys()) {
      index.emplace(k.path, DeckKeyMatch{&k, false});
      if (const auto unit = k.getUnit())
        index.emplace(io::toSIKey(k.path, *unit), DeckKeyMatch{&k, true});
    }
  }
  return index;
}

std::string numberText(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.12g", v);  // the deck's value without conversion noise
  return text;
}

// A summary value in the deck key's unit, as a person reads it.
std::string valueText(const Json& v, const std::optional<io::UnitSuffix>& unit) {
  auto convert = [&](const Json& x) {
    if (!x.is_number_float())
      return x.is_string() ? x.get<std::string>() : x.dump();
    const double si = x.get<double>();
    return numberText(unit ? (si - unit->offset) / unit->factor : si);
  };
  if (v.is_array()) {
    std::string text = "[";
    for (const Json& e : v)
      text += (text.size() > 1 ? ", " : "") + convert(e);
    return text + "]";
  }
  return convert(v);
}

void flattenInputs(const Json& j, const std::string& prefix,
                   std::vector<std::pair<std::string, const Json*>>& out) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string path = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (it.value().is_object())
      flattenInputs(it.value(), path, out);
    else
      out.emplace_back(path, &it.value());
  }
}

}  // namespace

std::map<std::string, std::string> readDeckKeyComments(const std::string& deckText) {
  std::map<std::string, std::string> out;
  std::vector<std::pair<int, std::string>> stack;  // indentation and key of open sections
  std::istringstream in(deckText);
  std::string line, flow, flowComment, flowPath;
  int flowDepth = 0;
  while (std::getline(in, line)) {
    const auto [content, comment] = splitComment(line);
    if (flowDepth > 0) {  // a flow mapping over several lines
      flow += " " + content;
      if (!comment.empty())
        flowComment += (flowComment.empty() ? "" : "; ") + comment;
      flowDepth += depthChange(content);
      if (flowDepth <= 0)
        readFlowMapping(flow, flowPath + ".", flowComment, out);
      continue;
    }
    if (trim(content).empty())
      continue;
    const int indent = static_cast<int>(content.find_first_not_of(' '));
    const std::string body = trim(content);
    if (body.rfind("- ", 0) == 0 || body == "-")
      continue;  // list items: not key paths
    const auto kv = splitKey(body);
    if (!kv)
      continue;
    while (!stack.empty() && stack.back().first >= indent)
      stack.pop_back();
    std::string path;
    for (const auto& [level, key] : stack)
      path += key + ".";
    path += kv->first;
    out[path] = comment;
    const std::string& rest = kv->second;
    if (rest.empty()) {
      stack.emplace_back(indent, kv->first);
    } else if (rest.front() == '{') {
      flowDepth = depthChange(rest);
      flow = rest;
      flowComment = comment;
      flowPath = path;
      if (flowDepth <= 0)
        readFlowMapping(flow, path + ".", comment, out);
    }
  }
  return out;
}

std::string findSourceMarks(const std::string& comment) {
  static const std::regex mark(R"(\[[A-Za-z0-9]+\]|\bEST\b)");
  std::string marks;
  for (auto it = std::sregex_iterator(comment.begin(), comment.end(), mark);
       it != std::sregex_iterator(); ++it) {
    if (marks.find(it->str()) == std::string::npos)
      marks += (marks.empty() ? "" : " ") + it->str();
  }
  return marks;
}

std::vector<InputRow> makeInputRows(const std::string& summaryJson, const std::string& deckText) {
  Json summary;
  try {
    summary = Json::parse(summaryJson);
  } catch (const Json::exception& e) {
    throw std::runtime_error(std::string("summary.json: not valid JSON: ") + e.what());
  }
  std::vector<std::string> overridden;
  if (summary.contains("overrides") && summary["overrides"].is_array()) {
    for (const Json& o : summary["overrides"]) {
      if (o.is_string())
        overridden.push_back(o.get<std::string>().substr(0, o.get<std::string>().find('=')));
    }
  }
  // A preview run appends its film-grid assignments to the overrides (io::loadEngineDeck with
  // Fidelity::Preview): they are the preview's, not the user's --set.
  std::vector<std::string> preview;
  if (summary.value("fidelity", "") == "preview") {
    for (auto key = std::rbegin(io::kPreviewGridKeys); key != std::rend(io::kPreviewGridKeys);
         ++key) {
      if (!overridden.empty() && overridden.back() == *key) {
        preview.push_back(*key);
        overridden.pop_back();
      }
    }
  }
  std::vector<std::pair<std::string, const Json*>> inputs;
  if (summary.contains("inputs") && summary["inputs"].is_object())
    flattenInputs(summary["inputs"], "", inputs);
  const std::map<std::string, std::string> comments = readDeckKeyComments(deckText);
  static const std::map<std::string, DeckKeyMatch> deckKeys = indexDeckKeys();
  std::vector<InputRow> rows;
  for (const auto& [path, value] : inputs) {
    InputRow row;
    row.section = path.substr(0, path.find('.'));
    const auto match = deckKeys.find(path);
    if (match != deckKeys.end()) {
      const io::DeckKey& key = *match->second.key;
      const std::optional<io::UnitSuffix> unit =
          match->second.converted ? key.getUnit() : std::nullopt;
      row.key = key.path;
      row.value = valueText(*value, unit);
      const std::optional<io::UnitSuffix> written = key.getUnit();
      row.unit = written ? units::getUnitText(written->suffix) : "";
    } else {
      // Not a key of the tables: a figure derived from the inputs, or a key of a liner model
      // registered by the user; shown as the report shows results.
      row.key = path;
      row.value = value->is_number_float() ? units::formatDisplayNumber(path, value->get<double>())
                                           : valueText(*value, std::nullopt);
      row.unit = value->is_number_float() ? units::getDisplayUnitText(path) : "";
    }
    const auto comment = comments.find(row.key);
    if (std::find(preview.begin(), preview.end(), row.key) != preview.end()) {
      row.source = "--fidelity preview";
    } else if (std::find(overridden.begin(), overridden.end(), row.key) != overridden.end()) {
      row.source = "--set";
    } else if (comment != comments.end()) {
      row.note = comment->second;
      row.source = findSourceMarks(row.note);
      if (row.source.empty())
        row.source = "deck";  // set by the deck, its comment names no source
    } else {
      row.source = match != deckKeys.end() ? "default" : "derived";
    }
    if (comment != comments.end())
      row.note = comment->second;
    row.estimated = (" " + row.source + " ").find(" EST ") != std::string::npos;
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace pistondyn::app
