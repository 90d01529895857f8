// Writes a mask or label volume to an image file (format from the extension, compressed).
// Kept apart from the phantom headers on purpose: ITK 5.2's IO headers include ITK's own copy
// of Eigen (itkeigen/, namespace Eigen, version 3.3), which clashes with the system Eigen 3.4
// that the phantoms use when both land in one translation unit.
#ifndef MaskFileWriter_h
#define MaskFileWriter_h

#include "VolumeReader.h"

#include <string>

namespace slicemesh
{

/** Throws slicemesh::Error naming the file when ITK cannot write it. */
void writeMaskFile(const MaskVolume* mask, const std::string& path);

} // namespace slicemesh

#endif
