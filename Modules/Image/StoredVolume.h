// What a volume read in the pixel type of its file (readStoredVolume) is used through: its image
// information, and its voxels as float where a grayscale method needs them.
#ifndef StoredVolume_h
#define StoredVolume_h

#include "VolumeReader.h"


namespace slicemesh
{

/** The image behind the variant (its region, spacing, origin, direction); null when empty. */
const itk::ImageBase<3>* imageOf(const StoredVolume& volume);

/** The volume as float voxels (the same values): the volume itself when it is float, else a copy
 *  (what grayscale segmentation works on). */
ScalarVolume::Pointer floatVolumeOf(const StoredVolume& volume);

} // namespace slicemesh

#endif
