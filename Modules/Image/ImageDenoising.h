// Smoothing a grayscale volume before it is segmented: Gaussian and/or curvature anisotropic diffusion.
#ifndef ImageDenoising_h
#define ImageDenoising_h

#include "ComponentLabeling.h"

namespace slicemesh
{

struct DenoisingOptions
{
  /** Standard deviation of a Gaussian blur in mm (recursive Gaussian, ITK); 0 turns it off. */
  double gaussianSigma = 0.0;
  /** Curvature anisotropic diffusion (edge-preserving; ITK): number of iterations; 0 turns it off. */
  unsigned int diffusionIterations = 0;
  /** Conductance of the diffusion: lower keeps more edges (ITK's usual 1..3). */
  double diffusionConductance = 1.0;
  /** Per slice (default) or in 3D. */
  ProcessingDimension dimension = ProcessingDimension::Slice2D;

  bool any() const { return gaussianSigma > 0.0 || diffusionIterations > 0; }
};

/** The Gaussian first, then the diffusion (each when on). The diffusion's time step is the stable
 *  limit for the spacing: min spacing / 2^(d+1) (d = 2 per slice, 3 in 3D). Returns a new volume;
 *  the input when nothing is on. */
ScalarVolume::Pointer denoiseVolume(const ScalarVolume* volume, const DenoisingOptions& options);

} // namespace slicemesh

#endif
