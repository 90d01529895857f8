#include "Correspondence/ContourCorrespondence.h"
#include "ContourStacks.h"
#include "Sections/IntermediateSections.h"
#include "Measures/MeshValidation.h"
#include "Core/PlanarGeometry.h"
#include "Tiling/SurfaceReconstruction.h"

#include <gtest/gtest.h>

#include <iostream>

using namespace slicemesh;
using namespace slicemesh::testing;

namespace
{

/** Circles of radius r whose centres move `shift` in x from one slice to the next. */
ContourStack tiltedCapsule(double r, double shift, double dz, int slices)
{
  ContourStack stack;
  stack.sliceSpacing = dz;
  for (int k = 0; k < slices; ++k)
    stack.slices.push_back({ k * dz, { circle(k * shift, 0.0, r, 64) } });
  return stack;
}

/** A sphere at the origin sliced symmetrically: z = 0, +-dz, +-2 dz, ... inside the sphere. */
ContourStack slicedSphere(double r, double dz, int points)
{
  const double top = std::floor((r - 1e-9) / dz) * dz;
  return sliceStack(-top, top, dz, [&](double z) {
    return std::vector<Polygon2>{ circle(0, 0, std::sqrt(r * r - z * z), points) };
  });
}

/** Mean distance of the mesh's vertices, and of its triangles' centroids weighted by area, to a sphere. */
void distanceToSphere(const TriangleMesh& mesh, double r, double& vertexMean, double& surfaceMean)
{
  vertexMean = 0.0;
  for (const Point3& p : mesh.points)
    vertexMean += sphereDistance(p, { 0, 0, 0 }, r);
  vertexMean /= static_cast<double>(mesh.points.size());
  double weighted = 0.0, area = 0.0;
  for (const Triangle& t : mesh.triangles)
  {
    const Point3 &a = mesh.points[t[0]], &b = mesh.points[t[1]], &c = mesh.points[t[2]];
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
    const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    const double s = 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
    const Point3 g{ (a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3 };
    weighted += s * sphereDistance(g, { 0, 0, 0 }, r);
    area += s;
  }
  surfaceMean = weighted / area;
}

std::size_t contourCount(const ContourStack& stack, std::size_t slice)
{
  return stack.slices[slice].contours.size();
}

/** An ellipse with semi-axes a (along x) and b, centred at (cx, 0), n points counter-clockwise. */
Polygon2 ellipse(double cx, double a, double b, int n)
{
  Polygon2 polygon;
  for (int i = 0; i < n; ++i)
  {
    const double t = 2.0 * M_PI * i / n;
    polygon.push_back({ cx + a * std::cos(t), b * std::sin(t) });
  }
  return polygon;
}

double regionArea(const std::vector<Polygon2>& contours)
{
  double twice = 0.0;
  for (const Polygon2& c : contours)
    twice += twiceSignedArea(c);
  return 0.5 * std::abs(twice);
}

/** Share of the smaller region that the other covers, counted on a grid of 0.02 mm (independent of
 *  the scanline measure the Logic uses). One contour per layer. */
double overlapShare(const Polygon2& a, const Polygon2& b)
{
  const Box2 ba = boundingBox(a), bb = boundingBox(b);
  const double x0 = std::max(ba.xmin, bb.xmin), x1 = std::min(ba.xmax, bb.xmax);
  const double y0 = std::max(ba.ymin, bb.ymin), y1 = std::min(ba.ymax, bb.ymax);
  const double h = 0.02;
  double both = 0.0;
  for (double x = x0 + 0.5 * h; x < x1; x += h)
    for (double y = y0 + 0.5 * h; y < y1; y += h)
      both += isInside(a, { x, y }) && isInside(b, { x, y }) ? h * h : 0.0;
  return both / std::min(regionArea({ a }), regionArea({ b }));
}

/** Area of the mesh's cross-section by the plane z (a closed, outward-wound mesh): each triangle the
 *  plane cuts adds its segment, directed with the solid on its left, to the shoelace sum. */
double crossSectionArea(const TriangleMesh& mesh, double z)
{
  double twice = 0.0;
  for (const Triangle& t : mesh.triangles)
  {
    const Point3* p[3] = { &mesh.points[t[0]], &mesh.points[t[1]], &mesh.points[t[2]] };
    std::vector<Point2> cut;
    for (int i = 0; i < 3; ++i)
    {
      const Point3 &u = *p[i], &v = *p[(i + 1) % 3];
      if ((u.z < z) != (v.z < z))
      {
        const double s = (z - u.z) / (v.z - u.z);
        cut.push_back({ u.x + s * (v.x - u.x), u.y + s * (v.y - u.y) });
      }
    }
    if (cut.size() != 2)
      continue;
    // Outward normal n: the section's boundary runs along (-n.y, n.x) (counter-clockwise seen from +z).
    const double ux = p[1]->x - p[0]->x, uy = p[1]->y - p[0]->y, uz = p[1]->z - p[0]->z;
    const double vx = p[2]->x - p[0]->x, vy = p[2]->y - p[0]->y, vz = p[2]->z - p[0]->z;
    const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz;
    if ((cut[1].x - cut[0].x) * -ny + (cut[1].y - cut[0].y) * nx < 0.0)
      std::swap(cut[0], cut[1]);
    twice += cut[0].x * cut[1].y - cut[1].x * cut[0].y;
  }
  return 0.5 * twice;
}

} // namespace

TEST(IntermediateSections, NothingAskedNothingChanged)
{
  const ContourStack stack = tiltedCapsule(5.0, 15.0, 3.0, 4);
  SectionStatistics statistics;
  const ContourStack same = insertIntermediateSections(stack, {}, &statistics);
  ASSERT_EQ(same.slices.size(), stack.slices.size());
  EXPECT_EQ(statistics.sectionsInserted, 0u);
  EXPECT_EQ(statistics.slabsFitted, 0u);
  for (std::size_t k = 0; k < stack.slices.size(); ++k)
  {
    EXPECT_EQ(same.slices[k].z, stack.slices[k].z);
    ASSERT_EQ(same.slices[k].contours.size(), 1u);
    EXPECT_EQ(same.slices[k].contours[0].size(), stack.slices[k].contours[0].size());
  }
  UndersamplingOptions bad;
  bad.correspondenceDistance = -1.0;
  EXPECT_THROW(insertIntermediateSections(stack, bad), Error);
}

TEST(IntermediateSections, TiltedCapsuleBecomesOneComponentWhenBridged)
{
  // Adjacent circles do not overlap: the centres move 1.5 diameters per slice (a gap of one radius).
  const double r = 5.0;
  const ContourStack stack = tiltedCapsule(r, 3.0 * r, 3.0, 5);
  ASSERT_EQ(matchContours(stack.slices[0].contours, stack.slices[1].contours).groups.size(), 2u);

  // Without bridging, every circle is capped as its own blob.
  const MeshValidation separate = validateMesh(reconstructSurface(stack));
  EXPECT_TRUE(separate.valid()) << separate.summary();
  EXPECT_EQ(separate.components, 5u);

  UndersamplingOptions options;
  options.correspondenceDistance = 1.2 * r;
  const ContourStack unbridged = insertIntermediateSections(stack, options);
  EXPECT_EQ(unbridged.slices.size(), stack.slices.size()) << "bridging is off by default";

  options.bridgeNonOverlapping = true;
  SectionStatistics statistics;
  const ContourStack bridged = insertIntermediateSections(stack, options, &statistics);
  for (const std::string& note : statistics.notes)
    std::cout << "[ note     ] " << note << "\n";
  std::cout << "[ sections ] capsule: " << statistics.sectionsInserted << " sections in " << statistics.slabsBridged
            << " slabs, fit " << statistics.fitSeconds * 1e3 << " ms (" << statistics.largestFit << " centres), extract "
            << statistics.extractSeconds * 1e3 << " ms\n";
  EXPECT_EQ(statistics.slabsBridged, 4u);
  EXPECT_EQ(statistics.bridgesFailed, 0u);
  ASSERT_GT(bridged.slices.size(), stack.slices.size());
  for (std::size_t k = 0; k < bridged.slices.size(); ++k)
    EXPECT_EQ(contourCount(bridged, k), 1u) << "slice " << k << " at z " << bridged.slices[k].z;

  const MeshValidation joined = validateMesh(reconstructSurface(bridged));
  EXPECT_TRUE(joined.valid()) << joined.summary();
  EXPECT_EQ(joined.components, 1u);
  EXPECT_EQ(joined.eulerCharacteristic, 2);
}

TEST(IntermediateSections, SparseSphereGetsCloserToTheTruth)
{
  const double r = 20.0, dz = 6.0;
  const ContourStack stack = slicedSphere(r, dz, 90);
  UndersamplingOptions options;
  options.maxSliceSpacingFactor = 2.0;
  SectionStatistics statistics;
  const ContourStack refined = insertIntermediateSections(stack, options, &statistics);
  for (const std::string& note : statistics.notes)
    std::cout << "[ note     ] " << note << "\n";
  EXPECT_GT(statistics.sectionsInserted, 0u);
  EXPECT_EQ(statistics.slabsRejected, 0u);
  EXPECT_EQ(refined.slices.size(), stack.slices.size() + statistics.sectionsInserted);
  for (std::size_t k = 0; k < refined.slices.size(); ++k)
    EXPECT_EQ(contourCount(refined, k), 1u) << "an overlapping slab keeps one contour per section";

  const TriangleMesh coarse = reconstructSurface(stack);
  const TriangleMesh fine = reconstructSurface(refined);
  const MeshValidation v = validateMesh(fine);
  EXPECT_TRUE(v.valid()) << v.summary();
  EXPECT_EQ(v.components, 1u);
  double coarseVertex, coarseSurface, fineVertex, fineSurface;
  distanceToSphere(coarse, r, coarseVertex, coarseSurface);
  distanceToSphere(fine, r, fineVertex, fineSurface);
  const double exact = 4.0 / 3.0 * M_PI * r * r * r;
  std::cout << "[ sections ] sphere r " << r << " at " << dz << " mm, in-plane " << statistics.inPlaneSpacing << " mm: "
            << statistics.sectionsInserted << " sections, fit " << statistics.fitSeconds * 1e3 << " ms, extract "
            << statistics.extractSeconds * 1e3 << " ms\n"
            << "[ sections ] mean vertex distance " << coarseVertex << " -> " << fineVertex << " mm, mean surface distance "
            << coarseSurface << " -> " << fineSurface << " mm, volume error "
            << 100.0 * (validateMesh(coarse).volume / exact - 1.0) << "% -> " << 100.0 * (v.volume / exact - 1.0) << "%\n";
  EXPECT_LT(fineVertex, coarseVertex);
  EXPECT_LT(fineSurface, coarseSurface);
  EXPECT_NEAR(v.volume, exact, 0.03 * exact);
}

TEST(IntermediateSections, OverlappingAnnulusKeepsItsTopologyAndUntouchedSlices)
{
  // A twisted annulus (outer and hole drift apart slowly): every slab overlaps one-to-one, so each
  // section must hold one outer boundary and one hole, and the original slices stay as they were.
  const ContourStack stack = sliceStack(0.0, 20.0, 5.0, [](double z) {
    return std::vector<Polygon2>{ circle(0.1 * z, 0, 12.0 - 0.1 * z, 120), circle(-0.05 * z, 0.1 * z, 5.0, 60, true) };
  });
  UndersamplingOptions options;
  options.maxSliceSpacingFactor = 2.0;
  SectionStatistics statistics;
  const ContourStack refined = insertIntermediateSections(stack, options, &statistics);
  EXPECT_GT(statistics.sectionsInserted, 0u);
  EXPECT_EQ(statistics.slabsRejected, 0u);
  std::size_t original = 0;
  for (const Slice& slice : refined.slices)
  {
    ASSERT_EQ(slice.contours.size(), 2u) << "z " << slice.z;
    int holes = 0;
    for (const Polygon2& c : slice.contours)
      holes += twiceSignedArea(c) < 0 ? 1 : 0;
    EXPECT_EQ(holes, 1) << "z " << slice.z;
    if (original < stack.slices.size() && slice.z == stack.slices[original].z)
    {
      EXPECT_EQ(slice.contours[0].size(), stack.slices[original].contours[0].size());
      EXPECT_EQ(slice.contours[1][3].x, stack.slices[original].contours[1][3].x);
      ++original;
    }
  }
  EXPECT_EQ(original, stack.slices.size());
  const MeshValidation v = validateMesh(reconstructSurface(refined));
  EXPECT_TRUE(v.valid()) << v.summary();
  EXPECT_EQ(v.eulerCharacteristic, 0); // a torus-like tube
}

TEST(IntermediateSections, TwoTubesDriftingApartAreBridgedSeparately)
{
  // Two tilted tubes in the same slices, drifting in opposite directions: each group gets its own
  // sheared fit, and the two never merge.
  const double r = 4.0, shift = 11.0, dz = 2.5;
  ContourStack stack;
  stack.sliceSpacing = dz;
  for (int k = 0; k < 4; ++k)
    stack.slices.push_back({ k * dz, { circle(-20.0 - k * shift, 0.0, r, 48), circle(20.0 + k * shift, 5.0, r, 48) } });
  UndersamplingOptions options;
  options.correspondenceDistance = 5.0;
  options.bridgeNonOverlapping = true;
  SectionStatistics statistics;
  const ContourStack bridged = insertIntermediateSections(stack, options, &statistics);
  EXPECT_EQ(statistics.slabsBridged, 3u);
  EXPECT_EQ(statistics.bridgesFailed, 0u);
  for (const Slice& slice : bridged.slices)
    EXPECT_EQ(slice.contours.size(), 2u) << "z " << slice.z;
  const MeshValidation v = validateMesh(reconstructSurface(bridged));
  EXPECT_TRUE(v.valid()) << v.summary();
  EXPECT_EQ(v.components, 2u);
}

TEST(IntermediateSections, BridgedSectionsKeepTheAreaAndOverlapEnough)
{
  // A sheared elliptic prism (the tilted capsule of the pipeline test): ellipses 5.85 x 2 mm whose
  // centres move 13.7 mm along their long axis per 5 mm slice, so consecutive slices do not overlap.
  // Every cross-section of the true solid is the same ellipse, so every section should have its area,
  // consecutive layers should overlap by the asked share, and the mesh between the slices should keep
  // the area (the tiling loses volume where consecutive contours overlap only in part).
  const double a = 5.85, b = 2.0, shift = 13.7, dz = 5.0;
  for (const int slices : { 2, 4 }) // 2: each fit sees the slab's two slices only
  {
    ContourStack stack;
    stack.sliceSpacing = dz;
    for (int k = 0; k < slices; ++k)
      stack.slices.push_back({ k * dz, { ellipse(k * shift, a, b, 64) } });
    const double area = regionArea(stack.slices[0].contours);
    UndersamplingOptions options;
    options.correspondenceDistance = 3.0;
    options.bridgeNonOverlapping = true;
    SectionStatistics statistics;
    const ContourStack bridged = insertIntermediateSections(stack, options, &statistics);
    EXPECT_EQ(statistics.slabsBridged, static_cast<std::size_t>(slices - 1));
    EXPECT_GE(statistics.smallestSectionOverlap, options.sectionOverlap);
    std::cout << "[ sections ] sheared ellipse, " << slices << " slices: " << statistics.sectionsInserted
              << " sections, least overlap " << statistics.smallestSectionOverlap << "\n";
    double worstArea = 0.0, leastOverlap = 1.0;
    for (std::size_t k = 0; k < bridged.slices.size(); ++k)
    {
      ASSERT_EQ(contourCount(bridged, k), 1u) << "z " << bridged.slices[k].z;
      worstArea = std::max(worstArea, std::abs(regionArea(bridged.slices[k].contours) / area - 1.0));
      if (k > 0)
        leastOverlap = std::min(leastOverlap, overlapShare(bridged.slices[k - 1].contours[0], bridged.slices[k].contours[0]));
    }
    std::cout << "[ sections ] worst section area " << 100.0 * worstArea << "%, least overlap (grid) " << leastOverlap
              << "\n";
    EXPECT_LT(worstArea, 0.03) << "sections should keep the prism's cross-section area";
    EXPECT_GE(leastOverlap, options.sectionOverlap - 0.02);

    const TriangleMesh mesh = reconstructSurface(bridged);
    const MeshValidation v = validateMesh(mesh);
    EXPECT_TRUE(v.valid()) << v.summary();
    EXPECT_EQ(v.components, 1u);
    // Mean cross-section area between the first and last slice, against the ellipse's.
    double sum = 0.0;
    const int samples = 40 * (slices - 1);
    for (int i = 0; i < samples; ++i)
      sum += crossSectionArea(mesh, (i + 0.5) * dz * (slices - 1) / samples);
    const double kept = sum / samples / area;
    std::cout << "[ sections ] mesh cross-sections between the slices: " << 100.0 * kept << "% of the area\n";
    EXPECT_GT(kept, 0.95);
    EXPECT_LT(kept, 1.02);
  }
}

TEST(IntermediateSections, PartlyOverlappingPairsGetSectionsWhenAsked)
{
  // Ellipses 5.85 x 2 mm sliding 4 mm along their long axis per 2.5 mm slice: consecutive slices
  // overlap by ~57%, and the tiling keeps only ~89% of the area between them. refineWeakOverlap adds
  // sections (from one plain fit: the pairs overlap already) until the overlap is sectionOverlap.
  const double a = 5.85, b = 2.0, shift = 4.0, dz = 2.5;
  ContourStack stack;
  stack.sliceSpacing = dz;
  for (int k = 0; k < 5; ++k)
    stack.slices.push_back({ k * dz, { ellipse(k * shift, a, b, 64) } });
  const double area = regionArea(stack.slices[0].contours);
  const double before = overlapShare(stack.slices[0].contours[0], stack.slices[1].contours[0]);
  EXPECT_LT(before, 0.6);

  UndersamplingOptions options;
  EXPECT_EQ(insertIntermediateSections(stack, options).slices.size(), stack.slices.size()) << "off by default";
  options.refineWeakOverlap = true;
  SectionStatistics statistics;
  const ContourStack refined = insertIntermediateSections(stack, options, &statistics);
  for (const std::string& note : statistics.notes)
    std::cout << "[ note     ] " << note << "\n";
  std::cout << "[ sections ] sliding ellipse: overlap " << before << ", " << statistics.sectionsInserted
            << " sections, least overlap " << statistics.smallestSectionOverlap << "\n";
  EXPECT_EQ(statistics.slabsOverlapRefined, 4u);
  EXPECT_EQ(statistics.slabsRejected, 0u);
  EXPECT_GE(statistics.smallestSectionOverlap, options.sectionOverlap);
  double worstArea = 0.0;
  for (std::size_t k = 0; k < refined.slices.size(); ++k)
  {
    ASSERT_EQ(contourCount(refined, k), 1u) << "z " << refined.slices[k].z;
    worstArea = std::max(worstArea, std::abs(regionArea(refined.slices[k].contours) / area - 1.0));
    if (k > 0)
      EXPECT_GE(overlapShare(refined.slices[k - 1].contours[0], refined.slices[k].contours[0]), options.sectionOverlap - 0.02);
  }
  // The plain (unsheared) fit pinches a thin tilted tube a little between slices (measured -2% to
  // -5% in area; the sheared fit of the bridging test keeps it within 2.5%).
  std::cout << "[ sections ] worst section area " << 100.0 * worstArea << "%\n";
  EXPECT_LT(worstArea, 0.06);

  const TriangleMesh coarse = reconstructSurface(stack), fine = reconstructSurface(refined);
  const MeshValidation v = validateMesh(fine);
  EXPECT_TRUE(v.valid()) << v.summary();
  EXPECT_EQ(v.components, 1u);
  double coarseSum = 0.0, fineSum = 0.0;
  const int samples = 160;
  for (int i = 0; i < samples; ++i)
  {
    const double z = (i + 0.5) * 4.0 * dz / samples;
    coarseSum += crossSectionArea(coarse, z);
    fineSum += crossSectionArea(fine, z);
  }
  std::cout << "[ sections ] mesh cross-sections between the slices: " << 100.0 * coarseSum / samples / area << "% -> "
            << 100.0 * fineSum / samples / area << "% of the area\n";
  EXPECT_GT(fineSum / samples / area, 0.95);
  EXPECT_GT(fineSum, coarseSum);
}

TEST(IntermediateSections, CapOnSectionsIsReportedWhenTheOverlapFallsShort)
{
  // The sheared ellipses again, with at most two sections per slab: the pair is still joined (the
  // sections overlap), but by less than sectionOverlap, and a note says so.
  ContourStack stack;
  stack.sliceSpacing = 5.0;
  for (int k = 0; k < 2; ++k)
    stack.slices.push_back({ k * 5.0, { ellipse(k * 13.7, 5.85, 2.0, 64) } });
  UndersamplingOptions options;
  options.correspondenceDistance = 3.0;
  options.bridgeNonOverlapping = true;
  options.maxSectionsPerSlab = 2;
  SectionStatistics statistics;
  const ContourStack bridged = insertIntermediateSections(stack, options, &statistics);
  EXPECT_EQ(statistics.slabsBridged, 1u);
  EXPECT_EQ(bridged.slices.size(), 4u);
  EXPECT_GT(statistics.smallestSectionOverlap, 0.0);
  EXPECT_LT(statistics.smallestSectionOverlap, options.sectionOverlap);
  ASSERT_EQ(statistics.notes.size(), 1u);
  EXPECT_NE(statistics.notes[0].find("overlap by"), std::string::npos) << statistics.notes[0];
  options.sectionOverlap = 1.0;
  EXPECT_THROW(insertIntermediateSections(stack, options), Error);
}
