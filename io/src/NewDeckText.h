#pragma once
// Internal to pistondyn new (NewDeck.h): the engine deck's YAML text in the example decks'
// layout, every key checked against the deck key table (DeckKeys.h) as it is written.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace pistondyn::io::newdeck {

/// Builds YAML with the example decks' layout: comments aligned at one column, wrapped
/// comment lines continuing at that column. Every key written with a value must be a key of
/// the deck key table (getEngineDeckKeys() or getLubricatedSkirtDeckKeys(), by its full
/// path: the sections it is written under and its name); any other throws std::logic_error,
/// so a deck `pistondyn new` writes never holds a key the readers do not know.
class DeckText {
 public:
  static constexpr std::size_t kCommentColumn = 36, kWidth = 100;

  /// A plain line (a comment line of the header, say).
  void line(const std::string& text);
  void blank();  ///< an empty line
  /// "# text" lines at `indent`, wrapped.
  void comment(int indent, const std::string& text);
  /// Comment lines that each start with `prefix` ("#    "), wrapped.
  void prefixed(const std::string& prefix, const std::string& text);
  /// "name:" opening a section at `indent` (0: top level), with an optional comment.
  void section(int indent, const std::string& name, const std::string& note = {});
  /// "key: value   # note" at `indent`, under the sections last opened at smaller
  /// indents; the note wrapped at the comment column. Throws std::logic_error if the full
  /// path is not a key of the deck key table, or `value` is empty.
  void entry(int indent, const std::string& key, const std::string& value,
             const std::string& note = {});
  /// The full key paths written, in order.
  const std::vector<std::string>& getKeys() const { return keys_; }
  const std::string& str() const { return text_; }  ///< the text so far

 private:
  void annotated(std::string head, const std::string& note);
  // Closes the sections at `indent` or deeper; the full path of `name` at `indent`.
  std::string pathAt(int indent, const std::string& name);
  std::string text_;
  std::vector<std::pair<int, std::string>> sections_;  // open sections, by indent
  std::vector<std::string> keys_;
};

/// A YAML double-quoted scalar.
std::string quoted(const std::string& text);

}  // namespace pistondyn::io::newdeck
