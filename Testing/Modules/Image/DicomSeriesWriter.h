// A CT series as a scanner writes it, one file per slice, for the tests that read DICOM folders.
#ifndef DicomSeriesWriter_h
#define DicomSeriesWriter_h

#include "itkImage.h"

#include <filesystem>

namespace slicemesh::testing
{

using CTVolume = itk::Image<short, 3>;

/** Writes `volume` into `folder` as slice000.dcm, slice001.dcm, ...: CT images of one study and one
 *  series, each slice with its instance number, position, orientation, pixel spacing and slice
 *  thickness, from the volume's origin, direction and spacing. */
void writeCTSeries(const CTVolume* volume, const std::filesystem::path& folder);

} // namespace slicemesh::testing

#endif
