#include "Phantom.h"

#include <Eigen/LU>

#include <cmath>
#include <stdexcept>

namespace slicemesh
{

void checkRotation(const Matrix3& rotation)
{
  if (!rotation.allFinite() || !(rotation.transpose() * rotation).isIdentity(1e-9) ||
      std::abs(rotation.determinant() - 1.0) > 1e-9)
    throw std::invalid_argument("phantom: the rotation matrix is not a proper rotation");
}

Vector3 unitAxis(const Vector3& axis)
{
  const double length = axis.norm();
  if (!std::isfinite(length) || length == 0.0)
    throw std::invalid_argument("phantom: the axis direction has no length");
  return axis / length;
}

} // namespace slicemesh
