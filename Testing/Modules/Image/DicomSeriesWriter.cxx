#include "DicomSeriesWriter.h"

#include "itkGDCMImageIO.h"
#include "itkImageSeriesWriter.h"
#include "itkMetaDataObject.h"
#include "itkNumericSeriesFileNames.h"

#include <sstream>
#include <vector>

namespace slicemesh::testing
{

void writeCTSeries(const CTVolume* volume, const std::filesystem::path& folder)
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
    itk::EncapsulateMetaData<std::string>(header, "0020|000e", "1.2.826.0.1.3680043.2.1125.1.2");
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
  writer->SetImageIO(itk::GDCMImageIO::New());
  writer->SetFileNames(names->GetFileNames());
  writer->Update();
}

} // namespace slicemesh::testing
