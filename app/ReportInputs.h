#pragma once
// The inputs table of `pistondyn report`: every input of a run (summary.json's `inputs`, in
// SI) shown in the unit its deck key is written in (geometry.bore_m as geometry.bore_mm
// 74.5 mm, the key tables of io/DeckKeys.h and the lubricated skirt's), with where the value
// comes from: the source marks of the comment on the key's line in the deck ([T], [V], EST
// ..., as the example decks mark every value), `deck` for a key the deck sets without a
// mark, `--set` for an override, `default` for a key the deck does not set, `derived` for a
// figure the program computed from the inputs.

#include <map>
#include <string>
#include <vector>

namespace pistondyn::app {

// The key paths a deck's text sets, each with the comment on its line ("" if none): block
// mappings and flow mappings of scalars ({a: 1, b: 2}, also over several lines: each key
// gets the comments of the lines it spans). A line the scanner does not understand is
// skipped; this is a reading of comments for people, the deck itself is read by yaml-cpp.
std::map<std::string, std::string> readDeckKeyComments(const std::string& deckText);

// The source marks in a comment, in order, separated by spaces: bracketed tags ("[T]",
// "[V]") and the word EST ("EST: typical" -> "EST", "[T] f_dry" -> "[T]",
// "EST: partially flooded [T]; ..." -> "EST [T]"); "" when it has none.
std::string findSourceMarks(const std::string& comment);

struct InputRow {
  std::string section;  // the first part of the key ("geometry")
  std::string key;      // as the deck writes it ("geometry.bore_mm"); the SI key if not a deck key
  std::string value;    // in the key's unit ("74.5"); text, switches and lists as written
  std::string unit;     // for a person ("mm", "µm", "" for none)
  std::string source;   // the marks, or "deck", "--set", "default", "derived"
  std::string note;     // the comment on the key's line in the deck
  bool estimated = false;  // EST among the marks
};

// The rows of the inputs table, in summary.json's order. `summaryJson`: the text of the
// run's summary.json; `deckText`: its deck ("" when it cannot be read: no marks then).
// Throws std::runtime_error if summaryJson is not JSON.
std::vector<InputRow> makeInputRows(const std::string& summaryJson, const std::string& deckText);

}  // namespace pistondyn::app
