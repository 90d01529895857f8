// Contours through the path a user's structure set takes: written as an RTSTRUCT, read back and
// meshed by the command line's pipeline with its default settings, the mesh read from its file. A
// file of its own: the phantoms' Vector3 (Eigen) and the structure set's (std::array) cannot meet in
// one file.
#ifndef StructureSetMeshing_h
#define StructureSetMeshing_h

#include "Core/SliceMeshTypes.h"

#include <string>
#include <vector>

namespace slicemesh::testing
{

/** The contours (LPS mm, each a closed polygon of one slice) written as the one ROI of
 *  `folder`/RS.dcm, meshed as `SliceMesh RS.dcm mesh.vtp` meshes them (cli::runPipeline with the
 *  default settings, or with --holdContours) into `folder`/mesh.vtp, and that mesh (LPS mm). Throws
 *  when the run fails or the ROI is not meshed. */
TriangleMesh meshAsStructureSet(const std::vector<std::vector<Point3>>& contours, const std::string& folder,
                                bool holdContours = false);

} // namespace slicemesh::testing

#endif
