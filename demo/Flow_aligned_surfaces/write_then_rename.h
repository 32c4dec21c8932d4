// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every file of the demo programs is written beside its name and renamed over it only when it is
// complete, so that a reader (ParaView watching the output folder, a second run) never sees half a
// file and a failed write never destroys what the user had.

#ifndef FAS_DEMO_WRITE_THEN_RENAME_H
#define FAS_DEMO_WRITE_THEN_RENAME_H

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace fas_demo {

/// Calls `write_to(temporary)`, which writes a whole file at the path it is given and returns
/// whether it succeeded (setting `reason` when not), then renames the temporary to `filename`.
/// On failure returns false with the reason in `reason`, removes the temporary and leaves
/// `filename` as it was.  The temporary keeps `filename`'s extension, for writers that go by it.
template <class WriteTo>
bool write_then_rename(const std::string& filename, std::string& reason, const WriteTo& write_to)
{
  const std::filesystem::path target(filename);
  const std::string temporary =
      (target.parent_path() / (target.stem().string() + ".partial" + target.extension().string())).string();
  if (!write_to(temporary)) {
    std::remove(temporary.c_str());
    return false;
  }
  std::error_code ec;
  std::filesystem::rename(temporary, target, ec);
  if (ec) {
    std::remove(temporary.c_str());
    reason = "cannot rename " + temporary + " to " + filename + ": " + ec.message();
    return false;
  }
  return true;
}

/// `write_then_rename()` for a file written as a stream: `write(os)` writes its content.
template <class Write>
bool write_stream_then_rename(const std::string& filename, std::string& reason, const Write& write)
{
  return write_then_rename(filename, reason, [&](const std::string& temporary) {
    std::ofstream os(temporary, std::ios::binary | std::ios::trunc);
    if (!os) {
      reason = "cannot open " + temporary + " for writing";
      return false;
    }
    write(os);
    os.flush();
    if (!os)
      reason = "writing " + temporary + " failed (disk full?)";
    return bool(os);
  });
}

} // namespace fas_demo

#endif // FAS_DEMO_WRITE_THEN_RENAME_H
