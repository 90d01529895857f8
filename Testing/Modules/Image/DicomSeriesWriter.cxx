#include "DicomSeriesWriter.h"

#include "dcmtk/config/osconfig.h"
#include "dcmtk/dcmdata/dcdeftag.h"
#include "dcmtk/dcmdata/dcfilefo.h"
#include "dcmtk/dcmdata/dcuid.h"

#include "itkGDCMImageIO.h"
#include "itkImageSeriesWriter.h"
#include "itkMetaDataObject.h"
#include "itkNumericSeriesFileNames.h"

#include <sstream>
#include <stdexcept>
#include <vector>

namespace slicemesh::testing
{

void writeCTSeries(const CTVolume* volume, const std::filesystem::path& folder, const std::string& seriesUID)
{
  std::filesystem::create_directories(folder);
  const long slices = static_cast<long>(volume->GetLargestPossibleRegion().GetSize()[2]);
  auto names = itk::NumericSeriesFileNames::New();
  names->SetSeriesFormat((folder / "slice%03d.dcm").string());
  names->SetStartIndex(0);
  names->SetEndIndex(slices - 1);
  const CTVolume::DirectionType& direction = volume->GetDirection();
  const CTVolume::SpacingType& spacing = volume->GetSpacing();
  std::vector<itk::MetaDataDictionary> dictionaries(static_cast<std::size_t>(slices));
  itk::ImageSeriesWriter<CTVolume, itk::Image<short, 2>>::DictionaryArrayType headers;
  for (long k = 0; k < slices; ++k)
  {
    CTVolume::PointType position;
    volume->TransformIndexToPhysicalPoint({ { 0, 0, k } }, position);
    std::ostringstream positionText, orientationText, pixelSpacing, thickness;
    positionText.precision(10);
    orientationText.precision(10);
    positionText << position[0] << "\\" << position[1] << "\\" << position[2];
    orientationText << direction[0][0] << "\\" << direction[1][0] << "\\" << direction[2][0] << "\\"
                    << direction[0][1] << "\\" << direction[1][1] << "\\" << direction[2][1];
    pixelSpacing << spacing[1] << "\\" << spacing[0]; // rows, then columns
    thickness << spacing[2];
    itk::MetaDataDictionary& header = dictionaries[static_cast<std::size_t>(k)];
    itk::EncapsulateMetaData<std::string>(header, "0008|0016", "1.2.840.10008.5.1.4.1.1.2"); // CT image
    itk::EncapsulateMetaData<std::string>(header, "0008|0060", "CT");
    itk::EncapsulateMetaData<std::string>(header, "0020|000d", "1.2.826.0.1.3680043.2.1125.1.1");
    itk::EncapsulateMetaData<std::string>(header, "0020|000e",
                                          seriesUID.empty() ? "1.2.826.0.1.3680043.2.1125.1.2" : seriesUID);
    if (!seriesUID.empty()) // kept UIDs: each file needs an instance UID of its own
      itk::EncapsulateMetaData<std::string>(header, "0008|0018",
                                            seriesUID + "." + std::to_string(k + 1));
    itk::EncapsulateMetaData<std::string>(header, "0020|0013", std::to_string(k + 1));
    itk::EncapsulateMetaData<std::string>(header, "0020|0032", positionText.str());
    itk::EncapsulateMetaData<std::string>(header, "0020|0037", orientationText.str());
    itk::EncapsulateMetaData<std::string>(header, "0028|0030", pixelSpacing.str());
    itk::EncapsulateMetaData<std::string>(header, "0018|0050", thickness.str());
    headers.push_back(&header);
  }
  auto writer = itk::ImageSeriesWriter<CTVolume, itk::Image<short, 2>>::New();
  writer->SetInput(volume);
  writer->SetMetaDataDictionaryArray(&headers);
  auto io = itk::GDCMImageIO::New();
  io->SetKeepOriginalUID(!seriesUID.empty()); // else GDCM makes new UIDs for every call
  writer->SetImageIO(io);
  writer->SetFileNames(names->GetFileNames());
  writer->Update();
}

void writeMultiFrameFile(const CTVolume* volume, const std::filesystem::path& file)
{
  // GDCM's writer refuses a 3-D image of this class; DCMTK writes the attributes as they are.
  const CTVolume::SizeType size = volume->GetLargestPossibleRegion().GetSize();
  DcmFileFormat format;
  DcmDataset* data = format.getDataset();
  data->putAndInsertString(DCM_SOPClassUID, UID_MultiframeGrayscaleWordSecondaryCaptureImageStorage);
  data->putAndInsertString(DCM_SOPInstanceUID, "1.2.826.0.1.3680043.2.1125.1.9.1");
  data->putAndInsertString(DCM_StudyInstanceUID, "1.2.826.0.1.3680043.2.1125.1.9");
  data->putAndInsertString(DCM_SeriesInstanceUID, "1.2.826.0.1.3680043.2.1125.1.9.2");
  data->putAndInsertString(DCM_Modality, "OT");
  data->putAndInsertString(DCM_NumberOfFrames, std::to_string(size[2]).c_str());
  data->putAndInsertUint16(DCM_Rows, static_cast<Uint16>(size[1]));
  data->putAndInsertUint16(DCM_Columns, static_cast<Uint16>(size[0]));
  data->putAndInsertUint16(DCM_SamplesPerPixel, 1);
  data->putAndInsertString(DCM_PhotometricInterpretation, "MONOCHROME2");
  data->putAndInsertUint16(DCM_BitsAllocated, 16);
  data->putAndInsertUint16(DCM_BitsStored, 16);
  data->putAndInsertUint16(DCM_HighBit, 15);
  data->putAndInsertUint16(DCM_PixelRepresentation, 1);
  data->putAndInsertUint16Array(DCM_PixelData, reinterpret_cast<const Uint16*>(volume->GetBufferPointer()),
                                static_cast<unsigned long>(volume->GetBufferedRegion().GetNumberOfPixels()));
  if (format.saveFile(file.string().c_str(), EXS_LittleEndianExplicit).bad())
    throw std::runtime_error("cannot write " + file.string());
}

void rewriteDicomString(const std::filesystem::path& file, unsigned short group, unsigned short element,
                        const std::string& value)
{
  DcmFileFormat format;
  if (format.loadFile(file.string().c_str()).bad() ||
      format.getDataset()->putAndInsertString(DcmTagKey(group, element), value.c_str()).bad() ||
      format.saveFile(file.string().c_str()).bad())
    throw std::runtime_error("cannot rewrite " + file.string());
}

} // namespace slicemesh::testing
