// DICOM RT Structure Sets through DCMTK (its ROIs by dcmrt's typed sequence, contours from the dataset): the plugin SliceMeshStructuresDicom.
#include "RTStructureSetPlugin.h"

#include "Core/Utf8.h"

#include <dcmtk/dcmdata/dcfilefo.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcitem.h>
#include <dcmtk/dcmdata/dcvr.h>
#include <dcmtk/dcmrt/seq/drtssrs.h>
#include <dcmtk/oflog/oflog.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace slicemesh
{
namespace
{

/** Files up to this size are read whole in one pass (the largest clinical structure sets are tens of
 *  megabytes). */
constexpr std::uintmax_t largestStructureSetBytes = 256ull << 20;

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

std::string trimmed(const OFString& text)
{
  std::string s(text.c_str());
  const auto first = s.find_first_not_of(" \t\r\n");
  const auto last = s.find_last_not_of(" \t\r\n");
  return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
}

/** Sets one of DCMTK's global flags for as long as it lives, then puts its value back: the flags are
 *  the process's, and an application that loads this plugin may rely on their defaults. */
class DcmtkFlag
{
public:
  DcmtkFlag(OFGlobal<OFBool>& flag, OFBool value)
    : m_Flag(flag)
    , m_Before(flag.get())
  {
    m_Flag.set(value);
  }
  ~DcmtkFlag() { m_Flag.set(m_Before); }
  DcmtkFlag(const DcmtkFlag&) = delete;
  DcmtkFlag& operator=(const DcmtkFlag&) = delete;

private:
  OFGlobal<OFBool>& m_Flag;
  const OFBool m_Before;
};

/** A value of a file quoted for a one-line message: at most 16 characters (a decimal string's
 *  most), anything unprintable as '?'. */
std::string quotedValue(std::string_view value)
{
  if (value.empty())
    return "an empty value";
  std::string quoted = "'";
  for (const char c : value.substr(0, 16))
    quoted += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return quoted + (value.size() > 16 ? "...'" : "'");
}

/** The numbers of a decimal string (DS) element, backslash-separated, each read as the nearest
 *  double (std::from_chars); none when the element is absent. A value that is no finite number
 *  stops the reading: it is returned, quoted, in `bad` (empty when every value was read). */
std::vector<double> decimalStrings(DcmItem& item, const DcmTagKey& tag, std::string& bad)
{
  std::vector<double> values;
  DcmElement* element = nullptr;
  char* text = nullptr;
  Uint32 length = 0;
  if (item.findAndGetElement(tag, element).bad() || !element || element->getString(text, length).bad() || !text)
    return values;
  const char* at = text;
  const char* const end = text + length;
  values.reserve(static_cast<std::size_t>(std::count(at, end, '\\')) + 1);
  while (at < end)
  {
    const char* const next = std::find(at, end, '\\');
    std::string_view value(at, static_cast<std::size_t>(next - at)); // padding aside
    value.remove_prefix(std::min(value.size(), value.find_first_not_of(' ')));
    value = value.substr(0, value.find_last_not_of(std::string_view(" \0", 2)) + 1);
    const std::size_t sign = value.size() > 0 && value[0] == '+' ? 1 : 0; // DS allows it, from_chars does not
    double number = 0.0;
    const std::from_chars_result parsed = std::from_chars(value.data() + sign, value.data() + value.size(), number);
    // from_chars reads "nan" and "inf", which a decimal string cannot hold.
    if (parsed.ec != std::errc() || parsed.ptr != value.data() + value.size() || !std::isfinite(number))
    {
      bad = quotedValue(value);
      return values;
    }
    values.push_back(number);
    at = next == end ? end : next + 1;
  }
  return values;
}

/** Latin-1 bytes as UTF-8 (each byte is the code point of its character). */
std::string latin1ToUtf8(const std::string& text)
{
  std::string utf8;
  for (const char c : text)
  {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x80)
      utf8 += c;
    else
    {
      utf8 += static_cast<char>(0xC0 | (byte >> 6));
      utf8 += static_cast<char>(0x80 | (byte & 0x3F));
    }
  }
  return utf8;
}

/** Converts the dataset's text (the ROI names) to UTF-8 from its Specific Character Set, so that
 *  names reach the output, the report and file names as one encoding. Returns why the text could
 *  not be converted (an unknown or unsupported character set, bytes invalid in it), empty when it
 *  was. Without a Specific Character Set the text should be ASCII; it is left to undeclaredToUtf8. */
std::string declaredCharacterSet(DcmFileFormat& file)
{
  OFString declared;
  file.getDataset()->findAndGetOFStringArray(DCM_SpecificCharacterSet, declared);
  return trimmed(declared);
}

std::string convertTextToUtf8(DcmFileFormat& file)
{
  const std::string charset = declaredCharacterSet(file);
  if (charset.empty())
    return {};
  const OFCondition converted = file.convertToUTF8();
  if (converted.good())
    return {};
  return "its text could not be converted to UTF-8 from Specific Character Set '" + charset + "' (" + converted.text() +
         "): the ROI names are kept as stored";
}

/** A name from a set that declares no Specific Character Set: kept if it is UTF-8 (what many tools
 *  write without saying so), else taken as Latin-1 (ISO_IR 100, the older systems' habit). */
std::string undeclaredToUtf8(const std::string& name)
{
  return isUtf8(name) ? name : latin1ToUtf8(name);
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
  // Every value read in the one pass: values over DCMTK's default 4 KB are otherwise read when first
  // asked for, each by opening the file again (a 50,000-point set: 240 opens; cheap from a local
  // disk, not from a network share). Not for a file larger than any structure set: an image given
  // by mistake is refused below before its pixels are read. No value is longer than the file: a
  // damaged length (4 GB in a 200-byte file) is left unread instead of allocated.
  std::error_code sizeError;
  const auto bytes = std::filesystem::file_size(path, sizeError);
  const Uint32 maxReadLength =
    !sizeError && bytes <= largestStructureSetBytes ? static_cast<Uint32>(bytes) : DCM_MaxReadLength;
  OFCondition loaded;
  {
    // A contour over 64 KiB of text cannot be a DS in explicit VR (its length has 16 bits), so
    // writers store it as UN with a 32-bit length, as the standard allows: read with the
    // dictionary's VR, it is the decimal string it was.
    const DcmtkFlag unknownAsDictionaryVR(dcmEnableUnknownVRConversion, OFTrue);
    loaded = file.loadFile(path.c_str(), EXS_Unknown, EGL_noChange, maxReadLength);
  }
  // A file cut short (a copy or a download that stopped) ends inside an element or a sequence, for
  // which DCMTK's words are "Invalid stream" and the like; a damaged length, or bytes that are no
  // DICOM, end one so too.
  if (loaded == EC_StreamNotifyClient || loaded == EC_InvalidStream || loaded == EC_SequDelimitationItemMissing ||
      loaded == EC_ItemDelimitationItemMissing)
    throw Error("cannot read '" + path +
                "' as DICOM: the file ends inside an element (cut short, a length damaged, or not DICOM)");
  if (loaded.bad())
    throw Error("cannot read '" + path + "' as DICOM: " + loaded.text());
  DcmDataset& dataset = *file.getDataset();
  OFString modality;
  dataset.findAndGetOFString(DCM_Modality, modality);
  if (modality != "RTSTRUCT")
    throw Error("'" + path + "' is not a DICOM RT Structure Set (Modality " +
                (modality.empty() ? std::string("missing") : std::string(modality.c_str())) + ")");
  StructureSet set;
  const bool undeclared = declaredCharacterSet(file).empty();
  if (const std::string fault = convertTextToUtf8(file); !fault.empty())
    set.notes.push_back("'" + path + "': " + fault);
  // The ROIs through dcmrt's typed sequence; the contours straight from the dataset. Reading the
  // whole IOD copies every contour's numbers into its own objects first, and dcmrt then parses
  // them one by one: together two thirds of the reading of a 50,000-point structure set.
  DRTStructureSetROISequence roiSequence;
  const OFCondition read = roiSequence.read(dataset, "1-n", "1", "StructureSetModule");
  if (read.bad())
    throw Error("cannot read the RT Structure Set '" + path + "': " + read.text());

  auto addFrameOfReference = [&set](const OFString& uid)
  {
    const std::string frame = trimmed(uid);
    if (!frame.empty() && std::find(set.framesOfReference.begin(), set.framesOfReference.end(), frame) ==
                            set.framesOfReference.end())
      set.framesOfReference.push_back(frame);
  };
  DcmSequenceOfItems* frames = nullptr;
  dataset.findAndGetSequence(DCM_ReferencedFrameOfReferenceSequence, frames);
  for (unsigned long n = 0; frames && n < frames->card(); ++n)
  {
    OFString uid;
    if (frames->getItem(n)->findAndGetOFString(DCM_FrameOfReferenceUID, uid).good())
      addFrameOfReference(uid);
  }
  std::map<Sint32, std::size_t> byNumber;
  forEachItem(roiSequence,
              [&](DRTStructureSetROISequence::Item& item)
              {
                PlanarStructure roi;
                Sint32 number = 0;
                if (item.getROINumber(number).bad())
                  return;
                OFString name, frame;
                item.getROIName(name);
                if (item.getReferencedFrameOfReferenceUID(frame).good())
                  addFrameOfReference(frame);
                roi.number = number;
                roi.name = undeclared ? undeclaredToUtf8(trimmed(name)) : trimmed(name);
                if (roi.name.empty())
                  roi.name = "ROI_" + std::to_string(number);
                byNumber.emplace(number, set.structures.size());
                set.structures.push_back(std::move(roi));
              });
  // The ROI Contour Sequence refers to an ROI by number only: where two ROIs share one, no contour
  // can be given to either. Both are listed, and neither gets contours.
  const std::vector<int> sharedNumbers =
    markSharedRoiNumbers(set, path, "which contours are whose cannot be told, so none of them is meshed",
                         "which contours are this ROI's cannot be told");
  const std::set<Sint32> ambiguous(sharedNumbers.begin(), sharedNumbers.end());

  DcmSequenceOfItems* contourSequences = nullptr;
  dataset.findAndGetSequence(DCM_ROIContourSequence, contourSequences);
  for (unsigned long n = 0; contourSequences && n < contourSequences->card(); ++n)
  {
    DcmItem& item = *contourSequences->getItem(n);
    Sint32 number = 0;
    if (item.findAndGetSint32(DCM_ReferencedROINumber, number).bad() || ambiguous.count(number) > 0)
      continue;
    auto found = byNumber.find(number);
    if (found == byNumber.end())
    {
      // Contours of an ROI the set does not declare: kept, under its number, and said.
      PlanarStructure roi;
      roi.number = number;
      roi.name = "ROI_" + std::to_string(number);
      roi.notes.push_back("not declared in the Structure Set ROI Sequence: named by its number");
      found = byNumber.emplace(number, set.structures.size()).first;
      set.structures.push_back(std::move(roi));
    }
    PlanarStructure& roi = set.structures[found->second];
    Sint32 rgb[3];
    if (item.findAndGetSint32(DCM_ROIDisplayColor, rgb[0], 0).good() &&
        item.findAndGetSint32(DCM_ROIDisplayColor, rgb[1], 1).good() &&
        item.findAndGetSint32(DCM_ROIDisplayColor, rgb[2], 2).good())
      for (int c = 0; c < 3; ++c)
        roi.rgb[c] = static_cast<unsigned char>(std::clamp<Sint32>(rgb[c], 0, 255));
    std::map<std::string, std::size_t> skipped;
    std::size_t miscounted = 0;
    std::string firstMiscount;
    DcmSequenceOfItems* contours = nullptr;
    item.findAndGetSequence(DCM_ContourSequence, contours);
    // A value that is no number fails its ROI alone, as a point beyond any anatomy does: the file's
    // other ROIs are still meshed. Its contours are dropped, none of its values reaching the geometry.
    for (unsigned long k = 0; contours && k < contours->card() && roi.unusableBecause.empty(); ++k)
    {
      DcmItem& contourItem = *contours->getItem(k);
      OFString type;
      contourItem.findAndGetOFString(DCM_ContourGeometricType, type);
      const std::string geometricType = trimmed(type);
      if (geometricType != "CLOSED_PLANAR")
      {
        ++skipped[geometricType.empty() ? "untyped" : geometricType];
        continue;
      }
      const std::string which = "the Contour Data of its contour " + std::to_string(k + 1) + " (of " +
                                  std::to_string(contours->card()) + ")";
      std::string bad;
      const std::vector<double> data = decimalStrings(contourItem, DCM_ContourData, bad);
      if (!bad.empty())
        roi.unusableBecause = which + " holds " + bad + ", which is not a number" +
                              (bad.find(',') != std::string::npos ? " (a decimal string has a point, not a comma)" : "");
      else if (data.size() % 3 != 0)
        roi.unusableBecause = which + " holds " + std::to_string(data.size()) +
                              " values, which is not x, y and z for each point (not a multiple of 3)";
      if (!roi.unusableBecause.empty())
        break;
      Sint32 stated = 0;
      if (contourItem.findAndGetSint32(DCM_NumberOfContourPoints, stated).good() &&
          static_cast<std::size_t>(std::max<Sint32>(stated, 0)) != data.size() / 3 && miscounted++ == 0)
        firstMiscount = std::to_string(stated) + " stated, " + std::to_string(data.size() / 3) + " present";
      Polygon3 contour;
      contour.reserve(data.size() / 3);
      for (std::size_t i = 0; i + 2 < data.size(); i += 3)
        contour.push_back({ data[i], data[i + 1], data[i + 2] });
      roi.contours.push_back(std::move(contour));
    }
    if (!roi.unusableBecause.empty())
      roi.contours.clear();
    if (miscounted > 0)
      roi.notes.push_back(std::to_string(miscounted) + " contour(s) whose Number of Contour Points differs from the points in " +
                          "their Contour Data (first: " + firstMiscount + "): the points present are used");
    for (const auto& [type, count] : skipped)
      roi.notes.push_back(std::to_string(count) + " " + type + " item(s) skipped: only CLOSED_PLANAR contours enclose a volume");
  }
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
