// In-plane Gaussian smoothing of one slice of a mask, before its contours are traced.
#ifndef SliceSmoothing_h
#define SliceSmoothing_h

namespace slicemesh
{

/** Half-width in pixels of the Gaussian kernel of standard deviation sigma (mm) along an axis of
 *  the given pixel spacing (mm): the kernel is cut at 3 sigma. 0 when sigma <= 0. */
long gaussianRadius(double sigma, double spacing);

/** Convolves a width x height float image (row-major, x fastest) in place with a separable
 *  Gaussian of standard deviation sigma (mm), sampled and normalised to sum 1 on the pixel grid,
 *  with zeros outside the image. A 0/1 mask becomes a smooth field whose 0.5 level runs near the
 *  mask's boundary without the voxel staircase; detail thinner than about sigma is lost. */
void smoothSlice(float* pixels, long width, long height, double spacingX, double spacingY, double sigma);

} // namespace slicemesh

#endif
