#include "PhantomStructureSet.h"

#include "StructureSetWriter.h"

namespace slicemesh
{

void writePhantomStructureSet(const std::string& path, const std::vector<std::vector<Point3>>& contours)
{
  PlanarStructure roi;
  roi.number = 1;
  roi.name = "Phantom";
  roi.contours = contours;
  writeRTStructureSet(path, { roi });
}

} // namespace slicemesh
