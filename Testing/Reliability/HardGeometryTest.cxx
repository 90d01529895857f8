// Hard geometry through the real path (mask -> extractContours -> reconstructSurface ->
// physical space -> validateMesh): voxels touching only at an edge or a corner, masks touching the
// border, one-slice-thick structures, single voxels, thousands of specks; and, at the Logic API,
// contours with repeated or collinear points and self-intersecting contours.
//
// Edge and corner contacts: contours are traced with face (4-) connectivity of the foreground, so
// in a slice two voxels touching at a corner get two separate contours (split); across slices,
// voxels that touch at an edge or a corner only are separate pieces too, their contours do not
// overlap in projection, so each becomes its own closed piece of surface. The surface is split,
// never joined, at such contacts, and stays 2-manifold.
#include "ReliabilitySupport.h"

#include "Tiling/SurfaceReconstruction.h"

#include <gtest/gtest.h>

#include <cmath>

namespace slicemesh::testing
{
namespace
{

/** The checks every case makes: no exception, a valid mesh, the volume within tolerance. */
void expectValid(const MaskVolume* mask, std::size_t expectedComponents = 0)
{
  const MaskMeshResult result = checkedMesh(mask);
  EXPECT_EQ(result.problem(), "") << maskAsCode(mask);
  if (expectedComponents)
    EXPECT_EQ(result.validation.components, expectedComponents);
}

TEST(HardGeometry, InPlaneDiagonalNeighboursSplitIntoSeparateValidPieces)
{
  // (2,2) and (3,3) touch at an edge of the voxels (a corner of the slice's pixels), 3 slices.
  expectValid(makeMask({ 6, 6, 5 }, { 1, 1, 1 }, [](long i, long j, long k)
                       { return k >= 1 && k <= 3 && ((i == 2 && j == 2) || (i == 3 && j == 3)); }),
              2);
  // The same in a single slice.
  expectValid(makeMask({ 6, 6, 3 }, { 1, 1, 2 }, [](long i, long j, long k)
                       { return k == 1 && ((i == 2 && j == 2) || (i == 3 && j == 3)); }),
              2);
  // A diagonal staircase of ten voxels, and the other diagonal crossing it (an X).
  expectValid(makeMask({ 12, 12, 4 }, { 0.8, 0.8, 2.5 }, [](long i, long j, long k)
                       { return k >= 1 && k <= 2 && i >= 1 && i <= 10 && (i == j || i == 11 - j); }));
}

TEST(HardGeometry, VoxelsTouchingAcrossSlicesAtAnEdgeStayManifold)
{
  // Voxel (i, j, k) and (i + 1, j, k + 1): they share an edge only.
  expectValid(makeMask({ 5, 5, 5 }, { 1, 1, 1 }, [](long i, long j, long k)
                       { return (i == 1 && j == 2 && k == 1) || (i == 2 && j == 2 && k == 2); }),
              2);
  // The same along j: (4, 1, 6) and (4, 2, 7) (found by the property test, seed 2004).
  expectValid(makeMask({ 6, 3, 8 }, { 1, 1, 1 }, [](long i, long j, long k)
                       { return (i == 4 && j == 1 && k == 6) || (i == 4 && j == 2 && k == 7); }),
              2);
  // A staircase along i and k, 1 x 1 x 3 mm voxels.
  expectValid(makeMask({ 8, 4, 8 }, { 1, 1, 3 }, [](long i, long j, long k)
                       { return j == 1 && i == k && i >= 1 && i <= 6; }));
}

TEST(HardGeometry, VoxelsTouchingAtACornerOnlyStayManifold)
{
  expectValid(makeMask({ 5, 5, 5 }, { 1, 1, 1 }, [](long i, long j, long k)
                       { return (i == 1 && j == 1 && k == 1) || (i == 2 && j == 2 && k == 2); }),
              2);
  // Two 2 x 2 x 2 blocks meeting at one corner point.
  expectValid(makeMask({ 7, 7, 7 }, { 0.5, 0.5, 1.5 }, [](long i, long j, long k)
                       {
                         const bool a = i >= 1 && i <= 2 && j >= 1 && j <= 2 && k >= 1 && k <= 2;
                         const bool b = i >= 3 && i <= 4 && j >= 3 && j <= 4 && k >= 3 && k <= 4;
                         return a || b;
                       }),
              2);
}

TEST(HardGeometry, ThreeDimensionalCheckerboardIsValid)
{
  // Every voxel touches its neighbours at edges only: the worst case of saddles in and across slices.
  expectValid(makeMask({ 6, 6, 4 }, { 1, 1, 1 }, [](long i, long j, long k) { return (i + j + k) % 2 == 0; }));
}

TEST(HardGeometry, MasksTouchingTheImageBorderAreClosed)
{
  // Every voxel set: the object is the whole image.
  expectValid(makeMask({ 4, 5, 3 }, { 1, 1, 2 }, [](long, long, long) { return true; }), 1);
  // A box touching the first and last slice and two sides.
  expectValid(makeMask({ 8, 8, 6 }, { 1, 1, 1 }, [](long i, long j, long) { return i <= 4 && j >= 3; }), 1);
  // A sphere cut by three faces of the image.
  expectValid(makeMask({ 10, 10, 10 }, { 1, 1, 1.5 }, [](long i, long j, long k)
                       { return i * i + j * j + (k - 9) * (k - 9) * 2.25 <= 49; }),
              1);
}

TEST(HardGeometry, OneSliceThickStructuresAreClosed)
{
  expectValid(makeMask({ 12, 12, 1 }, { 1, 1, 2 }, [](long i, long j, long)
                       { return (i - 6) * (i - 6) + (j - 6) * (j - 6) <= 16; }),
              1);
  expectValid(makeMask({ 12, 12, 5 }, { 0.5, 0.5, 3 }, [](long i, long j, long k)
                       { return k == 2 && (i - 6) * (i - 6) + (j - 6) * (j - 6) <= 16 && !(i == 6 && j == 6); }),
              1);
}

TEST(HardGeometry, OneVoxelStructureIsAClosedSolid)
{
  expectValid(makeMask({ 1, 1, 1 }, { 1, 1, 1 }, [](long, long, long) { return true; }), 1);
  expectValid(makeMask({ 3, 3, 3 }, { 0.5, 0.5, 2 }, [](long i, long j, long k) { return i == 1 && j == 1 && k == 1; }),
              1);
  expectValid(makeMask({ 3, 3, 3 }, { 1, 1, 1 }, [](long i, long j, long k) { return i == 0 && j == 2 && k == 2; }),
              1);
}

TEST(HardGeometry, ThousandsOfOneVoxelSpecksAreEachClosed)
{
  // 13^3 = 2197 isolated voxels.
  const MaskVolume::Pointer mask = makeMask({ 40, 40, 40 }, { 1, 1, 1 }, [](long i, long j, long k)
                                            { return i % 3 == 1 && j % 3 == 1 && k % 3 == 1; });
  const MaskMeshResult result = checkedMesh(mask);
  EXPECT_EQ(result.problem(), "");
  EXPECT_EQ(result.validation.components, 2197u);
}

/** A square prism of three slices whose contours carry repeated and collinear points. */
ContourStack prismWith(const Polygon2& square)
{
  ContourStack stack;
  stack.sliceSpacing = 1.0;
  for (int k = 0; k < 3; ++k)
    stack.slices.push_back({ static_cast<double>(k), { square } });
  return stack;
}

/** Caps flat on the end slices, so the prism's volume is exact. */
ReconstructionOptions flatCaps()
{
  ReconstructionOptions options;
  options.capPlacement = CapPlacement::AtSlice;
  return options;
}

TEST(HardGeometry, ContoursWithRepeatedAndCollinearPointsGiveTheExactPrism)
{
  const Polygon2 square = { { 0, 0 }, { 0, 0 }, { 1, 0 }, { 2, 0 }, { 3, 0 }, { 3, 0 }, { 3, 1.5 }, { 3, 3 },
                            { 1.5, 3 }, { 0, 3 }, { 0, 3 }, { 0, 2 }, { 0, 1 }, { 0, 0 } };
  for (const Polygon2& contour : { square, Polygon2(square.rbegin(), square.rend()) })
  {
    TriangleMesh mesh;
    ASSERT_NO_THROW(mesh = reconstructSurface(prismWith(contour), flatCaps()));
    const MeshValidation v = validateMesh(mesh);
    EXPECT_TRUE(v.valid()) << v.summary();
    EXPECT_NEAR(v.volume, 9.0 * 2.0, 1e-9); // flat caps on the first and last slice, 2 mm apart
  }
}

TEST(HardGeometry, ContoursCollapsingToNothingAreDropped)
{
  // A contour of one repeated point and a degenerate (zero-area) sliver next to a real square.
  ContourStack stack = prismWith({ { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } });
  stack.slices[1].contours.push_back({ { 5, 5 }, { 5, 5 }, { 5, 5 } });
  stack.slices[1].contours.push_back({ { 7, 7 }, { 8, 8 }, { 9, 9 } });
  TriangleMesh mesh;
  ASSERT_NO_THROW(mesh = reconstructSurface(stack, flatCaps()));
  const MeshValidation v = validateMesh(mesh);
  EXPECT_TRUE(v.valid()) << v.summary();
  EXPECT_NEAR(v.volume, 2.0, 1e-9);
}

/** Contours do not come from files yet, so a self-intersecting one can only reach Logic through
 *  its API. The choice: reject, with a slicemesh::Error that says so (a repair would have to guess
 *  which lobe is inside). */
void expectRejected(const Polygon2& contour)
{
  try
  {
    const TriangleMesh mesh = reconstructSurface(prismWith(contour));
    const MeshValidation v = validateMesh(mesh);
    ADD_FAILURE() << "accepted a self-intersecting contour; mesh: " << v.summary();
  }
  catch (const Error& e)
  {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos);
    EXPECT_TRUE(message.find("intersect") != std::string::npos || message.find("cross") != std::string::npos) << message;
  }
}

TEST(HardGeometry, SelfIntersectingContourIsRejectedWithAClearError)
{
  expectRejected({ { 0, 0 }, { 2, 2 }, { 2, 0 }, { 0, 2 } });                     // a bow tie
  expectRejected({ { 0, 0 }, { 4, 0 }, { 4, 4 }, { 2, 4 }, { 2, -1 }, { 0, -1 } }); // an edge crossing another
  expectRejected({ { 0, 0 }, { 4, 0 }, { 4, 4 }, { 2, 0 }, { 0, 4 } });             // a vertex on an edge
}

} // namespace
} // namespace slicemesh::testing
