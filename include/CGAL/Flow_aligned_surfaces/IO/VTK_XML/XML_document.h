// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A small, strict XML parser for what VTK writes: an optional byte-order mark and declaration,
// comments and processing instructions, elements with attributes (the five predefined entities
// and character references decoded), and character data.  The `<AppendedData>` element of a
// VTK XML file holds arbitrary bytes after its '_': they are never parsed as XML; the data end
// at the last `</AppendedData>` of the file.  Nothing is copied but names and attribute values:
// an element's character data is a byte range of the file.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_XML_DOCUMENT_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_XML_DOCUMENT_H

#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

struct XML_element {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::vector<std::size_t> children; ///< indices in `XML_document::elements`, in file order
  std::size_t byte = 0;              ///< the offset of the start tag's '<'
  std::size_t text_begin = 0, text_end = 0; ///< the first run of character data that is not blank

  /// The value of attribute `n`, or null.
  const std::string* attribute(std::string_view n) const
  {
    for (const auto& a : attributes)
      if (a.first == n)
        return &a.second;
    return nullptr;
  }
};

/// The elements of a file (the root first), and where its appended data lie.
class XML_document {
public:
  /// Parses `bytes`, which must outlive the document; `reader` and `file` name the messages.
  XML_document(std::string reader, std::string file, std::string_view bytes)
      : m_reader(std::move(reader)), m_file(std::move(file)), m_bytes(bytes)
  {
    parse();
  }

  std::vector<XML_element> elements;
  /// The bytes of the `<AppendedData>` element after its '_' (up to its end tag), if any.
  std::size_t appended_begin = 0, appended_end = 0;
  bool has_appended = false;

  std::string_view bytes() const { return m_bytes; }
  const std::string& file() const { return m_file; }
  const XML_element& root() const { return elements.front(); }

  /// The first child of `e` named `name`, or null.
  const XML_element* child(const XML_element& e, std::string_view name) const
  {
    for (std::size_t c : e.children)
      if (elements[c].name == name)
        return &elements[c];
    return nullptr;
  }

  /// The line of byte `offset`, or 0 (no line named) inside the appended data.
  std::size_t line_of(std::size_t offset) const
  {
    if (has_appended && offset >= appended_begin)
      return 0;
    offset = std::min(offset, m_bytes.size());
    return 1 + static_cast<std::size_t>(std::count(m_bytes.begin(), m_bytes.begin() + offset, '\n'));
  }

  [[noreturn]] void fail_at(std::size_t offset, const std::string& what) const
  {
    std::ostringstream msg;
    msg << m_reader << ": " << m_file << ": ";
    if (const std::size_t line = line_of(offset))
      msg << "line " << line << ", ";
    msg << "byte " << offset << ": " << what;
    throw Read_error(msg.str());
  }
  [[noreturn]] void fail_file(const std::string& what) const { throw Read_error(m_reader + ": " + m_file + ": " + what); }
  /// "byte B: <Name> " for messages about element `e` (with its line).
  [[noreturn]] void fail_element(const XML_element& e, const std::string& what) const
  {
    fail_at(e.byte, "<" + e.name + ">: " + what);
  }

private:
  static constexpr std::size_t max_depth = 64;

  bool at(std::string_view s) const { return m_bytes.substr(m_pos, s.size()) == s; }
  bool at_end() const { return m_pos >= m_bytes.size(); }
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
  static bool is_name_char(char c)
  {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == ':' ||
           c == '-' || c == '.' || static_cast<unsigned char>(c) >= 0x80;
  }
  void skip_space()
  {
    while (!at_end() && is_space(m_bytes[m_pos]))
      ++m_pos;
  }
  [[noreturn]] void fail(const std::string& what) const { fail_at(m_pos, what); }

  // Skips past `end`, which must follow (the end of a comment or processing instruction).
  void skip_past(std::string_view end, const char* what)
  {
    const std::size_t start = m_pos;
    const std::size_t e = m_bytes.find(end, m_pos);
    if (e == std::string_view::npos)
      fail_at(start, std::string("the ") + what + " does not end (no '" + std::string(end) + "'; truncated file?)");
    m_pos = e + end.size();
  }

  // Skips comments, processing instructions and white space; false at anything else.
  bool skip_misc()
  {
    skip_space();
    if (at("<!--"))
      skip_past("-->", "comment");
    else if (at("<?"))
      skip_past("?>", "processing instruction");
    else
      return false;
    return true;
  }

  std::string name()
  {
    const std::size_t start = m_pos;
    while (!at_end() && is_name_char(m_bytes[m_pos]))
      ++m_pos;
    if (m_pos == start || (m_bytes[start] >= '0' && m_bytes[start] <= '9') || m_bytes[start] == '-' ||
        m_bytes[start] == '.')
      fail_at(start, at_end() ? "the file ends where a name was expected (truncated file?)"
                              : "'" + printable(m_bytes.substr(start, 1)) + "' cannot start an XML name");
    return std::string(m_bytes.substr(start, m_pos - start));
  }

  // The character reference or predefined entity at m_pos ('&'), appended to `out` as UTF-8.
  void entity(std::string& out)
  {
    const std::size_t start = m_pos;
    const std::size_t semicolon = m_bytes.find(';', m_pos);
    if (semicolon == std::string_view::npos || semicolon - m_pos > 12)
      fail("'&' starts no entity (write '&amp;' for an ampersand)");
    const std::string_view e = m_bytes.substr(m_pos + 1, semicolon - m_pos - 1);
    m_pos = semicolon + 1;
    static const std::pair<const char*, char> named[] = {{"amp", '&'}, {"lt", '<'}, {"gt", '>'}, {"quot", '"'}, {"apos", '\''}};
    for (const auto& n : named)
      if (e == n.first) {
        out += n.second;
        return;
      }
    std::uint32_t code = 0;
    const bool hex = e.size() > 2 && e[0] == '#' && e[1] == 'x';
    if (e.size() < 2 || e[0] != '#' || e.size() > 9)
      fail_at(start, "unknown entity '&" + printable(e) + ";'");
    for (std::size_t i = hex ? 2 : 1; i < e.size(); ++i) {
      const char c = e[i];
      const int d = (c >= '0' && c <= '9') ? c - '0'
                    : hex && (c | 0x20) >= 'a' && (c | 0x20) <= 'f' ? (c | 0x20) - 'a' + 10
                                                                     : -1;
      if (d < 0)
        fail_at(start, "bad character reference '&" + printable(e) + ";'");
      code = code * (hex ? 16 : 10) + static_cast<std::uint32_t>(d);
    }
    if (code == 0 || code > 0x10FFFF)
      fail_at(start, "bad character reference '&" + printable(e) + ";'");
    if (code < 0x80)
      out += static_cast<char>(code);
    else if (code < 0x800)
      out += {static_cast<char>(0xC0 | (code >> 6)), static_cast<char>(0x80 | (code & 0x3F))};
    else if (code < 0x10000)
      out += {static_cast<char>(0xE0 | (code >> 12)), static_cast<char>(0x80 | ((code >> 6) & 0x3F)),
              static_cast<char>(0x80 | (code & 0x3F))};
    else
      out += {static_cast<char>(0xF0 | (code >> 18)), static_cast<char>(0x80 | ((code >> 12) & 0x3F)),
              static_cast<char>(0x80 | ((code >> 6) & 0x3F)), static_cast<char>(0x80 | (code & 0x3F))};
  }

  std::string attribute_value()
  {
    if (at_end() || (m_bytes[m_pos] != '"' && m_bytes[m_pos] != '\''))
      fail("an attribute value in quotes was expected");
    const char quote = m_bytes[m_pos++];
    std::string v;
    for (;;) {
      if (at_end())
        fail("the file ends inside an attribute value (truncated file?)");
      const char c = m_bytes[m_pos];
      if (c == quote)
        break;
      if (c == '<')
        fail("'<' inside an attribute value");
      if (c == '&') {
        entity(v);
        continue;
      }
      v += c;
      ++m_pos;
    }
    ++m_pos;
    return v;
  }

  // The start tag at m_pos ('<'): the element is added; returns whether it has content (not `/>`).
  bool start_tag(std::size_t parent)
  {
    XML_element e;
    e.byte = m_pos++;
    e.name = name();
    for (;;) {
      const std::size_t before = m_pos;
      skip_space();
      if (at_end())
        fail_at(e.byte, "the start tag of <" + e.name + "> does not end (truncated file?)");
      if (at("/>") || at(">"))
        break;
      if (m_pos == before)
        fail("white space was expected before an attribute of <" + e.name + ">");
      const std::size_t attribute_start = m_pos;
      std::string n = name();
      skip_space();
      if (at_end() || m_bytes[m_pos] != '=')
        fail("'=' was expected after the attribute name '" + printable(n) + "'");
      ++m_pos;
      skip_space();
      std::string v = attribute_value();
      if (e.attribute(n) != nullptr)
        fail_at(attribute_start, "<" + e.name + "> has two attributes named '" + printable(n) + "'");
      e.attributes.emplace_back(std::move(n), std::move(v));
    }
    const bool content = m_bytes[m_pos] == '>';
    m_pos += content ? 1 : 2;
    if (parent != std::size_t(-1))
      elements[parent].children.push_back(elements.size());
    elements.push_back(std::move(e));
    return content;
  }

  // The raw bytes of <AppendedData>: after white space and '_', up to the last end tag.
  void appended_data()
  {
    skip_space();
    if (at_end() || m_bytes[m_pos] != '_')
      fail("the appended data must start with '_'");
    const std::size_t end = m_bytes.rfind("</AppendedData");
    if (end == std::string_view::npos || end <= m_pos)
      fail_at(elements.back().byte, "<AppendedData> has no end tag </AppendedData> (truncated file?)");
    if (has_appended)
      fail_at(elements.back().byte, "a second <AppendedData> element");
    has_appended = true;
    appended_begin = m_pos + 1;
    appended_end = end;
    m_pos = end;
  }

  void end_tag(std::vector<std::size_t>& open)
  {
    const std::size_t start = m_pos;
    m_pos += 2;
    const std::string n = name();
    skip_space();
    if (at_end() || m_bytes[m_pos] != '>')
      fail("'>' was expected to end the end tag </" + printable(n) + ">");
    ++m_pos;
    const XML_element& e = elements[open.back()];
    if (n != e.name)
      fail_at(start, "the end tag </" + printable(n) + "> does not match the start tag <" + e.name + "> at byte " +
                         std::to_string(e.byte));
    open.pop_back();
  }

  // Character data up to the next '<', recorded as the element's text if it is its first
  // non-blank run.
  void text(XML_element& e)
  {
    const std::size_t start = m_pos;
    const std::size_t lt = m_bytes.find('<', m_pos);
    m_pos = lt == std::string_view::npos ? m_bytes.size() : lt;
    if (e.text_end == 0 &&
        std::any_of(m_bytes.begin() + start, m_bytes.begin() + m_pos, [](char c) { return !is_space(c); })) {
      e.text_begin = start;
      e.text_end = m_pos;
    }
  }

  void parse()
  {
    if (at("\xEF\xBB\xBF"))
      m_pos = 3;
    while (skip_misc()) {
    }
    if (at_end())
      fail("the file holds no XML element");
    if (at("<!DOCTYPE"))
      fail("a document type declaration (<!DOCTYPE); VTK XML files have none");
    if (m_bytes[m_pos] != '<')
      fail("'" + printable(m_bytes.substr(m_pos, 1)) + "' where the root element '<' was expected: not an XML file");
    std::vector<std::size_t> open;
    if (start_tag(std::size_t(-1)))
      open.push_back(0);
    while (!open.empty()) {
      text(elements[open.back()]);
      if (at_end())
        fail("the file ends inside <" + elements[open.back()].name + "> (opened at byte " +
             std::to_string(elements[open.back()].byte) + "; truncated file?)");
      if (at("<!--"))
        skip_past("-->", "comment");
      else if (at("<?"))
        skip_past("?>", "processing instruction");
      else if (at("</"))
        end_tag(open);
      else if (at("<!"))
        fail("CDATA sections and declarations are not supported here");
      else if (start_tag(open.back())) {
        if (open.size() >= max_depth)
          fail_at(elements.back().byte, "elements nested more than " + std::to_string(max_depth) + " deep");
        open.push_back(elements.size() - 1);
        if (elements.back().name == "AppendedData")
          appended_data();
      }
    }
    while (skip_misc()) {
    }
    if (!at_end())
      fail("content after the end of the root element <" + root().name + ">");
  }

  std::string m_reader, m_file;
  std::string_view m_bytes;
  std::size_t m_pos = 0;
};

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_XML_DOCUMENT_H
