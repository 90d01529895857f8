#include "Meshing/MeshContours.h"

#include "Contours/ContourResampling.h"
#include "Measures/StackVolume.h"

#include "Core/ParallelFor.h"

#include <future>
#include <memory>
#include <utility>

namespace slicemesh
{
namespace
{

void measure(MeshedContours& meshing, DirichletEnergy tilingEnergy)
{
  MeshMeasures& m = meshing.measures;
  const ContourStack& stack = meshing.stack;
  m.shape = measureMeshQuality(meshing.surface.mesh, meshing.options.threads);
  m.dirichlet = tilingEnergy;
  m.genus = genusOf(meshing.surface.validation);
  m.pointSpacing = meanPointSpacing(stack);
  m.sliceSpacing = stack.sliceSpacing > 0.0 ? stack.sliceSpacing
                   : stack.slices.size() > 1
                     ? (stack.slices.back().z - stack.slices.front().z) / static_cast<double>(stack.slices.size() - 1)
                     : 0.0;
}

} // namespace

const char* meshingStageName(MeshingStage stage)
{
  switch (stage)
  {
    case MeshingStage::Preparation: return "Preparation";
    case MeshingStage::Correspondence: return "Correspondence";
    case MeshingStage::Tiling: return "Tiling";
    case MeshingStage::Validation: return "Validation";
    case MeshingStage::Finishing: break;
  }
  return "Finishing";
}

MeshedContours startMeshing(ContourStack traced, const MeshingOptions& options, const std::array<double, 3>& spacing,
                            double volume)
{
  MeshedContours meshing;
  meshing.options = resolvedMeshingOptions(options, spacing);
  // Voxels and planning systems count a structure's end slices whole: so do caps half a slice beyond.
  if (meshing.options.reconstruction.capPlacement == CapPlacement::HalfSliceBeyond)
  {
    meshing.targetVolume = volume > 0.0 ? volume : prismVolume(traced);
    // A mask's contours are traced on its pixels: their shares are its voxels, not their areas.
    meshing.targetShares = volume > 0.0 ? contourVolumes(traced, { spacing[0], spacing[1] }) : contourVolumes(traced);
  }
  meshing.stack = std::move(traced);
  return meshing;
}

void runMeshingStage(MeshingStage stage, MeshedContours& meshing, const std::function<void(double)>& fraction)
{
  switch (stage)
  {
    case MeshingStage::Preparation:
      meshing.stack = prepareContours(meshing.stack, meshing.options.contours);
      break;
    case MeshingStage::Correspondence:
      // Overlapping contours are matched inside the tiling; this stage joins what only the distance
      // rule matches, and thickens undersampled slabs (a copy of the stack when both are off).
      meshing.stack = insertIntermediateSections(meshing.stack, meshing.options.undersampling, &meshing.sections);
      break;
    case MeshingStage::Tiling:
    {
      ReconstructionOptions options = meshing.options.reconstruction;
      options.threads = meshing.options.threads;
      options.progress = fraction;
      meshing.tiling = reconstructSurface(meshing.stack, options, &meshing.reconstruction);
      if (meshing.tiling.triangles.empty())
        throw Error("the reconstruction produced no triangles");
      break;
    }
    case MeshingStage::Validation:
      // A tiling that is finished is not written as it is: its self-intersections are looked for
      // only in what of it is kept (finishSurface). The test costs as much as the rest of the
      // validation many times over.
      meshing.tilingValidation = meshing.options.finishing.finish == SurfaceFinish::Tiled ? validateMesh(meshing.tiling)
                                                                                        : validateMeshTopology(meshing.tiling);
      break;
    case MeshingStage::Finishing:
    {
      // The tiling's Dirichlet energy (a measure for the report: one sort of every edge) is taken
      // beside the finishing, whose steps on one thread leave the other cores idle; on one thread
      // when only one is asked.
      std::future<DirichletEnergy> tilingEnergy =
        std::async(threadCount(meshing.options.threads) > 1 ? std::launch::async : std::launch::deferred,
                   [&meshing] { return measureDirichletEnergy(meshing.tiling, meshing.stack); });
      // Drawn contours are the anatomy: the finished surface passes through the contours it was tiled
      // from (held for the finishing only: the stack outlives it).
      SurfaceFinishingOptions finishing = meshing.options.finishing;
      if (meshing.options.holdContours)
        finishing.heldContours = std::shared_ptr<const ContourStack>(std::shared_ptr<void>(), &meshing.stack);
      meshing.surface =
        finishSurface(meshing.tiling, meshing.tilingValidation, finishing, meshing.options.threads,
                      meshing.sections.sectionsInserted == 0 ? meshing.targetVolume : 0.0, meshing.targetShares);
      measure(meshing, tilingEnergy.get());
      break;
    }
  }
}

MeshedContours meshContours(const ContourStack& traced, const MeshingOptions& options,
                            const std::array<double, 3>& spacing,
                            const std::function<void(MeshingStage, double)>& progress)
{
  MeshedContours meshing = startMeshing(traced, options, spacing);
  runMeshingStages(meshing, progress);
  return meshing;
}

void runMeshingStages(MeshedContours& meshing, const std::function<void(MeshingStage, double)>& progress)
{
  for (MeshingStage stage : { MeshingStage::Preparation, MeshingStage::Correspondence, MeshingStage::Tiling,
                              MeshingStage::Validation, MeshingStage::Finishing })
  {
    std::function<void(double)> fraction;
    if (progress)
      fraction = [&progress, stage](double f) { progress(stage, f); };
    runMeshingStage(stage, meshing, fraction);
  }
}

} // namespace slicemesh
