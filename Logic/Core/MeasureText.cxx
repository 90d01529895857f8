#include "MeasureText.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace slicemesh
{

std::string measureText(double value, int decimals)
{
  // From 2^53 (about 9e15) on a double holds no fraction, and its integer digits are mostly noise.
  constexpr double largestInFixed = 1e15;
  std::ostringstream out;
  if (std::abs(value) >= largestInFixed)
    out << std::setprecision(6) << value; // as %g: 1e+300
  else if (value != 0.0 && std::abs(value) < 0.5 * std::pow(10.0, -decimals))
    out << std::setprecision(3) << value;
  else
    out << std::fixed << std::setprecision(decimals) << value;
  return out.str();
}

} // namespace slicemesh
