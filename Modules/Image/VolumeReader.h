// Reads a 3D image (NIfTI, NRRD, MetaImage, DICOM series directory) with ITK.
#ifndef VolumeReader_h
#define VolumeReader_h

#include "itkImage.h"

#include <string>

namespace slicemesh
{

using ScalarVolume = itk::Image<float, 3>;
using MaskVolume = itk::Image<unsigned char, 3>;

/** Reads a volume as float voxels. A directory is read as a DICOM series (the first series found).
 *  Throws slicemesh::Error with a one-line message on a missing, unreadable or non-3D input. */
ScalarVolume::Pointer readVolume(const std::string& path);

} // namespace slicemesh

#endif
