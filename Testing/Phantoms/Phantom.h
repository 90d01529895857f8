// An analytic shape for tests and benchmarks: an exact signed distance function in physical
// space (millimetres, negative inside), its exact volume and an axis-aligned box around it.
#ifndef Phantom_h
#define Phantom_h

#include <Eigen/Core>

#include <memory>

namespace slicemesh
{

using Vector3 = Eigen::Vector3d;
/** A rotation: its columns are the shape's own axes expressed in physical space. */
using Matrix3 = Eigen::Matrix3d;

/** Axis-aligned bounds in physical space (mm). */
struct Bounds
{
  Vector3 lower = Vector3::Zero();
  Vector3 upper = Vector3::Zero();
};

class Phantom
{
public:
  virtual ~Phantom() = default;
  /** Euclidean distance to the surface, negative inside, positive outside (mm). */
  virtual double signedDistance(const Vector3& point) const = 0;
  /** Enclosed volume (mm^3). */
  virtual double volume() const = 0;
  /** A box containing the shape; tight for the primitive shapes. */
  virtual Bounds bounds() const = 0;
};

using PhantomPointer = std::shared_ptr<const Phantom>;

/** Throws std::invalid_argument unless rotation is orthonormal with determinant +1. */
void checkRotation(const Matrix3& rotation);

/** The unit vector along axis; throws std::invalid_argument for a zero or non-finite axis. */
Vector3 unitAxis(const Vector3& axis);

} // namespace slicemesh

#endif
