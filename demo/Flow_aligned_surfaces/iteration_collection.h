// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The deformation's iterations as a ParaView collection: the surface before the first iteration
// and after each one, as VTP files NAME_iterations/NAME_0000.vtp, NAME_0001.vtp, ... (with the
// velocity and the normalized flux, as the other surfaces), listed with their iteration as the
// time step in NAME_iterations.pvd, so that ParaView's time controls animate the alignment
// (growth steps included: their surfaces have more faces).  The folder is emptied first, so
// that no file of an earlier run is listed or left looking like this run's.

#ifndef FAS_DEMO_ITERATION_COLLECTION_H
#define FAS_DEMO_ITERATION_COLLECTION_H

#include "demo_support.h"
#include "write_then_rename.h"

#include <filesystem>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace fas_demo {

/// See the file's comment.
class Iteration_collection {
public:
  /// Collects into `out`/`name`_iterations/ (emptied; `error()` says why when it cannot be).
  Iteration_collection(const std::filesystem::path& out, const std::string& name)
      : m_out(out), m_name(name), m_folder(out / (name + "_iterations"))
  {
    std::error_code ec;
    std::filesystem::remove_all(m_folder, ec);
    if (!ec)
      std::filesystem::create_directories(m_folder, ec);
    if (ec)
      m_error = "cannot empty or create " + m_folder.string() + ": " + ec.message();
  }

  /// Writes `tm` as the next time step; false (and `error()`) when it cannot.
  bool add(const Mesh& tm, const Flow& flow)
  {
    if (!m_error.empty())
      return false;
    std::ostringstream name;
    name << m_name << '_' << std::setw(4) << std::setfill('0') << m_files.size() << ".vtp";
    const std::filesystem::path path = m_folder / name.str();
    if (!write_surface_VTP(path, tm, flow)) {
      m_error = "cannot write " + path.string();
      return false;
    }
    m_files.push_back(m_name + "_iterations/" + name.str());
    return true;
  }

  /// Writes `out`/`name`_iterations.pvd listing the time steps written (beside it first, then
  /// renamed over it).
  bool write_pvd()
  {
    if (!m_error.empty())
      return false;
    const std::string pvd = (m_out / (m_name + "_iterations.pvd")).string();
    std::string reason;
    const bool written = write_stream_then_rename(pvd, reason, [&](std::ostream& os) {
      os << "<?xml version=\"1.0\"?>\n"
         << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
      for (std::size_t i = 0; i < m_files.size(); ++i)
        os << "    <DataSet timestep=\"" << i << "\" group=\"\" part=\"0\" file=\"" << m_files[i] << "\"/>\n";
      os << "  </Collection>\n</VTKFile>\n";
    });
    if (!written)
      m_error = "cannot write " + pvd + ": " + reason;
    return written;
  }

  const std::vector<std::string>& files() const { return m_files; } ///< relative to the output folder
  const std::string& error() const { return m_error; }              ///< empty unless a write failed

private:
  std::filesystem::path m_out;
  std::string m_name;
  std::filesystem::path m_folder;
  std::vector<std::string> m_files;
  std::string m_error;
};

} // namespace fas_demo

#endif // FAS_DEMO_ITERATION_COLLECTION_H
