// A DICOM image series through ITK's GDCM reader (part of the plugin SliceMeshImageDicom).
#include "DicomImageReaders.h"

#include "ItkErrorText.h"

#include "Core/SliceMeshTypes.h"

#include "itkGDCMImageIO.h"
#include "itkGDCMSeriesFileNames.h"
#include "itkImageSeriesReader.h"

namespace slicemesh
{

namespace
{

/** The files of the largest DICOM image series in the folder, in slice order. */
std::vector<std::string> dicomSeriesFiles(const std::string& folder)
{
  auto names = itk::GDCMSeriesFileNames::New();
  std::vector<std::string> fileNames;
  try
  {
    names->SetUseSeriesDetails(true);
    names->SetDirectory(folder);
    const std::vector<std::string>& seriesUIDs = names->GetSeriesUIDs();
    if (seriesUIDs.empty())
      throw Error(folder + ": a directory without a DICOM image series");
    // The series of the most files: an export holds the image series beside one-file objects of
    // their own series (a structure set, a localizer, a dose), which are no volume.
    for (const std::string& uid : seriesUIDs)
    {
      std::vector<std::string> files = names->GetFileNames(uid);
      if (files.size() > fileNames.size())
        fileNames = std::move(files);
    }
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(folder + ": cannot list the DICOM series: " + itkErrorText(error));
  }
  if (fileNames.size() < 2)
    throw Error(folder + ": the DICOM series has a single slice (a 2-D image); SliceMesh needs a 3-D volume");
  return fileNames;
}

} // namespace

ScalarVolume::Pointer readDicomSeriesIn(const std::string& folder, bool voxels)
{
  auto reader = itk::ImageSeriesReader<ScalarVolume>::New();
  reader->SetImageIO(itk::GDCMImageIO::New());
  reader->SetFileNames(dicomSeriesFiles(folder));
  // The series reader orders the slices and takes the spacing between them from their positions.
  if (voxels)
    reader->Update();
  else
    reader->UpdateOutputInformation();
  ScalarVolume::Pointer volume = reader->GetOutput();
  volume->DisconnectPipeline();
  return volume;
}

} // namespace slicemesh
