// The functions of the plugin SliceMeshImageDicom, as its entry puts them in its table
// (DicomImagePlugin.h). Only the plugin's own files use this header: the rest of SliceMesh goes
// through dicomImageFunctions(), so that it does not link GDCM and DCMTK.
#ifndef DicomImageReaders_h
#define DicomImageReaders_h

#include "SegmentationFile.h"
#include "VolumeReader.h"

#include <string>

namespace slicemesh
{

ScalarVolume::Pointer readDicomSeriesIn(const std::string& folder, bool voxels); // DicomSeriesReader.cxx
bool isDicomSegmentation(const std::string& path);                               // DicomSegmentationReader.cxx
SegmentationFile readDicomSegmentationFile(const std::string& path);             // DicomSegmentationReader.cxx

} // namespace slicemesh

#endif
