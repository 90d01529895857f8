// The voxel data an uncompressed NRRD or MetaImage file holds, measured on disk before a voxel is
// read: ITK allocates the whole volume a header claims before it finds the data short (a 308-byte
// NRRD claiming 1000^3 bytes took 985 MiB to say so).
#ifndef RawVoxelBytes_h
#define RawVoxelBytes_h

#include "itkImageIOBase.h"

#include <string>

namespace slicemesh
{

/** Throws slicemesh::Error ("<path>: the file holds N bytes of voxel data where its header claims
 *  M ...") when the NRRD (.nrrd, .nhdr) or MetaImage (.mha, .mhd) file at `path`, whose header `io`
 *  has read, stores its voxels uncompressed in binary (NRRD's raw encoding; MetaImage's BinaryData
 *  without CompressedData) in one file that holds fewer bytes than the header's sizes and voxel
 *  type need. The bytes held are the data file's size less the header and the bytes it says to
 *  skip (an upper bound: lines to skip are not counted). Compressed and text encodings, data in
 *  several files and other formats are not checked: their size on disk says nothing cheaply. */
void checkRawVoxelBytes(const std::string& path, const itk::ImageIOBase* io);

} // namespace slicemesh

#endif
