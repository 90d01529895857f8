// 3D Slicer's segmentation file (.seg.nrrd): a NRRD label map, or a stack of them along a list axis
// (the layers, when segments overlap), with the segments described in SegmentN_ header fields.
// ITK's NRRD reader gives the list axis as the voxel's components and keeps the fields in the
// image's MetaDataDictionary. A fractional labelmap has a layer of fractions per segment, each
// thresholded here into that segment's label map (FractionalLabelmap.h).
#include "SegmentationFile.h"

#include "ColorTable.h"
#include "FractionalLabelmap.h"
#include "ItkErrorText.h"
#include "MemoryBudget.h"
#include "RawVoxelBytes.h"

#include "Core/SliceMeshTypes.h"

#include "itkImageFileReader.h"
#include "itkMetaDataObject.h"
#include "itkNrrdImageIO.h"
#include "itkVectorImage.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace slicemesh
{
namespace
{

/** The SegmentN_ fields of the header, by N and then by field name ("Name", "Color", ...). */
std::map<int, std::map<std::string, std::string>> segmentFields(const itk::MetaDataDictionary& dictionary)
{
  std::map<int, std::map<std::string, std::string>> fields;
  const std::string prefix = "Segment";
  for (const std::string& key : dictionary.GetKeys())
  {
    if (key.compare(0, prefix.size(), prefix) != 0)
      continue;
    std::size_t at = prefix.size();
    while (at < key.size() && key[at] >= '0' && key[at] <= '9')
      ++at;
    if (at == prefix.size() || at >= key.size() || key[at] != '_' || at - prefix.size() > 6)
      continue;
    std::string value;
    if (itk::ExposeMetaData<std::string>(dictionary, key, value))
      fields[std::stoi(key.substr(prefix.size(), at - prefix.size()))][key.substr(at + 1)] = value;
  }
  return fields;
}

std::string headerField(const itk::MetaDataDictionary& dictionary, const std::string& key)
{
  std::string value;
  itk::ExposeMetaData<std::string>(dictionary, key, value);
  return value;
}

/** A field's value as an error message quotes it: on one line, at most 60 characters. */
std::string quoted(const std::string& text)
{
  const std::string line = collapsedWhitespace(text);
  return "'" + (line.size() > 60 ? line.substr(0, 57) + "..." : line) + "'";
}

/** An integer field; throws naming the field when it is not one. */
long integerField(const std::string& path, const std::string& key, const std::string& text)
{
  std::istringstream in(text);
  long value = 0;
  std::string rest;
  if (!(in >> value) || (in >> rest))
    throw Error(path + ": header field " + key + " is " + quoted(text) + ", not an integer");
  return value;
}

std::array<unsigned char, 4> colorField(const std::string& path, const std::string& key, const std::string& text)
{
  std::istringstream in(text);
  double rgb[3];
  if (!(in >> rgb[0] >> rgb[1] >> rgb[2]))
    throw Error(path + ": header field " + key + " is " + quoted(text) + ", not three numbers 0..1 (red green blue)");
  std::array<unsigned char, 4> rgba{ 0, 0, 0, 255 };
  for (int c = 0; c < 3; ++c)
    rgba[c] = static_cast<unsigned char>(std::lround(std::clamp(rgb[c], 0.0, 1.0) * 255.0));
  return rgba;
}

/** A fractional labelmap's range when the header gives none: Slicer's, for its signed char voxels.
 *  Slicer keeps the range as field data of the image in memory, which its NRRD writer does not
 *  write; voxels of another type are of a scale SliceMesh cannot know. */
FractionalRange defaultRange(const std::string& path, itk::IOComponentEnum voxelType)
{
  if (voxelType != itk::IOComponentEnum::CHAR)
  {
    std::string type = itk::ImageIOBase::GetComponentTypeAsString(voxelType);
    std::replace(type.begin(), type.end(), '_', ' ');
    throw Error(path + ": a fractional labelmap of " + type +
                " voxels without SegmentN_ScalarRange fields; Slicer's are signed char from -108 to 108");
  }
  return slicerFractionalRange;
}

} // namespace

SegmentationFile readSlicerSegmentation(const std::string& path)
{
  auto io = itk::NrrdImageIO::New();
  try
  {
    io->SetFileName(path);
    io->ReadImageInformation();
  }
  catch (const itk::ExceptionObject& error)
  {
    // ITK's NRRD reader decompresses the voxels of a gzip file already here.
    throw Error(path + ": cannot read the NRRD header or voxels (a truncated or damaged file?): " + itkErrorText(error));
  }
  if (io->GetNumberOfDimensions() != 3)
    throw Error(path + ": a segmentation of " + std::to_string(io->GetNumberOfDimensions()) +
                " spatial dimensions; SliceMesh needs 3 (and a list axis of layers at most)");
  const itk::MetaDataDictionary dictionary = io->GetMetaDataDictionary();
  // Slicer writes Segmentation_MasterRepresentation (its source representation, by its old name).
  std::string representation = headerField(dictionary, "Segmentation_MasterRepresentation");
  if (representation.empty())
    representation = headerField(dictionary, "Segmentation_SourceRepresentation");
  const bool fractional = representation == "Fractional labelmap";
  if (!representation.empty() && representation != "Binary labelmap" && !fractional)
    throw Error(path + ": holds a '" + representation +
                "' segmentation; SliceMesh reads binary and fractional labelmaps");

  checkRawVoxelBytes(path, io); // before the memory its layers would take is checked, or allocated
  const std::size_t layerCount = io->GetNumberOfComponents();
  {
    double voxels = 1.0;
    for (unsigned int axis = 0; axis < 3; ++axis)
      voxels *= static_cast<double>(io->GetDimensions(axis));
    // The file's voxels, the float stack ITK reads them into and the layers split from it, and the run.
    const double layerBytesPerVoxel = static_cast<double>(layerCount) * (io->GetComponentSize() + 4.0 + 4.0);
    std::ostringstream what;
    what << path << ": a " << io->GetDimensions(0) << " x " << io->GetDimensions(1) << " x " << io->GetDimensions(2)
         << " segmentation of " << layerCount << " layer(s)";
    checkMemoryBudget(what.str(), runMemoryBytes(voxels, layerBytesPerVoxel));
  }

  using LayerStack = itk::VectorImage<float, 3>;
  auto reader = itk::ImageFileReader<LayerStack>::New();
  reader->SetFileName(path);
  reader->SetImageIO(io);
  try
  {
    reader->Update();
  }
  catch (const itk::ExceptionObject& error)
  {
    throw Error(path + ": cannot read the voxels (a truncated or damaged file?): " + itkErrorText(error));
  }
  const LayerStack* stack = reader->GetOutput();

  SegmentationFile file;
  file.format = "3D Slicer segmentation";
  const std::size_t voxels = stack->GetBufferedRegion().GetNumberOfPixels();
  for (std::size_t layer = 0; layer < layerCount; ++layer)
  {
    auto volume = ScalarVolume::New();
    volume->CopyInformation(stack);
    volume->SetRegions(stack->GetBufferedRegion());
    volume->Allocate();
    const float* in = stack->GetBufferPointer() + layer;
    float* out = volume->GetBufferPointer();
    for (std::size_t n = 0; n < voxels; ++n, in += layerCount)
      out[n] = *in;
    checkVolumeGeometry(path, volume);
    file.layers.push_back(volume);
  }

  const auto fields = segmentFields(dictionary);
  struct FractionalSegment
  {
    std::size_t layer;
    FractionalRange range;
    VoxelExtent extent;
    std::string what; ///< "<path>: Segment<N>", for messages
  };
  std::vector<FractionalSegment> fractionalSegments;
  std::map<std::size_t, std::string> layerSegment; // a fractional file's layers, each with its SegmentN
  // Slicer before 4.11 wrote one layer per segment, each segment's voxels 1, without _Layer and
  // _LabelValue.
  const bool layerPerSegment = layerCount > 1 && layerCount == fields.size();
  std::size_t position = 0;
  for (const auto& entry : fields)
  {
    const int index = entry.first;
    const std::map<std::string, std::string>& segmentField = entry.second;
    auto field = [&](const std::string& name)
    {
      const auto found = segmentField.find(name);
      return found == segmentField.end() ? std::string() : found->second;
    };
    auto key = [&](const std::string& name) { return "Segment" + std::to_string(index) + "_" + name; };
    SegmentationFile::Segment segment;
    segment.number = index + 1;
    segment.id = field("ID");
    segment.name = !field("Name").empty() ? field("Name")
                   : !segment.id.empty()  ? segment.id
                                          : "Segment_" + std::to_string(segment.number);
    segment.rgba =
      field("Color").empty() ? ColorTable::generatedColor(segment.number) : colorField(path, key("Color"), field("Color"));
    const long layer = field("Layer").empty() ? (layerPerSegment ? static_cast<long>(position) : 0)
                                              : integerField(path, key("Layer"), field("Layer"));
    if (layer < 0 || layer >= static_cast<long>(layerCount))
      throw Error(path + ": " + key("Layer") + " is " + std::to_string(layer) + " but the file has " +
                  std::to_string(layerCount) + " layer(s)");
    segment.layer = static_cast<std::size_t>(layer);
    if (fractional)
    {
      // The layer holds this segment's fractions only; its _LabelValue does not apply.
      const std::string name = "Segment" + std::to_string(index);
      if (!layerSegment.emplace(segment.layer, name).second)
        throw Error(path + ": " + name + " is in layer " + std::to_string(segment.layer) + " with " +
                    layerSegment[segment.layer] + "; a fractional labelmap has a layer of its own for each segment");
      fractionalSegments.push_back(
        { segment.layer,
          field("ScalarRange").empty() ? defaultRange(path, io->GetComponentType())
                                       : fractionalRangeField(path, key("ScalarRange"), field("ScalarRange")),
          field("Extent").empty() ? wholeExtent(file.layers[segment.layer])
                                  : voxelExtentField(path, key("Extent"), field("Extent")),
          path + ": " + name });
      segment.labelValue = 1;
    }
    else
    {
      const long value = field("LabelValue").empty() ? 1 : integerField(path, key("LabelValue"), field("LabelValue"));
      if (value <= 0 || value > 2147483647L)
        throw Error(path + ": " + key("LabelValue") + " is " + std::to_string(value) +
                    "; a label value is a positive integer");
      segment.labelValue = static_cast<int>(value);
    }
    file.segments.push_back(segment);
    ++position;
  }
  if (file.segments.empty())
    throw Error(path + ": a segmentation file without segments (no SegmentN_ header fields)");
  // Each fractional layer becomes its segment's label map (value 1), as a binary layer is one; a
  // layer no segment names holds no voxel.
  for (const FractionalSegment& s : fractionalSegments)
    thresholdFractionalLayer(file.layers[s.layer], s.range, s.extent, s.what);
  if (fractional)
    for (std::size_t layer = 0; layer < layerCount; ++layer)
      if (layerSegment.count(layer) == 0)
        file.layers[layer]->FillBuffer(0.0f);
  return file;
}

} // namespace slicemesh
