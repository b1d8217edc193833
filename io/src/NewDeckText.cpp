// The deck text of pistondyn new (NewDeckText.h).

#include "NewDeckText.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "pistondyn/io/DeckKeys.h"
#include "pistondyn/io/LubricatedSkirtDeck.h"

namespace pistondyn::io::newdeck {
namespace {

std::vector<std::string> wrap(const std::string& text, std::size_t width) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  std::string word, current;
  while (words >> word) {
    if (!current.empty() && current.size() + 1 + word.size() > width) {
      lines.push_back(current);
      current.clear();
    }
    current += (current.empty() ? "" : " ") + word;
  }
  if (!current.empty() || lines.empty())
    lines.push_back(current);
  return lines;
}

bool isDeckKey(const std::string& path) {
  return getEngineDeckKeys().find(path) != nullptr ||
         getLubricatedSkirtDeckKeys().find(path) != nullptr;
}

}  // namespace

void DeckText::line(const std::string& text) {
  text_ += text + "\n";
}

void DeckText::blank() {
  text_ += "\n";
}

void DeckText::comment(int indent, const std::string& text) {
  const std::string lead(static_cast<std::size_t>(indent), ' ');
  for (const std::string& l : wrap(text, kWidth - lead.size() - 2))
    text_ += lead + "# " + l + "\n";
}

void DeckText::prefixed(const std::string& prefix, const std::string& text) {
  for (const std::string& l : wrap(text, kWidth - prefix.size()))
    text_ += prefix + l + "\n";
}

std::string DeckText::pathAt(int indent, const std::string& name) {
  // Sections at this indent or deeper are closed by a name at this indent.
  while (!sections_.empty() && sections_.back().first >= indent)
    sections_.pop_back();
  std::string path;
  for (const auto& s : sections_)
    path += s.second + ".";
  return path + name;
}

void DeckText::section(int indent, const std::string& name, const std::string& note) {
  pathAt(indent, name);  // closes the sections this one follows
  sections_.emplace_back(indent, name);
  annotated(std::string(static_cast<std::size_t>(indent), ' ') + name + ":", note);
}

void DeckText::entry(int indent, const std::string& key, const std::string& value,
                     const std::string& note) {
  const std::string path = pathAt(indent, key);
  if (value.empty())
    throw std::logic_error("pistondyn new: " + path + " written without a value");
  if (!isDeckKey(path))
    throw std::logic_error("pistondyn new: " + path + " is not a key of the deck key table");
  keys_.push_back(path);
  annotated(std::string(static_cast<std::size_t>(indent), ' ') + key + ": " + value, note);
}

void DeckText::annotated(std::string head, const std::string& note) {
  if (note.empty()) {
    text_ += head + "\n";
    return;
  }
  const std::size_t column = std::max(kCommentColumn, head.size() + 2);
  head.resize(column, ' ');
  const std::vector<std::string> lines = wrap(note, kWidth - column - 2);
  for (std::size_t i = 0; i < lines.size(); ++i)
    text_ += (i == 0 ? head : std::string(column, ' ')) + "# " + lines[i] + "\n";
}

std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\')
      out += '\\';
    out += c;
  }
  return out + "\"";
}

}  // namespace pistondyn::io::newdeck
