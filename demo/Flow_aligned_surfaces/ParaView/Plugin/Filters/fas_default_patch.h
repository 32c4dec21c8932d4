// Where Flow-Aligned Surface puts its patch before the user moves it: where the main job puts
// its patches (feature_placement.h: near the obstacle or the largest vorticity, the normal 30
// degrees off the aligned orientation, so that the first Apply shows a real deformation), with a
// size of a quarter of the data's smallest extent, so that the patch fits in a channel.  Private
// to the plugin.
#ifndef FAS_DEFAULT_PATCH_H
#define FAS_DEFAULT_PATCH_H

#include "fas_paraview_support.h"
#include "feature_placement.h"

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

namespace fas_paraview {

/// A patch pose and size, and one sentence saying why it is there.
struct Default_patch {
  std::array<double, 3> center{}, normal{};
  double size = 0;
  std::string description;
};

/// The default patch in the flow `field` over the box `bounds` (xmin, xmax, ...), for an
/// orthogonal (seeding) or a tangential (stream) surface; nothing when the box is empty or no
/// point of the lattice the placement samples has a flow.
template <class Field>
std::optional<Default_patch> default_patch(const Field& field, const double bounds[6], bool orthogonal)
{
  if (!(bounds[0] < bounds[1] && bounds[2] < bounds[3] && bounds[4] < bounds[5]))
    return std::nullopt;
  const double size = 0.25 * std::min({bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]});
  const CGAL::Bbox_3 box(bounds[0], bounds[2], bounds[4], bounds[1], bounds[3], bounds[5]);
  const auto placed = fas_demo::place_near_feature<Point, Vector>(field, box, size, CGAL_PI / 6);
  if (!placed)
    return std::nullopt;
  const Point& c = orthogonal ? placed->orthogonal_center : placed->tangential_center;
  const Vector& n = orthogonal ? placed->orthogonal_normal : placed->tangential_normal;
  Default_patch patch;
  patch.center = {c.x(), c.y(), c.z()};
  patch.normal = {n.x(), n.y(), n.z()};
  patch.size = size;
  patch.description = placed->description;
  return patch;
}

} // namespace fas_paraview

#endif // FAS_DEFAULT_PATCH_H
