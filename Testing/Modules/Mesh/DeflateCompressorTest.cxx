// The .vtp writer's compressor: a block that barely compresses (random low bits, as a smoothed
// surface's coordinates have) is stored, one that compresses (a mesh's connectivity) is compressed,
// and VTK's own zlib compressor inflates both back exactly.
#include "DeflateCompressor.h"

#include <gtest/gtest.h>

#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkZLibDataCompressor.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

namespace slicemesh
{
namespace
{

struct Compressed
{
  std::vector<unsigned char> bytes;
  /** The first DEFLATE block's type (after the 2-byte zlib header): 0 stored, 1 fixed, 2 dynamic. */
  int firstBlockType() const { return bytes.size() > 2 ? (bytes[2] >> 1) & 3 : -1; }
};

Compressed compress(const std::vector<unsigned char>& data)
{
  vtkSmartPointer<DeflateCompressor> compressor = vtkSmartPointer<DeflateCompressor>::Take(DeflateCompressor::New());
  Compressed out;
  out.bytes.resize(compressor->GetMaximumCompressionSpace(data.size()));
  out.bytes.resize(compressor->Compress(data.data(), data.size(), out.bytes.data(), out.bytes.size()));
  return out;
}

std::vector<unsigned char> inflatedByVtk(const Compressed& compressed, std::size_t size)
{
  vtkNew<vtkZLibDataCompressor> zlib;
  std::vector<unsigned char> out(size);
  out.resize(zlib->Uncompress(compressed.bytes.data(), compressed.bytes.size(), out.data(), out.size()));
  return out;
}

} // namespace

TEST(DeflateCompressor, StoresABlockThatBarelyCompressesAndCompressesOneThatDoes)
{
  constexpr std::size_t blockSize = 32768; // VTK's XML writers' block
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> coordinate(-250.0, 250.0);
  std::vector<unsigned char> coordinates(blockSize);
  for (std::size_t at = 0; at < blockSize; at += sizeof(double))
  {
    const double value = coordinate(random);
    std::memcpy(coordinates.data() + at, &value, sizeof value);
  }
  std::vector<unsigned char> connectivity(blockSize);
  for (std::size_t at = 0, n = 0; at < blockSize; at += sizeof(std::int32_t), ++n)
  {
    const std::int32_t corner = static_cast<std::int32_t>(n / 3 + n % 3);
    std::memcpy(connectivity.data() + at, &corner, sizeof corner);
  }

  const Compressed stored = compress(coordinates);
  ASSERT_FALSE(stored.bytes.empty());
  EXPECT_EQ(stored.bytes[0], 0x78) << "a zlib stream";
  EXPECT_EQ(stored.firstBlockType(), 0) << "random coordinates are stored";
  EXPECT_LE(stored.bytes.size(), blockSize + 16) << "storing adds a few bytes";
  EXPECT_EQ(inflatedByVtk(stored, blockSize), coordinates);

  const Compressed deflated = compress(connectivity);
  ASSERT_FALSE(deflated.bytes.empty());
  EXPECT_NE(deflated.firstBlockType(), 0) << "the connectivity is compressed";
  EXPECT_LT(deflated.bytes.size(), blockSize / 4);
  EXPECT_EQ(inflatedByVtk(deflated, blockSize), connectivity);
}

} // namespace slicemesh
