#include "RealDataSupport.h"

#include "ContourExtraction.h"

#include "itkImageRegionConstIteratorWithIndex.h"

#include <filesystem>

namespace slicemesh::testing
{

std::string externalData(const std::string& name)
{
  return std::string(SLICEMESH_EXTERNAL_DATA_DIR) + "/" + name;
}

std::string outputPath(const std::string& name)
{
  std::filesystem::create_directories(SLICEMESH_TEST_OUTPUT_DIR);
  return std::string(SLICEMESH_TEST_OUTPUT_DIR) + "/" + name;
}

void Box::add(const std::array<double, 3>& p)
{
  for (int a = 0; a < 3; ++a)
  {
    lower[a] = std::min(lower[a], p[a]);
    upper[a] = std::max(upper[a], p[a]);
  }
}

bool Box::contains(const Box& inner, double tolerance) const
{
  for (int a = 0; a < 3; ++a)
    if (inner.lower[a] < lower[a] - tolerance || inner.upper[a] > upper[a] + tolerance)
      return false;
  return true;
}

MaskMesh meshMask(const MaskVolume* mask, const ReconstructionOptions& options)
{
  MaskMesh result;
  const TriangleMesh stackMesh = reconstructSurface(extractContours(mask), options);
  result.validation = validateMesh(stackMesh);
  result.physical = mapToPhysicalSpace(stackMesh, sliceFrameOf(mask), CoordinateSystem::LPS);
  for (const Point3& p : result.physical.points)
    result.meshBox.add({ p.x, p.y, p.z });

  const auto region = mask->GetBufferedRegion();
  const auto spacing = mask->GetSpacing();
  const auto direction = mask->GetDirection();
  result.voxelVolume = 0.0;
  const unsigned char* voxel = mask->GetBufferPointer();
  for (itk::ImageRegionConstIteratorWithIndex<MaskVolume> it(mask, region); !it.IsAtEnd(); ++it)
  {
    if (!it.Get())
      continue;
    itk::Point<double, 3> centre;
    mask->TransformIndexToPhysicalPoint(it.GetIndex(), centre);
    result.centreBox.add({ centre[0], centre[1], centre[2] });
    for (int corner = 0; corner < 8; ++corner)
    {
      std::array<double, 3> p{ centre[0], centre[1], centre[2] };
      for (int axis = 0; axis < 3; ++axis)
      {
        const double half = ((corner >> axis) & 1 ? 0.5 : -0.5) * spacing[axis];
        for (int row = 0; row < 3; ++row)
          p[row] += direction[row][axis] * half;
      }
      result.cubeBox.add(p);
    }
    result.voxelVolume += spacing[0] * spacing[1] * spacing[2];
  }
  (void)voxel;
  return result;
}

} // namespace slicemesh::testing
