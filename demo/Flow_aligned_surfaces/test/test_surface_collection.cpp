// The main job's collection of iterations (surface_collection.h), without ParaView: the .pvd
// lists exactly the files written, in order, with the time steps 0, 1, 2, ..., every one of them
// exists and holds the surface of its step, and a file of an earlier run in the folder is gone.

#include "test_files.h"

#include "surface_collection.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

namespace {

using namespace fas_demo;

TEST(IterationCollection, PvdListsExactlyTheFilesWritten)
{
  const std::filesystem::path out = temporary_file("iteration_collection_", "out");
  std::filesystem::create_directories(out / "run_iterations");
  write_bytes((out / "run_iterations" / "run_0007.vtp").string(), "stale"); // an earlier, longer run

  const Flow flow = FAS::Cylinder_potential_flow<Kernel>(1.0, 1.0);
  Surface_collection collection(out, "run");
  Mesh tm;
  FAS::make_planar_patch(tm, Point(-2, 1, 0), Vector(0, 1, 0), 1.0, 1.0, 50);
  for (int step = 0; step < 3; ++step) {
    ASSERT_TRUE(collection.add(tm, flow)) << collection.error();
    for (auto v : tm.vertices()) // each step moves the surface
      tm.point(v) = tm.point(v) + Vector(0, 0.1, 0);
  }
  ASSERT_TRUE(collection.write_pvd()) << collection.error();

  const std::string pvd = read_bytes((out / "run_iterations.pvd").string());
  const std::regex entry("<DataSet timestep=\"([0-9]+)\" group=\"\" part=\"0\" file=\"([^\"]+)\"/>");
  std::vector<std::string> listed;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), entry); it != std::sregex_iterator(); ++it) {
    EXPECT_EQ(std::stoul((*it)[1]), listed.size());
    listed.push_back((*it)[2]);
  }
  EXPECT_EQ(listed, (std::vector<std::string>{"run_iterations/run_0000.vtp", "run_iterations/run_0001.vtp",
                                              "run_iterations/run_0002.vtp"}));
  std::vector<std::string> present;
  for (const auto& file : std::filesystem::directory_iterator(out / "run_iterations"))
    present.push_back("run_iterations/" + file.path().filename().string());
  std::sort(present.begin(), present.end());
  EXPECT_EQ(present, listed) << "the stale run_0007.vtp must be gone";
  // Each file holds its step's surface (written binary or ASCII; both name the flux array).
  for (const std::string& file : listed)
    EXPECT_NE(read_bytes((out / file).string()).find("normalized_flux"), std::string::npos) << file;
  EXPECT_NE(read_bytes((out / listed[0]).string()), read_bytes((out / listed[2]).string()));
  EXPECT_EQ(collection.files(), listed);
}

TEST(IterationCollection, UnwritableFolderIsReported)
{
  const std::filesystem::path out = temporary_file("iteration_collection_", "blocked");
  std::filesystem::remove_all(out);
  std::filesystem::create_directories(out);
  write_bytes((out / "x").string(), "a file where the output folder should be");
  Surface_collection collection(out / "x", "run");
  const Flow flow = FAS::Cylinder_potential_flow<Kernel>(1.0, 1.0);
  Mesh tm;
  FAS::make_planar_patch(tm, Point(-2, 1, 0), Vector(0, 1, 0), 1.0, 1.0, 20);
  EXPECT_FALSE(collection.add(tm, flow));
  EXPECT_FALSE(collection.write_pvd());
  EXPECT_NE(collection.error().find("run_iterations"), std::string::npos) << collection.error();
  EXPECT_FALSE(std::filesystem::exists(out / "x" / "run_iterations.pvd"));
}

} // namespace
