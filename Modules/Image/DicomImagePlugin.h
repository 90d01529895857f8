// DICOM images - series of slices through ITK's GDCM reader, segmentation objects (SEG) through
// DCMTK's dcmseg - live in the plugin SliceMeshImageDicom (Modules/Plugins): only a run that reads
// DICOM loads GDCM and DCMTK.
#ifndef DicomImagePlugin_h
#define DicomImagePlugin_h

#include "SegmentationFile.h"
#include "VolumeReader.h"

#include <cstddef>
#include <string>

namespace slicemesh
{

/** What the plugin does, as its table of functions. Each throws slicemesh::Error (or, reading
 *  voxels, itk::ExceptionObject) on failure. */
struct DicomImageFunctions
{
  std::size_t size; ///< sizeof(DicomImageFunctions) as the plugin was built (pluginFunctions)
  /** The largest image series in the folder (an export holds one-file objects beside it: a
   *  structure set, a localizer), its slices ordered by position; `voxels` false: the image
   *  information only (spacing, direction, size), no voxels read. */
  ScalarVolume::Pointer (*readSeries)(const std::string& folder, bool voxels);
  /** Whether the DICOM file (Part 10) is a segmentation object (Modality SEG). */
  bool (*isSegmentation)(const std::string& path);
  /** A DICOM SEG file, as readDicomSegmentation (SegmentationFile.h) describes. */
  SegmentationFile (*readSegmentation)(const std::string& path);
};

/** The plugin's functions, the plugin loaded on first use (which also lets ITK read a single DICOM
 *  image file: the plugin registers ITK's GDCM reader). Throws slicemesh::Error when the plugin
 *  cannot be loaded. */
const DicomImageFunctions& dicomImageFunctions();

} // namespace slicemesh

#endif
