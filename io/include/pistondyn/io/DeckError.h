#pragma once
/// \file
/// Bad user input at the edge (deck, table, command line). The message names the file,
/// the line or the key, and what is expected; it may hold several lines, one per problem.

#include <stdexcept>
#include <string>

namespace pistondyn::io {

class DeckError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace pistondyn::io
