// Per-slice (or 3D) segmentation of a grayscale volume: denoise, threshold (window, manual, Otsu
// with one or several thresholds), and optionally cut the regions apart along Canny edges.
#ifndef GrayscaleSegmentation_h
#define GrayscaleSegmentation_h

#include "CannyEdges.h"
#include "ImageDenoising.h"

#include <limits>
#include <string>

namespace slicemesh
{

enum class ThresholdMethod
{
  Otsu,   ///< Otsu's threshold(s) on the whole volume; keeps one class
  Manual, ///< voxels >= threshold
  Window  ///< lower <= voxel <= upper
};

enum class RegionMode
{
  Intensity, ///< the thresholded voxels are the regions
  Edges      ///< the thresholded voxels minus the Canny edges: the edges delimit the regions
};

struct GrayscaleSegmentationOptions
{
  /** Per slice (default, as the paper) or in 3D: denoising and edge detection. */
  ProcessingDimension dimension = ProcessingDimension::Slice2D;
  DenoisingOptions denoising; ///< its own dimension is replaced by the one above
  ThresholdMethod method = ThresholdMethod::Otsu;
  double threshold = 0.0; ///< Manual
  double lower = -std::numeric_limits<double>::infinity(); ///< Window (image intensity units)
  double upper = std::numeric_limits<double>::infinity();
  /** Otsu: number of thresholds (1 = the classic two classes). */
  unsigned int otsuThresholds = 1;
  /** Otsu: the class kept, 1 = darkest ... otsuThresholds + 1 = brightest; 0 = the brightest. */
  unsigned int otsuClass = 0;
  RegionMode regions = RegionMode::Intensity;
  CannyOptions canny;

  /** True when these options ask for more than the plain Otsu/manual threshold. */
  bool beyondPlainThreshold() const
  {
    return denoising.any() || method == ThresholdMethod::Window || otsuThresholds != 1 ||
           (otsuClass != 0 && otsuClass != 2) || regions == RegionMode::Edges;
  }
};

struct GrayscaleMask
{
  MaskVolume::Pointer mask;
  /** Edge mode: the voxels inside the intensity criterion that lie on an edge and were cut out of
   *  the mask; refineMask gives back those that border the regions kept. Null otherwise. */
  MaskVolume::Pointer edgeVoxels;
};

/** Throws slicemesh::Error naming the fault when the parameters are inconsistent (lower > upper,
 *  a class beyond the number of thresholds) or the mask is empty. */
GrayscaleMask segmentGrayscale(const ScalarVolume* volume, const GrayscaleSegmentationOptions& options);

/** "the intensities run from 0 to 255": the smallest and largest finite voxel value, for messages
 *  that say a threshold selects nothing. */
std::string intensityRangeText(const ScalarVolume* volume);

} // namespace slicemesh

#endif
