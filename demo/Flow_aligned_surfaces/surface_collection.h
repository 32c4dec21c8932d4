// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Surfaces over time as a ParaView collection, so that ParaView's time controls animate them:
// VTP files NAME_WHAT/NAME_0000.vtp, NAME_0001.vtp, ... listed with their time steps in
// NAME_WHAT.pvd.  The deformation's iterations (WHAT = iterations): the surface before the first
// iteration and after each one (with the velocity and the normalized flux, as the other
// surfaces), the iteration as the time step (growth steps included: their surfaces have more
// faces); path surfaces as they grow, at the data's times.  The folder is emptied first, so that
// no file of an earlier run is listed or left looking like this run's.

#ifndef FAS_DEMO_SURFACE_COLLECTION_H
#define FAS_DEMO_SURFACE_COLLECTION_H

#include "demo_support.h"
#include "write_then_rename.h"

#include <filesystem>
#include <functional>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace fas_demo {

/// See the file's comment.
class Surface_collection {
public:
  /// Collects into `out`/`name`_`what`/ (emptied; `error()` says why when it cannot be).
  Surface_collection(const std::filesystem::path& out, const std::string& name,
                     const std::string& what = "iterations")
      : m_out(out), m_name(name), m_collection(name + "_" + what), m_folder(out / m_collection)
  {
    std::error_code ec;
    std::filesystem::remove_all(m_folder, ec);
    if (!ec)
      std::filesystem::create_directories(m_folder, ec);
    if (ec)
      m_error = "cannot empty or create " + m_folder.string() + ": " + ec.message();
  }

  /// Writes the next iteration's surface `tm` (with the velocity and flux of `flow`), its number
  /// as the time step; false (and `error()`) when it cannot.
  bool add(const Mesh& tm, const Flow& flow)
  {
    return add([&](const std::filesystem::path& path) { return write_surface_VTP(path, tm, flow); },
               double(m_files.size()));
  }

  /// Writes the next file by `write(path)` (false: it could not), at time step `time`.
  bool add(const std::function<bool(const std::filesystem::path&)>& write, double time)
  {
    if (!m_error.empty())
      return false;
    std::ostringstream name;
    name << m_name << '_' << std::setw(4) << std::setfill('0') << m_files.size() << ".vtp";
    const std::filesystem::path path = m_folder / name.str();
    if (!write(path)) {
      m_error = "cannot write " + path.string();
      return false;
    }
    m_files.push_back(m_collection + "/" + name.str());
    m_times.push_back(time);
    return true;
  }

  /// Writes `out`/`name`_`what`.pvd listing the time steps written (beside it first, then
  /// renamed over it).
  bool write_pvd()
  {
    if (!m_error.empty())
      return false;
    const std::string pvd = (m_out / (m_collection + ".pvd")).string();
    std::string reason;
    const bool written = write_stream_then_rename(pvd, reason, [&](std::ostream& os) {
      os.precision(17);
      os << "<?xml version=\"1.0\"?>\n"
         << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
      for (std::size_t i = 0; i < m_files.size(); ++i)
        os << "    <DataSet timestep=\"" << m_times[i] << "\" group=\"\" part=\"0\" file=\"" << m_files[i]
           << "\"/>\n";
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
  std::string m_name, m_collection;
  std::filesystem::path m_folder;
  std::vector<std::string> m_files;
  std::vector<double> m_times;
  std::string m_error;
};

} // namespace fas_demo

#endif // FAS_DEMO_SURFACE_COLLECTION_H
