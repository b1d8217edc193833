#pragma once
// How an error message shows a value the user gave (not installed).

#include <string>

namespace pistondyn::io::detail {

// Values longer than this many characters are shortened in messages.
inline constexpr std::size_t kMaxEchoedValue = 80;

// `text` in single quotes as a message echoes it; a value longer than kMaxEchoedValue is
// cut to its first kMaxEchoedValue characters and says so, so that a 100 kB --set value
// gives a message of one line: 'xxxx...' (100000 characters, shown shortened).
inline std::string quoteValue(const std::string& text) {
  if (text.size() <= kMaxEchoedValue)
    return "'" + text + "'";
  return "'" + text.substr(0, kMaxEchoedValue) + "...' (" + std::to_string(text.size()) +
         " characters, shown shortened)";
}

// `text` as it is when short, else quoteValue(text): for messages that show a short value
// unquoted ("(got 0)").
inline std::string shortenValue(const std::string& text) {
  return text.size() <= kMaxEchoedValue ? text : quoteValue(text);
}

}  // namespace pistondyn::io::detail
