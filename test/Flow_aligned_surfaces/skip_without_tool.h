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

// FAS_SKIP_WITHOUT_CHOLMOD(): a test case of the CHOLMOD solver in a build whose package does not
// use CHOLMOD.  Hidden on purpose (FAS_WITH_CHOLMOD=OFF, which defines FAS_TEST_CHOLMOD_HIDDEN), it
// skips and says so, also under CI; not found, it is a missing tool.
#ifdef FAS_TEST_CHOLMOD_HIDDEN
#define FAS_SKIP_WITHOUT_CHOLMOD()                                                                     \
  GTEST_SKIP() << "CHOLMOD hidden (FAS_WITH_CHOLMOD=OFF): the package factors with Eigen's SimplicialLDLT"
#else
#define FAS_SKIP_WITHOUT_CHOLMOD() FAS_SKIP_WITHOUT_TOOL("CHOLMOD not found (Debian: libsuitesparse-dev)")
#endif

#endif // FAS_TEST_SKIP_WITHOUT_TOOL_H
