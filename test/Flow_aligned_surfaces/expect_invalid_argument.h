// The test suite's one check for bad input: a call throws std::invalid_argument whose
// message contains every given part (the input's name, the index, the values).

#ifndef FAS_TEST_EXPECT_INVALID_ARGUMENT_H
#define FAS_TEST_EXPECT_INVALID_ARGUMENT_H

#include <gtest/gtest.h>

#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

template <class Call>
void expect_invalid_argument(const Call& call, const std::vector<std::string>& parts)
{
  try {
    call();
    ADD_FAILURE() << "no exception thrown; expected std::invalid_argument mentioning \"" << parts.front()
                  << "\"";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    for (const std::string& part : parts)
      EXPECT_NE(what.find(part), std::string::npos) << "message \"" << what << "\" lacks \"" << part << "\"";
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected std::invalid_argument, got another exception: " << e.what();
  }
}

#endif // FAS_TEST_EXPECT_INVALID_ARGUMENT_H
