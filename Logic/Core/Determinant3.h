// The determinant of the 3 x 3 matrix in the first three rows and columns of any m[row][column]:
// a direction matrix, an affine map's linear part.
#ifndef Determinant3_h
#define Determinant3_h

namespace slicemesh
{

template <typename Matrix>
double determinant3(const Matrix& m)
{
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

} // namespace slicemesh

#endif
