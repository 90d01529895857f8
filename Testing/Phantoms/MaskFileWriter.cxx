#include "MaskFileWriter.h"

#include "Core/SliceMeshTypes.h"

#include "itkImageFileWriter.h"

namespace slicemesh
{

void writeMaskFile(const MaskVolume* mask, const std::string& path)
{
  auto writer = itk::ImageFileWriter<MaskVolume>::New();
  writer->SetInput(mask);
  writer->SetFileName(path);
  writer->UseCompressionOn();
  try
  {
    writer->Update();
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(path + ": cannot write the image: " + error.GetDescription());
  }
}

} // namespace slicemesh
