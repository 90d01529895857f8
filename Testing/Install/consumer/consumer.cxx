// Two squares, one above the other: reconstructSurface must close them into a box.
#include <MeshValidation.h>
#include <SurfaceReconstruction.h>

#include <cstdio>

int main()
{
  using namespace slicemesh;
  const Polygon2 square{ { 0.0, 0.0 }, { 10.0, 0.0 }, { 10.0, 10.0 }, { 0.0, 10.0 } };
  ContourStack stack;
  stack.slices = { Slice{ 0.0, { square } }, Slice{ 2.0, { square } } };
  stack.sliceSpacing = 2.0;
  const TriangleMesh mesh = reconstructSurface(stack);
  const MeshValidation validation = validateMesh(mesh);
  std::printf("%s\n", validation.summary().c_str());
  return validation.valid() && validation.closed() && validation.components == 1 ? 0 : 1;
}
