// Two squares, one above the other, through the installed library's one meshing path: a valid box.
#include <slicemesh/Meshing/MeshContours.h>

#include <cstdio>

int main()
{
  using namespace slicemesh;
  const Polygon2 square{ { 0.0, 0.0 }, { 10.0, 0.0 }, { 10.0, 10.0 }, { 0.0, 10.0 } };
  ContourStack stack;
  stack.slices = { Slice{ 0.0, { square } }, Slice{ 2.0, { square } } };
  stack.sliceSpacing = 2.0;
  const MeshedContours meshed = meshContours(stack, {}, { 1.0, 1.0, 2.0 });
  const MeshValidation& validation = meshed.surface.validation;
  std::printf("%s\n", validation.summary().c_str());
  return validation.valid() && validation.closed() && validation.components == 1 ? 0 : 1;
}
