// Fills the holes of a binary mask, per slice or in 3D.
#ifndef HoleFilling_h
#define HoleFilling_h

#include "ComponentLabeling.h"

namespace slicemesh
{

/** Sets to 1 every background region that does not reach the border: of its slice (2D; background
 *  8-connected in the slice, the dual of the 4-connected foreground) or of the volume (3D;
 *  background 26-connected). Returns the number of voxels filled. */
std::size_t fillHoles(MaskVolume* mask, ProcessingDimension dimension);

} // namespace slicemesh

#endif
