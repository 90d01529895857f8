// removeSmallComponents: 26-connected components below a volume in mm^3 are cleared.
#include "ReliabilitySupport.h"
#include "SmallComponentRemoval.h"

#include <gtest/gtest.h>

namespace slicemesh::testing
{
namespace
{

std::size_t countSet(const MaskVolume* mask)
{
  std::size_t n = 0;
  const unsigned char* v = mask->GetBufferPointer();
  for (std::size_t i = 0; i < mask->GetBufferedRegion().GetNumberOfPixels(); ++i)
    n += v[i] != 0;
  return n;
}

/** 2744 one-voxel specks around a 6 x 6 x 6 block, 0.5 x 0.5 x 2 mm voxels (0.5 mm^3 each). */
MaskVolume::Pointer specksAndABlock()
{
  return makeMask({ 40, 40, 40 }, { 0.5, 0.5, 2.0 }, [](long i, long j, long k)
                  {
                    const bool block = i >= 16 && i < 22 && j >= 16 && j < 22 && k >= 16 && k < 22;
                    const bool speck = i % 3 == 1 && j % 3 == 1 && k % 3 == 1 && !(i >= 15 && i < 23 && j >= 15 &&
                                                                                    j < 23 && k >= 15 && k < 23);
                    return block || speck;
                  });
}

TEST(SmallComponentRemoval, DropsThousandsOfSpecksAndKeepsTheStructure)
{
  MaskVolume::Pointer mask = specksAndABlock();
  const std::size_t before = countSet(mask);
  const SmallComponentRemoval removal = removeSmallComponents(mask, 1.0); // mm^3: two voxels
  EXPECT_EQ(removal.components, removal.removedComponents + 1);
  EXPECT_GT(removal.removedComponents, 2000u);
  EXPECT_DOUBLE_EQ(removal.largestComponentVolume, 216 * 0.5);
  EXPECT_EQ(countSet(mask), 216u);
  EXPECT_EQ(before - countSet(mask), removal.removedVoxels);

  const MaskMeshResult result = checkedMesh(mask);
  EXPECT_EQ(result.problem(), "");
  EXPECT_EQ(result.validation.components, 1u);
}

TEST(SmallComponentRemoval, VoxelsTouchingAtEdgesOrCornersAreOneComponent)
{
  // Four voxels in a diagonal line across slices: 26-connected, 4 voxels = 4 mm^3, kept at 3 mm^3.
  MaskVolume::Pointer mask = makeMask({ 6, 6, 6 }, { 1, 1, 1 }, [](long i, long j, long k)
                                      { return i == j && j == k && i >= 1 && i <= 4; });
  EXPECT_EQ(removeSmallComponents(mask, 3.0).removedComponents, 0u);
  EXPECT_EQ(countSet(mask), 4u);
  EXPECT_EQ(removeSmallComponents(mask, 4.5).removedComponents, 1u);
  EXPECT_EQ(countSet(mask), 0u);
}

TEST(SmallComponentRemoval, ZeroKeepsEverythingAndBadMinimaAreErrors)
{
  MaskVolume::Pointer mask = specksAndABlock();
  const std::size_t before = countSet(mask);
  EXPECT_EQ(removeSmallComponents(mask, 0.0).removedComponents, 0u);
  EXPECT_EQ(countSet(mask), before);
  EXPECT_THROW(removeSmallComponents(mask, -1.0), Error);
  EXPECT_THROW(removeSmallComponents(mask, std::nan("")), Error);
}

} // namespace
} // namespace slicemesh::testing
