// The entry of the plugin SliceMeshImageDicom: its table of functions (DicomImagePlugin.h).
#include "DicomImagePlugin.h"
#include "DicomImageReaders.h"

#include "itkGDCMImageIOFactory.h"

extern "C" __attribute__((visibility("default"))) const slicemesh::DicomImageFunctions* slicemeshDicomImageFunctions()
{
  // Registered once, when the plugin is first asked for: from then on ITK's own reader factory
  // finds GDCM for a single DICOM image file too.
  static const bool registered = (itk::GDCMImageIOFactory::RegisterOneFactory(), true);
  (void)registered;
  static const slicemesh::DicomImageFunctions functions{ sizeof(slicemesh::DicomImageFunctions),
                                                         &slicemesh::readDicomSeriesIn, &slicemesh::isDicomSegmentation,
                                                         &slicemesh::readDicomSegmentationFile };
  return &functions;
}
