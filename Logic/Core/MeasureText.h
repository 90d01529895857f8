// How a message prints a measure (mm, mm^3, a count): with the decimals it is read to, and compact
// where those would mislead or run on.
#ifndef MeasureText_h
#define MeasureText_h

#include <string>

namespace slicemesh
{

/** `value` with `decimals` decimals, as the messages and the summary print a measure; in three
 *  significant digits where that would round a non-zero value to 0 (a structure on a micrometre
 *  grid), and in six with an exponent from 1e15 on (a stray coordinate of 1e300 in a contour file),
 *  where a double's fixed digits would be hundreds of noise. */
std::string measureText(double value, int decimals);

} // namespace slicemesh

#endif
