#include "DicomImagePlugin.h"

#include "PluginLoader.h"

namespace slicemesh
{

const DicomImageFunctions& dicomImageFunctions()
{
  return pluginFunctions<DicomImageFunctions>("libSliceMeshImageDicom.so", "slicemeshDicomImageFunctions",
                                              "Reading DICOM images");
}

} // namespace slicemesh
