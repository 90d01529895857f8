// Turns a label map or a grayscale volume into a binary mask (1 inside, 0 outside).
#ifndef VolumeSegmentation_h
#define VolumeSegmentation_h

#include "GrayscaleSegmentation.h"
#include "MaskRefinement.h"
#include "VolumeReader.h"

#include <optional>
#include <string>

namespace slicemesh
{

enum class InputKind
{
  Automatic, ///< a label map when every voxel is a whole number >= 0 (at most 65535 values), else grayscale
  LabelMap,
  Grayscale
};

struct SegmentationOptions
{
  InputKind kind = InputKind::Automatic;
  /** Label map: the label to mesh; empty means every non-zero voxel. */
  std::optional<int> label;
  /** Grayscale: voxels >= threshold are inside; empty means Otsu's threshold. */
  std::optional<double> threshold;
  /** Grayscale: denoising, intensity window, several Otsu thresholds, Canny edge mode. Used when
   *  it asks for more than the plain threshold above (then its own method decides; `threshold`
   *  still sets the Manual one). */
  GrayscaleSegmentationOptions grayscale;
  /** Either kind, after the mask is made: small-region removal, seeds, hole filling. */
  MaskRefinementOptions refinement;
};

/** The option that asks for a grayscale segmentation ("--thresholdMethod Manual", "--gaussianSigma"),
 *  empty when none does. With InputKind::Automatic such a request makes the volume grayscale
 *  whatever its voxels (an MR's whole non-negative intensities look like labels); beside
 *  InputKind::LabelMap it has no effect. */
std::string grayscaleRequest(const SegmentationOptions& options);

/** Throws slicemesh::Error when the mask would be empty (naming the labels that do occur). With
 *  InputKind::Automatic, `automaticChoice` (when given) receives one line saying which kind was
 *  chosen from the voxels and why ("input kind Grayscale, chosen from the voxels: a voxel is
 *  negative (-1) ..."), for the user to pass --inputKind when it is not what they meant. */
MaskVolume::Pointer segmentVolume(const ScalarVolume* volume, const SegmentationOptions& options,
                                  std::string* automaticChoice = nullptr);

/** segmentVolume on a volume in the pixel type its file stores (readStoredVolume), with the same
 *  mask. Taken by value: integers segmented as grayscale are widened to float and then released,
 *  so that both are held only while widening, as when the file is read as float. */
MaskVolume::Pointer segmentStoredVolume(StoredVolume volume, const SegmentationOptions& options,
                                        std::string* automaticChoice = nullptr);

} // namespace slicemesh

#endif
