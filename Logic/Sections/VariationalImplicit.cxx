#include "Sections/VariationalImplicit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace slicemesh
{

Eigen::Vector3d VariationalImplicitFunction::normalised(const Point3& p) const
{
  return (Eigen::Vector3d(p.x, p.y, p.z) - m_Shift) / m_Scale;
}

void VariationalImplicitFunction::fit(const std::vector<ImplicitConstraint>& constraints)
{
  // Drop exact duplicate positions: they would make two rows of A equal.
  std::vector<std::size_t> order(constraints.size());
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](std::size_t i) {
    const Point3& p = constraints[i].position;
    return std::make_tuple(p.x, p.y, p.z);
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  std::vector<std::size_t> kept;
  for (std::size_t k = 0; k < order.size(); ++k)
    if (k == 0 || key(order[k]) != key(order[k - 1]))
      kept.push_back(order[k]);
  std::sort(kept.begin(), kept.end()); // back to input order: the result does not depend on sorting
  const auto n = static_cast<Eigen::Index>(kept.size());
  if (n < 4)
    throw Error("implicit function: fewer than four distinct constraints");

  Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo;
  for (std::size_t i : kept)
  {
    const Point3& p = constraints[i].position;
    lo = lo.cwiseMin(Eigen::Vector3d(p.x, p.y, p.z));
    hi = hi.cwiseMax(Eigen::Vector3d(p.x, p.y, p.z));
  }
  m_Shift = 0.5 * (lo + hi);
  m_Scale = std::max(0.5 * (hi - lo).maxCoeff(), 1e-12);

  m_Centres.resize(3, n);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + 4);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    const ImplicitConstraint& c = constraints[kept[static_cast<std::size_t>(i)]];
    m_Centres.col(i) = normalised(c.position);
    rhs(i) = c.value;
  }

  // The linear term is determined only if the centres span 3D (P of full column rank 4).
  Eigen::Matrix<double, Eigen::Dynamic, 4> P(n, 4);
  P.col(0).setOnes();
  P.rightCols<3>() = m_Centres.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> gram(P.transpose() * P);
  if (!(gram.eigenvalues()(0) > 1e-12 * gram.eigenvalues()(3)))
    throw Error("implicit function: all centres lie in one plane, so the linear term is undetermined");

  // The block system of the header: A (phi = r^3) bordered by the linear polynomial P.
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(n + 4, n + 4);
  for (Eigen::Index j = 0; j < n; ++j)
  {
    for (Eigen::Index i = j + 1; i < n; ++i)
    {
      const double r = (m_Centres.col(i) - m_Centres.col(j)).norm();
      system(i, j) = system(j, i) = r * r * r;
    }
    system(j, n) = system(n, j) = 1.0;
    for (int d = 0; d < 3; ++d)
      system(j, n + 1 + d) = system(n + 1 + d, j) = m_Centres(d, j);
  }
  // The matrix is symmetric but indefinite (a saddle-point system): LU with partial pivoting.
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(system);
  const Eigen::VectorXd solution = lu.solve(rhs);
  if (!solution.allFinite())
    throw Error("implicit function: the interpolation system is singular");
  m_Weights = solution.head(n);
  m_Polynomial = solution.tail<4>();
  const Eigen::VectorXd check = system * solution - rhs;
  m_Residual = check.head(n).cwiseAbs().maxCoeff();
  const double scaleOfValues = std::max(rhs.cwiseAbs().maxCoeff(), 1e-12);
  if (!(m_Residual <= 1e-6 * scaleOfValues + 1e-9))
    throw Error("implicit function: the interpolation system is too ill-conditioned to solve");
}

double VariationalImplicitFunction::operator()(const Point3& p) const
{
  const Eigen::Vector3d x = normalised(p);
  double f = m_Polynomial(0) + m_Polynomial.tail<3>().dot(x);
  for (Eigen::Index i = 0; i < m_Centres.cols(); ++i)
  {
    const double r = (m_Centres.col(i) - x).norm();
    f += m_Weights(i) * r * r * r;
  }
  return f;
}

void VariationalImplicitFunction::evaluatePlane(const std::vector<Point2>& points, double z,
                                                std::vector<double>& values) const
{
  // The z part of every squared distance is the same for all points of the plane.
  const Eigen::Index n = m_Centres.cols();
  const double zn = (z - m_Shift(2)) / m_Scale;
  const Eigen::ArrayXd dz2 = (m_Centres.row(2).array() - zn).square().transpose();
  const Eigen::ArrayXd cx = m_Centres.row(0).transpose().array(), cy = m_Centres.row(1).transpose().array();
  const Eigen::ArrayXd w = m_Weights.array();
  values.resize(points.size());
  Eigen::ArrayXd r(n);
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    const double xn = (points[k].x - m_Shift(0)) / m_Scale, yn = (points[k].y - m_Shift(1)) / m_Scale;
    r = ((cx - xn).square() + (cy - yn).square() + dz2).sqrt();
    values[k] = m_Polynomial(0) + m_Polynomial(1) * xn + m_Polynomial(2) * yn + m_Polynomial(3) * zn +
                (w * r * r * r).sum();
  }
}

} // namespace slicemesh
