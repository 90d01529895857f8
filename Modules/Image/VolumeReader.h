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

/** Throws slicemesh::Error naming `path` unless the volume's spacing is positive and finite and its
 *  direction matrix finite and invertible: a mesh cannot be placed otherwise. */
void checkVolumeGeometry(const std::string& path, const itk::ImageBase<3>* volume);

} // namespace slicemesh

#endif
