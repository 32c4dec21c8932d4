// Copyright (c) 2026 The Flow_aligned_surfaces developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The steps of a ParaView data collection (.pvd), parsed without VTK: the `<DataSet>` elements
// of its `<Collection>`, each a time and a file (relative to the folder of the .pvd file unless
// absolute), sorted by time, distinct times required.

#ifndef CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_PVD_STEPS_H
#define CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_PVD_STEPS_H

#include <CGAL/Flow_aligned_surfaces/IO/VTK_XML/VTK_XML_data_set.h>
#include <CGAL/Flow_aligned_surfaces/IO/VTK_XML/XML_document.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/read_file.h>
#include <CGAL/Flow_aligned_surfaces/IO/internal/text_cursor.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Flow_aligned_surfaces {
namespace IO {
namespace internal {

/// A step of a .pvd file: its time, its file and the byte of its DataSet element.
struct PVD_step {
  double time;
  std::string file;
  std::size_t byte;
};

inline PVD_step read_PVD_step(const XML_document& doc, const XML_element& e, std::size_t index,
                              const std::filesystem::path& folder)
{
  const std::string where = "DataSet element " + std::to_string(index) + ": ";
  const std::string* timestep = e.attribute("timestep");
  const std::string* file = e.attribute("file");
  if (timestep == nullptr)
    doc.fail_at(e.byte, where + "no timestep attribute");
  if (file == nullptr || file->empty())
    doc.fail_at(e.byte, where + "no file attribute");
  double t = 0;
  Text_cursor c(std::string(), doc.file(), *timestep);
  const std::string_view token = c.token();
  if (!Text_cursor::parse_number(token, t) || !std::isfinite(t) || !c.token().empty())
    doc.fail_at(e.byte, where + "the timestep '" + printable(*timestep) + "' is not a finite number");
  std::filesystem::path path(*file);
  if (path.is_relative())
    path = folder / path;
  return PVD_step{t, path.string(), e.byte};
}

/// The steps of the .pvd file `file`, sorted by time; `reader` names the messages.
inline std::vector<PVD_step> read_PVD_steps(const std::string& reader, const std::string& file)
{
  check_readable(reader, file);
  const File_contents contents(file, reader);
  const XML_document doc(reader, file, contents.view());
  const XML_element& root = doc.root();
  const std::string* type = root.attribute("type");
  if (root.name != "VTKFile" || type == nullptr || *type != "Collection")
    doc.fail_file("the root element is <" + root.name + " type=\"" + (type ? printable(*type) : std::string()) +
                  "\">; a ParaView data collection has <VTKFile type=\"Collection\">");
  const XML_element* collection = doc.child(root, "Collection");
  if (collection == nullptr)
    doc.fail_element(root, "the VTKFile element has no <Collection> element");
  const std::filesystem::path folder = std::filesystem::path(file).parent_path();
  std::vector<PVD_step> steps;
  for (std::size_t c : collection->children)
    if (doc.elements[c].name == "DataSet")
      steps.push_back(read_PVD_step(doc, doc.elements[c], steps.size(), folder));
  if (steps.empty())
    doc.fail_element(*collection, "the Collection holds no DataSet element");
  std::stable_sort(steps.begin(), steps.end(), [](const PVD_step& a, const PVD_step& b) { return a.time < b.time; });
  for (std::size_t i = 1; i < steps.size(); ++i)
    if (steps[i - 1].time == steps[i].time)
      doc.fail_file("the DataSet elements at bytes " + std::to_string(steps[i - 1].byte) + " (file " +
                    steps[i - 1].file + ") and " + std::to_string(steps[i].byte) + " (file " + steps[i].file +
                    ") have the same timestep " + number_string(steps[i].time) +
                    "; expected distinct times (several parts per step are not supported)");
  return steps;
}

} // namespace internal
} // namespace IO
} // namespace Flow_aligned_surfaces
} // namespace CGAL

#endif // CGAL_FLOW_ALIGNED_SURFACES_IO_VTK_XML_PVD_STEPS_H
