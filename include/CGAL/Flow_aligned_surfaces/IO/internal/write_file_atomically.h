// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writes a file through a temporary beside it and renames it into place only when
// everything was written, so that a failure never destroys what the user had.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_WRITE_FILE_ATOMICALLY_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_WRITE_FILE_ATOMICALLY_H

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <string>
#include <system_error>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

/// Calls `write(stream)` on a temporary file and renames it to `filename`; on failure returns
/// false with the reason in `error`, removes the temporary and leaves `filename` as it was.
template <class Write>
bool write_file_atomically(const std::string& filename, std::string& error, const Write& write)
{
  const std::string temporary = filename + ".partial";
  {
    std::ofstream os(temporary, std::ios::binary | std::ios::trunc);
    if (!os) {
      error = "cannot open " + temporary + " for writing";
      return false;
    }
    write(os);
    os.flush();
    if (!os) {
      error = "writing " + temporary + " failed (disk full?)";
      os.close();
      std::remove(temporary.c_str());
      return false;
    }
  }
  if (std::rename(temporary.c_str(), filename.c_str()) != 0) {
    error = "cannot rename " + temporary + " to " + filename + ": " +
            std::error_code(errno, std::generic_category()).message();
    std::remove(temporary.c_str());
    return false;
  }
  return true;
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_INTERNAL_WRITE_FILE_ATOMICALLY_H
