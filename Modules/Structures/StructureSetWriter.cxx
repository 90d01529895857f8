#include "StructureSetWriter.h"

#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcsequen.h>
#include <dcmtk/dcmdata/dcuid.h>

#include <algorithm>
#include <map>
#include <sstream>

namespace slicemesh
{
namespace
{

void put(DcmItem& item, const DcmTagKey& tag, const std::string& value)
{
  if (item.putAndInsertString(tag, value.c_str()).bad())
    throw Error("cannot set a DICOM attribute of the structure set");
}

/** A new item at the end of the sequence `tag` of `parent`, the sequence made when missing. */
DcmItem& appendItem(DcmItem& parent, const DcmTagKey& tag)
{
  DcmSequenceOfItems* sequence = nullptr;
  if (parent.findAndGetSequence(tag, sequence).bad() || !sequence)
  {
    sequence = new DcmSequenceOfItems(tag);
    if (parent.insert(sequence).bad())
      throw Error("cannot add a sequence to the structure set");
  }
  auto* item = new DcmItem();
  if (sequence->append(item).bad())
    throw Error("cannot add an item to the structure set");
  return *item;
}

std::string decimals(const Polygon3& points)
{
  std::ostringstream text;
  text.precision(10);
  for (std::size_t i = 0; i < points.size(); ++i)
    text << (i ? "\\" : "") << points[i].x << "\\" << points[i].y << "\\" << points[i].z;
  return text.str();
}

void addContour(DcmItem& roiContour, const ContourItem& contour, int contourNumber)
{
  DcmItem& item = appendItem(roiContour, DCM_ContourSequence);
  put(item, DCM_ContourNumber, std::to_string(contourNumber));
  put(item, DCM_ContourGeometricType, contour.geometricType);
  if (contour.contourData.empty())
  {
    put(item, DCM_NumberOfContourPoints, std::to_string(contour.points.size()));
    put(item, DCM_ContourData, decimals(contour.points));
  }
  else
  {
    // As many points as the values make (a reader compares the two).
    const auto values = std::count(contour.contourData.begin(), contour.contourData.end(), '\\') + 1;
    put(item, DCM_NumberOfContourPoints, std::to_string(values / 3));
    put(item, DCM_ContourData, contour.contourData);
  }
}

} // namespace

void writeRTStructureSet(const std::string& path, const std::vector<PlanarStructure>& structures,
                         const std::vector<ContourItem>& extraItems, const std::string& frameOfReferenceUid)
{
  DcmFileFormat file;
  DcmDataset& data = *file.getDataset();
  char uid[100];
  const std::string frameOfReference =
    frameOfReferenceUid.empty() ? std::string(dcmGenerateUniqueIdentifier(uid, SITE_INSTANCE_UID_ROOT)) : frameOfReferenceUid;
  put(data, DCM_SOPClassUID, UID_RTStructureSetStorage);
  put(data, DCM_SOPInstanceUID, dcmGenerateUniqueIdentifier(uid, SITE_INSTANCE_UID_ROOT));
  put(data, DCM_StudyInstanceUID, dcmGenerateUniqueIdentifier(uid, SITE_STUDY_UID_ROOT));
  put(data, DCM_SeriesInstanceUID, dcmGenerateUniqueIdentifier(uid, SITE_SERIES_UID_ROOT));
  put(data, DCM_Modality, "RTSTRUCT");
  put(data, DCM_PatientName, "SliceMesh^Test");
  put(data, DCM_PatientID, "SLICEMESH");
  put(data, DCM_StructureSetLabel, "SliceMesh");
  put(data, DCM_Manufacturer, "SliceMesh");
  put(data, DCM_SeriesNumber, "1");
  put(data, DCM_InstanceNumber, "1");
  put(data, DCM_StructureSetDate, "20260101");
  put(data, DCM_StructureSetTime, "120000");
  // Type 2: present, may be empty.
  for (const DcmTagKey& tag : { DCM_PatientBirthDate, DCM_PatientSex, DCM_StudyDate, DCM_StudyTime,
                                DCM_ReferringPhysicianName, DCM_StudyID, DCM_AccessionNumber, DCM_OperatorsName })
    put(data, tag, "");

  std::map<int, DcmItem*> contoursOf;
  for (const PlanarStructure& s : structures)
  {
    DcmItem* roi = &appendItem(data, DCM_StructureSetROISequence);
    DcmItem* roiContour = &appendItem(data, DCM_ROIContourSequence);
    DcmItem* observation = &appendItem(data, DCM_RTROIObservationsSequence);
    put(*roi, DCM_ROINumber, std::to_string(s.number));
    put(*roi, DCM_ReferencedFrameOfReferenceUID, frameOfReference);
    put(*roi, DCM_ROIName, s.name);
    put(*roi, DCM_ROIGenerationAlgorithm, "MANUAL");
    put(*roiContour, DCM_ROIDisplayColor,
        std::to_string(s.rgb[0]) + "\\" + std::to_string(s.rgb[1]) + "\\" + std::to_string(s.rgb[2]));
    put(*roiContour, DCM_ReferencedROINumber, std::to_string(s.number));
    put(*observation, DCM_ObservationNumber, std::to_string(s.number));
    put(*observation, DCM_ReferencedROINumber, std::to_string(s.number));
    put(*observation, DCM_RTROIInterpretedType, "ORGAN");
    put(*observation, DCM_ROIInterpreter, "");
    contoursOf[s.number] = roiContour;
    int contourNumber = 0;
    for (const Polygon3& contour : s.contours)
      addContour(*roiContour, { s.number, "CLOSED_PLANAR", contour }, ++contourNumber);
  }
  for (const ContourItem& extra : extraItems)
  {
    const auto found = contoursOf.find(extra.roiNumber);
    if (found == contoursOf.end())
      throw Error("an extra contour item names ROI " + std::to_string(extra.roiNumber) + ", which is not written");
    addContour(*found->second, extra, 1000 + static_cast<int>(&extra - extraItems.data()));
  }
  const OFCondition saved = file.saveFile(path.c_str(), EXS_LittleEndianExplicit);
  if (saved.bad())
    throw Error("cannot write the structure set '" + path + "': " + saved.text());
}

} // namespace slicemesh
