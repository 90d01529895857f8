// The line that says a mesh encloses more than 5% more or less than it should: of a label map's
// structure, than its voxels; of an ROI, than its contours' slabs (there are no voxels).
#include "PipelineStructures.h"

#include <gtest/gtest.h>

using namespace slicemesh::cli;

namespace
{

Structure structureOf(int label, const std::string& name, double volume, double target)
{
  Structure s;
  s.report.label = label;
  s.report.name = name;
  s.report.validation.volume = volume;
  s.report.quality.targetVolume = target;
  return s;
}

} // namespace

TEST(VolumeShortfall, ALabelFallsShortOfItsVoxelsAnROIOfItsContours)
{
  const std::vector<Structure> one{ structureOf(1, "Sliver", 123.7, 137.5) };
  ASSERT_TRUE(volumeShortfall(one[0].report));
  EXPECT_EQ(volumeShortfallWarning(one, { 0 }, "ROI", true),
            "the mesh encloses 123.7 mm^3, 10% less than the 137.5 mm^3 of its contours' slabs");
  EXPECT_EQ(volumeShortfallWarning(one, { 0 }, "label", false), "the mesh encloses 123.7 mm^3, 10% less than the 137.5 mm^3 of its voxels");

  const std::vector<Structure> two{ structureOf(3, "Body", 1000.0, 1001.0), structureOf(4, "Speck", 0.3, 1.0) };
  EXPECT_FALSE(volumeShortfall(two[0].report));
  const std::string rois = volumeShortfallWarning(two, { 1 }, "ROI", true);
  EXPECT_EQ(rois.rfind("1 of the 2 meshes enclose more than 5% more or less than their contours; the first, ROI 4 (Speck), "
                       "encloses 0.3 mm^3, 70% less than the 1.0 mm^3 of its contours' slabs",
                       0),
            0u)
    << rois;
  EXPECT_EQ(volumeShortfallWarning(two, { 1 }, "label", false).find("contours"), std::string::npos);
}
