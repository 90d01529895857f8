// A check shared by the tests of the validations that take a shortcut (after moving points, after a
// local change, the widening's): the result is the whole validation's, field by field.
#ifndef SameValidation_h
#define SameValidation_h

#include "Measures/MeshValidation.h"

#include <gtest/gtest.h>

#include <string>

namespace slicemesh
{
namespace testing
{

inline void expectSameValidation(const MeshValidation& a, const MeshValidation& b, const std::string& where)
{
  EXPECT_EQ(a.vertices, b.vertices) << where;
  EXPECT_EQ(a.triangles, b.triangles) << where;
  EXPECT_EQ(a.degenerateTriangles, b.degenerateTriangles) << where;
  EXPECT_EQ(a.boundaryEdges, b.boundaryEdges) << where;
  EXPECT_EQ(a.nonManifoldEdges, b.nonManifoldEdges) << where;
  EXPECT_EQ(a.nonManifoldVertices, b.nonManifoldVertices) << where;
  EXPECT_EQ(a.inconsistentEdges, b.inconsistentEdges) << where;
  EXPECT_EQ(a.misorientedComponents, b.misorientedComponents) << where;
  EXPECT_EQ(a.foldedEdges, b.foldedEdges) << where;
  EXPECT_EQ(a.selfIntersections, b.selfIntersections) << where;
  EXPECT_EQ(a.selfIntersectionChecked, b.selfIntersectionChecked) << where;
  EXPECT_EQ(a.components, b.components) << where;
  EXPECT_EQ(a.eulerCharacteristic, b.eulerCharacteristic) << where;
  EXPECT_EQ(a.area, b.area) << where; // bit for bit: the same sums in the same order
  EXPECT_EQ(a.volume, b.volume) << where;
  EXPECT_EQ(a.minAngleDegrees, b.minAngleDegrees) << where;
  EXPECT_EQ(a.fractionAnglesBelow30, b.fractionAnglesBelow30) << where;
}

} // namespace testing
} // namespace slicemesh

#endif
