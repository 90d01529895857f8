// The intensity histogram Otsu's thresholds are computed on, of the finite voxels only.
#ifndef FiniteHistogram_h
#define FiniteHistogram_h

#include "VolumeReader.h"

#include "itkScalarImageToHistogramGenerator.h"

#include <optional>
#include <utility>

namespace slicemesh
{

using IntensityHistogram = itk::Statistics::ScalarImageToHistogramGenerator<ScalarVolume>::HistogramType;

/** The smallest and largest finite voxel values; nothing when no voxel is finite. */
std::optional<std::pair<float, float>> finiteIntensityRange(const ScalarVolume* volume);

/** `bins` equal bins from the smallest finite voxel value to a hundredth of a bin above the largest,
 *  each finite voxel counted, as ITK's ScalarImageToHistogramGenerator makes them for a volume
 *  without NaN or infinity (the same thresholds then). NaN and infinities are left out: ITK's
 *  generator takes its bounds from every voxel, and one NaN voxel made every threshold NaN.
 *  Throws slicemesh::Error when no voxel is finite. */
IntensityHistogram::Pointer finiteIntensityHistogram(const ScalarVolume* volume, unsigned int bins);

} // namespace slicemesh

#endif
