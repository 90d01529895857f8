// Reads a 3D image (NIfTI, NRRD, MetaImage, DICOM series directory) with ITK.
#ifndef VolumeReader_h
#define VolumeReader_h

#include "itkImage.h"
#include "itkVector.h"

#include <array>
#include <cstdint>
#include <string>
#include <variant>

namespace slicemesh
{

using ScalarVolume = itk::Image<float, 3>;
using MaskVolume = itk::Image<unsigned char, 3>;

/** A volume in the pixel type its file stores, so that a label map of bytes takes one byte a voxel
 *  in memory, not the four of float (on a large label map, the largest share of a run's peak).
 *  Integers of one to four bytes as stored (label maps: NRRD's uchar, NIfTI's uint8 and int16,
 *  Slicer's short; four bytes for atlases whose labels pass float's 2^24, which float would merge);
 *  anything else (wider integers, floating point) as float. */
using StoredVolume =
  std::variant<ScalarVolume::Pointer, itk::Image<std::uint8_t, 3>::Pointer, itk::Image<std::int8_t, 3>::Pointer,
               itk::Image<std::uint16_t, 3>::Pointer, itk::Image<std::int16_t, 3>::Pointer,
               itk::Image<std::uint32_t, 3>::Pointer, itk::Image<std::int32_t, 3>::Pointer>;

/** The key of a DICOM series' metadata under which a folder of several series says which one was
 *  read (a line for the user); absent when the folder holds one. */
constexpr const char* seriesChoiceKey = "SliceMesh.SeriesChoice";

/** Reads a volume as float voxels. A directory is read as a DICOM series (the first series found).
 *  Throws slicemesh::Error with a one-line message on a missing, unreadable or non-3D input. */
ScalarVolume::Pointer readVolume(const std::string& path);

/** Reads a volume in the pixel type of its file (StoredVolume), with readVolume's checks and errors.
 *  A DICOM series is read as float. The voxel values are those readVolume gives. */
StoredVolume readStoredVolume(const std::string& path);

/** Where a volume's slices lie, from its header alone: what contours drawn on it are stacked by. */
struct VolumeGeometry
{
  std::array<double, 3> spacing{ 1.0, 1.0, 1.0 };
  /** The first voxel's centre (LPS mm). */
  std::array<double, 3> origin{ 0.0, 0.0, 0.0 };
  /** Columns: the directions of the voxel axes in LPS; the third is the slice direction. */
  std::array<std::array<double, 3>, 3> direction{ { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } } };
  /** Column `k` of direction: where voxel axis k points. */
  itk::Vector<double, 3> axis(int k) const;
  itk::Vector<double, 3> sliceDirection() const { return axis(2); }
  /** The unit normal of the slices' planes, on the side the slices go: the slice direction, unless
   *  the grid is sheared (a gantry-tilted CT, whose slices step sideways as they go). */
  itk::Vector<double, 3> sliceNormal() const;
  /** The distance between the slices' planes along sliceNormal (spacing[2] unless sheared). */
  double sliceDistance() const;
  /** A DICOM image's Frame of Reference UID (0020,0052); empty for other formats or when absent. */
  std::string frameOfReference;
};

/** The geometry of the volume at `path` (a file, or a DICOM series directory) without reading its
 *  voxels. Throws slicemesh::Error with a one-line message as readVolume does. */
VolumeGeometry readVolumeGeometry(const std::string& path);

/** Throws slicemesh::Error naming `path` unless the volume's spacing is positive and finite and its
 *  direction matrix finite and invertible: a mesh cannot be placed otherwise. */
void checkVolumeGeometry(const std::string& path, const itk::ImageBase<3>* volume);

} // namespace slicemesh

#endif
