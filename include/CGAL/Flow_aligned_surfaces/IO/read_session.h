// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads an interactive session (Section 4 of the paper: iterations interleaved with the user's
// translations, rotations and growing) from a plain-text file, one operation a line, so that
// the session can be replayed exactly (`replay_session()`).  The whole file is read and checked
// before anything is returned, so a replay never starts on a file with a bad line.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_READ_SESSION_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_READ_SESSION_H

#include <CGAL/Flow_aligned_surfaces/Session.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/text_cursor.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {

/// \cond SKIP_IN_MANUAL
namespace internal {

/// The iterations of `iterate until-converged` when the line gives no bound.
constexpr std::size_t default_iterations_until_converged = 100;

class Session_parser {
public:
  Session_parser(const std::string& filename, std::string_view bytes) : m_filename(filename), m_bytes(bytes)
  {
  }

  Session parse()
  {
    Session session;
    Setup_lines_seen seen;
    std::size_t start = 0;
    while (next_line(start)) {
      if (m_words.empty())
        continue;
      if (is_setup_keyword(m_words[0])) {
        parse_setup_line(session, seen);
        continue;
      }
      if (!seen.patch)
        fail("'" + printable(m_words[0]) + "' before the 'patch' line that gives the initial surface");
      session.operations.push_back(parse_operation(session.alignment));
    }
    if (!seen.patch)
      throw Read_error("read_session: " + m_filename + ": no 'patch' line gives the initial surface");
    return session;
  }

private:
  // Which of the set-up lines, each allowed once, the file has given so far.
  struct Setup_lines_seen {
    bool flow = false, alignment = false, patch = false;
  };

  static bool is_setup_keyword(std::string_view keyword)
  {
    return keyword == "flow" || keyword == "alignment" || keyword == "patch";
  }

  // The line that begins at `start` into m_line and m_words (without its comment), and `start` to
  // the next line; false after the last line.
  bool next_line(std::size_t& start)
  {
    if (start >= m_bytes.size())
      return false;
    std::size_t end = m_bytes.find('\n', start);
    if (end == std::string_view::npos)
      end = m_bytes.size();
    ++m_line;
    std::string_view text = m_bytes.substr(start, end - start);
    start = end + 1;
    if (const std::size_t hash = text.find('#'); hash != std::string_view::npos)
      text = text.substr(0, hash);
    m_words = split(text);
    return true;
  }

  void parse_setup_line(Session& session, Setup_lines_seen& seen) const
  {
    const std::string_view keyword = m_words[0];
    if (!session.operations.empty())
      fail("'" + std::string(keyword) +
           "' sets up the session and must come before its first operation (line " +
           std::to_string(session.operations.front().line) + ")");
    bool& given = keyword == "flow" ? seen.flow : keyword == "alignment" ? seen.alignment : seen.patch;
    if (given)
      fail("a second '" + std::string(keyword) + "' line");
    given = true;
    if (keyword == "flow") {
      expect_arguments(1, "flow NAME-OR-FILE");
      session.flow = std::string(m_words[1]);
    }
    else if (keyword == "alignment")
      session.alignment = parse_alignment();
    else
      session.patch = parse_patch();
  }

  Alignment parse_alignment() const
  {
    expect_arguments(1, "alignment tangential|orthogonal");
    if (m_words[1] == "tangential")
      return Alignment::TANGENTIAL;
    if (m_words[1] != "orthogonal")
      fail("unknown alignment '" + printable(m_words[1]) + "' (expected tangential or orthogonal)");
    return Alignment::ORTHOGONAL;
  }

  // The operation of the current line, in a session of the given alignment.
  Session_operation parse_operation(Alignment alignment) const
  {
    const std::string_view keyword = m_words[0];
    Session_operation op;
    op.line = m_line;
    if (keyword == "iterate")
      parse_iterate(op);
    else if (keyword == "translate") {
      expect_arguments(3, "translate dx dy dz");
      op.kind = Session_operation::Kind::TRANSLATE;
      op.vector = vector(1, "the translation");
    }
    else if (keyword == "rotate") {
      expect_arguments(4, "rotate ax ay az angle");
      op.kind = Session_operation::Kind::ROTATE;
      op.vector = nonzero_vector(1, "the rotation axis");
      op.angle = number(4, "the angle in degrees") * 3.14159265358979323846 / 180;
    }
    else if (keyword == "grow")
      parse_grow(op, alignment);
    else if (keyword == "save") {
      expect_arguments(1, "save path (no spaces)");
      op.kind = Session_operation::Kind::SAVE;
      op.path = std::string(m_words[1]);
    }
    else
      fail("unknown operation '" + printable(keyword) +
           "' (expected flow, alignment, patch, iterate, translate, rotate, grow or save)");
    return op;
  }

  void parse_iterate(Session_operation& op) const
  {
    op.kind = Session_operation::Kind::ITERATE;
    if (m_words.size() >= 2 && m_words[1] == "until-converged") {
      if (m_words.size() > 3)
        fail("too many arguments (expected: iterate until-converged [N])");
      op.until_converged = true;
      op.number_of_iterations = m_words.size() == 3 ? positive_count(2, "the largest number of iterations")
                                                    : default_iterations_until_converged;
    }
    else {
      expect_arguments(1, "iterate N | iterate until-converged [N]");
      op.number_of_iterations = positive_count(1, "the number of iterations");
    }
  }

  void parse_grow(Session_operation& op, Alignment alignment) const
  {
    op.kind = Session_operation::Kind::GROW;
    if (m_words.size() != 2 && m_words.size() != 3 && m_words.size() != 5)
      fail("expected: grow distance [dx dy dz | across-flow]");
    op.distance = number(1, "the distance");
    if (!(op.distance > 0))
      fail("the distance " + printable(m_words[1]) + " is not positive");
    if (m_words.size() == 3) {
      if (m_words[2] != "across-flow")
        fail("'" + printable(m_words[2]) + "' is neither a direction dx dy dz nor across-flow");
      if (alignment != Alignment::TANGENTIAL)
        fail("'grow ... across-flow' grows a tangential surface, and this session's alignment is "
             "orthogonal");
      op.growth = Session_operation::Growth::ACROSS_FLOW;
    }
    else if (m_words.size() == 5) {
      op.growth = Session_operation::Growth::DIRECTION;
      op.vector = nonzero_vector(2, "the growth direction");
    }
  }

  static std::string printable(std::string_view s) { return internal::printable(s); }

  static std::vector<std::string_view> split(std::string_view text)
  {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < text.size()) {
      while (i < text.size() && Text_cursor::is_space(text[i]))
        ++i;
      const std::size_t b = i;
      while (i < text.size() && !Text_cursor::is_space(text[i]))
        ++i;
      if (i > b)
        words.push_back(text.substr(b, i - b));
    }
    return words;
  }

  [[noreturn]] void fail(const std::string& what) const
  {
    throw Read_error("read_session: " + m_filename + ": line " + std::to_string(m_line) + ": " + what);
  }

  void expect_arguments(std::size_t n, const char* usage) const
  {
    if (m_words.size() != n + 1)
      fail(std::string(m_words.size() < n + 1 ? "too few" : "too many") + " arguments (expected: " + usage +
           ")");
  }

  double number(std::size_t i, const std::string& what) const
  {
    double v = 0;
    if (!Text_cursor::parse_number(m_words[i], v) || !std::isfinite(v))
      fail("'" + printable(m_words[i]) + "' is not a finite number (" + what + ")");
    return v;
  }

  std::size_t positive_count(std::size_t i, const std::string& what) const
  {
    const double v = number(i, what);
    if (!(v >= 1) || v != std::floor(v) || v > 1e9)
      fail("'" + printable(m_words[i]) + "' is not a positive integer (" + what + ")");
    return static_cast<std::size_t>(v);
  }

  std::array<double, 3> vector(std::size_t i, const std::string& what) const
  {
    return {{number(i, what), number(i + 1, what), number(i + 2, what)}};
  }

  std::array<double, 3> nonzero_vector(std::size_t i, const std::string& what) const
  {
    const std::array<double, 3> v = vector(i, what);
    if (v[0] == 0 && v[1] == 0 && v[2] == 0)
      fail(what + " is the zero vector");
    return v;
  }

  double positive(std::size_t i, const std::string& what) const
  {
    const double v = number(i, what);
    if (!(v > 0))
      fail(what + " " + printable(m_words[i]) + " is not positive");
    return v;
  }

  Session_patch parse_patch() const
  {
    Session_patch patch;
    if (m_words.size() >= 2 && m_words[1] == "planar") {
      expect_arguments(10, "patch planar cx cy cz nx ny nz width height faces");
      patch.shape = Session_patch::Shape::PLANAR;
      patch.width = positive(8, "the width");
      patch.height = positive(9, "the height");
    }
    else if (m_words.size() >= 2 && m_words[1] == "disk") {
      expect_arguments(9, "patch disk cx cy cz nx ny nz radius faces");
      patch.shape = Session_patch::Shape::DISK;
      patch.radius = positive(8, "the radius");
    }
    else {
      fail("expected: patch planar cx cy cz nx ny nz width height faces | patch disk cx cy cz nx ny nz "
           "radius faces");
    }
    patch.center = vector(2, "the center");
    patch.normal = nonzero_vector(5, "the normal");
    patch.target_number_of_faces = positive_count(m_words.size() - 1, "the target number of faces");
    return patch;
  }

  std::string m_filename;
  std::string_view m_bytes;
  std::size_t m_line = 0;
  std::vector<std::string_view> m_words;
};

} // namespace internal
/// \endcond

/*!
\ingroup PkgFlowAlignedSurfacesIO

\brief Reads an interactive deformation session from a plain-text file.

One operation a line; `#` starts a comment; blank lines are skipped.  First the set-up lines
(each at most once, before the first operation):
- `flow NAME-OR-FILE`: where the session takes place, for the program that replays it (the
  example `replay_session` takes a built-in flow's name or a data file); optional;
- `alignment tangential|orthogonal` (default `tangential`);
- `patch planar cx cy cz nx ny nz width height faces` or `patch disk cx cy cz nx ny nz radius faces`:
  the initial surface, built with `make_planar_patch()` / `make_disk_patch()`; required.

Then the operations, in the order the user performed them:
- `iterate N`: `N` deformation iterations;
- `iterate until-converged [N]`: iterations until one converges, at most `N` (default 100);
- `translate dx dy dz`: a rigid translation;
- `rotate ax ay az angle`: a rigid rotation by `angle` degrees (right-handed) about the axis
  `(ax, ay, az)` through the centroid of the surface's vertices;
- `grow distance`, `grow distance dx dy dz`, `grow distance across-flow`: growing the boundary
  (all of it, the part facing a direction, or across the flow; see `Flow_aligned_deformation::grow()`);
- `save path`: the surface as it is now, to `path` (relative paths are the replaying
  program's business; the example writes them into its output folder).

The whole file is checked before the function returns: a malformed line (an unknown word, a
missing or extra argument, a number that is not finite, a zero axis or direction, a distance,
size or count that is not positive, a set-up line after an operation or twice, `across-flow`
in an orthogonal session) makes it
return `false` with a message naming the file, the line and what is wrong, and `session` is
left untouched.

\param filename the file to read
\param session receives the session on success; left untouched on failure
\param error if not null, receives the reason of a failure
\returns `true` on success.

\sa `replay_session()`
*/
inline bool read_session(const std::string& filename, Session& session, std::string* error = nullptr)
{
  try {
    const std::string bytes = internal::read_file_contents(filename, "read_session");
    session = internal::Session_parser(filename, bytes).parse();
    return true;
  } catch (const internal::Read_error& e) {
    if (error)
      *error = e.what();
  } catch (const std::bad_alloc&) {
    if (error)
      *error = "read_session: " + filename + ": not enough memory";
  }
  return false;
}

} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_READ_SESSION_H
