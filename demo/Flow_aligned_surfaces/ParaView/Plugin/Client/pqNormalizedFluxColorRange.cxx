#include "pqNormalizedFluxColorRange.h"

#include <pqApplicationCore.h>
#include <pqDataRepresentation.h>
#include <pqServerManagerModel.h>
#include <QPointer>
#include <QTimer>
#include <vtkSMPropertyHelper.h>
#include <vtkSMProxy.h>
#include <vtkSMTransferFunctionManager.h>
#include <vtkSMTransferFunctionProxy.h>

#include <algorithm>
#include <cstring>

namespace {

// The array whose colour map is fixed: the per-face normalized flux of every filter's output.
constexpr const char* flux_array_name = "normalized_flux";

bool colours_by_normalized_flux(vtkSMProxy* representation)
{
  vtkSMPropertyHelper colour_array(representation, "ColorArrayName", /*quiet=*/true);
  const char* name = colour_array.GetInputArrayNameToProcess();
  return name != nullptr && std::strcmp(name, flux_array_name) == 0;
}

} // namespace

pqNormalizedFluxColorRange::pqNormalizedFluxColorRange(QObject* parent)
  : QObject(parent)
{
}

pqNormalizedFluxColorRange::~pqNormalizedFluxColorRange() = default;

void pqNormalizedFluxColorRange::startup()
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  connect(model, &pqServerManagerModel::representationAdded, this,
    &pqNormalizedFluxColorRange::watch);
  // A state loaded before the plugin, or the plugin loaded after data was shown.
  for (pqDataRepresentation* representation : model->findItems<pqDataRepresentation*>())
    watch(representation);
}

void pqNormalizedFluxColorRange::shutdown()
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  disconnect(model, nullptr, this, nullptr);
  for (pqDataRepresentation* representation : model->findItems<pqDataRepresentation*>())
    disconnect(representation, nullptr, this, nullptr);
}

void pqNormalizedFluxColorRange::watch(pqRepresentation* representation)
{
  auto* data = qobject_cast<pqDataRepresentation*>(representation);
  if (data == nullptr)
    return;
  // Emitted when the representation gets a colour map: on Show, and when the user (or a
  // script's ColorBy) picks another array.
  connect(data, &pqDataRepresentation::colorTransferFunctionModified, this,
    &pqNormalizedFluxColorRange::onColorMapChanged);
  fix_range_later(data);
}

void pqNormalizedFluxColorRange::onColorMapChanged()
{
  fix_range_later(qobject_cast<pqDataRepresentation*>(sender()));
}

void pqNormalizedFluxColorRange::fix_range_later(pqDataRepresentation* representation)
{
  // The colour map is assigned in the middle of Apply (or of a script's ColorBy), which then
  // rescales it to the data; the range is set once that is over, when the GUI's event loop runs.
  QPointer<pqDataRepresentation> watched(representation);
  QTimer::singleShot(0, this, [this, watched]() {
    if (watched)
      fix_range_of_flux_colour_map(watched);
  });
}

void pqNormalizedFluxColorRange::fix_range_of_flux_colour_map(pqDataRepresentation* data)
{
  if (data == nullptr || !colours_by_normalized_flux(data->getProxy()))
    return;
  vtkSMProxy* colour_map = data->getLookupTableProxy();
  if (colour_map == nullptr)
    return;
  auto gone = [](const vtkWeakPointer<vtkSMProxy>& map) { return map.GetPointer() == nullptr; };
  fixed_maps_.erase(std::remove_if(fixed_maps_.begin(), fixed_maps_.end(), gone), fixed_maps_.end());
  auto same = [colour_map](const vtkWeakPointer<vtkSMProxy>& map) {
    return map.GetPointer() == colour_map;
  };
  if (std::any_of(fixed_maps_.begin(), fixed_maps_.end(), same))
    return;
  fixed_maps_.emplace_back(colour_map);

  vtkSMPropertyHelper(colour_map, "AutomaticRescaleRangeMode")
    .Set(vtkSMTransferFunctionManager::NEVER);
  vtkSMTransferFunctionProxy::RescaleTransferFunction(colour_map, 0.0, 1.0);
  if (vtkSMProxy* opacity =
        vtkSMPropertyHelper(colour_map, "ScalarOpacityFunction", /*quiet=*/true).GetAsProxy())
    vtkSMTransferFunctionProxy::RescaleTransferFunction(opacity, 0.0, 1.0);
  colour_map->UpdateVTKObjects();
  data->renderViewEventually();
}
