// The two orientations a NIfTI-1 header can carry (qform and sform), and whether they disagree.
#ifndef NiftiOrientation_h
#define NiftiOrientation_h

#include "itkImageBase.h"

#include <array>
#include <optional>
#include <string>

namespace slicemesh
{

using Affine3x4 = std::array<std::array<double, 4>, 3>;

struct NiftiOrientation
{
  int qformCode = 0;
  int sformCode = 0;
  Affine3x4 qform{}; ///< voxel index -> RAS mm, NIfTI "method 2" (quaternion, pixdim, qoffset)
  Affine3x4 sform{}; ///< voxel index -> RAS mm, NIfTI "method 3" (srow_x/y/z)
};

/** The orientations of a NIfTI-1 file's header (readNifti1Header); nothing for other files or a
 *  header that cannot be read. */
std::optional<NiftiOrientation> readNiftiOrientation(const std::string& path);

/** When both forms are set (code > 0) and map some corner voxel more than `toleranceMm` apart, a
 *  one-line warning that says so and which of the two the volume as read follows. SliceMesh takes
 *  the geometry ITK's NIfTI reader gives (3D Slicer reads NIfTI through ITK too); `volume` is that
 *  volume (LPS), compared with both forms (RAS) to name the one in use. Nothing when they agree. */
std::optional<std::string> niftiOrientationWarning(const std::string& path, const itk::ImageBase<3>* volume,
                                                   double toleranceMm = 0.1);

} // namespace slicemesh

#endif
