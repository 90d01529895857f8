// Otsu's thresholds (one or several) of a grayscale volume.
#ifndef OtsuThresholds_h
#define OtsuThresholds_h

#include "VolumeReader.h"

#include <vector>

namespace slicemesh
{

/** The `count` thresholds that split the volume's 256-bin histogram (coarser past four thresholds,
 *  so that the exhaustive search ends in seconds) into count + 1 classes with
 *  the largest between-class variance (ITK's OtsuMultipleThresholdsCalculator), in increasing
 *  order. Computed on the whole volume, also when the rest of the segmentation works per slice:
 *  a slice's own histogram (often background only) gives meaningless thresholds. NaN and
 *  infinite voxels are left out (finiteIntensityHistogram).
 *  Throws slicemesh::Error on a volume uniform in its finite voxels, or count 0. */
std::vector<double> otsuThresholds(const ScalarVolume* volume, unsigned int count);

} // namespace slicemesh

#endif
