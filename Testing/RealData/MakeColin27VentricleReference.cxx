// Derives the reference mask of Colin27's lateral ventricles (Testing/Data/colin27-ventricles-reference.nii.gz),
// run once and committed: the 6-connected 3D region of the raw T1 (ch2.nii.gz, no smoothing) with
// intensities in [0, 45] holding the seed LPS (5, -5, 15) mm (RAS/MNI (-5, 5, 15), the left frontal horn), its
// enclosed holes filled in 3D. The test segments the same structure differently (per slice, smoothed, seed followed
// from slice to slice, holes filled per slice, specks removed) and compares.
//   make MakeColin27VentricleReference && ./MakeColin27VentricleReference <out.nii.gz>
#include "VolumeSegmentation.h"

#include "itkImageFileWriter.h"

#include <iostream>

int main(int argc, char* argv[])
{
  using namespace slicemesh;
  if (argc != 2)
  {
    std::cerr << "usage: MakeColin27VentricleReference <out.nii.gz>" << std::endl;
    return 2;
  }
  const ScalarVolume::Pointer t1 = readVolume("/usr/share/mricron/templates/ch2.nii.gz");
  SegmentationOptions options;
  options.kind = InputKind::Grayscale;
  options.grayscale.method = ThresholdMethod::Window;
  options.grayscale.lower = 0.0;
  options.grayscale.upper = 45.0;
  options.grayscale.dimension = ProcessingDimension::Volume3D;
  options.refinement.dimension = ProcessingDimension::Volume3D;
  options.refinement.seeds = { { 5.0, -5.0, 15.0 } };
  options.refinement.fillHoles = true;
  const MaskVolume::Pointer mask = segmentVolume(t1, options);
  auto writer = itk::ImageFileWriter<MaskVolume>::New();
  writer->SetInput(mask);
  writer->SetFileName(argv[1]);
  writer->SetUseCompression(true);
  writer->Update();
  return 0;
}
