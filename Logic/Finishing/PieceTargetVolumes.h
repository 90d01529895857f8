// The volume each connected piece of a tiling should enclose once finished: the shares of the
// contours it was tiled from, not a share of the whole in proportion to its tiled volume (a speck's
// tiling falls far shorter of its voxels than a large piece's, and the large pieces would make up
// for it).
#ifndef PieceTargetVolumes_h
#define PieceTargetVolumes_h

#include "Measures/ContourVolumes.h"

#include <vector>

namespace slicemesh
{

/** Each piece's target (mm^3): the sum of the shares that fall on it, times total over the sum of all
 *  shares (so that the targets keep to `total` whatever rounding the shares carry). A share falls on
 *  the piece with the nearest vertex at exactly its height: the tiling's vertices on a slice are its
 *  contours' points, or lie next to them where the contours were resampled. A piece no share falls
 *  on gets 0; a share whose height no vertex has counts for no piece. */
std::vector<double> pieceTargetVolumes(const std::vector<const TriangleMesh*>& pieces,
                                       const std::vector<ContourVolume>& shares, double total);

} // namespace slicemesh

#endif
