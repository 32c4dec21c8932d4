// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// FAS_SKIP_WITHOUT_TOOL(message): a test case that needs a tool (a library, a display) that is
// missing skips with the message, except under CI=true, where every tool must be there and the
// test case fails instead.  Missing data (../shared/data) is not a tool: it skips.

#ifndef FAS_TEST_SKIP_WITHOUT_TOOL_H
#define FAS_TEST_SKIP_WITHOUT_TOOL_H

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>

inline bool fas_test_tools_required()
{
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::strcmp(ci, "true") == 0;
}

#define FAS_SKIP_WITHOUT_TOOL(message)                                                                 \
  do {                                                                                                 \
    if (fas_test_tools_required())                                                                     \
      GTEST_FAIL() << message << " (CI=true: every tool the tests need must be installed)";           \
    else                                                                                               \
      GTEST_SKIP() << message;                                                                         \
  } while (false)

#endif // FAS_TEST_SKIP_WITHOUT_TOOL_H
