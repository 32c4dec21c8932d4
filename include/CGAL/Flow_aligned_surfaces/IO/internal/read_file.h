// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What every flow-field reader needs before it parses: the error it throws internally (turned
// into `false` + message by its public function), the whole file as bytes (mapped into memory
// where the system can, else read into a string), and tokens shown in messages without control
// characters.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_READ_FILE_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_READ_FILE_H

#include <cctype>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

// POSIX systems map the file instead of copying it (see File_contents).  Under AddressSanitizer
// the file is copied into the heap, so that a parser reading past its end is reported (the tail
// of a mapping's last page is readable and not checked).
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CGAL_FLOW_ALIGNED_SURFACES_NO_MMAP
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define CGAL_FLOW_ALIGNED_SURFACES_NO_MMAP
#endif
#if !defined(CGAL_FLOW_ALIGNED_SURFACES_NO_MMAP) && (defined(__unix__) || defined(__APPLE__))
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#if defined(_POSIX_MAPPED_FILES) && _POSIX_MAPPED_FILES > 0
#define CGAL_FLOW_ALIGNED_SURFACES_HAS_MMAP 1
#endif
#endif

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

/// Thrown inside the readers only, with the complete message ("reader: file: where: what").
struct Read_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The contents of `filename`; throws `Read_error` naming `reader` and the file if it cannot be
/// read or is empty.  Reading the whole file at once is the fastest way on every system (one `read()`), and
/// lets the parsers check every count against the bytes that are really there.
inline std::string read_file_contents(const std::string& filename, const std::string& reader)
{
  std::error_code ec;
  // A directory opens as a stream that reads nothing: it would be called empty or unsized.
  if (std::filesystem::is_directory(filename, ec))
    throw Read_error(reader + ": " + filename + ": is a directory, not a file");
  std::ifstream is(filename, std::ios::binary);
  if (!is)
    throw Read_error(reader + ": " + filename + ": cannot open the file for reading");
  is.seekg(0, std::ios::end);
  const std::streamoff size = is.tellg();
  if (size < 0)
    throw Read_error(reader + ": " + filename +
                     ": cannot determine the size of the file (not a regular file?)");
  std::string contents;
  contents.resize(static_cast<std::size_t>(size));
  is.seekg(0, std::ios::beg);
  is.read(&contents[0], size);
  if (!is)
    throw Read_error(reader + ": " + filename + ": reading the file failed");
  if (contents.empty())
    throw Read_error(reader + ": " + filename + ": the file is empty (0 bytes)");
  return contents;
}

/// The bytes of a file, held for as long as the object lives: on POSIX systems a read-only
/// private mapping of the file (no copy: the parsers decode straight from the page cache), else,
/// or when the file cannot be mapped (not a regular file, empty, `mmap()` refused), its contents
/// read by `read_file_contents()`, which then gives the same messages for files that cannot be
/// read.  A file that another process shortens while it is mapped makes the reader's access past
/// the new end fail with `SIGBUS`, and one changed in place is seen changing; the readers do not
/// guard against either (nor does copying guard against a file changed while it is read).
class File_contents {
public:
  /// Maps or reads `filename`; throws `Read_error` naming `reader` and the file if it cannot be read.
  File_contents(const std::string& filename, const std::string& reader)
  {
#if defined(CGAL_FLOW_ALIGNED_SURFACES_HAS_MMAP)
    const int fd = ::open(filename.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat st;
    if (fd >= 0 && ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0 &&
        static_cast<unsigned long long>(st.st_size) <= (std::numeric_limits<std::size_t>::max)()) {
      const std::size_t size = static_cast<std::size_t>(st.st_size);
      void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
      if (p != MAP_FAILED) {
        // The parsers read the file front to back: ask for read-ahead of all of it now.
        ::madvise(p, size, MADV_SEQUENTIAL);
        ::madvise(p, size, MADV_WILLNEED);
        m_map = p;
        m_size = size;
      }
    }
    if (fd >= 0)
      ::close(fd); // the mapping keeps the file
    if (m_map != nullptr)
      return;
#endif
    m_copy = read_file_contents(filename, reader);
  }
  File_contents(File_contents&& other) noexcept
      : m_map(std::exchange(other.m_map, nullptr)), m_size(std::exchange(other.m_size, 0)),
        m_copy(std::move(other.m_copy))
  {
  }
  File_contents& operator=(File_contents&& other) noexcept
  {
    if (this != &other) {
      release();
      m_map = std::exchange(other.m_map, nullptr);
      m_size = std::exchange(other.m_size, 0);
      m_copy = std::move(other.m_copy);
    }
    return *this;
  }
  File_contents(const File_contents&) = delete;
  File_contents& operator=(const File_contents&) = delete;
  ~File_contents()
  {
    release();
  }

  /// All the bytes of the file; valid while `*this` lives (and is not moved from).
  std::string_view view() const
  {
    return m_map != nullptr ? std::string_view(static_cast<const char*>(m_map), m_size)
                            : std::string_view(m_copy);
  }
  /// Whether the bytes are a mapping of the file rather than a copy.
  bool is_mapped() const
  {
    return m_map != nullptr;
  }

private:
  void release()
  {
#if defined(CGAL_FLOW_ALIGNED_SURFACES_HAS_MMAP)
    if (m_map != nullptr)
      ::munmap(m_map, m_size);
#endif
    m_map = nullptr;
    m_size = 0;
  }

  void* m_map = nullptr;
  std::size_t m_size = 0;
  std::string m_copy;
};

/// A token shown in a message: at most 40 characters, non-printable bytes escaped as `\xNN`.
inline std::string printable(std::string_view s)
{
  std::string r;
  for (std::size_t i = 0; i < s.size() && i < 40; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (std::isprint(c))
      r += static_cast<char>(c);
    else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      r += hex;
    }
  }
  if (s.size() > 40)
    r += "...";
  return r;
}

/// A number shown in a message, with all the digits that tell it apart.
inline std::string number_string(double v)
{
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_READ_FILE_H
