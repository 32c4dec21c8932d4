// The GUI side of the plugin: the colour map of `normalized_flux` spans [0, 1] and stays there.
//
// The normalized flux is a fraction by definition (0 where the flow is tangential, 1 where it
// crosses the surface), and the iterations that ParaView plays as time steps sweep it from
// nearly 1 on the initial patch to nearly 0.  ParaView's default colour map range follows the
// data at Apply and then stays, so the map set on the initial patch (0.9998 to 1) would show
// every later step in one colour.  This auto-start object, loaded with the plugin by the GUI,
// gives each colour map of an array named `normalized_flux` the range [0, 1] the first time a
// representation uses it, and sets its automatic rescale mode to "Never" — as a user would in
// the colour map editor — so that the range holds through playing and later Applies.  The
// user's later changes to that map are kept.  pvpython and pvbatch have no GUI objects; their
// scripts set the range themselves (the tutorial shows how).
#ifndef pqNormalizedFluxColorRange_h
#define pqNormalizedFluxColorRange_h

#include <QObject>

#include <vtkWeakPointer.h>

#include <vector>

class pqDataRepresentation;
class pqRepresentation;
class vtkSMProxy;

class pqNormalizedFluxColorRange : public QObject
{
  Q_OBJECT

public:
  explicit pqNormalizedFluxColorRange(QObject* parent = nullptr);
  ~pqNormalizedFluxColorRange() override;

  void startup();
  void shutdown();

private Q_SLOTS:
  void watch(pqRepresentation* representation);
  void onColorMapChanged();

private:
  void fix_range_later(pqDataRepresentation* representation);
  void fix_range_of_flux_colour_map(pqDataRepresentation* representation);

  // The colour maps already given [0, 1]: each once, so that a user's own range is not undone.
  std::vector<vtkWeakPointer<vtkSMProxy>> fixed_maps_;
};

#endif
