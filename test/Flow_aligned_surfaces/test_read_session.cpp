// IO::read_session(): a hand-written session read into exactly the operations it spells, and
// every kind of malformed line refused with the file, the line and the fault, the session
// left untouched.

#include <CGAL/Flow_aligned_surfaces/IO/read_session.h>

#include "test_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

// This file's tests and helpers in a namespace of their own: the suite is compiled in unity
// batches (test/Flow_aligned_surfaces/CMakeLists.txt), where files share a translation unit.
namespace test_read_session {

namespace FAS = CGAL::Flow_aligned_surfaces;
using Op = FAS::Session_operation;

namespace {

const std::string valid_session = "# a comment line\n"
                                  "flow cylinder\n"
                                  "alignment tangential   # trailing comment\n"
                                  "patch planar -2 0.8 0  0.3 1 0.4  1.2 0.6  2000\n"
                                  "\n"
                                  "iterate 5\r\n"
                                  "iterate until-converged\n"
                                  "iterate until-converged 7\n"
                                  "translate 0 0.25 -1e-1\n"
                                  "\trotate 0 0 2 90\n"
                                  "grow 0.3\n"
                                  "grow 0.3 0 1 0\n"
                                  "grow 0.125 across-flow\n"
                                  "save out/aligned.vtp\n";

std::string write_session(const std::string& name, const std::string& text)
{
  const std::string file = temporary_file("read_session_", name);
  write_bytes(file, text);
  return file;
}

} // namespace

TEST(ReadSession, ReadsEveryOperationAsWritten)
{
  const std::string file = write_session("valid.session", valid_session);
  FAS::Session session;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_session(file, session, &error)) << error;
  EXPECT_EQ(session.flow, "cylinder");
  EXPECT_EQ(session.alignment, FAS::Alignment::TANGENTIAL);
  EXPECT_EQ(session.patch.shape, FAS::Session_patch::Shape::PLANAR);
  EXPECT_EQ(session.patch.center, (std::array<double, 3>{{-2, 0.8, 0}}));
  EXPECT_EQ(session.patch.normal, (std::array<double, 3>{{0.3, 1, 0.4}}));
  EXPECT_EQ(session.patch.width, 1.2);
  EXPECT_EQ(session.patch.height, 0.6);
  EXPECT_EQ(session.patch.target_number_of_faces, 2000u);

  const auto& ops = session.operations;
  ASSERT_EQ(ops.size(), 9u);
  EXPECT_EQ(ops[0].kind, Op::Kind::ITERATE);
  EXPECT_EQ(ops[0].line, 6u);
  EXPECT_EQ(ops[0].number_of_iterations, 5u);
  EXPECT_FALSE(ops[0].until_converged);
  EXPECT_TRUE(ops[1].until_converged);
  EXPECT_EQ(ops[1].number_of_iterations, FAS::IO::internal::default_iterations_until_converged);
  EXPECT_TRUE(ops[2].until_converged);
  EXPECT_EQ(ops[2].number_of_iterations, 7u);
  EXPECT_EQ(ops[3].kind, Op::Kind::TRANSLATE);
  EXPECT_EQ(ops[3].vector, (std::array<double, 3>{{0, 0.25, -0.1}}));
  EXPECT_EQ(ops[4].kind, Op::Kind::ROTATE);
  EXPECT_EQ(ops[4].line, 10u);
  EXPECT_EQ(ops[4].vector, (std::array<double, 3>{{0, 0, 2}}));
  EXPECT_DOUBLE_EQ(ops[4].angle, std::acos(-1.0) / 2);
  EXPECT_EQ(ops[5].kind, Op::Kind::GROW);
  EXPECT_EQ(ops[5].growth, Op::Growth::WHOLE_BOUNDARY);
  EXPECT_EQ(ops[5].distance, 0.3);
  EXPECT_EQ(ops[6].growth, Op::Growth::DIRECTION);
  EXPECT_EQ(ops[6].vector, (std::array<double, 3>{{0, 1, 0}}));
  EXPECT_EQ(ops[7].growth, Op::Growth::ACROSS_FLOW);
  EXPECT_EQ(ops[7].distance, 0.125);
  EXPECT_EQ(ops[8].kind, Op::Kind::SAVE);
  EXPECT_EQ(ops[8].path, "out/aligned.vtp");
  EXPECT_EQ(ops[8].line, 14u);
}

TEST(ReadSession, ReadsADiskAndTheDefaults)
{
  const std::string file =
      write_session("disk.session", "alignment orthogonal\npatch disk 1 2 3 0 0 1 0.5 300\nsave a.ply");
  FAS::Session session;
  std::string error;
  ASSERT_TRUE(FAS::IO::read_session(file, session, &error)) << error;
  EXPECT_TRUE(session.flow.empty());
  EXPECT_EQ(session.alignment, FAS::Alignment::ORTHOGONAL);
  EXPECT_EQ(session.patch.shape, FAS::Session_patch::Shape::DISK);
  EXPECT_EQ(session.patch.center, (std::array<double, 3>{{1, 2, 3}}));
  EXPECT_EQ(session.patch.radius, 0.5);
  EXPECT_EQ(session.patch.target_number_of_faces, 300u);
  ASSERT_EQ(session.operations.size(), 1u);
  EXPECT_EQ(session.operations[0].path, "a.ply"); // the last line has no end of line
}

TEST(ReadSession, MalformedLinesNameTheFileTheLineAndTheFault)
{
  const std::string head = "flow cylinder\npatch planar 0 0 0 0 0 1 1 1 100\n"; // lines 1-2
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {head + "iterate\n", "line 3: too few arguments (expected: iterate N"},
      {head + "iterate 0\n", "line 3: '0' is not a positive integer (the number of iterations)"},
      {head + "iterate 2.5\n", "line 3: '2.5' is not a positive integer"},
      {head + "iterate five\n", "line 3: 'five' is not a finite number"},
      {head + "iterate until-converged 3 4\n", "line 3: too many arguments (expected: iterate until-converged [N])"},
      {head + "translate 1 2\n", "line 3: too few arguments (expected: translate dx dy dz)"},
      {head + "translate 1 2 3 4\n", "line 3: too many arguments"},
      {head + "translate 1 nan 3\n", "line 3: 'nan' is not a finite number (the translation)"},
      {head + "translate 1 1e400 3\n", "line 3: '1e400' is not a finite number"},
      {head + "rotate 0 0 0 30\n", "line 3: the rotation axis is the zero vector"},
      {head + "rotate 0 0 1 inf\n", "line 3: 'inf' is not a finite number (the angle in degrees)"},
      {head + "grow -0.1\n", "line 3: the distance -0.1 is not positive"},
      {head + "grow 0\n", "line 3: the distance 0 is not positive"},
      {head + "grow 0.1 sideways\n", "line 3: 'sideways' is neither a direction dx dy dz nor across-flow"},
      {head + "grow 0.1 0 0 0\n", "line 3: the growth direction is the zero vector"},
      {head + "grow 0.1 1 0\n", "line 3: expected: grow distance [dx dy dz | across-flow]"},
      {head + "save\n", "line 3: too few arguments (expected: save path"},
      {head + "save a b\n", "line 3: too many arguments"},
      {head + "jump 1\n", "line 3: unknown operation 'jump'"},
      {head + "iterate 1\nalignment orthogonal\n", "line 4: 'alignment' sets up the session and must come before"},
      {head + "flow abc\n", "line 3: a second 'flow' line"},
      {"alignment sideways\n", "line 1: unknown alignment 'sideways'"},
      {"alignment orthogonal\npatch disk 0 0 0 0 0 1 1 10\ngrow 1 across-flow\n",
       "line 3: 'grow ... across-flow' grows a tangential surface"},
      {"iterate 3\n", "line 1: 'iterate' before the 'patch' line"},
      {"patch square 0 0 0 0 0 1 1 1 100\n", "line 1: expected: patch planar"},
      {"patch planar 0 0 0 0 0 1 1 1\n", "line 1: too few arguments (expected: patch planar"},
      {"patch planar 0 0 0 0 0 0 1 1 100\n", "line 1: the normal is the zero vector"},
      {"patch planar 0 0 0 0 0 1 -1 1 100\n", "line 1: the width -1 is not positive"},
      {"patch disk 0 0 0 0 0 1 0 100\n", "line 1: the radius 0 is not positive"},
      {"patch disk 0 0 0 0 0 1 1 -5\n", "line 1: '-5' is not a positive integer (the target number of faces)"},
      {"flow cylinder\n", "no 'patch' line gives the initial surface"},
      {"", "the file is empty (0 bytes)"},
  };
  int i = 0;
  for (const Case& c : cases) {
    const std::string file = write_session("bad_" + std::to_string(i++) + ".session", c.text);
    FAS::Session session;
    session.flow = "untouched";
    std::string error;
    EXPECT_FALSE(FAS::IO::read_session(file, session, &error)) << c.text;
    EXPECT_NE(error.find("read_session: " + file + ": "), std::string::npos) << error;
    EXPECT_NE(error.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << error;
    EXPECT_EQ(session.flow, "untouched");
    EXPECT_TRUE(session.operations.empty());
  }
}

TEST(ReadSession, AMissingFileIsAnError)
{
  FAS::Session session;
  std::string error;
  EXPECT_FALSE(FAS::IO::read_session(temporary_file("read_session_", "absent.session"), session, &error));
  EXPECT_NE(error.find("absent.session: cannot open the file for reading"), std::string::npos) << error;
}

TEST(ReadSession, TheShippedSessionsAreValid)
{
  for (const char* name : {"tangential.session", "orthogonal.session"}) {
    FAS::Session session;
    std::string error;
    EXPECT_TRUE(FAS::IO::read_session(std::string(FAS_EXAMPLE_DATA_DIR) + "/" + name, session, &error)) << error;
    int moves = 0, grows = 0;
    for (const auto& op : session.operations) {
      moves += op.kind == Op::Kind::TRANSLATE || op.kind == Op::Kind::ROTATE;
      grows += op.kind == Op::Kind::GROW;
    }
    EXPECT_GE(moves, 2) << name; // translations and rotations ...
    EXPECT_GE(grows, 1) << name; // ... and growing: the sessions show both
  }
}

} // namespace test_read_session
