// Reads a 3D image (NIfTI, NRRD, MetaImage, DICOM series directory) with ITK.
#ifndef VolumeReader_h
#define VolumeReader_h

#include "itkImage.h"

#include <array>

#include <string>

namespace slicemesh
{

using ScalarVolume = itk::Image<float, 3>;
using MaskVolume = itk::Image<unsigned char, 3>;

/** Reads a volume as float voxels. A directory is read as a DICOM series (the first series found).
 *  Throws slicemesh::Error with a one-line message on a missing, unreadable or non-3D input. */
ScalarVolume::Pointer readVolume(const std::string& path);

/** Where a volume's slices lie, from its header alone: what contours drawn on it are stacked by. */
struct VolumeGeometry
{
  std::array<double, 3> spacing{ 1.0, 1.0, 1.0 };
  /** Columns: the directions of the voxel axes in LPS; the third is the slice direction. */
  std::array<std::array<double, 3>, 3> direction{ { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } } };
  std::array<double, 3> sliceDirection() const { return { direction[0][2], direction[1][2], direction[2][2] }; }
};

/** The geometry of the volume at `path` (a file, or a DICOM series directory) without reading its
 *  voxels. Throws slicemesh::Error with a one-line message as readVolume does. */
VolumeGeometry readVolumeGeometry(const std::string& path);

/** Throws slicemesh::Error naming `path` unless the volume's spacing is positive and finite and its
 *  direction matrix finite and invertible: a mesh cannot be placed otherwise. */
void checkVolumeGeometry(const std::string& path, const itk::ImageBase<3>* volume);

} // namespace slicemesh

#endif
