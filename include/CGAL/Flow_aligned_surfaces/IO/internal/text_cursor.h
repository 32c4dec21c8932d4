// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A read position in the bytes of a text (or mixed text and binary) file, with the line number
// kept up to date, and the failures of a reader thrown as `Read_error` with the message
// "reader: file: line L, byte B: what".  Tokens are the runs of bytes between white space;
// numbers are parsed with `std::from_chars` (no locale, no allocation).

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_TEXT_CURSOR_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_TEXT_CURSOR_H

#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

class Text_cursor {
public:
  /// `reader` and `file` name the messages; `bytes` must outlive the cursor.
  Text_cursor(std::string reader, std::string file, std::string_view bytes)
      : m_reader(std::move(reader)), m_file(std::move(file)), m_buffer(bytes)
  {
  }

  std::size_t pos = 0;  ///< the byte offset of the next byte to read
  std::size_t line = 1; ///< the line of `pos`, 0 once in binary data (no line is named then)

  std::string_view bytes() const { return m_buffer; }
  const std::string& file() const { return m_file; }
  bool at_end() const { return pos >= m_buffer.size(); }
  std::size_t left() const { return pos < m_buffer.size() ? m_buffer.size() - pos : 0; }

  [[noreturn]] void fail_at(std::size_t offset, std::size_t at_line, const std::string& what) const
  {
    std::ostringstream msg;
    msg << m_reader << ": " << m_file << ": ";
    if (at_line != 0)
      msg << "line " << at_line << ", ";
    msg << "byte " << offset << ": " << what;
    throw Read_error(msg.str());
  }
  [[noreturn]] void fail(const std::string& what) const { fail_at(pos, line, what); }
  [[noreturn]] void fail_file(const std::string& what) const
  {
    throw Read_error(m_reader + ": " + m_file + ": " + what);
  }

  static bool is_space(char c)
  {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
  }

  /// The rest of the current line without its end (`\n` or `\r\n`); moves to the next line.
  std::string_view read_line()
  {
    const std::size_t start = pos;
    while (pos < m_buffer.size() && m_buffer[pos] != '\n')
      ++pos;
    std::string_view l = m_buffer.substr(start, pos - start);
    if (pos < m_buffer.size()) {
      ++pos;
      ++line;
    }
    if (!l.empty() && l.back() == '\r')
      l.remove_suffix(1);
    return l;
  }

  /// Skips white space, new lines included.
  void skip_space()
  {
    while (pos < m_buffer.size() && is_space(m_buffer[pos])) {
      if (m_buffer[pos] == '\n')
        ++line;
      ++pos;
    }
  }

  /// Skips spaces and tabs (and `\r`), not the end of the line.
  void skip_blanks()
  {
    while (pos < m_buffer.size() && (m_buffer[pos] == ' ' || m_buffer[pos] == '\t' || m_buffer[pos] == '\r'))
      ++pos;
  }

  /// The next white-space separated token, empty at the end of the bytes.
  std::string_view token()
  {
    skip_space();
    const std::size_t start = pos;
    while (pos < m_buffer.size() && !is_space(m_buffer[pos]))
      ++pos;
    return m_buffer.substr(start, pos - start);
  }

  /// The next token as `token()` would return it, without moving.
  std::string_view peek_token()
  {
    const std::size_t p = pos, l = line;
    const std::string_view t = token();
    pos = p;
    line = l;
    return t;
  }

  /// Whether only spaces and tabs (and `\r`) are left on the current line; does not move.
  bool rest_of_line_blank() const
  {
    std::size_t p = pos;
    while (p < m_buffer.size() && (m_buffer[p] == ' ' || m_buffer[p] == '\t' || m_buffer[p] == '\r'))
      ++p;
    return p >= m_buffer.size() || m_buffer[p] == '\n';
  }

  /// Parses `t` as a number; a value out of the range of `double` becomes an infinity.
  static bool parse_number(std::string_view t, double& v)
  {
    const char* b = t.data();
    const char* e = b + t.size();
    if (b != e && *b == '+')
      ++b;
    const auto r = std::from_chars(b, e, v);
    if (r.ec == std::errc::result_out_of_range && r.ptr == e) {
      v = (b != e && *b == '-') ? -std::numeric_limits<double>::infinity()
                                : std::numeric_limits<double>::infinity();
      return true;
    }
    return r.ec == std::errc() && r.ptr == e;
  }

  /// `t` (just read, so it ends at `pos`) as a finite number, else a failure naming `what`.
  double finite_number(std::string_view t, const std::string& what) const
  {
    double v = 0;
    if (t.empty())
      fail("the file ends where " + what + " was expected (truncated file?)");
    if (!parse_number(t, v) || !std::isfinite(v))
      fail_at(pos - t.size(), line, "'" + printable(t) + "' is not a finite number (" + what + ")");
    return v;
  }

  /// `t` (just read, so it ends at `pos`) as a non-negative integer, else a failure naming `what`.
  std::size_t count(std::string_view t, const std::string& what) const
  {
    std::size_t v = 0;
    if (t.empty())
      fail("the file ends where " + what + " was expected (truncated file?)");
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size())
      fail_at(pos - t.size(), line, "'" + printable(t) + "' is not a non-negative integer (" + what + ")");
    return v;
  }

  static std::string lower(std::string_view s)
  {
    std::string r(s);
    for (char& c : r)
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return r;
  }

  static std::string upper(std::string_view s)
  {
    std::string r(s);
    for (char& c : r)
      c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return r;
  }

private:
  std::string m_reader, m_file;
  std::string_view m_buffer;
};

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_TEXT_CURSOR_H
