#include "CtLikeLabelMap.h"

#include "Sphere.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

namespace slicemesh
{
namespace
{

constexpr std::size_t nx = 512, ny = 512, nz = 400;
constexpr double sx = 0.9766, sy = 0.9766, sz = 1.25;

/** The label map being painted: voxel (i, j, k) at (i sx, j sy, k sz) mm. */
class Canvas
{
public:
  explicit Canvas(MaskVolume* labels) : m_Voxels(labels->GetBufferPointer()) {}

  unsigned char& at(std::size_t i, std::size_t j, std::size_t k) { return m_Voxels[(k * ny + j) * nx + i]; }

  /** Sets `label` on the voxels of the box [low, high] (mm) where inside(x, y, z) holds. */
  void paint(const Vector3& low, const Vector3& high, unsigned char label,
             const std::function<bool(double, double, double, unsigned char)>& inside)
  {
    const auto from = [](double v, double s) { return static_cast<std::size_t>(std::max(0.0, std::floor(v / s))); };
    const auto to = [](double v, double s, std::size_t n)
    { return static_cast<std::size_t>(std::clamp(std::ceil(v / s) + 1.0, 0.0, static_cast<double>(n))); };
    for (std::size_t k = from(low.z(), sz); k < to(high.z(), sz, nz); ++k)
      for (std::size_t j = from(low.y(), sy); j < to(high.y(), sy, ny); ++j)
        for (std::size_t i = from(low.x(), sx); i < to(high.x(), sx, nx); ++i)
        {
          unsigned char& voxel = at(i, j, k);
          if (inside(i * sx, j * sy, k * sz, voxel))
            voxel = label;
        }
  }

  /** An axis-aligned ellipsoid; a shell `shell` mm thick if positive; only over `onlyInto` if set. */
  void ellipsoid(unsigned char label, const Vector3& c, const Vector3& r, double shell = 0.0, int onlyInto = -1)
  {
    const Vector3 inner = r - Vector3::Constant(shell);
    paint(c - r, c + r, label,
          [&](double x, double y, double z, unsigned char was)
          {
            const Vector3 d(x - c.x(), y - c.y(), z - c.z());
            if (onlyInto >= 0 && was != onlyInto)
              return false;
            if (d.cwiseQuotient(r).squaredNorm() > 1.0)
              return false;
            return shell <= 0.0 || d.cwiseQuotient(inner).squaredNorm() > 1.0;
          });
  }

  /** A tube of radius r along the polyline. */
  void tube(unsigned char label, const std::vector<Vector3>& line, double r)
  {
    for (std::size_t s = 0; s + 1 < line.size(); ++s)
    {
      const Vector3 a = line[s], b = line[s + 1], ab = b - a;
      paint(a.cwiseMin(b) - Vector3::Constant(r), a.cwiseMax(b) + Vector3::Constant(r), label,
            [&](double x, double y, double z, unsigned char)
            {
              const Vector3 p(x, y, z);
              const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-12), 0.0, 1.0);
              return (p - a - t * ab).squaredNorm() <= r * r;
            });
    }
  }

private:
  unsigned char* m_Voxels;
};

} // namespace

MaskVolume::Pointer ctLikeLabelMap()
{
  GridSpec grid;
  grid.size = { nx, ny, nz };
  grid.spacing = { sx, sy, sz };
  MaskVolume::Pointer labels = rasterizePhantom(Sphere(Vector3(1e6, 0, 0), 1.0), grid); // all 0
  Canvas canvas(labels.GetPointer());
  const Vector3 c(nx / 2 * sx, ny / 2 * sy, nz / 2 * sz);
  // Skin (2) and body (1): an elliptic cylinder over slices 10 to 389.
  canvas.paint(Vector3(0, 0, 10 * sz), Vector3(nx * sx, ny * sy, 389 * sz), 2,
               [&](double x, double y, double, unsigned char)
               { return std::pow((x - c.x()) / 230.0, 2) + std::pow((y - c.y()) / 160.0, 2) <= 1.0; });
  canvas.paint(Vector3(0, 0, 10 * sz), Vector3(nx * sx, ny * sy, 389 * sz), 1,
               [&](double x, double y, double, unsigned char)
               { return std::pow((x - c.x()) / 228.0, 2) + std::pow((y - c.y()) / 158.0, 2) <= 1.0; });
  canvas.ellipsoid(3, c + Vector3(-75, 0, 120), Vector3(60, 80, 110), 0.0, 1); // lungs, within the body
  canvas.ellipsoid(4, c + Vector3(75, 0, 120), Vector3(60, 80, 110), 0.0, 1);
  canvas.ellipsoid(5, c + Vector3(-10, -30, 90), Vector3(55, 45, 50));         // heart, touching the lungs
  // Liver: eight segments (7-14) by three planes through its centre.
  const Vector3 liver = c + Vector3(-70, 0, 0);
  for (int segment = 0; segment < 8; ++segment)
    canvas.paint(liver - Vector3(90, 75, 70), liver + Vector3(90, 75, 70), static_cast<unsigned char>(7 + segment),
                 [&](double x, double y, double z, unsigned char)
                 {
                   const Vector3 d = (Vector3(x, y, z) - liver).cwiseQuotient(Vector3(90, 75, 70));
                   const int side = (d.x() > 0) + 2 * (d.y() > 0) + 4 * (d.z() > 0);
                   return d.squaredNorm() <= 1.0 && side == segment;
                 });
  canvas.ellipsoid(6, c + Vector3(-40, 20, 0), Vector3(15, 12, 20)); // a lobe inside the liver
  for (const auto& [side, medulla, cortex] : { std::tuple{ -1.0, 15, 17 }, std::tuple{ 1.0, 16, 18 } })
  {
    canvas.ellipsoid(static_cast<unsigned char>(cortex), c + Vector3(side * 80, 60, -40), Vector3(30, 25, 55));
    canvas.ellipsoid(static_cast<unsigned char>(medulla), c + Vector3(side * 80, 60, -40), Vector3(26, 21, 51));
  }
  canvas.ellipsoid(19, c + Vector3(90, 30, 20), Vector3(40, 30, 50));         // spleen
  canvas.ellipsoid(20, c + Vector3(40, -40, 10), Vector3(45, 35, 40), 3.0);   // stomach wall
  canvas.ellipsoid(21, c + Vector3(0, -50, -170), Vector3(40, 35, 25), 2.5);  // bladder wall
  canvas.tube(22, { Vector3(c.x(), c.y() + 100, 10 * sz), Vector3(c.x(), c.y() + 100, 389 * sz) }, 6.0); // spinal canal
  for (int v = 0; v < 23; ++v) // vertebral bodies, each on the one below
  {
    const double z0 = 12 * sz + v * 21.0;
    const Vector3 axis(c.x(), c.y() + 75, 0);
    canvas.paint(Vector3(axis.x() - 20, axis.y() - 20, z0), Vector3(axis.x() + 20, axis.y() + 20, z0 + 21),
                 static_cast<unsigned char>(23 + v),
                 [&](double x, double y, double z, unsigned char)
                 { return std::pow(x - axis.x(), 2) + std::pow(y - axis.y(), 2) <= 400.0 && z >= z0 && z < z0 + 21; });
  }
  for (int r = 0; r < 24; ++r) // ribs: curved tubes 7 mm thick
  {
    const double side = r % 2 ? -1.0 : 1.0, z = c.z() + 10 + (r / 2) * 14;
    std::vector<Vector3> line;
    for (int s = 0; s < 25; ++s)
    {
      const double t = 0.1 + 2.5 * s / 24.0;
      line.emplace_back(c.x() + side * (25 + 180 * std::sin(t / 1.3)), c.y() + 90 - 84 * (1 - std::cos(t)), z - 8 * t);
    }
    canvas.tube(static_cast<unsigned char>(46 + r), line, 3.5);
  }
  canvas.tube(70, { Vector3(c.x() + 20, c.y() + 50, 20), Vector3(c.x() + 20, c.y() + 50, 350), Vector3(c.x(), c.y() + 10, 400),
                    Vector3(c.x() - 20, c.y() + 30, 440) },
              12.0); // aorta
  canvas.tube(71, { Vector3(c.x() - 30, c.y() + 50, 20), Vector3(c.x() - 30, c.y() + 45, 380) }, 10.0); // vena cava
  for (int n = 0; n < 10; ++n) // lymph nodes
    canvas.ellipsoid(static_cast<unsigned char>(72 + n), c + Vector3(-100 + 22 * n, -80 + (n % 3) * 10, -80 + 6 * n),
                     Vector3(3 + 0.3 * n, 3 + 0.3 * n, 4));
  canvas.at(100, 100, 100) = 82; // labels of one to three voxels
  canvas.at(110, 100, 100) = canvas.at(110, 100, 101) = 83;
  canvas.at(120, 100, 100) = canvas.at(120, 101, 100) = canvas.at(120, 102, 100) = 84;
  canvas.at(130, 130, 130) = canvas.at(131, 131, 131) = 85; // two voxels meeting at a corner
  std::vector<Vector3> helix;
  for (int s = 0; s <= 200; ++s)
  {
    const double t = 8.0 * M_PI * s / 200.0;
    helix.emplace_back(c.x() + 60 + 25 * std::cos(t), c.y() - 10 + 25 * std::sin(t), 80 + 10 * t);
  }
  canvas.tube(86, helix, 1.5); // a thin vessel
  std::mt19937 random(1);
  std::normal_distribution<double> step(0.0, 6.0);
  std::vector<Vector3> bowel{ c + Vector3(-40, -60, -60) };
  for (int s = 0; s < 60; ++s)
    bowel.push_back(bowel.back() + Vector3(step(random), step(random), step(random)));
  canvas.tube(87, bowel, 7.0);
  return labels;
}

} // namespace slicemesh
