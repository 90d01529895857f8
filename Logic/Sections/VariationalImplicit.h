// A variational implicit function: the smoothest function through scattered values in 3D.
//
// Turk & O'Brien, "Shape transformation using variational implicit functions" (SIGGRAPH 1999) and
// "Modelling with implicit surfaces that interpolate" (ACM TOG 2002); Carr et al., "Reconstruction
// and representation of 3D objects with radial basis functions" (SIGGRAPH 2001).
//
//   f(x) = sum_i w_i phi(|x - c_i|) + p(x),   phi(r) = r^3,   p(x) = a + b.x   (linear polynomial)
//
// In 3D, phi(r) = r^3 is the radial basis for which the interpolant minimises the thin-plate
// (biharmonic-type) energy, integral of |D^2 f|^2 over R^3 with derivatives of order two. The weights
// and polynomial follow from the symmetric, indefinite system
//
//   [ A   P ] [ w ]   [ h ]        A_ij = phi(|c_i - c_j|),  P_i = (1, c_i),
//   [ P^T 0 ] [ a ] = [ 0 ]        h_i = the value required at c_i,
//
// whose last rows say the weights are orthogonal to linear polynomials (so f grows like |x| at
// infinity, not |x|^3). Dense LU costs O(n^3): keep n to a few thousand at most (see ContourConstraints
// for the subsampling that keeps it near 600).
#ifndef VariationalImplicit_h
#define VariationalImplicit_h

#include "Core/SliceMeshTypes.h"

#include <Eigen/Core>

#include <vector>

namespace slicemesh
{

/** Asks f(position) == value. */
struct ImplicitConstraint
{
  Point3 position;
  double value = 0.0;
};

class VariationalImplicitFunction
{
public:
  /** Solves for the function through the constraints. Exact duplicates of a position are dropped
   *  (the first one counts). Throws slicemesh::Error when fewer than four constraints remain or when
   *  the centres all lie in one plane (the linear term is then undetermined) or the solve fails. */
  void fit(const std::vector<ImplicitConstraint>& constraints);

  double operator()(const Point3& p) const;

  /** Values at many points of one plane z (faster than one call per point). */
  void evaluatePlane(const std::vector<Point2>& points, double z, std::vector<double>& values) const;

  std::size_t centres() const { return static_cast<std::size_t>(m_Centres.cols()); }
  /** Largest |f - value| over the constraints after the solve (a check on the solve). */
  double residual() const { return m_Residual; }

private:
  // Centres and evaluation points are shifted and scaled into about [-1, 1]^3 for conditioning.
  Eigen::Vector3d normalised(const Point3& p) const;

  Eigen::Matrix3Xd m_Centres;
  Eigen::VectorXd m_Weights;
  Eigen::Vector4d m_Polynomial = Eigen::Vector4d::Zero();
  Eigen::Vector3d m_Shift = Eigen::Vector3d::Zero();
  double m_Scale = 1.0;
  double m_Residual = 0.0;
};

} // namespace slicemesh

#endif
