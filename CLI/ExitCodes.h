// SliceMesh's exit codes; the README lists them. 0 only when a valid mesh was written.
#ifndef ExitCodes_h
#define ExitCodes_h

namespace slicemesh::cli
{

enum ExitCode : int
{
  Success = 0,
  InternalError = 1,     ///< an unexpected failure (a bug): please report it
  BadArguments = 2,      ///< unknown option, bad value, missing argument
  UnreadableInput = 3,   ///< the input volume is missing or cannot be read as a 3D image
  EmptySegmentation = 4, ///< nothing to mesh (the label / threshold selects no voxel), or a volume that cannot
                         ///< be segmented as asked (a label map refused for its values)
  MeshingFailed = 5,     ///< contour extraction or surface reconstruction failed
  WriteFailed = 6,       ///< the mesh (or the return-parameter file) could not be written
  InvalidMesh = 7        ///< the mesh was written but failed validation (see the warning on stderr)
};

} // namespace slicemesh::cli

#endif
