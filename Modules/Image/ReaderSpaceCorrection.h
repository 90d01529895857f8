// Where ITK 5.2's readers put a file's voxels in two cases they get wrong, and the correction
// SliceMesh applies after them: the volume then lies where the file says, as in 3D Slicer.
#ifndef ReaderSpaceCorrection_h
#define ReaderSpaceCorrection_h

#include "Nifti1Header.h"

#include "itkImageIOBase.h"

#include <array>
#include <optional>
#include <string>

namespace slicemesh
{

/** An affine correction of the reader's geometry, in LPS: origin' = sign * (scale * origin), and
 *  each direction's components multiplied by the same signs. */
struct ReaderSpaceCorrection
{
  std::array<double, 3> sign{ 1.0, 1.0, 1.0 };
  double originScale = 1.0;

  bool needed() const { return sign != std::array<double, 3>{ 1.0, 1.0, 1.0 } || originScale != 1.0; }
  /** The corrected origin, or a direction's corrected components (scaled = false). */
  std::array<double, 3> applied(const std::array<double, 3>& point, bool scaled) const;
};

/** The correction the file at `path` needs, read from its own header:
 *  - a NRRD in left-anterior-superior space: ITK turns it into LPS by negating x (as it would
 *    for right-anterior-superior) where y must be negated, which mirrors the volume left-right
 *    and front-back;
 *  - a NIfTI-1 file whose spatial unit is the metre or the micron: ITK converts its spacing to
 *    millimetres but leaves its origin in the file's unit.
 *  No correction for any other file. `nifti`: the file's NIfTI-1 header (readNifti1Header), if it is one. */
ReaderSpaceCorrection readerSpaceCorrection(const std::string& path, const std::optional<Nifti1Header>& nifti);

/** The header's origin and directions as the file states them: `correction` applied to what ITK's
 *  reader `io` read. */
void correctHeaderSpace(itk::ImageIOBase* io, const ReaderSpaceCorrection& correction);

} // namespace slicemesh

#endif
