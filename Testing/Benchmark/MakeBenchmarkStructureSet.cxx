// Writes the structure set of the speed benchmark (Documentation/Benchmark.md, "Structure sets"):
// 20 ROIs as a planning system draws them - a BODY of 100 axial slices with 500 irregularly spaced
// points each (50,000 points), and 19 organs and targets of 2 to 40 mm radius, one of them hollow.
//   MakeBenchmarkStructureSet <RS.dcm>
#include "StructureSetWriter.h"

#include <cmath>
#include <cstdio>
#include <random>

namespace
{

using namespace slicemesh;

constexpr double Pi = 3.14159265358979323846;
constexpr double SliceSpacing = 3.0;

/** An ellipse of n points at irregular angle steps (a planner's point spacing varies), with a
 *  gentle wobble of its radius. */
Polygon3 ellipse(double cx, double cy, double z, double a, double b, int n, std::mt19937& random, bool clockwise = false)
{
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  Polygon3 points;
  for (int k = 0; k < n; ++k)
  {
    const double t = 2.0 * Pi * (k + jitter(random)) / n;
    const double wobble = 1.0 + 0.01 * std::sin(7.0 * t + 0.1 * z);
    const double angle = clockwise ? -t : t;
    points.push_back({ cx + wobble * a * std::cos(angle), cy + wobble * b * std::sin(angle), z });
  }
  return points;
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: MakeBenchmarkStructureSet <RS.dcm>\n");
    return 2;
  }
  std::mt19937 random(14);
  std::vector<PlanarStructure> rois;
  PlanarStructure body;
  body.number = 1;
  body.name = "BODY";
  body.rgb = { 180, 150, 120 };
  std::size_t bodyPoints = 0;
  for (int k = 0; k < 100; ++k)
  {
    const double z = -150.0 + SliceSpacing * k;
    body.contours.push_back(ellipse(0.0, 0.0, z, 170.0 + 10.0 * std::sin(k / 15.0), 110.0, 500, random));
    bodyPoints += 500;
  }
  rois.push_back(body);
  // Organs: ellipsoids inside the BODY, points about 1 mm apart.
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n = 2; n <= 20; ++n)
  {
    PlanarStructure organ;
    organ.number = n;
    organ.name = n == 20 ? "Bladder_wall" : "Organ_" + std::to_string(n);
    organ.rgb = { static_cast<unsigned char>(40 * n % 256), static_cast<unsigned char>(90 * n % 256),
                  static_cast<unsigned char>(150 + 5 * n % 100) };
    const double radius = 2.0 + 38.0 * (n - 2) / 18.0;
    const double cx = -100.0 + 200.0 * unit(random), cy = -50.0 + 100.0 * unit(random);
    const double cz = -100.0 + 200.0 * unit(random);
    for (double z = cz - radius + 0.5 * SliceSpacing; z < cz + radius; z += SliceSpacing)
    {
      const double r = std::sqrt(std::max(0.0, radius * radius - (z - cz) * (z - cz)));
      const double sz = -150.0 + SliceSpacing * std::round((z + 150.0) / SliceSpacing); // on the CT slices
      if (r < 1.0)
        continue;
      const int points = std::max(8, static_cast<int>(2.0 * Pi * r));
      organ.contours.push_back(ellipse(cx, cy, sz, r, 0.8 * r, points, random));
      if (n == 20 && r > 12.0) // a hollow organ: its lumen as a nested contour
        organ.contours.push_back(ellipse(cx, cy, sz, r - 6.0, 0.8 * (r - 6.0), points, random, true));
    }
    rois.push_back(organ);
  }
  writeRTStructureSet(argv[1], rois);
  std::printf("wrote %s: %zu ROIs, BODY %zu points\n", argv[1], rois.size(), bodyPoints);
  return 0;
}
