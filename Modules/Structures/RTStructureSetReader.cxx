// DICOM RT Structure Sets through DCMTK's typed RT classes (dcmrt): the plugin SliceMeshStructuresDicom.
#include "RTStructureSetPlugin.h"

#include <dcmtk/dcmdata/dcbytstr.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmrt/drtstrct.h>
#include <dcmtk/oflog/oflog.h>

#include <algorithm>
#include <map>

namespace slicemesh
{
namespace
{

/** DCMTK logs warnings about a file's small faults to stderr, several lines each; what matters
 *  reaches the caller through the returned conditions. */
void quietDcmtk()
{
  static const bool quiet = []
  {
    OFLog::configure(OFLogger::FATAL_LOG_LEVEL);
    return true;
  }();
  (void)quiet;
}

/** Turns off DCMTK's character-by-character check of string values while it lives: dcmrt runs it on
 *  every number of every contour as it reads them, which took most of the reading of a 50,000-point
 *  structure set, to raise warnings that are not shown (quietDcmtk). A value that is no number is
 *  still caught where the points are taken. The setting is put back as it was. */
class StringValueCheckOff
{
public:
  StringValueCheckOff()
    : Before(dcmEnableVRCheckerForStringValues.get())
  {
    dcmEnableVRCheckerForStringValues.set(OFFalse);
  }
  ~StringValueCheckOff() { dcmEnableVRCheckerForStringValues.set(this->Before); }
  StringValueCheckOff(const StringValueCheckOff&) = delete;
  StringValueCheckOff& operator=(const StringValueCheckOff&) = delete;

private:
  const OFBool Before;
};

std::string trimmed(const OFString& text)
{
  std::string s(text.c_str());
  const auto first = s.find_first_not_of(" \t\r\n");
  const auto last = s.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

/** Each item of a dcmrt sequence, in order (by index: its cursor steps once past the last item). */
template <typename Sequence, typename Visit>
void forEachItem(Sequence& sequence, Visit&& visit)
{
  for (std::size_t n = 0; n < sequence.getNumberOfItems(); ++n)
  {
    typename Sequence::Item* item = nullptr;
    if (sequence.getItem(n, item).good() && item)
      visit(*item);
  }
}

StructureSet readWithDcmtk(const std::string& path)
{
  quietDcmtk();
  DcmFileFormat file;
  const OFCondition loaded = file.loadFile(path.c_str());
  if (loaded.bad())
    throw Error("cannot read '" + path + "' as DICOM: " + loaded.text());
  DcmDataset& dataset = *file.getDataset();
  OFString modality;
  dataset.findAndGetOFString(DCM_Modality, modality);
  if (modality != "RTSTRUCT")
    throw Error("'" + path + "' is not a DICOM RT Structure Set (Modality " +
                (modality.empty() ? std::string("missing") : std::string(modality.c_str())) + ")");
  DRTStructureSetIOD iod;
  const StringValueCheckOff unchecked;
  const OFCondition read = iod.read(dataset);
  if (read.bad())
    throw Error("cannot read the RT Structure Set '" + path + "': " + read.text());

  StructureSet set;
  std::map<Sint32, std::size_t> byNumber;
  forEachItem(iod.getStructureSetROISequence(),
              [&](DRTStructureSetROISequence::Item& item)
              {
                PlanarStructure roi;
                Sint32 number = 0;
                if (item.getROINumber(number).bad())
                  return;
                OFString name;
                item.getROIName(name);
                roi.number = number;
                roi.name = trimmed(name);
                if (roi.name.empty())
                  roi.name = "ROI_" + std::to_string(number);
                byNumber[number] = set.structures.size();
                set.structures.push_back(std::move(roi));
              });

  forEachItem(iod.getROIContourSequence(),
              [&](DRTROIContourSequence::Item& item)
              {
                Sint32 number = 0;
                if (item.getReferencedROINumber(number).bad())
                  return;
                auto found = byNumber.find(number);
                if (found == byNumber.end())
                {
                  // Contours of an ROI the set does not declare: kept, under its number.
                  PlanarStructure roi;
                  roi.number = number;
                  roi.name = "ROI_" + std::to_string(number);
                  found = byNumber.emplace(number, set.structures.size()).first;
                  set.structures.push_back(std::move(roi));
                }
                PlanarStructure& roi = set.structures[found->second];
                Sint32 rgb[3];
                if (item.getROIDisplayColor(rgb[0], 0).good() && item.getROIDisplayColor(rgb[1], 1).good() &&
                    item.getROIDisplayColor(rgb[2], 2).good())
                  for (int c = 0; c < 3; ++c)
                    roi.rgb[c] = static_cast<unsigned char>(std::clamp<Sint32>(rgb[c], 0, 255));
                std::map<std::string, std::size_t> skipped;
                forEachItem(item.getContourSequence(),
                            [&](DRTContourSequence::Item& contourItem)
                            {
                              OFString type;
                              contourItem.getContourGeometricType(type);
                              const std::string geometricType = trimmed(type);
                              if (geometricType != "CLOSED_PLANAR")
                              {
                                ++skipped[geometricType.empty() ? "untyped" : geometricType];
                                return;
                              }
                              OFVector<Float64> data;
                              contourItem.getContourData(data);
                              if (data.size() % 3 != 0)
                                throw Error("'" + path + "': ROI " + std::to_string(roi.number) +
                                            ": a contour's data has a number of values that is not a multiple of 3");
                              Polygon3 contour;
                              contour.reserve(data.size() / 3);
                              for (std::size_t i = 0; i + 2 < data.size(); i += 3)
                                contour.push_back({ data[i], data[i + 1], data[i + 2] });
                              roi.contours.push_back(std::move(contour));
                            });
                for (const auto& [type, count] : skipped)
                  roi.notes.push_back(std::to_string(count) + " " + type + " item(s) skipped: only CLOSED_PLANAR contours enclose a volume");
              });
  if (set.structures.empty())
    throw Error("'" + path + "': the RT Structure Set lists no ROI");
  return set;
}

} // namespace

} // namespace slicemesh

/** The plugin's entry: its table of functions (RTStructureSetPlugin.h). */
extern "C" __attribute__((visibility("default"))) const slicemesh::RTStructureSetFunctions* slicemeshRTStructureSetFunctions()
{
  static const slicemesh::RTStructureSetFunctions functions{ sizeof(slicemesh::RTStructureSetFunctions),
                                                             &slicemesh::readWithDcmtk };
  return &functions;
}
