// Bad-input tests: a call must throw std::invalid_argument whose message contains every given
// fragment (the argument's name, what is wrong, the hint), as CONVENTIONS.md asks of every
// module.
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>

namespace pistondyn::test {

template <class F>
void expectInvalidArgument(F&& f, std::initializer_list<std::string_view> fragments) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected std::invalid_argument mentioning '"
                  << *fragments.begin() << "'";
  } catch (const std::invalid_argument& e) {
    const std::string_view msg = e.what();
    for (std::string_view fragment : fragments)
      EXPECT_NE(msg.find(fragment), std::string_view::npos)
          << "message '" << msg << "' does not mention '" << fragment << "'";
  }
}

template <class F>
void expectInvalidArgument(F&& f, const std::string& fragment) {
  expectInvalidArgument(std::forward<F>(f), {std::string_view(fragment)});
}

}  // namespace pistondyn::test
