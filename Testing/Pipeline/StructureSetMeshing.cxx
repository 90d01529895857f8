#include "StructureSetMeshing.h"

#include "MeshReader.h"
#include "SliceMeshPipeline.h"
#include "StructureSetWriter.h"

#include <filesystem>

namespace slicemesh::testing
{

TriangleMesh meshAsStructureSet(const std::vector<std::vector<Point3>>& contours, const std::string& folder,
                                bool holdContours)
{
  const std::filesystem::path path(folder);
  PlanarStructure roi;
  roi.number = 1;
  roi.name = "Phantom";
  roi.contours = contours;
  writeRTStructureSet((path / "RS.dcm").string(), { roi });

  cli::PipelineSettings settings;
  settings.contours.path = (path / "RS.dcm").string();
  settings.outputModel = (path / "mesh.vtp").string();
  settings.meshing.holdContours = holdContours;
  cli::ProgressReporter silent(cli::pipelineStages(), nullptr, nullptr);
  std::vector<cli::LabelReport> rois;
  cli::runPipeline(settings, silent, &rois);
  // A failed ROI does not fail a run of several: its report says so.
  if (rois.size() != 1 || !rois.front().meshed())
    throw Error("the ROI was not meshed: " + (rois.empty() ? std::string("no report") : rois.front().error));
  return readMesh(settings.outputModel).mesh;
}

} // namespace slicemesh::testing
