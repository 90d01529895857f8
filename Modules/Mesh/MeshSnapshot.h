// A picture of a mesh: rendered off screen with VTK, coloured by triangle quality (one mesh) or by
// structure (several meshes, e.g. the labels of an atlas), saved as PNG.
#ifndef MeshSnapshot_h
#define MeshSnapshot_h

#include "Core/SliceMeshTypes.h"

#include <array>
#include <string>
#include <vector>

namespace slicemesh
{

struct SnapshotOptions
{
  int width = 800;
  int height = 600;
  /** Colour scale of each triangle's smallest angle (degrees): red at 0, through yellow at half of
   *  this, to green at and above it. */
  double goodAngleDegrees = 60.0;
};

/** Whether an off-screen picture can be rendered here. VTK 9.1 as Debian builds it renders through
 *  an X display (GLX): without one (no DISPLAY, or no server answering it) this returns false and
 *  says why in `reason`. Run under `xvfb-run` on a machine without a screen. Also false when the
 *  plugin that renders (SnapshotPlugin.h) cannot be loaded, with the loader's reason. */
bool snapshotAvailable(std::string* reason = nullptr);

/** Renders the mesh (physical millimetres) off screen, seen obliquely from the front-right-top of
 *  its bounding box with the whole mesh in view, each triangle coloured by its smallest angle (see
 *  SnapshotOptions), edges drawn, on a white background, and writes it as a PNG file (atomically:
 *  a temporary name in the same folder, renamed when complete). Throws slicemesh::Error when no
 *  display is available or the file cannot be written. */
void writeSnapshot(const TriangleMesh& physicalMesh, const std::string& path, const SnapshotOptions& options = {});

/** Several meshes in one picture, each in its own colour: `meshes` holds them merged (each its own
 *  closed pieces, as the multi-label output model) and `triangleColors` the RGB colour of each
 *  triangle, its mesh's. Same view, background, size and file handling as above; smooth shading,
 *  no edges drawn (an atlas has millions of triangles), and `goodAngleDegrees` is not used.
 *  Throws slicemesh::Error as above, and when there is not one colour per triangle. */
void writeSnapshot(const TriangleMesh& meshes, const std::vector<std::array<unsigned char, 3>>& triangleColors,
                   const std::string& path, const SnapshotOptions& options = {});

} // namespace slicemesh

#endif
