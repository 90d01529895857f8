#include "RTStructureSetPlugin.h"

#include "PluginLoader.h"

namespace slicemesh
{

const RTStructureSetFunctions& rtStructureSetFunctions()
{
  return pluginFunctions<RTStructureSetFunctions>("libSliceMeshStructuresDicom.so", "slicemeshRTStructureSetFunctions",
                                                  "Reading a DICOM RT Structure Set");
}

} // namespace slicemesh
