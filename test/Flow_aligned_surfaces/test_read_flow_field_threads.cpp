// The readers start no thread the caller did not ask for: by default a binary file is decoded on
// the calling thread; with use_parallelism(true) its blocks run on the threads of the caller's
// TBB arena, and the field read is the same.
//
// The answer is known without the package: the threads of the process (/proc/self/task) after a
// read must be those it had before.  Each count runs in a process of its own (the "threadsafe"
// death-test style re-executes the test binary), so that threads left by other tests cannot hide
// new ones.

#include <CGAL/Flow_aligned_surfaces/IO/read_VTK_legacy.h>
#include <CGAL/Flow_aligned_surfaces/IO/write_flow_field.h>

#include "read_flow_field_test_helpers.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include <sys/wait.h>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_read_flow_field_threads {

namespace {

using namespace fas_read_flow_field_test;
using Grid = Sampled::Regular_grid;

std::size_t number_of_threads()
{
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& task : std::filesystem::directory_iterator("/proc/self/task"))
    ++n;
  return n;
}

// The linear field on 64^3 nodes, written as a binary legacy VTK file: 786432 floats, a dozen of
// the decoder's blocks.
const std::string& binary_grid_file()
{
  static const std::string file = [] {
    const std::string name = scratch("threads_64.vtk");
    const Grid grid = FAS::sample_on_grid([](const Point& p) { return std::optional<Vector>(linear(p)); },
                                          Point(0, 0, 0), Vector(0.125, 0.125, 0.125), {{64, 64, 64}});
    std::string error;
    if (!FAS::IO::write_VTK_flow_field(name, grid, FAS::parameters::error_message(&error)))
      ADD_FAILURE() << error;
    return name;
  }();
  return file;
}

// Reads the file and exits with the number of threads the process gained (255 if the read failed
// or gave a wrong value).
template <class NamedParameters>
[[noreturn]] void exit_with_new_threads(const NamedParameters& np)
{
  const std::size_t before = number_of_threads();
  Grid grid;
  std::string error;
  const bool read =
      FAS::IO::read_VTK_flow_field(binary_grid_file(), grid, FAS::parameters::error_message(&error, np));
  const std::size_t after = number_of_threads();
  const Point p(3.3, 4.4, 5.5);
  const bool right = read && grid(p) && (*grid(p) - linear(p)).squared_length() < 1e-8;
  std::fprintf(stderr, "%s threads before %zu, after %zu\n", error.c_str(), before, after);
  std::fflush(stderr);
  std::_Exit(right ? int(after - before) : 255);
}

} // namespace

TEST(ReadFlowFieldThreads, NoThreadStartedWithoutParallelism)
{
  binary_grid_file(); // written in this process, read in the child
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(exit_with_new_threads(CGAL::parameters::default_values()), testing::ExitedWithCode(0), "");
}

#ifdef CGAL_LINKED_WITH_TBB
// The counterpart, which shows that the count above sees threads: with use_parallelism(true), on a
// machine of several cores, the decoding runs on TBB's workers (and gives the same field).
TEST(ReadFlowFieldThreads, ParallelismUsesTheArenasThreads)
{
  if (std::thread::hardware_concurrency() < 2)
    GTEST_SKIP() << "one core: TBB starts no worker";
  binary_grid_file();
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(exit_with_new_threads(FAS::parameters::use_parallelism(true)),
              [](int status) { return WIFEXITED(status) && WEXITSTATUS(status) > 0 && WEXITSTATUS(status) < 255; },
              "");
}
#endif

} // namespace test_read_flow_field_threads
