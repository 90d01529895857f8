// A CT series as a scanner writes it, one file per slice, for the tests that read DICOM folders.
#ifndef DicomSeriesWriter_h
#define DicomSeriesWriter_h

#include "itkImage.h"

#include <filesystem>
#include <string>

namespace slicemesh::testing
{

using CTVolume = itk::Image<short, 3>;

/** Writes `volume` into `folder` as slice000.dcm, slice001.dcm, ...: CT images of one study and one
 *  series, each slice with its instance number, position, orientation, pixel spacing and slice
 *  thickness, from the volume's origin, direction and spacing. Each call makes a series of its own,
 *  unless `seriesUID` is given: the files of every call given the same one are one series. */
void writeCTSeries(const CTVolume* volume, const std::filesystem::path& folder, const std::string& seriesUID = {});

/** Writes `volume` as one multi-frame file (Multi-frame Grayscale Word Secondary Capture), a frame
 *  per slice, as an enhanced CT or MR keeps a whole series in one file. */
void writeMultiFrameFile(const CTVolume* volume, const std::filesystem::path& file);

/** Rewrites one string attribute (group, element) of a DICOM file as `value`, to make a header
 *  that no writer would (GDCM's normalises the orientation it writes). */
void rewriteDicomString(const std::filesystem::path& file, unsigned short group, unsigned short element,
                        const std::string& value);

} // namespace slicemesh::testing

#endif
