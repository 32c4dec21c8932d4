// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A stream buffer that writes what goes through it to another stream as base64 (RFC 4648, with
// padding), for the inline binary arrays of VTK XML files: every VTK reads those, whereas
// ParaView 5.11's VTK cannot parse appended data with the expat of an up-to-date Debian
// bookworm.  Whatever writes bytes to a `std::ostream` can so write base64 unchanged.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_BASE64_STREAMBUF_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_BASE64_STREAMBUF_H

#include <algorithm>
#include <array>
#include <cstddef>
#include <ostream>
#include <streambuf>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

class Base64_streambuf : public std::streambuf {
public:
  explicit Base64_streambuf(std::ostream& out) : m_out(out) { setp(m_in.data(), m_in.data() + m_in.size()); }
  Base64_streambuf(const Base64_streambuf&) = delete;
  Base64_streambuf& operator=(const Base64_streambuf&) = delete;

  /// Encodes what is left, with padding; call it once, after the last byte.
  void finish()
  {
    encode(true);
    m_out.write(m_encoded.data(), static_cast<std::streamsize>(m_used));
    m_used = 0;
  }

protected:
  int_type overflow(int_type c) override
  {
    encode(false);
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }

private:
  // Encodes the bytes buffered so far: all of them (padding the last group) when `last`, else
  // the whole groups of 3, keeping the rest for the next call.
  void encode(bool last)
  {
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    const std::size_t whole = n / 3 * 3;
    std::size_t i = 0;
    auto put = [&](char c) {
      if (m_used == m_encoded.size()) {
        m_out.write(m_encoded.data(), static_cast<std::streamsize>(m_used));
        m_used = 0;
      }
      m_encoded[m_used++] = c;
    };
    auto byte = [&](std::size_t k) { return k < n ? static_cast<unsigned char>(m_in[k]) : 0u; };
    for (; i < whole || (last && i < n); i += 3) {
      const unsigned group = (byte(i) << 16) | (byte(i + 1) << 8) | byte(i + 2);
      put(digits[(group >> 18) & 63]);
      put(digits[(group >> 12) & 63]);
      put(i + 1 < n ? digits[(group >> 6) & 63] : '=');
      put(i + 2 < n ? digits[group & 63] : '=');
    }
    const std::size_t rest = n - std::min(i, n);
    for (std::size_t k = 0; k < rest; ++k)
      m_in[k] = m_in[i + k];
    setp(m_in.data(), m_in.data() + m_in.size());
    pbump(static_cast<int>(rest));
  }

  std::ostream& m_out;
  std::array<char, 3 * 4096> m_in;
  std::array<char, 4 * 4096> m_encoded;
  std::size_t m_used = 0;
};

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_BASE64_STREAMBUF_H
