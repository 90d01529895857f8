#include "DeflateCompressor.h"

#include <libdeflate.h>

#include <algorithm>

namespace slicemesh
{
namespace
{
/** libdeflate's level 2: measured on a 260,000-triangle mesh, files 1% smaller than zlib's level 1
 *  in 0.5 of its time (level 1: 8% larger files for 0.35). */
constexpr int deflateLevel = 2;
} // namespace

DeflateCompressor* DeflateCompressor::New()
{
  auto* compressor = new DeflateCompressor;
  compressor->InitializeObjectBase();
  return compressor;
}

DeflateCompressor::~DeflateCompressor()
{
  if (compressor)
    libdeflate_free_compressor(compressor);
}

libdeflate_compressor* DeflateCompressor::deflater()
{
  if (!compressor)
    compressor = libdeflate_alloc_compressor(deflateLevel);
  return compressor;
}

size_t DeflateCompressor::GetMaximumCompressionSpace(size_t size)
{
  const size_t zlibBound = vtkZLibDataCompressor::GetMaximumCompressionSpace(size);
  return deflater() ? std::max(zlibBound, libdeflate_zlib_compress_bound(deflater(), size)) : zlibBound;
}

size_t DeflateCompressor::CompressBuffer(unsigned char const* uncompressedData, size_t uncompressedSize,
                                         unsigned char* compressedBuffer, size_t compressionSpace)
{
  if (!deflater())
    return 0; // VTK's writer takes 0 for a failed block and reports the error
  return libdeflate_zlib_compress(deflater(), uncompressedData, uncompressedSize, compressedBuffer, compressionSpace);
}

} // namespace slicemesh
