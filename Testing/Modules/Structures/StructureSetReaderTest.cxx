// Reading structure sets and contour files: RTSTRUCTs written with DCMTK in the test, 3D Slicer's
// polydata contours, the JSON format; what the file kind detection says; and the one-line errors
// of files that are not structure sets or are cut short.
#include "StructureSet.h"
#include "StructureSetWriter.h"
#include "TestContours.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcuid.h>
#include <dcmtk/dcmdata/dcvr.h>
#include <dcmtk/dcmdata/dcvrobow.h>

#include <vtkCellArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkStringArray.h>
#include <vtkFieldData.h>
#include <vtkXMLPolyDataWriter.h>

#include <filesystem>
#include <fstream>

#include <sys/resource.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace slicemesh::testing
{
namespace
{

fs::path folder(const std::string& name)
{
  const fs::path path = fs::path(SLICEMESH_TEST_OUTPUT_DIR) / name;
  fs::remove_all(path);
  fs::create_directories(path);
  return path;
}

std::vector<PlanarStructure> twoStructures()
{
  PlanarStructure gtv;
  gtv.number = 3;
  gtv.name = "GTV";
  gtv.rgb = { 255, 0, 0 };
  for (int k = 0; k < 4; ++k)
    gtv.contours.push_back(circle(10.0, -20.0, 2.5 * k, 8.0, 32));
  PlanarStructure empty;
  empty.number = 7;
  empty.name = "Empty ROI";
  empty.rgb = { 0, 0, 255 };
  return { gtv, empty };
}

void writeText(const fs::path& path, const std::string& text)
{
  std::ofstream(path) << text;
}

TEST(StructureSetReader, ReadsEveryROIWithNumberNameColourAndContoursInLPS)
{
  const fs::path path = folder("rtstruct") / "RS.dcm";
  const std::vector<PlanarStructure> written = twoStructures();
  writeRTStructureSet(path.string(), written,
                      { { 3, "POINT", { { 1, 2, 3 } } }, { 3, "OPEN_PLANAR", circle(0, 0, 1, 2, 8) } });
  EXPECT_EQ(detectContourFileKind(path.string()), ContourFileKind::RTStruct);
  const StructureSet set = readStructureSet(path.string());
  ASSERT_EQ(set.structures.size(), 2u);
  const PlanarStructure& gtv = set.structures[0];
  EXPECT_EQ(gtv.number, 3);
  EXPECT_EQ(gtv.name, "GTV");
  EXPECT_EQ(gtv.rgb, (std::array<unsigned char, 3>{ 255, 0, 0 }));
  ASSERT_EQ(gtv.contours.size(), 4u) << "the POINT and OPEN_PLANAR items are not contours";
  ASSERT_EQ(gtv.contours[2].size(), 32u);
  for (std::size_t i = 0; i < 32; ++i)
  {
    EXPECT_NEAR(gtv.contours[2][i].x, written[0].contours[2][i].x, 1e-6);
    EXPECT_NEAR(gtv.contours[2][i].y, written[0].contours[2][i].y, 1e-6);
    EXPECT_NEAR(gtv.contours[2][i].z, 5.0, 1e-9);
  }
  ASSERT_EQ(gtv.notes.size(), 2u) << "each skipped kind of item is reported: " << gtv.notes.back();
  EXPECT_NE(gtv.notes[0].find("OPEN_PLANAR"), std::string::npos);
  EXPECT_NE(gtv.notes[1].find("POINT"), std::string::npos);
  EXPECT_EQ(set.structures[1].name, "Empty ROI");
  EXPECT_TRUE(set.structures[1].contours.empty());
}

/** The structure set of twoStructures() at `path`, with its first contour's data replaced by `data`
 *  (a decimal string as a planning system may write it). */
void writeWithFirstContourData(const fs::path& path, const std::string& data)
{
  writeRTStructureSet(path.string(), twoStructures());
  DcmFileFormat file;
  ASSERT_TRUE(file.loadFile(path.c_str()).good());
  DcmItem* contour = nullptr;
  DcmItem* roi = nullptr;
  ASSERT_TRUE(file.getDataset()->findAndGetSequenceItem(DCM_ROIContourSequence, roi, 0).good());
  ASSERT_TRUE(roi->findAndGetSequenceItem(DCM_ContourSequence, contour, 0).good());
  ASSERT_TRUE(contour->putAndInsertString(DCM_ContourData, data.c_str()).good());
  ASSERT_TRUE(contour->putAndInsertString(DCM_NumberOfContourPoints, "3").good());
  ASSERT_TRUE(file.saveFile(path.c_str(), EXS_LittleEndianExplicit).good());
}

TEST(StructureSetReader, ReadsDecimalStringsWithSignsExponentsAndPaddingExactly)
{
  const fs::path path = folder("decimal-strings") / "RS.dcm";
  writeWithFirstContourData(path, "+1.5\\ -2.25E+01\\0.1 \\3\\-4e-1\\7.0\\.5\\1E2\\+0");
  const StructureSet set = readStructureSet(path.string());
  ASSERT_EQ(set.structures.size(), 2u);
  ASSERT_EQ(set.structures[0].contours.size(), 4u);
  const Polygon3& contour = set.structures[0].contours[0];
  ASSERT_EQ(contour.size(), 3u);
  // Each value is the double nearest its decimal string, as a compiler reads the same literal.
  EXPECT_EQ(contour[0].x, 1.5);
  EXPECT_EQ(contour[0].y, -22.5);
  EXPECT_EQ(contour[0].z, 0.1);
  EXPECT_EQ(contour[1].x, 3.0);
  EXPECT_EQ(contour[1].y, -0.4);
  EXPECT_EQ(contour[1].z, 7.0);
  EXPECT_EQ(contour[2].x, 0.5);
  EXPECT_EQ(contour[2].y, 100.0);
  EXPECT_EQ(contour[2].z, 0.0);
}

TEST(StructureSetReader, AContourStoredAsUNIsReadAsItsDecimalStringsAndTheFlagPutBack)
{
  // 5000 points are over 64 KiB of text, more than an explicit-VR DS length holds: writers store
  // such a ContourData as UN with a 32-bit length.
  const fs::path path = folder("contour-as-UN") / "RS.dcm";
  const Polygon3 big = circle(1.0, -2.0, 2.5, 40.0, 5000);
  std::string text;
  for (const Point3& p : big)
    for (const double value : { p.x, p.y, p.z })
      text += (text.empty() ? "" : "\\") + std::to_string(value);
  if (text.size() % 2 != 0)
    text += ' ';
  ASSERT_GT(text.size(), 65535u);
  writeRTStructureSet(path.string(), twoStructures());
  {
    DcmFileFormat file;
    ASSERT_TRUE(file.loadFile(path.c_str()).good());
    DcmItem* roi = nullptr;
    DcmItem* contour = nullptr;
    ASSERT_TRUE(file.getDataset()->findAndGetSequenceItem(DCM_ROIContourSequence, roi, 0).good());
    ASSERT_TRUE(roi->findAndGetSequenceItem(DCM_ContourSequence, contour, 1).good());
    auto* unknown = new DcmOtherByteOtherWord(DcmTag(DCM_ContourData, EVR_UN));
    ASSERT_TRUE(unknown->putUint8Array(reinterpret_cast<const Uint8*>(text.data()), text.size()).good());
    ASSERT_TRUE(contour->insert(unknown, true).good());
    ASSERT_TRUE(contour->putAndInsertString(DCM_NumberOfContourPoints, "5000").good());
    ASSERT_TRUE(file.saveFile(path.c_str(), EXS_LittleEndianExplicit).good());
  }
  {
    // The fixture is what it means to be: read without the conversion, the element is UN.
    DcmFileFormat file;
    ASSERT_TRUE(file.loadFile(path.c_str()).good());
    DcmItem* roi = nullptr;
    DcmItem* contour = nullptr;
    DcmElement* data = nullptr;
    ASSERT_TRUE(file.getDataset()->findAndGetSequenceItem(DCM_ROIContourSequence, roi, 0).good());
    ASSERT_TRUE(roi->findAndGetSequenceItem(DCM_ContourSequence, contour, 1).good());
    ASSERT_TRUE(contour->findAndGetElement(DCM_ContourData, data).good());
    ASSERT_EQ(data->getVR(), EVR_UN);
  }
  const StructureSet set = readStructureSet(path.string());
  EXPECT_FALSE(dcmEnableUnknownVRConversion.get()) << "the reader puts DCMTK's flag back";
  ASSERT_EQ(set.structures[0].contours.size(), 4u);
  const Polygon3& read = set.structures[0].contours[1];
  ASSERT_EQ(read.size(), 5000u);
  for (std::size_t i = 0; i < read.size(); i += 499)
  {
    EXPECT_NEAR(read[i].x, big[i].x, 1e-6);
    EXPECT_NEAR(read[i].y, big[i].y, 1e-6);
    EXPECT_EQ(read[i].z, 2.5);
  }
  EXPECT_TRUE(set.structures[0].notes.empty()) << set.structures[0].notes.front();
}

TEST(StructureSetReader, ANumberOfContourPointsThatDisagreesWithTheDataIsSaidAndTheDataUsed)
{
  // writeWithFirstContourData states 3 points; four are given.
  const fs::path path = folder("miscounted") / "RS.dcm";
  writeWithFirstContourData(path, "0\\0\\0\\10\\0\\0\\10\\10\\0\\0\\10\\0");
  const StructureSet set = readStructureSet(path.string());
  const PlanarStructure& gtv = set.structures[0];
  ASSERT_EQ(gtv.contours[0].size(), 4u);
  EXPECT_EQ(gtv.contours[0][3].y, 10.0);
  ASSERT_EQ(gtv.notes.size(), 1u) << "one line for the ROI";
  EXPECT_NE(gtv.notes[0].find("3 stated, 4 present"), std::string::npos) << gtv.notes[0];
  EXPECT_TRUE(set.structures[1].notes.empty());
}

/** twoStructures() at `path`, the first ROI named by the bytes `name`, the file's Specific
 *  Character Set `charset` (none when empty). */
void writeWithFirstName(const fs::path& path, const std::string& name, const std::string& charset)
{
  writeRTStructureSet(path.string(), twoStructures());
  DcmFileFormat file;
  ASSERT_TRUE(file.loadFile(path.c_str()).good());
  if (!charset.empty())
    ASSERT_TRUE(file.getDataset()->putAndInsertString(DCM_SpecificCharacterSet, charset.c_str()).good());
  DcmItem* roi = nullptr;
  ASSERT_TRUE(file.getDataset()->findAndGetSequenceItem(DCM_StructureSetROISequence, roi, 0).good());
  ASSERT_TRUE(roi->putAndInsertString(DCM_ROIName, name.c_str()).good());
  ASSERT_TRUE(file.saveFile(path.c_str(), EXS_LittleEndianExplicit).good());
}

TEST(StructureSetReader, NamesAreReadAsUtf8FromTheFilesCharacterSet)
{
  const fs::path dir = folder("character-sets");
  const std::string latin1 = "R\xFC" "ckenmark", utf8 = "R\xC3\xBC" "ckenmark";
  struct Case
  {
    std::string charset, stored, read;
  };
  // Latin-1 declared; none declared, whose bytes beyond ASCII are taken as Latin-1 unless they are
  // UTF-8 (many tools write it without saying so); UTF-8 declared (kept); ASCII with none declared
  // (kept).
  for (const Case& c : { Case{ "ISO_IR 100", latin1, utf8 }, Case{ "", latin1, utf8 }, Case{ "ISO_IR 192", utf8, utf8 },
                         Case{ "", utf8, utf8 }, Case{ "ISO_IR 100", "Leber \xE4 \xE9", "Leber \xC3\xA4 \xC3\xA9" },
                         Case{ "", "\xC3", "\xC3\x83" }, Case{ "", "PTV/CTV 1", "PTV/CTV 1" } })
  {
    const fs::path path = dir / "RS.dcm";
    writeWithFirstName(path, c.stored, c.charset);
    const StructureSet set = readStructureSet(path.string());
    EXPECT_EQ(set.structures[0].name, c.read) << "Specific Character Set '" << c.charset << "'";
    EXPECT_EQ(set.structures[1].name, "Empty ROI");
    EXPECT_TRUE(set.notes.empty()) << set.notes.front();
    EXPECT_EQ(set.structures[0].contours.size(), 4u);
  }
}

TEST(StructureSetReader, NamesInACharacterSetThatCannotBeConvertedAreKeptAndSaid)
{
  const fs::path path = folder("unknown-character-set") / "RS.dcm";
  writeWithFirstName(path, "R\xFC" "ckenmark", "ISO_IR 999");
  const StructureSet set = readStructureSet(path.string());
  EXPECT_EQ(set.structures[0].name, "R\xFC" "ckenmark");
  ASSERT_EQ(set.notes.size(), 1u);
  EXPECT_NE(set.notes[0].find("'ISO_IR 999'"), std::string::npos) << set.notes[0];
  EXPECT_EQ(set.notes[0].find('\n'), std::string::npos) << set.notes[0];
}

TEST(StructureSetReader, TwoROIsOfOneNumberGetNoContoursAndAreSaidOnce)
{
  // The ROI Contour Sequence names its ROI by number only: contours of number 3 could be either's.
  const fs::path path = folder("shared-number") / "RS.dcm";
  std::vector<PlanarStructure> rois = twoStructures();
  rois[1].number = 3;
  rois[1].name = "Other";
  rois[1].contours.push_back(circle(60.0, 0.0, 0.0, 5.0, 16));
  PlanarStructure third = rois[0];
  third.number = 5;
  third.name = "Kept";
  rois.push_back(third);
  writeRTStructureSet(path.string(), rois);
  const StructureSet set = readStructureSet(path.string());
  ASSERT_EQ(set.structures.size(), 3u);
  for (std::size_t n = 0; n < 2; ++n)
  {
    EXPECT_EQ(set.structures[n].number, 3);
    EXPECT_TRUE(set.structures[n].contours.empty()) << set.structures[n].name << " gets no contour of the other's";
    EXPECT_NE(set.structures[n].unusableBecause.find("ROI number 3"), std::string::npos)
      << set.structures[n].unusableBecause;
  }
  EXPECT_NE(set.structures[0].unusableBecause.find("'Other'"), std::string::npos) << set.structures[0].unusableBecause;
  EXPECT_NE(set.structures[1].unusableBecause.find("'GTV'"), std::string::npos) << set.structures[1].unusableBecause;
  EXPECT_EQ(set.structures[2].name, "Kept");
  EXPECT_EQ(set.structures[2].contours.size(), 4u);
  EXPECT_TRUE(set.structures[2].unusableBecause.empty());
  ASSERT_EQ(set.notes.size(), 1u) << "one line for the number";
  EXPECT_NE(set.notes[0].find("ROI number 3 is given to 2 ROIs, 'GTV' and 'Other'"), std::string::npos) << set.notes[0];
}

TEST(StructureSetReader, ContoursOfAnUndeclaredROIAreKeptAndSaid)
{
  // The first ROI's contours refer to ROI 99, which the Structure Set ROI Sequence does not list.
  const fs::path path = folder("undeclared") / "RS.dcm";
  writeRTStructureSet(path.string(), twoStructures());
  DcmFileFormat file;
  ASSERT_TRUE(file.loadFile(path.c_str()).good());
  DcmItem* roi = nullptr;
  ASSERT_TRUE(file.getDataset()->findAndGetSequenceItem(DCM_ROIContourSequence, roi, 0).good());
  ASSERT_TRUE(roi->putAndInsertString(DCM_ReferencedROINumber, "99").good());
  ASSERT_TRUE(file.saveFile(path.c_str(), EXS_LittleEndianExplicit).good());
  const StructureSet set = readStructureSet(path.string());
  const auto undeclared = std::find_if(set.structures.begin(), set.structures.end(),
                                       [](const PlanarStructure& s) { return s.number == 99; });
  ASSERT_NE(undeclared, set.structures.end());
  EXPECT_EQ(undeclared->name, "ROI_99");
  EXPECT_FALSE(undeclared->contours.empty());
  ASSERT_EQ(undeclared->notes.size(), 1u);
  EXPECT_NE(undeclared->notes[0].find("not declared"), std::string::npos) << undeclared->notes[0];
}

TEST(StructureSetReader, AContourValueThatIsNoNumberMakesItsROIAloneUnusable)
{
  // One bad value is a fault of one ROI, as a point a kilometre away is: that ROI cannot be meshed,
  // says what was wrong in one line and keeps no contour (nothing not finite reaches the geometry);
  // the file and its other ROIs still read. NaN and infinity too: the parser reads them as numbers,
  // but a decimal string cannot hold them.
  const fs::path dir = folder("not-a-number");
  for (const auto& [data, said] :
       { std::pair{ "1.0\\abc\\2.0", "'abc'" }, std::pair{ "1,5\\2.0\\3.0", "'1,5'" },
         std::pair{ "1.0\\\\2.0\\3.0", "an empty value" }, std::pair{ "1.0\\2.0x\\3.0", "'2.0x'" },
         std::pair{ "1.0\\nan\\2.0", "'nan'" }, std::pair{ "inf\\1.0\\2.0", "'inf'" },
         std::pair{ "1.0\\2.0\\-INF", "'-INF'" }, std::pair{ "1.0\\2.0\\3.0\\4.0", "4 values" } })
  {
    const fs::path path = dir / "RS.dcm";
    writeWithFirstContourData(path, data);
    const StructureSet set = readStructureSet(path.string());
    ASSERT_EQ(set.structures.size(), 2u) << data;
    const PlanarStructure& gtv = set.structures[0];
    EXPECT_EQ(gtv.number, 3);
    EXPECT_NE(gtv.unusableBecause.find(said), std::string::npos) << data << ": " << gtv.unusableBecause;
    EXPECT_NE(gtv.unusableBecause.find("contour 1"), std::string::npos) << gtv.unusableBecause;
    EXPECT_EQ(gtv.unusableBecause.find('\n'), std::string::npos) << gtv.unusableBecause;
    EXPECT_TRUE(gtv.contours.empty()) << data;
    EXPECT_EQ(set.structures[1].name, "Empty ROI");
    EXPECT_TRUE(set.structures[1].unusableBecause.empty());
  }
}

TEST(StructureSetReader, ChoosesROIsByNameOrNumberAndNamesWhatMatchesNothing)
{
  StructureSet set;
  set.structures = twoStructures();
  EXPECT_EQ(chosenStructures(set, {}).size(), 2u);
  const auto byNumber = chosenStructures(set, { "7" });
  ASSERT_EQ(byNumber.size(), 1u);
  EXPECT_EQ(byNumber[0].name, "Empty ROI");
  EXPECT_EQ(chosenStructures(set, { "gtv" }).front().number, 3) << "names match regardless of case";
  try
  {
    chosenStructures(set, { "GTV", "Heart" });
    FAIL() << "an ROI that does not exist must be an error";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("'Heart'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("3 (GTV)"), std::string::npos) << e.what();
  }
  // A number is an ROI number first: ROI 9 named "3" is not picked by "3" beside ROI 3, only by "9"
  // (it was picked by both, two files for one asked); a name no number takes still picks it.
  StructureSet tricky = set;
  tricky.structures.push_back(set.structures[0]);
  tricky.structures.back().number = 9;
  tricky.structures.back().name = "3";
  tricky.structures.push_back(set.structures[0]);
  tricky.structures.back().number = 11;
  tricky.structures.back().name = "40";
  const auto three = chosenStructures(tricky, { "3" });
  ASSERT_EQ(three.size(), 1u);
  EXPECT_EQ(three[0].name, "GTV");
  EXPECT_EQ(chosenStructures(tricky, { "40" }).front().number, 11);
  // A name with a comma cannot be given in the list (3D Slicer splits it at commas): the message
  // says to use its number.
  tricky.structures.back().name = "Rectum,wall";
  try
  {
    chosenStructures(tricky, { "Rectum", "wall" });
    FAIL() << "no ROI is called Rectum";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("a name with a comma is picked by its number"), std::string::npos) << e.what();
  }
  EXPECT_EQ(chosenStructures(tricky, { "11" }).front().name, "Rectum,wall");
}

TEST(StructureSetReader, ADicomFileOfAnotherModalityIsNotAStructureSet)
{
  const fs::path path = folder("ct") / "CT.dcm";
  DcmFileFormat file;
  char uid[100];
  file.getDataset()->putAndInsertString(DCM_SOPClassUID, UID_CTImageStorage);
  file.getDataset()->putAndInsertString(DCM_SOPInstanceUID, dcmGenerateUniqueIdentifier(uid));
  file.getDataset()->putAndInsertString(DCM_Modality, "CT");
  ASSERT_TRUE(file.saveFile(path.c_str(), EXS_LittleEndianExplicit).good());
  EXPECT_FALSE(detectContourFileKind(path.string()).has_value());
  try
  {
    readStructureSet(path.string(), ContourFileKind::RTStruct);
    FAIL() << "a CT file read as a structure set must fail";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("not a DICOM RT Structure Set (Modality CT)"), std::string::npos) << e.what();
  }
}

TEST(StructureSetReader, ReadsTheFrameOfReferenceTheROIsAreIn)
{
  const fs::path path = folder("frame-of-reference") / "RS.dcm";
  writeRTStructureSet(path.string(), twoStructures(), {}, "1.2.826.0.1.3680043.2.1125.7.7");
  const StructureSet set = readStructureSet(path.string());
  EXPECT_EQ(set.framesOfReference, std::vector<std::string>{ "1.2.826.0.1.3680043.2.1125.7.7" }) << "once for both ROIs";
}

TEST(StructureSetReader, ATruncatedStructureSetFailsWithOneLine)
{
  const fs::path dir = folder("truncated");
  const fs::path whole = dir / "RS.dcm", cut = dir / "RS-cut.dcm";
  writeRTStructureSet(whole.string(), twoStructures());
  const auto size = fs::file_size(whole);
  fs::copy_file(whole, cut);
  fs::resize_file(cut, size * 2 / 3);
  EXPECT_EQ(detectContourFileKind(cut.string()), ContourFileKind::RTStruct) << "recognised, so the error says what is wrong";
  try
  {
    readStructureSet(cut.string());
    FAIL() << "a truncated file must not read";
  }
  catch (const Error& e)
  {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find("RS-cut.dcm"), std::string::npos) << message;
  }
}

TEST(StructureSetReader, AStructureSetWithoutPreambleIsDetectedAndRead)
{
  // Older systems write the dataset alone, in implicit or explicit little endian, without the
  // 128-byte preamble and "DICM", most without the meta header too; DCMTK reads each.
  const fs::path dir = folder("no-preamble");
  const fs::path part10 = dir / "part10.dcm";
  writeRTStructureSet(part10.string(), twoStructures());
  DcmFileFormat file;
  ASSERT_TRUE(file.loadFile(part10.c_str()).good());
  ASSERT_TRUE(file.getDataset()->saveFile((dir / "implicit.dcm").c_str(), EXS_LittleEndianImplicit).good());
  ASSERT_TRUE(file.getDataset()->saveFile((dir / "explicit.dcm").c_str(), EXS_LittleEndianExplicit).good());
  {
    std::ifstream in(part10, std::ios::binary);
    in.seekg(132); // the meta header kept, the preamble and "DICM" gone
    std::ofstream(dir / "meta.dcm", std::ios::binary) << in.rdbuf();
  }
  for (const std::string name : { "implicit.dcm", "explicit.dcm", "meta.dcm" })
  {
    const std::string path = (dir / name).string();
    EXPECT_EQ(detectContourFileKind(path), ContourFileKind::RTStruct) << name;
    const StructureSet set = readStructureSet(path);
    ASSERT_EQ(set.structures.size(), 2u) << name;
    EXPECT_EQ(set.structures[0].name, "GTV");
    EXPECT_EQ(set.structures[0].contours.size(), 4u) << name;
  }
}

TEST(StructureSetReader, ImagesAndOtherDicomDatasetsAreNoStructureSetWithoutAPreambleEither)
{
  // Each names RTSTRUCT and the RT Structure Set's SOP class in its first bytes, which is not enough.
  const fs::path dir = folder("no-preamble-others");
  const std::string words = std::string("RTSTRUCT ") + UID_RTStructureSetStorage;
  std::string nifti(352, '\0'); // NIfTI-1: sizeof_hdr 348 (little endian), its description at byte 148
  nifti[0] = '\x5c', nifti[1] = '\x01';
  nifti.replace(148, words.size(), words);
  nifti.replace(344, 4, "n+1");
  writeText(dir / "image.nii", nifti);
  writeText(dir / "image.nrrd", "NRRD0004\n# " + words + "\ntype: unsigned char\ndimension: 3\nsizes: 2 2 2\n"
                                "encoding: raw\n\n" + std::string(8, '\0'));
  writeText(dir / "image.vtk", "# vtk DataFile Version 3.0\n" + words + "\nASCII\nDATASET STRUCTURED_POINTS\n");
  DcmFileFormat ct;
  char uid[100];
  ct.getDataset()->putAndInsertString(DCM_SOPClassUID, UID_CTImageStorage);
  ct.getDataset()->putAndInsertString(DCM_SOPInstanceUID, dcmGenerateUniqueIdentifier(uid));
  ct.getDataset()->putAndInsertString(DCM_Modality, "CT");
  ASSERT_TRUE(ct.getDataset()->saveFile((dir / "ct.dcm").c_str(), EXS_LittleEndianImplicit).good());
  for (const std::string name : { "image.nii", "image.nrrd", "image.vtk", "ct.dcm" })
    EXPECT_FALSE(detectContourFileKind((dir / name).string()).has_value()) << name;
}

TEST(StructureSetReader, AStructureSetCutShortAnywhereSaysSoNamingTheFile)
{
  // Wherever a copy or a download stopped, the one line says that the file is cut short and which
  // file it is (DCMTK's own words for most cuts were a bare "Invalid stream").
  const fs::path dir = folder("cut-anywhere");
  const fs::path whole = dir / "RS.dcm", cut = dir / "RS-cut.dcm";
  writeRTStructureSet(whole.string(), twoStructures());
  const auto size = fs::file_size(whole);
  for (const auto length : { size / 20, size / 10, size / 4, size / 2, size * 3 / 4, size * 9 / 10, size - 10, size - 1 })
  {
    fs::copy_file(whole, cut, fs::copy_options::overwrite_existing);
    fs::resize_file(cut, length);
    try
    {
      readStructureSet(cut.string());
      ADD_FAILURE() << "cut to " << length << " of " << size << " bytes, it must not read";
    }
    catch (const Error& e)
    {
      const std::string message = e.what();
      EXPECT_NE(message.find("'" + cut.string() + "'"), std::string::npos) << message;
      EXPECT_NE(message.find("cut short"), std::string::npos) << length << " of " << size << ": " << message;
    }
  }
}

/** The file's bytes with the first run of `find` replaced by `replace`. */
std::string withBytesReplaced(const fs::path& path, const std::string& find, const std::string& replace)
{
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t at = bytes.find(find);
  EXPECT_NE(at, std::string::npos);
  return at == std::string::npos ? bytes : bytes.replace(at, find.size(), replace);
}

/** Reads the structure set with `spare` bytes of address space beyond what the process holds, then
 *  exits: 0 if it read, 3 with the error on stderr if it failed (for a death test's child). */
[[noreturn]] void readUnderAddressLimit(const fs::path& path, rlim_t spare)
{
  std::ifstream statm("/proc/self/statm");
  unsigned long pages = 0;
  statm >> pages;
  const rlim_t held = static_cast<rlim_t>(pages) * static_cast<rlim_t>(::sysconf(_SC_PAGESIZE));
  const rlimit limit{ held + spare, held + spare };
  ::setrlimit(RLIMIT_AS, &limit);
  try
  {
    readStructureSet(path.string());
  }
  catch (const Error& e)
  {
    std::cerr << e.what() << std::endl;
    std::exit(3);
  }
  std::exit(0);
}

TEST(StructureSetReader, ADamagedLengthIsNotAllocated)
{
  // An element claiming about 4 GB in a file of a few kilobytes: DCMTK allocated the value before
  // finding the file too short (the fuzzer's out-of-memory). Under an address-space limit 1 GB above
  // what the process holds, the read must fail on the damage, not on memory.
  const fs::path dir = folder("damaged-length");
  const fs::path whole = dir / "RS.dcm";
  writeRTStructureSet(whole.string(), twoStructures());
  // (0002,0001) OB, the meta header's version; and the first ContourData (3006,0050), its VR made
  // OB so that its length takes four bytes.
  const std::string metaHuge = withBytesReplaced(whole, std::string("\x02\x00\x01\x00OB\x00\x00\x02\x00\x00\x00", 12),
                                                 std::string("\x02\x00\x01\x00OB\x00\x00\x02\x00\xff\xff", 12));
  const std::string dataHuge = withBytesReplaced(whole, std::string("\x06\x30\x50\x00" "DS", 6),
                                                 std::string("\x06\x30\x50\x00" "OB\x00\x00\x00\x00\xf0\xff", 12));
  for (const auto& [name, bytes] : { std::pair{ "meta.dcm", metaHuge }, std::pair{ "data.dcm", dataHuge } })
  {
    const fs::path path = dir / name;
    std::ofstream(path, std::ios::binary) << bytes;
    ASSERT_LT(fs::file_size(path), 1u << 20);
    EXPECT_EXIT(readUnderAddressLimit(path, 1ull << 30), ::testing::ExitedWithCode(3), "the file ends inside an element")
      << name;
  }
}

TEST(StructureSetReader, ReadsTheJsonFormatWithItsSlicesAndCoordinateSystem)
{
  const fs::path path = folder("json") / "contours.json";
  writeText(path, R"({
    "coordinateSystem": "RAS",
    "rois": [
      { "number": 5, "name": "Bladder", "color": [200, 150, 0],
        "slices": [ { "z": 4.5, "polygons": [ [[0, 0], [10, 0], [10, 10], [0, 10]] ] },
                    { "polygons": [ [[0, 0, 7.5], [10, 0, 7.5], [10, 10, 7.5]] ] } ] },
      { "name": "Nothing" }
    ] })");
  EXPECT_EQ(detectContourFileKind(path.string()), ContourFileKind::Json);
  const StructureSet set = readStructureSet(path.string());
  ASSERT_EQ(set.structures.size(), 2u);
  const PlanarStructure& bladder = set.structures[0];
  EXPECT_EQ(bladder.number, 5);
  EXPECT_EQ(bladder.rgb, (std::array<unsigned char, 3>{ 200, 150, 0 }));
  ASSERT_EQ(bladder.contours.size(), 2u);
  EXPECT_EQ(bladder.contours[0][1].x, -10.0) << "RAS x is LPS -x";
  EXPECT_EQ(bladder.contours[0][2].y, -10.0);
  EXPECT_EQ(bladder.contours[0][2].z, 4.5);
  EXPECT_EQ(bladder.contours[1][0].z, 7.5);
  EXPECT_EQ(set.structures[1].number, 2) << "an ROI without a number gets its place";
  EXPECT_TRUE(set.structures[1].contours.empty());
}

TEST(StructureSetReader, AJsonSliceWhosePointsSayAnotherZIsSaid)
{
  // The points' own z are used (they may be a tilted plane's), but a slice "z" they contradict is a
  // mistake of the writer to say.
  const fs::path path = folder("jsonZ") / "contours.json";
  writeText(path, R"({ "rois": [
      { "name": "Agrees", "slices": [ { "z": 4.5, "polygons": [ [[0, 0, 4.5], [10, 0, 4.5], [10, 10, 4.5]] ] } ] },
      { "name": "Contradicts", "slices": [ { "z": 4.5, "polygons": [ [[0, 0], [10, 0], [10, 10]] ] },
                                           { "z": 7.5, "polygons": [ [[0, 0, 9], [10, 0, 9], [10, 10, 9]] ] } ] }
    ] })");
  const StructureSet set = readStructureSet(path.string());
  ASSERT_EQ(set.structures.size(), 2u);
  EXPECT_TRUE(set.structures[0].notes.empty());
  ASSERT_EQ(set.structures[1].notes.size(), 1u);
  EXPECT_NE(set.structures[1].notes[0].find("rois[1].slices[1] has points whose z is not its \"z\""), std::string::npos)
    << set.structures[1].notes[0];
  EXPECT_EQ(set.structures[1].contours[1][0].z, 9.0);
}

TEST(StructureSetReader, AJsonFileWithAByteOrderMarkIsDetectedAndRead)
{
  // Windows editors start a UTF-8 file with the byte order mark EF BB BF.
  const fs::path path = folder("json-bom") / "contours.json";
  writeText(path, "\xEF\xBB\xBF" R"({ "rois": [ { "name": "Mark", "slices": [ { "z": 2, "polygons": [ [[0, 0], [4, 0], [0, 4]] ] } ] } ] })");
  EXPECT_EQ(detectContourFileKind(path.string()), ContourFileKind::Json);
  const StructureSet set = readStructureSet(path.string());
  ASSERT_EQ(set.structures.size(), 1u);
  EXPECT_EQ(set.structures[0].name, "Mark");
  ASSERT_EQ(set.structures[0].contours.size(), 1u);
  EXPECT_EQ(set.structures[0].contours[0][1].x, 4.0);
}

TEST(StructureSetReader, AMalformedJsonFileSaysWhere)
{
  const fs::path dir = folder("badjson");
  writeText(dir / "b.json", R"({ "rois": [ )");
  writeText(dir / "c.json", R"({ "rois": [ { "name": 5 } ] })");
  writeText(dir / "d.json", R"({ "rois": [ { "slices": [ { "z": 1e999, "polygons": [] } ] } ] })");
  for (const std::string name : { "b.json", "c.json", "d.json" })
  {
    try
    {
      readStructureSet((dir / name).string());
      FAIL() << name << " must not read";
    }
    catch (const Error& e)
    {
      const std::string message = e.what();
      EXPECT_NE(message.find(name), std::string::npos) << message;
      EXPECT_EQ(message.find("[json.exception"), std::string::npos) << "the parser's tag is not for users: " << message;
      if (name == "c.json")
        EXPECT_NE(message.find("rois[0].name: not a string"), std::string::npos) << message;
      if (name == "d.json")
        EXPECT_NE(message.find("1e999"), std::string::npos) << message;
    }
  }
}

TEST(StructureSetReader, AJsonROIWithContourDataThatIsNoNumberIsUnusableAlone)
{
  // As in a structure set: a fault in one ROI's points fails that ROI, with where and what in one
  // line and no contour kept; the file's other ROIs read.
  const fs::path dir = folder("badjson-roi");
  const std::string square = R"([[0, 0], [4, 0], [4, 4], [0, 4]])";
  for (const auto& [bad, said] :
       { std::pair{ R"([[0, 0], [4, "abc"], [0, 4]])", "rois[1].slices[0].polygons[0]: a coordinate is not a number" },
         std::pair{ R"([[0, 0], [4], [0, 4]])", "rois[1].slices[0].polygons[0]: a point needs" },
         std::pair{ R"("not a polygon")", "rois[1].slices[0].polygons[0]: a polygon is not an array" } })
  {
    const fs::path path = dir / "contours.json";
    writeText(path, R"({ "rois": [ { "name": "Good", "slices": [ { "z": 0, "polygons": [ )" + square +
                      R"( ] } ] }, { "name": "Bad", "slices": [ { "z": 0, "polygons": [ )" + std::string(bad) +
                      R"( ] } ] } ] })");
    const StructureSet set = readStructureSet(path.string());
    ASSERT_EQ(set.structures.size(), 2u) << bad;
    EXPECT_TRUE(set.structures[0].unusableBecause.empty()) << set.structures[0].unusableBecause;
    EXPECT_EQ(set.structures[0].contours.size(), 1u);
    const PlanarStructure& failed = set.structures[1];
    EXPECT_EQ(failed.name, "Bad");
    EXPECT_NE(failed.unusableBecause.find(said), std::string::npos) << failed.unusableBecause;
    EXPECT_TRUE(failed.contours.empty());
  }
}

TEST(StructureSetReader, AJsonROIWithAnUnknownKeyIsUnusableAlone)
{
  // "Slices" for "slices": the ROI had no contours and was said only to have no closed contour.
  const fs::path path = folder("json-unknown-key") / "contours.json";
  writeText(path, R"({ "rois": [ { "name": "Good", "slices": [ { "z": 0, "polygons": [ [[0, 0], [4, 0], [4, 4]] ] } ] },
                                 { "name": "Typo", "Slices": [ { "z": 0, "polygons": [ [[0, 0], [4, 0], [4, 4]] ] } ] } ] })");
  const StructureSet set = readStructureSet(path.string());
  ASSERT_EQ(set.structures.size(), 2u);
  EXPECT_TRUE(set.structures[0].unusableBecause.empty()) << set.structures[0].unusableBecause;
  EXPECT_NE(set.structures[1].unusableBecause.find("rois[1]: unknown key \"Slices\""), std::string::npos)
    << set.structures[1].unusableBecause;
}

TEST(StructureSetReader, JsonROIsThatShareANumberAreNeitherMeshedWithOneNote)
{
  // The number names an ROI's mesh (its file, its Label, what --rois picks): two ROIs given one
  // number wrote one file over the other without a word. The third ROI has no number of its own and
  // is numbered by its place (3), which the fourth also claims.
  const fs::path path = folder("json-shared-number") / "contours.json";
  const std::string slices = R"("slices": [ { "z": 0, "polygons": [ [[0, 0], [4, 0], [4, 4], [0, 4]] ] } ])";
  writeText(path, R"({ "rois": [ { "number": 7, "name": "A B", )" + slices + R"( }, { "number": 7, "name": "A/B", )" +
                    slices + R"( }, { "name": "Third", )" + slices + R"( }, { "number": 3, "name": "Fourth", )" + slices +
                    R"( }, { "number": 9, "name": "Alone", )" + slices + R"( } ] })");
  const StructureSet set = readStructureSet(path.string());
  ASSERT_EQ(set.structures.size(), 5u);
  ASSERT_EQ(set.notes.size(), 2u);
  EXPECT_NE(set.notes[0].find("ROI number 3 is given to 2 ROIs, 'Third' and 'Fourth'"), std::string::npos) << set.notes[0];
  EXPECT_NE(set.notes[1].find("ROI number 7 is given to 2 ROIs, 'A B' and 'A/B'"), std::string::npos) << set.notes[1];
  for (std::size_t n = 0; n < 4; ++n)
  {
    EXPECT_TRUE(set.structures[n].contours.empty()) << n;
    EXPECT_NE(set.structures[n].unusableBecause.find("is also given to"), std::string::npos) << n;
  }
  EXPECT_TRUE(set.structures[4].unusableBecause.empty());
  EXPECT_EQ(set.structures[4].contours.size(), 1u);
}

TEST(StructureSetReader, AnROINameWithLineBreaksIsReadOnOneLine)
{
  // Each message that names an ROI is one line: a line feed, a carriage return, a tab, a C1 control
  // or a line separator in a name becomes a space, in the name and in the notes that quote it.
  const fs::path path = folder("json-name-lines") / "contours.json";
  const std::string slices = R"("slices": [ { "z": 0, "polygons": [ [[0, 0], [4, 0], [4, 4], [0, 4]] ] } ])";
  writeText(path, R"({ "rois": [ { "number": 2, "name": "B\nsecond\rline\tX\u0085Y\u2028Z", )" + slices +
                    R"( }, { "number": 2, "name": "C", )" + slices + R"( } ] })");
  const StructureSet set = readStructureSet(path.string());
  ASSERT_EQ(set.structures.size(), 2u);
  EXPECT_EQ(set.structures[0].name, "B second line X Y Z");
  ASSERT_EQ(set.notes.size(), 1u);
  // The note names both ROIs, and C's reason names B.
  for (const std::string& text : { set.notes[0], set.structures[1].unusableBecause })
  {
    EXPECT_EQ(text.find_first_of("\n\r\t"), std::string::npos) << text;
    EXPECT_NE(text.find("B second line X Y Z"), std::string::npos) << text;
  }
}

TEST(StructureSetReader, ReadsSlicerPlanarContoursFromLegacyAndXmlPolyData)
{
  const fs::path dir = folder("polydata");
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (int k = 0; k < 3; ++k)
  {
    const Polygon3 c = circle(5.0, 5.0, 2.0 * k, 4.0, 16);
    std::vector<vtkIdType> ids;
    for (const Point3& p : c)
      ids.push_back(points->InsertNextPoint(p.x, p.y, p.z));
    ids.push_back(ids.front()); // closed: back to the first point, as Slicer writes them
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  const vtkIdType open[3] = { 0, 1, 2 };
  lines->InsertNextCell(3, open);
  vtkNew<vtkPolyData> polyData;
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  vtkNew<vtkStringArray> space;
  space->SetName("SPACE");
  space->InsertNextValue("RAS");
  polyData->GetFieldData()->AddArray(space);
  vtkNew<vtkXMLPolyDataWriter> xml;
  xml->SetFileName((dir / "Prostate.vtp").c_str());
  xml->SetInputData(polyData);
  ASSERT_EQ(xml->Write(), 1);
  polyData->GetFieldData()->RemoveArray("SPACE");
  vtkNew<vtkPolyDataWriter> legacy;
  legacy->SetFileName((dir / "Rectum.vtk").c_str());
  legacy->SetInputData(polyData);
  ASSERT_EQ(legacy->Write(), 1);

  for (const std::string name : { "Prostate.vtp", "Rectum.vtk" })
  {
    const std::string path = (dir / name).string();
    EXPECT_EQ(detectContourFileKind(path), ContourFileKind::PolyData) << name;
    const StructureSet set = readStructureSet(path);
    ASSERT_EQ(set.structures.size(), 1u);
    const PlanarStructure& roi = set.structures[0];
    EXPECT_EQ(roi.name, name.substr(0, name.find('.')));
    ASSERT_EQ(roi.contours.size(), 3u) << "the open polyline is skipped";
    EXPECT_EQ(roi.notes.size(), 1u);
    const double sign = name == "Prostate.vtp" ? -1.0 : 1.0; // RAS -> LPS
    EXPECT_NEAR(roi.contours[1][0].x, sign * 9.0, 1e-6);
    EXPECT_NEAR(roi.contours[1][0].y, sign * 5.0, 1e-6);
    EXPECT_NEAR(roi.contours[1][0].z, 2.0, 1e-6);
  }
}

TEST(StructureSetReader, ASurfaceMeshGivenAsContoursIsRefused)
{
  // A closed surface (a tetrahedron, and a mesh SliceMesh wrote) read as contours: each triangle
  // was a "contour", tilted ones skipped, into a mesh of a tenth of the volume with exit 0.
  const fs::path dir = folder("surfaceAsContours");
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(10, 0, 0);
  points->InsertNextPoint(0, 10, 0);
  points->InsertNextPoint(0, 0, 10);
  vtkNew<vtkCellArray> triangles;
  for (const std::array<vtkIdType, 3>& t : { std::array<vtkIdType, 3>{ 0, 2, 1 }, std::array<vtkIdType, 3>{ 0, 1, 3 },
                                             std::array<vtkIdType, 3>{ 1, 2, 3 }, std::array<vtkIdType, 3>{ 0, 3, 2 } })
    triangles->InsertNextCell(3, t.data());
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  surface->SetPolys(triangles);
  vtkNew<vtkXMLPolyDataWriter> xml;
  xml->SetFileName((dir / "Liver.vtp").c_str());
  xml->SetInputData(surface);
  ASSERT_EQ(xml->Write(), 1);
  try
  {
    readStructureSet((dir / "Liver.vtp").string());
    ADD_FAILURE() << "a surface read as contours";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("holds a surface mesh (4 polygons joined at their edges), not contours"),
              std::string::npos)
      << e.what();
  }
}

TEST(StructureSetReader, ReadsLegacyPolyDataAsVtkWritesItInEitherFormatAsciiOrBinary)
{
  const fs::path dir = folder("legacyFormats");
  // Two closed contours, one as a polygon, in float and double points, with a named ROI and an
  // integer field and per-point values the reader reads past.
  for (const int dataType : { VTK_FLOAT, VTK_DOUBLE })
  {
    vtkNew<vtkPoints> points;
    points->SetDataType(dataType);
    vtkNew<vtkCellArray> lines, polygons;
    for (int k = 0; k < 2; ++k)
    {
      std::vector<vtkIdType> ids;
      for (const Point3& p : circle(-3.25, 7.5, -1.5 + 2.0 * k, 6.0, 24))
        ids.push_back(points->InsertNextPoint(p.x, p.y, p.z));
      if (k == 0)
      {
        ids.push_back(ids.front());
        lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
      }
      else
        polygons->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    }
    vtkNew<vtkPolyData> polyData;
    polyData->SetPoints(points);
    polyData->SetLines(lines);
    polyData->SetPolys(polygons);
    vtkNew<vtkStringArray> name;
    name->SetName("LabelName");
    name->InsertNextValue("Left lung 2%");
    polyData->GetFieldData()->AddArray(name);
    vtkNew<vtkIntArray> label;
    label->SetName("Label");
    label->InsertNextValue(12);
    polyData->GetFieldData()->AddArray(label);
    vtkNew<vtkIntArray> perPoint;
    perPoint->SetName("index");
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
      perPoint->InsertNextValue(static_cast<int>(i));
    polyData->GetPointData()->AddArray(perPoint);

    for (const int version : { vtkDataWriter::VTK_LEGACY_READER_VERSION_4_2, vtkDataWriter::VTK_LEGACY_READER_VERSION_5_1 })
      for (const bool binary : { false, true })
      {
        const std::string file = "roi" + std::to_string(dataType) + "_" + std::to_string(version) + (binary ? "b" : "a") + ".vtk";
        vtkNew<vtkPolyDataWriter> writer;
        writer->SetFileName((dir / file).c_str());
        writer->SetFileVersion(version);
        if (binary)
          writer->SetFileTypeToBinary();
        writer->SetInputData(polyData);
        ASSERT_EQ(writer->Write(), 1) << file;

        const StructureSet set = readStructureSet((dir / file).string());
        ASSERT_EQ(set.structures.size(), 1u) << file;
        const PlanarStructure& roi = set.structures[0];
        EXPECT_EQ(roi.name, "Left lung 2%") << file;
        ASSERT_EQ(roi.contours.size(), 2u) << file;
        EXPECT_EQ(roi.contours[0].size(), 25u) << file;
        EXPECT_EQ(roi.contours[1].size(), 24u) << file;
        EXPECT_TRUE(roi.notes.empty()) << file;
        for (std::size_t c = 0; c < 2; ++c)
          for (std::size_t i = 0; i < 24; ++i)
          {
            double expected[3];
            points->GetPoint(static_cast<vtkIdType>(24 * c + i), expected);
            // Binary values are exact; VTK writes ASCII floats with 6 digits and doubles with 11.
            const double tolerance = binary ? 0.0 : dataType == VTK_FLOAT ? 1e-4 : 1e-9;
            EXPECT_NEAR(roi.contours[c][i].x, expected[0], tolerance) << file;
            EXPECT_NEAR(roi.contours[c][i].y, expected[1], tolerance) << file;
            EXPECT_NEAR(roi.contours[c][i].z, expected[2], tolerance) << file;
          }
      }
  }
}

TEST(StructureSetReader, MalformedLegacyPolyDataIsAOneLineError)
{
  const fs::path dir = folder("legacyMalformed");
  const std::string header = "# vtk DataFile Version 4.2\nRing\nASCII\nDATASET POLYDATA\n";
  const std::string points = header + "POINTS 4 double\n0 0 0 4 0 0 4 4 0 0 4 0\n";
  const std::string header5 = "# vtk DataFile Version 5.1\nRing\nASCII\nDATASET POLYDATA\n";
  const std::vector<std::pair<std::string, std::string>> files = {
    { "keyword", points + "LINES^ 2 12\n5 0 1 2 300\n5 4 5 6 7 4\n" }, // VTK 9.1 read past its buffer
    { "short", points + "LINES 1 34\n5 0 1 2 3 0\n" },
    { "overrun", points + "LINES 1 6\n9 0 1 2 3 0\n" },
    { "cellCount", points + "LINES 2 6\n5 0 1 2 3 0\n" },
    { "stray", points + "LINES 1 6@\n5 0 1 2 3 0\n" },
    { "negative", points + "LINES -1 6\n5 0 1 2 3 0\n" },
    { "fewPoints", header + "POINTS 4 double\n0 0 0 4 0 0 4\n" },
    { "pointType", header + "POINTS 4 bit\n0 0 0 4 0 0 4 4 0 0 4 0\n" },
    { "notANumber", header + "POINTS 1 double\n0 zero 0\n" },
    { "nanPoint", header + "POINTS 4 double\n0 0 0 4 0 0 nan 4 0 0 4 0\nLINES 1 6\n5 0 1 2 3 0\n" },
    { "infinitePoint", header + "POINTS 4 double\n0 0 0 4 0 0 4 4 0 0 4 -inf\nLINES 1 6\n5 0 1 2 3 0\n" },
    { "grid", "# vtk DataFile Version 4.2\nRing\nASCII\nDATASET STRUCTURED_POINTS\n" },
    { "encoding", "# vtk DataFile Version 4.2\nRing\nEBCDIC\nDATASET POLYDATA\n" },
    { "noHeader", "vtk DataFile Version 4.2\nRing\nASCII\nDATASET POLYDATA\n" },
    { "titleOnly", "# vtk DataFile Version 4.2\n" },
    { "offsetsFall", header5 + "POINTS 4 double\n0 0 0 4 0 0 4 4 0 0 4 0\nLINES 3 5\nOFFSETS vtktypeint64\n0 5 2\n"
                                "CONNECTIVITY vtktypeint64\n0 1 2 3 0\n" },
    { "offsetsBeyond", header5 + "POINTS 4 double\n0 0 0 4 0 0 4 4 0 0 4 0\nLINES 2 5\nOFFSETS vtktypeint64\n0 9\n"
                                  "CONNECTIVITY vtktypeint64\n0 1 2 3 0\n" },
    { "noOffsets", header5 + "POINTS 4 double\n0 0 0 4 0 0 4 4 0 0 4 0\nLINES 2 5\n0 5\n" },
    { "binaryBeyond", "# vtk DataFile Version 4.2\nRing\nBINARY\nDATASET POLYDATA\nPOINTS 100000000 float\n\x01\x02\n" },
    { "stringBeyond", "# vtk DataFile Version 4.2\nRing\nBINARY\nDATASET POLYDATA\nFIELD FieldData 1\n"
                      "LabelName 1 1 string\n\x7f\xff\xff\xff\x01\n" },
  };
  for (const auto& [name, text] : files)
  {
    const fs::path path = dir / (name + ".vtk");
    writeText(path, text);
    try
    {
      const StructureSet set = readStructureSet(path.string());
      ADD_FAILURE() << name << ": read without an error";
    }
    catch (const Error& error)
    {
      const std::string message = error.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << name << ": " << message;
      EXPECT_NE(message.find(path.string()), std::string::npos) << name << ": " << message;
    }
  }
}

TEST(StructureSetReader, AnImageOrTextIsNoContourFile)
{
  const fs::path dir = folder("other");
  writeText(dir / "image.mha", "ObjectType = Image\nNDims = 3\n");
  writeText(dir / "notes.txt", "hello");
  EXPECT_FALSE(detectContourFileKind((dir / "image.mha").string()).has_value());
  EXPECT_FALSE(detectContourFileKind((dir / "notes.txt").string()).has_value());
  EXPECT_FALSE(detectContourFileKind((dir / "missing.dcm").string()).has_value());
  EXPECT_THROW(readStructureSet((dir / "notes.txt").string()), Error);
}

} // namespace
} // namespace slicemesh::testing
