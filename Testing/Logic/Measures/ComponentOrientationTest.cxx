// Every component of a surface faces as its nesting says: outer surfaces out, cavity walls in. A
// check of the total volume alone passes an inside-out piece beside a larger one.
#include "ContourStacks.h"
#include "Measures/ComponentOrientation.h"
#include "Measures/MeshComponents.h"
#include "Measures/MeshValidation.h"
#include "Tiling/SurfaceReconstruction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace slicemesh::testing
{
namespace
{

/** A closed ball of `radius` mm about (cx, 0, 0), sliced every radius / 4 mm, facing out. */
TriangleMesh ball(double cx, double radius)
{
  return reconstructSurface(ballStack(cx, 0.0, 0.0, radius, 48, radius / 4.0));
}

TriangleMesh insideOut(TriangleMesh mesh)
{
  for (Triangle& t : mesh.triangles)
    std::swap(t[1], t[2]);
  return mesh;
}

TriangleMesh joined(const std::vector<TriangleMesh>& meshes)
{
  std::vector<const TriangleMesh*> pointers;
  for (const TriangleMesh& m : meshes)
    pointers.push_back(&m);
  return joinMeshes(pointers);
}

TEST(ComponentOrientation, AnInsideOutPieceBesideALargerOneIsCaught)
{
  const TriangleMesh mesh = joined({ ball(0.0, 8.0), insideOut(ball(30.0, 3.0)) });
  const MeshValidation v = validateMesh(mesh);
  ASSERT_TRUE(v.closed() && v.manifold());
  EXPECT_GT(v.volume, 0.0); // the total alone looks right
  EXPECT_EQ(v.misorientedComponents, 1u);
  EXPECT_FALSE(v.oriented());
  EXPECT_FALSE(v.valid());
  EXPECT_NE(v.summary().find("1 component facing the wrong way"), std::string::npos) << v.summary();
}

TEST(ComponentOrientation, ACavityWallFacesIntoTheCavity)
{
  // A hollow ball: the wall of the cavity faces in (towards the centre) to be right.
  const TriangleMesh outer = ball(0.0, 8.0), wall = ball(0.0, 4.0);
  const MeshValidation right = validateMesh(joined({ outer, insideOut(wall) }));
  EXPECT_EQ(right.components, 2u);
  EXPECT_EQ(right.misorientedComponents, 0u);
  EXPECT_TRUE(right.valid()) << right.summary();
  const MeshValidation wrong = validateMesh(joined({ outer, wall }));
  EXPECT_EQ(wrong.misorientedComponents, 1u);
  EXPECT_FALSE(wrong.oriented());
  EXPECT_EQ(misorientedComponents(joined({ insideOut(outer), wall })), 2u);
}

TEST(ComponentOrientation, AnIslandInACavityFacesOut)
{
  const TriangleMesh outer = ball(0.0, 9.0), wall = insideOut(ball(0.0, 6.0)), island = ball(0.0, 2.0);
  EXPECT_EQ(misorientedComponents(joined({ outer, wall, island })), 0u);
  EXPECT_EQ(misorientedComponents(joined({ outer, wall, insideOut(island) })), 1u);
  // Taken as separate pieces with their volumes, as the finishing does: the same answer.
  const std::vector<TriangleMesh> pieces{ outer, wall, insideOut(island) };
  std::vector<const TriangleMesh*> pointers;
  std::vector<double> volumes;
  for (const TriangleMesh& p : pieces)
  {
    pointers.push_back(&p);
    volumes.push_back(signedVolume(p));
  }
  // On any number of threads (the trees built and the points tested side by side).
  for (unsigned int threads : { 1u, 2u, 8u })
    EXPECT_EQ(misorientedComponents(pointers, volumes, threads), 1u) << threads << " threads";
}

TEST(ComponentOrientation, AmongManyPiecesEachIsJudgedByThoseAroundIt)
{
  // A hollow ball with three islands in its cavity, beside a row of 120 specks (as a thresholded
  // noisy image has by the thousand): one island and one speck inside out, and only they are caught.
  // The boxes that hold one another are found among all pairs of boxes that meet, not pair by pair.
  std::vector<TriangleMesh> pieces{ ball(0.0, 20.0), insideOut(ball(0.0, 15.0)), ball(-8.0, 2.0),
                                    insideOut(ball(0.0, 2.0)), ball(8.0, 2.0) };
  for (int k = 0; k < 120; ++k)
    pieces.push_back(k == 77 ? insideOut(ball(25.0 + 4.0 * k, 1.5)) : ball(25.0 + 4.0 * k, 1.5));
  EXPECT_EQ(misorientedComponents(joined(pieces)), 2u);
  std::vector<const TriangleMesh*> pointers;
  std::vector<double> volumes;
  for (const TriangleMesh& p : pieces)
  {
    pointers.push_back(&p);
    volumes.push_back(signedVolume(p));
  }
  for (unsigned int threads : { 1u, 2u })
    EXPECT_EQ(misorientedComponents(pointers, volumes, threads), 2u) << threads << " threads";
  // The cavity's wall facing out too: now three.
  pieces[1] = ball(0.0, 15.0);
  EXPECT_EQ(misorientedComponents(joined(pieces)), 3u);
}

TEST(ComponentOrientation, TheTilingOfAHollowStackIsOriented)
{
  // Slices of a hollow ball (outer radius 8, cavity radius 4), the cavity as a clockwise hole: the
  // tiling's two components face out and in.
  ContourStack stack;
  stack.sliceSpacing = 1.0;
  for (double z = -7.5; z < 8.0; z += 1.0)
  {
    Slice slice{ z, { circle(0.0, 0.0, std::sqrt(64.0 - z * z), 64) } };
    if (std::abs(z) < 4.0)
      slice.contours.push_back(circle(0.0, 0.0, std::sqrt(16.0 - z * z), 48, true));
    stack.slices.push_back(slice);
  }
  const MeshValidation v = validateMesh(reconstructSurface(stack));
  EXPECT_EQ(v.components, 2u);
  EXPECT_EQ(v.misorientedComponents, 0u);
  EXPECT_TRUE(v.valid()) << v.summary();
  // Its volume is the shell's, within the slicing's error.
  const double shell = 4.0 / 3.0 * M_PI * (512.0 - 64.0);
  EXPECT_NEAR(v.volume, shell, 0.05 * shell);
}

} // namespace
} // namespace slicemesh::testing
