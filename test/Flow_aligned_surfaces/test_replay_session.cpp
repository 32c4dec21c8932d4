// replay_session(): the operations of a session performed in order, with the flux spikes
// that known moves must cause (a plane tilted by α out of a uniform flow has normalized flux
// sin α), bit-for-bit determinism, and refused operations named by their session line.

#include <CGAL/Flow_aligned_surfaces/Flow_aligned_deformation.h>
#include <CGAL/Flow_aligned_surfaces/IO/read_session.h>
#include <CGAL/Flow_aligned_surfaces/analytic_flow_fields.h>
#include <CGAL/Flow_aligned_surfaces/make_surface_patch.h>
#include <CGAL/Flow_aligned_surfaces/measure.h>
#include <CGAL/Flow_aligned_surfaces/replay_session.h>

#include "test_files.h"
#include "test_kernel.h"

#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_replay_session {

using namespace fas_test;
using Mesh = CGAL::Surface_mesh<Point_3>;
using Flow = FAS::Uniform_flow<K>;
using Op = FAS::Session_operation;

namespace {

FAS::Session read(const std::string& name, const std::string& text)
{
  const std::string file = temporary_file("replay_session_", name);
  write_bytes(file, text);
  FAS::Session session;
  std::string error;
  EXPECT_TRUE(FAS::IO::read_session(file, session, &error)) << error;
  return session;
}

Mesh make_patch(const FAS::Session& session)
{
  const auto& p = session.patch;
  Mesh tm;
  FAS::make_planar_patch(tm, Point_3(p.center[0], p.center[1], p.center[2]),
                         Vector_3(p.normal[0], p.normal[1], p.normal[2]), p.width, p.height,
                         p.target_number_of_faces);
  return tm;
}

// A tangential plane in the uniform flow along x: tilted by 20 degrees about y, then moved.
const std::string tilt_session = "alignment tangential\n"
                                 "patch planar 0 0 0  0 0 1  1 1 800\n"
                                 "iterate 2\n"                  // line 3
                                 "rotate 0 1 0 20\n"            // line 4
                                 "iterate until-converged 80\n" // line 5
                                 "save a.vtp\n"                 // line 6
                                 "translate 0 0 1\n"            // line 7
                                 "rotate 1 0 0 30\n"            // line 8: about the flow
                                 "iterate 1\n"                  // line 9
                                 "save b.vtp\n";                // line 10

} // namespace

TEST(ReplaySession, MovesMakeTheFluxSpikesTheyMust)
{
  const FAS::Session session = read("tilt.session", tilt_session);
  Mesh tm = make_patch(session);
  const Flow flow;
  FAS::Flow_aligned_deformation<Mesh, Flow> deformation(tm, flow, FAS::Alignment::TANGENTIAL);
  std::vector<std::size_t> saved_at; // the number of iterations done at each save
  std::vector<std::size_t> save_lines;
  const FAS::Session_replay_report replay = FAS::replay_session(deformation, session, [&](const Op& op) {
    saved_at.push_back(deformation.number_of_iterations());
    save_lines.push_back(op.line);
  });

  const auto& it = replay.iterations;
  ASSERT_GE(it.size(), 4u);
  // The plane contains the flow: no flux, nothing moves.
  EXPECT_LT(it[0].report.normalized_flux.value.value(), 1e-12);
  EXPECT_EQ(it[0].line, 3u);
  EXPECT_EQ(it[1].line, 3u);
  EXPECT_TRUE(it[1].moves_before.empty());
  // Tilted by 20 degrees out of the flow: f_n = |n . v| / |v| = sin 20 degrees.
  EXPECT_EQ(it[2].moves_before, "rotate");
  EXPECT_EQ(it[2].line, 5u);
  EXPECT_NEAR(it[2].report.normalized_flux.value.value(), std::sin(20 * std::acos(-1.0) / 180), 1e-9);
  // ... and aligned again by the iterations of line 5.
  const std::size_t last_of_line_5 = it.size() - 2;
  EXPECT_EQ(it[last_of_line_5].line, 5u);
  EXPECT_TRUE(it[last_of_line_5].report.converged);
  EXPECT_LT(it[last_of_line_5].report.normalized_flux.value.value(), 0.01);
  // A translation and a rotation about the flow keep a plane that contains a uniform flow
  // tangential: no spike.
  const auto& after_moves = it.back();
  EXPECT_EQ(after_moves.line, 9u);
  EXPECT_EQ(after_moves.moves_before, "translate rotate");
  EXPECT_LT(after_moves.report.normalized_flux.value.value(), 0.01);
  // Every iteration counts once, in order.
  for (std::size_t i = 0; i < it.size(); ++i)
    EXPECT_EQ(it[i].report.iteration, i + 1);
  EXPECT_EQ(save_lines, (std::vector<std::size_t>{6, 10}));
  EXPECT_EQ(saved_at, (std::vector<std::size_t>{it.size() - 1, it.size()}));
  EXPECT_TRUE(replay.growths.empty());
  EXPECT_NEAR(replay.final_normalized_flux.value.value(), FAS::normalized_flux(tm, Flow()).value.value(),
              1e-15);
}

TEST(ReplaySession, TheSameSessionGivesTheSameNumbersBitForBit)
{
  // Moves and growing in a flow that is not uniform, so that every number depends on all
  // that came before.
  const std::string text = "alignment tangential\n"
                           "patch planar -2 0.8 0  0.3 1 0.4  1 1 600\n"
                           "iterate until-converged 40\n"
                           "translate 0 0.2 0\n"
                           "iterate 5\n"
                           "rotate 1 0 0 10\n"
                           "iterate 5\n"
                           "grow 0.2 across-flow\n"
                           "iterate until-converged 40\n";
  const FAS::Session session = read("determinism.session", text);
  using Cylinder = FAS::Cylinder_potential_flow<K>;
  auto replay_once = [&](std::vector<Point_3>& points) {
    Mesh tm = make_patch(session);
    const Cylinder flow(1.0, 1.0);
    FAS::Flow_aligned_deformation<Mesh, Cylinder> deformation(tm, flow, FAS::Alignment::TANGENTIAL);
    const FAS::Session_replay_report replay = FAS::replay_session(deformation, session, [](const Op&) {});
    for (auto v : tm.vertices())
      points.push_back(tm.point(v));
    return replay;
  };
  std::vector<Point_3> first_points, second_points;
  const FAS::Session_replay_report first = replay_once(first_points);
  const FAS::Session_replay_report second = replay_once(second_points);
  ASSERT_EQ(first.iterations.size(), second.iterations.size());
  ASSERT_GT(first.iterations.size(), 11u);
  for (std::size_t i = 0; i < first.iterations.size(); ++i) {
    const auto &a = first.iterations[i], &b = second.iterations[i];
    EXPECT_EQ(a.line, b.line);
    EXPECT_EQ(a.moves_before, b.moves_before);
    EXPECT_EQ(a.report.normalized_flux.value.value(), b.report.normalized_flux.value.value())
        << "iteration " << i + 1;
    EXPECT_EQ(a.report.max_rotation_angle, b.report.max_rotation_angle) << "iteration " << i + 1;
    EXPECT_EQ(a.report.max_vertex_step, b.report.max_vertex_step) << "iteration " << i + 1;
  }
  ASSERT_EQ(first.growths.size(), 1u);
  EXPECT_GT(first.growths[0].number_of_new_faces, 0u);
  EXPECT_EQ(first.growths[0].number_of_new_faces, second.growths[0].number_of_new_faces);
  EXPECT_EQ(first.growths[0].added_area, second.growths[0].added_area);
  EXPECT_EQ(first_points, second_points);
  EXPECT_EQ(first.final_normalized_flux.value.value(), second.final_normalized_flux.value.value());
  EXPECT_LT(first.final_normalized_flux.value.value(),
            0.01); // and the grown surface is a stream surface again
}

TEST(ReplaySession, ARefusedOperationNamesItsSessionLine)
{
  // Growing towards the normal of a planar patch: there is no boundary that faces it.
  const FAS::Session session = read("refused.session", "patch planar 0 0 0  0 0 1  1 1 200\n"
                                                           "iterate 1\n"
                                                           "grow 0.1 0 0 1\n"
                                                           "save never.vtp\n");
  Mesh tm = make_patch(session);
  const Flow flow;
  FAS::Flow_aligned_deformation<Mesh, Flow> deformation(tm, flow, FAS::Alignment::TANGENTIAL);
  bool saved = false;
  try {
    FAS::replay_session(deformation, session, [&](const Op&) { saved = true; });
    ADD_FAILURE() << "growing along the normal was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("session line 3: ", 0), 0u) << e.what();
  }
  EXPECT_FALSE(saved);
  EXPECT_EQ(deformation.number_of_iterations(), 1u);
  EXPECT_EQ(tm.number_of_faces(), deformation.mesh().number_of_faces());
}

} // namespace test_replay_session
