// DICOM RT Structure Sets are read through DCMTK's dcmrt in the plugin SliceMeshStructuresDicom
// (Modules/Plugins): only a run that reads one loads DCMTK.
#ifndef RTStructureSetPlugin_h
#define RTStructureSetPlugin_h

#include "StructureSet.h"

#include <cstddef>
#include <string>

namespace slicemesh
{

/** What the plugin does, as its table of functions. */
struct RTStructureSetFunctions
{
  std::size_t size; ///< sizeof(RTStructureSetFunctions) as the plugin was built (pluginFunctions)
  /** The structure set in the file, as readRTStructureSet (StructureSet.h) describes. */
  StructureSet (*read)(const std::string& path);
};

/** The plugin's functions, the plugin loaded on first use. Throws slicemesh::Error when it cannot
 *  be loaded. */
const RTStructureSetFunctions& rtStructureSetFunctions();

} // namespace slicemesh

#endif
