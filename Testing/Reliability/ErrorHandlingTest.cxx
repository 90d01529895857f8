// Every documented failure of the executable, run end to end: a one-line error on stderr, the
// documented exit code (README, "Exit codes"), no output and no temporary file left behind, and an
// existing output file left untouched.
#include "CLITestSupport.h"
#include "ExitCodes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace slicemesh::testing
{
namespace
{


const std::string precious = "an earlier mesh, to be kept";

/** Runs SliceMesh on input -> folder/out.vtp (which holds `precious` beforehand) and checks the
 *  failure: code, one line naming `mention`, the old output intact, nothing else in the folder. */
void expectFailure(const fs::path& folder, const std::string& input, int code, const std::string& mention,
                   const std::string& options = "", const std::string& output = "out.vtp")
{
  const fs::path out = folder / output;
  std::ofstream(folder / "out.vtp") << precious;
  std::vector<fs::path> before;
  for (const auto& entry : fs::directory_iterator(folder))
    before.push_back(entry.path());

  const RunResult r = runSliceMesh(options + " " + quoted(input) + " " + quoted(out.string()));
  SCOPED_TRACE(options + " " + input + " -> " + output);
  EXPECT_EQ(r.exitCode, code) << r.err;
  const std::vector<std::string> lines = linesOf(r.err);
  ASSERT_EQ(lines.size(), 1u) << r.err;
  EXPECT_EQ(lines[0].rfind("SliceMesh: error: ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(mention), std::string::npos) << lines[0];
  EXPECT_EQ(fileText(folder / "out.vtp"), precious);
  std::vector<fs::path> after;
  for (const auto& entry : fs::directory_iterator(folder))
    after.push_back(entry.path());
  std::sort(before.begin(), before.end());
  std::sort(after.begin(), after.end());
  EXPECT_EQ(after, before) << "a file was left behind";
}

/** The inputs live in their own folder so the output folder's listing is only the outputs. */
struct Folders
{
  fs::path inputs, outputs;
};

Folders foldersFor(const std::string& name)
{
  return { freshFolder(name + "-in"), freshFolder(name + "-out") };
}

void writeText(const fs::path& path, const std::string& text)
{
  std::ofstream(path, std::ios::binary) << text;
}

/** A MetaImage with a free-form header (a line per entry) and `voxels` bytes of data. */
void writeMetaImageWith(const fs::path& path, const std::string& header, std::size_t voxels, unsigned char value = 1)
{
  std::ofstream out(path, std::ios::binary);
  out << "ObjectType = Image\n" << header << "ElementType = MET_UCHAR\nElementDataFile = LOCAL\n";
  for (std::size_t v = 0; v < voxels; ++v)
    out.put(static_cast<char>(v % 7 == 0 ? value : 0));
}

void writeNrrd(const fs::path& path, const std::string& spaceDirections, const std::string& origin = "(0,0,0)")
{
  std::ofstream out(path, std::ios::binary);
  out << "NRRD0004\ntype: uchar\ndimension: 3\nspace: left-posterior-superior\nsizes: 8 8 8\n"
      << "space directions: " << spaceDirections << "\nencoding: raw\nspace origin: " << origin << "\n\n";
  for (int v = 0; v < 512; ++v)
    out.put(static_cast<char>(v % 5 == 0));
}

/** A 2 x 2 x 2 voxel box in a 6^3 label map, box.mha in `folder`: an input every run meshes. */
std::string writeBoxInput(const fs::path& folder)
{
  writeMetaImage(folder / "box.mha", { 6, 6, 6 }, { 1, 1, 1 },
                 [](int i, int j, int k) -> unsigned char { return i > 1 && i < 4 && j > 1 && j < 4 && k > 1 && k < 4; });
  return (folder / "box.mha").string();
}

std::string readBytes(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

/** The sample label map, uncompressed, with header fields replaced: floats and 16-bit integers at
 *  their byte offsets in the NIfTI-1 header. */
fs::path niftiWithFields(const fs::path& folder, const std::string& name, const std::vector<std::pair<int, float>>& floats,
                         const std::vector<std::pair<int, std::int16_t>>& shorts = {})
{
  const fs::path path = folder / name;
  const RunResult r = runCommand("gzip -dc " + quoted(SLICEMESH_DATA_DIR "/sample-labelmap.nii.gz") + " > " +
                                 quoted(path.string()));
  EXPECT_EQ(r.exitCode, cli::Success) << r.err;
  std::string bytes = readBytes(path);
  for (const auto& [offset, value] : floats)
    std::memcpy(&bytes[static_cast<std::size_t>(offset)], &value, sizeof value);
  for (const auto& [offset, value] : shorts)
    std::memcpy(&bytes[static_cast<std::size_t>(offset)], &value, sizeof value);
  writeText(path, bytes);
  return path;
}

/** The sample label map, uncompressed, with pixdim[axis + 1] (the spacing) replaced. */
fs::path niftiWithSpacing(const fs::path& folder, const std::string& name, int axis, float spacing)
{
  return niftiWithFields(folder, name, { { 80 + 4 * axis, spacing } }); // NIfTI-1: float pixdim[8] at byte 76
}

/** The NIfTI-1 file `single` (from niftiWithFields) as a pair, name.hdr and name.img: the same header
 *  with the pair's magic and the voxels from the start of the .img. `single` is removed. */
fs::path asNiftiPair(const fs::path& single, const std::string& name)
{
  const std::string bytes = readBytes(single);
  fs::remove(single);
  std::string header = bytes.substr(0, 348);
  header.replace(344, 4, std::string("ni1\0", 4));
  const float voxOffset = 0.0f;
  std::memcpy(&header[108], &voxOffset, sizeof voxOffset);
  const fs::path path = single.parent_path() / (name + ".hdr");
  writeText(path, header);
  writeText(single.parent_path() / (name + ".img"), bytes.substr(352));
  return path;
}

TEST(ErrorHandling, MissingInput)
{
  const Folders f = foldersFor("missing");
  expectFailure(f.outputs, (f.inputs / "nothing-here.nii.gz").string(), cli::UnreadableInput, "no such file");
}

TEST(ErrorHandling, NotAnImage)
{
  const Folders f = foldersFor("not-an-image");
  writeText(f.inputs / "notes.nii", "this is not an image\n");
  writeText(f.inputs / "notes.txt", "this is not an image\n");
  expectFailure(f.outputs, (f.inputs / "notes.nii").string(), cli::UnreadableInput, "not an image file");
  expectFailure(f.outputs, (f.inputs / "notes.txt").string(), cli::UnreadableInput, "not an image file");
  expectFailure(f.outputs, f.inputs.string(), cli::UnreadableInput, "DICOM"); // a folder without a series
}

TEST(ErrorHandling, TruncatedOrCorruptFiles)
{
  const Folders f = foldersFor("truncated");
  const std::string sample = readBytes(SLICEMESH_DATA_DIR "/sample-labelmap.nii.gz");
  writeText(f.inputs / "half.nii.gz", sample.substr(0, sample.size() / 2));
  writeText(f.inputs / "head.nii.gz", sample.substr(0, 100));
  std::string flipped = sample;
  flipped[flipped.size() / 2] = static_cast<char>(flipped[flipped.size() / 2] ^ 0x5a);
  writeText(f.inputs / "flipped.nii.gz", flipped);
  expectFailure(f.outputs, (f.inputs / "half.nii.gz").string(), cli::UnreadableInput, "truncated");
  expectFailure(f.outputs, (f.inputs / "head.nii.gz").string(), cli::UnreadableInput, "truncated");
  expectFailure(f.outputs, (f.inputs / "flipped.nii.gz").string(), cli::UnreadableInput, "damaged");

  // Uncompressed files cut short: ITK alone reads them without complaint.
  const fs::path whole = niftiWithSpacing(f.inputs, "whole.nii", 0, 1.0f);
  const std::string nifti = readBytes(whole);
  fs::remove(whole);
  writeText(f.inputs / "cut.nii", nifti.substr(0, nifti.size() / 3));
  expectFailure(f.outputs, (f.inputs / "cut.nii").string(), cli::UnreadableInput, "truncated");
  writeMetaImageWith(f.inputs / "cut.mha", "NDims = 3\nDimSize = 8 8 8\nElementSpacing = 1 1 1\n", 300);
  expectFailure(f.outputs, (f.inputs / "cut.mha").string(), cli::UnreadableInput, "cannot read the voxels");

  // A DICOM file cut off in or just after its File Meta Information: GDCM's reader aborted the
  // process (a failed assertion) before ITK could say anything.
  // The preamble, "DICM", and the meta group's length (0002,0000) UL 200, then its first element
  // (0002,0001) OB begun: a file that promises 200 bytes of meta information.
  std::string dicom(128, '\0');
  dicom += "DICM";
  dicom += std::string("\x02\x00\x00\x00UL\x04\x00\xc8\x00\x00\x00", 12);
  dicom += std::string("\x02\x00\x01\x00OB\x00\x00\x02\x00\x00\x00\x00\x01", 14);
  dicom.resize(198, '\0');
  for (std::size_t bytes : { 132u, 150u, 198u })
  {
    const fs::path cut = f.inputs / ("cut" + std::to_string(bytes) + ".dcm");
    writeText(cut, dicom.substr(0, bytes));
    expectFailure(f.outputs, cut.string(), cli::UnreadableInput, "truncated DICOM file");
  }
}

TEST(ErrorHandling, FilesThatAbortedTheReadersAreRefusedFirst)
{
  // A NIfTI affine (sform) or quaternion offset (qform) that is not a finite number, in use by its
  // code: ITK aborted the process on the first (an assertion in its decomposition) and took the
  // second for 0. A negative vox_offset was read from before the voxels.
  const Folders f = foldersFor("aborting-readers");
  const float nan = std::nanf("");
  const std::int16_t inUse = 1;
  expectFailure(f.outputs, niftiWithFields(f.inputs, "sform.nii", { { 280, nan } }, { { 254, inUse } }).string(),
                cli::UnreadableInput, "(sform) holds a value that is not a finite number");
  expectFailure(f.outputs,
                niftiWithFields(f.inputs, "sform-offset.nii", { { 292, std::numeric_limits<float>::infinity() } },
                                { { 254, inUse } })
                  .string(),
                cli::UnreadableInput, "(sform)");
  expectFailure(f.outputs, niftiWithFields(f.inputs, "qform.nii", { { 268, nan } }, { { 252, inUse } }).string(),
                cli::UnreadableInput, "(qform) holds a value that is not a finite number");
  expectFailure(f.outputs, niftiWithFields(f.inputs, "offset.nii", { { 108, -4.0f } }).string(), cli::UnreadableInput,
                "vox_offset");
  // The same affine where a reference volume is only read for its geometry (contours given).
  const fs::path contours = f.inputs / "contours.json";
  writeText(contours, R"({"rois": [{"name": "A", "slices": [{"z": 0, "polygons": [[[0, 0], [5, 0], [5, 5]]]}]}]})");
  expectFailure(f.outputs, (f.inputs / "sform.nii").string(), cli::UnreadableInput, "(sform)",
                "--inputContours " + quoted(contours.string()));

  // DICOM File Meta Information that GDCM's reader aborted on (a failed assertion): a value
  // representation that does not exist, and an element longer than the file. In a series folder,
  // GDCM's scan of the folder aborted on such a file as well.
  std::string meta(128, '\0');
  meta += "DICM";
  meta += std::string("\x02\x00\x00\x00UL\x04\x00\x1a\x00\x00\x00", 12); // group length 26
  std::string badVr = meta + std::string("\x02\x00\x10\x00ZZ\x12\x00", 8) + "1.2.840.10008.1.2.1";
  badVr.resize(400, '\0');
  writeText(f.inputs / "bad-vr.dcm", badVr);
  expectFailure(f.outputs, (f.inputs / "bad-vr.dcm").string(), cli::UnreadableInput,
                "value representation 'ZZ', which does not exist");
  std::string tooLong = meta + std::string("\x02\x00\x01\x00OB\x00\x00\x00\x00\x01\x00", 12);
  tooLong.resize(400, '\0');
  fs::create_directories(f.inputs / "series");
  writeText(f.inputs / "series" / "a.dcm", tooLong);
  expectFailure(f.outputs, (f.inputs / "series" / "a.dcm").string(), cli::UnreadableInput, "truncated DICOM file");
  expectFailure(f.outputs, (f.inputs / "series").string(), cli::UnreadableInput, "truncated DICOM file");

  // A MetaImage whose voxels are in a list of slice files, the list shorter than its sizes: MetaIO
  // read what memory held for the rest.
  writeText(f.inputs / "slice0.raw", std::string(64, '\1'));
  writeText(f.inputs / "slice1.raw", std::string(64, '\1'));
  writeText(f.inputs / "list.mhd", "ObjectType = Image\nNDims = 3\nDimSize = 8 8 4\nElementSpacing = 1 1 1\n"
                                   "ElementType = MET_UCHAR\nElementDataFile = LIST\nslice0.raw\nslice1.raw\n");
  expectFailure(f.outputs, (f.inputs / "list.mhd").string(), cli::UnreadableInput, "names 2 files where its sizes need 4");
}

TEST(ErrorHandling, ANiftiPairsHeaderIsCheckedAsASingleFilesIs)
{
  // A .hdr/.img pair has the header of a .nii: an sform that is not finite aborted the process in
  // ITK's reader there too, and a zero pixdim was meshed at a made-up 1 mm.
  const Folders f = foldersFor("nifti-pair");
  const float nan = std::nanf("");
  const std::int16_t inUse = 1;
  const fs::path sform = asNiftiPair(niftiWithFields(f.inputs, "s.nii", { { 280, nan } }, { { 254, inUse } }), "sform");
  expectFailure(f.outputs, sform.string(), cli::UnreadableInput, "(sform) holds a value that is not a finite number");
  const fs::path zero = asNiftiPair(niftiWithSpacing(f.inputs, "z.nii", 0, 0.0f), "zero");
  expectFailure(f.outputs, zero.string(), cli::UnreadableInput,
                "spacing along axis 0 is 0 in the NIfTI header; SliceMesh needs positive, finite voxel spacing");
  // The pair as written is read.
  const fs::path sound = asNiftiPair(niftiWithSpacing(f.inputs, "o.nii", 0, 0.8f), "sound");
  const RunResult r = runSliceMesh(quoted(sound.string()) + " " + quoted((f.outputs / "sound.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::Success) << r.err;
}

TEST(ErrorHandling, ReadersThatSpeakOnStandardErrorLeaveOneLine)
{
  // GDCM's trace (a preamble and "DICM", then bytes that are no data set) and the NIfTI library (a
  // dim[0] of 8) wrote several lines before the error line; MetaIO's unknown element type came out
  // as ITK's raw exception, with its reader's address.
  const Folders f = foldersFor("speaking-readers");
  std::string junk(128, '\0');
  junk += "DICM";
  for (int i = 0; i < 5120; ++i)
    junk += static_cast<char>(i % 256);
  writeText(f.inputs / "junk.dcm", junk);
  expectFailure(f.outputs, (f.inputs / "junk.dcm").string(), cli::UnreadableInput, "not an image file");
  const std::int16_t eightDimensions = 8;
  expectFailure(f.outputs, niftiWithFields(f.inputs, "dim8.nii", {}, { { 40, eightDimensions } }).string(),
                cli::UnreadableInput, "not recognized as a NIFTI file");
  writeText(f.inputs / "foo.raw", std::string(512, '\1'));
  writeText(f.inputs / "foo.mhd", "ObjectType = Image\nNDims = 3\nDimSize = 8 8 8\nElementSpacing = 1 1 1\n"
                                  "ElementType = MET_FOO\nElementDataFile = foo.raw\n");
  expectFailure(f.outputs, (f.inputs / "foo.mhd").string(), cli::UnreadableInput, "its voxel type is not one");
}

TEST(ErrorHandling, GridsOutsideWhatCanBeMeshedAreRefusedAtReading)
{
  // Voxel sides of 1e-10 or 1e10 mm (the tiling's points coincided, or memory ran out), sides a
  // thousand times apart (minutes, then a surface without its shape), and an origin so far away
  // that every vertex landed on the same coordinate (written as a flat mesh, exit 0).
  const Folders f = foldersFor("grid-range");
  writeNrrd(f.inputs / "tiny.nrrd", "(1e-10,0,0) (0,1e-10,0) (0,0,1e-10)");
  writeNrrd(f.inputs / "huge.nrrd", "(1e10,0,0) (0,1e10,0) (0,0,1e10)");
  writeNrrd(f.inputs / "thick.nrrd", "(1,0,0) (0,1,0) (0,0,1000)");
  writeNrrd(f.inputs / "far.nrrd", "(1,0,0) (0,1,0) (0,0,1)", "(1e300,0,0)");
  expectFailure(f.outputs, (f.inputs / "tiny.nrrd").string(), cli::UnreadableInput, "meshes voxel sides from");
  expectFailure(f.outputs, (f.inputs / "huge.nrrd").string(), cli::UnreadableInput, "meshes voxel sides from");
  expectFailure(f.outputs, (f.inputs / "thick.nrrd").string(), cli::UnreadableInput, "at most 200 times apart");
  expectFailure(f.outputs, (f.inputs / "far.nrrd").string(), cli::UnreadableInput, "cannot be told apart");
  // A micrometre grid far from nothing, and slices 100 times the pixel, are meshed.
  writeNrrd(f.inputs / "micro.nrrd", "(0.001,0,0) (0,0.001,0) (0,0,0.001)", "(-200,150,-80)");
  writeNrrd(f.inputs / "slices.nrrd", "(0.5,0,0) (0,0.5,0) (0,0,50)");
  for (const char* name : { "micro.nrrd", "slices.nrrd" })
  {
    const RunResult r = runSliceMesh(quoted((f.inputs / name).string()) + " " + quoted((f.outputs / "ok.vtp").string()));
    EXPECT_EQ(r.exitCode, cli::Success) << name << ": " << r.err;
  }
}

TEST(ErrorHandling, AMalformedNrrdIsOneLineNamingTheFileAndTheFault)
{
  // ITK reports a bad NRRD as its reader's class and address followed by the NRRD library's chain
  // of messages; the user gets the file and the NRRD library's reason, and nothing is written.
  const Folders f = foldersFor("malformed-nrrd");
  const std::string voxels(512, '\1');
  struct File
  {
    std::string name, content, fault;
  };
  const std::vector<File> files{
    { "type.nrrd", "NRRD0004\ntype: floot\ndimension: 3\nsizes: 8 8 8\nencoding: raw\n\n" + voxels,
      "couldn't parse type \"floot\"" },
    { "sizes.nrrd", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 8 8\nencoding: raw\n\n" + voxels,
      "parsed 2 values, but dimension is 3" },
    { "short.nrrd", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 8 8 8\nencoding: raw\n\n" + voxels.substr(0, 100),
      "the file holds 100 bytes of voxel data where its header claims 512 (a truncated file?)" },
    { "gzip.nrrd", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 8 8 8\nencoding: gzip\n\n" + voxels.substr(0, 100),
      "cannot read the voxels: expected 512 bytes but received 100" },
  };
  for (const auto& [name, content, fault] : files)
  {
    writeText(f.inputs / name, content);
    const RunResult r = runSliceMesh(quoted((f.inputs / name).string()) + " " + quoted((f.outputs / "out.vtp").string()));
    SCOPED_TRACE(name);
    EXPECT_EQ(r.exitCode, cli::UnreadableInput) << r.err;
    const std::vector<std::string> lines = linesOf(r.err);
    ASSERT_EQ(lines.size(), 1u) << r.err;
    EXPECT_EQ(lines[0].rfind("SliceMesh: error: " + (f.inputs / name).string() + ": ", 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find(fault), std::string::npos) << lines[0];
    for (const std::string noise : { "0x", "itk::", "ITK ERROR", "[nrrd]", "NrrdImageIO", "trouble" })
      EXPECT_EQ(lines[0].find(noise), std::string::npos) << "'" << noise << "' in: " << lines[0];
    EXPECT_TRUE(fs::is_empty(f.outputs)) << "nothing written";
  }
}

TEST(ErrorHandling, AHeaderClaimingMoreVoxelsThanItsFilesHoldIsRefusedBeforeTheyAreAllocated)
{
  // A 308-byte NRRD claiming 1000^3 bytes: ITK allocated the whole volume (985 MiB) before it found
  // the file short. The data's size on disk is compared with the header's first; gzip data by the
  // most deflate can decompress to (1032 bytes a byte).
  const Folders f = foldersFor("claimed-voxels");
  const std::string grid = "type: uchar\ndimension: 3\nsizes: 1000 1000 1000\nspacings: 1 1 1\n";
  const std::string hundred(100, '\1');
  const auto gzipped = [&](const std::string& bytes)
  {
    writeText(f.inputs / "plain", bytes);
    EXPECT_EQ(runCommand("gzip -c -n " + quoted((f.inputs / "plain").string()) + " > " +
                         quoted((f.inputs / "plain.gz").string()))
                .exitCode,
              0);
    const std::string compressed = readBytes(f.inputs / "plain.gz");
    fs::remove(f.inputs / "plain");
    fs::remove(f.inputs / "plain.gz");
    return compressed;
  };
  const std::string hundredGzipped = gzipped(hundred);
  writeText(f.inputs / "raw.nrrd", "NRRD0004\n" + grid + "encoding: raw\n\n" + hundred);
  writeText(f.inputs / "short.raw", hundred);
  writeText(f.inputs / "detached.nhdr", "NRRD0004\n" + grid + "encoding: raw\ndata file: short.raw\n\n");
  writeText(f.inputs / "local.mha", "ObjectType = Image\nNDims = 3\nBinaryData = True\nDimSize = 1000 1000 1000\n"
                                    "ElementSpacing = 1 1 1\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n" +
                                      hundred);
  writeText(f.inputs / "gzip.nrrd", "NRRD0004\n" + grid + "encoding: gzip\n\n" + hundredGzipped);
  writeText(f.inputs / "layers.seg.nrrd",
            "NRRD0004\ntype: uchar\ndimension: 4\nspace: left-posterior-superior\nsizes: 3 600 600 600\n"
            "space directions: none (1,0,0) (0,1,0) (0,0,1)\nkinds: list domain domain domain\nencoding: raw\n"
            "space origin: (0,0,0)\nSegment0_ID:=a\nSegment0_Name:=A\nSegment0_Layer:=0\nSegment0_LabelValue:=1\n\n" +
              hundred);
  const std::string held = "holds 100 bytes of voxel data where its header claims ";
  const std::vector<std::pair<std::string, std::string>> refused{
    { "raw.nrrd", "raw.nrrd: the file " + held + "1000000000 (a truncated file?)" },
    { "detached.nhdr", "detached.nhdr: its data file '" + (f.inputs / "short.raw").string() + "' " + held + "1000000000" },
    { "local.mha", "local.mha: the file " + held + "1000000000" },
    { "gzip.nrrd", "gzip.nrrd: the file holds " + std::to_string(hundredGzipped.size()) +
                     " bytes of compressed voxel data (at most " + std::to_string(1032 * hundredGzipped.size()) +
                     " decompressed) where its header claims 1000000000" },
    { "layers.seg.nrrd", "layers.seg.nrrd: the file " + held + "648000000" },
  };
  for (const auto& [name, message] : refused)
    expectFailure(f.outputs, (f.inputs / name).string(), cli::UnreadableInput, message);

  // Where the header says the voxels start, they are counted from there: a file that holds them all
  // is read, one a byte short is not.
  std::string box(512, '\0');
  for (int k = 2; k < 6; ++k)
    for (int j = 2; j < 6; ++j)
      for (int i = 2; i < 6; ++i)
        box[static_cast<std::size_t>(i + 8 * (j + 8 * k))] = '\1';
  const std::string boxGrid = "type: uchar\ndimension: 3\nsizes: 8 8 8\nspacings: 1 1 1\n";
  const std::string sixteen(16, '\7');
  writeText(f.inputs / "end.nrrd", "NRRD0004\n" + boxGrid + "encoding: raw\nbyte skip: -1\n\n" + sixteen + box);
  writeText(f.inputs / "box.raw", sixteen + box);
  writeText(f.inputs / "skip.nhdr", "NRRD0004\n" + boxGrid + "encoding: raw\ndata file: box.raw\nbyte skip: 16\n\n");
  writeText(f.inputs / "box.nrrd", "NRRD0004\n" + boxGrid + "encoding: gzip\n\n" + gzipped(box));
  const std::string metaGrid = "ObjectType = Image\nNDims = 3\nBinaryData = True\nDimSize = 8 8 8\nElementSpacing = 1 1 1\n"
                               "ElementType = MET_UCHAR\n";
  writeText(f.inputs / "skip.mhd", metaGrid + "HeaderSize = 16\nElementDataFile = box.raw\n");
  writeText(f.inputs / "end.mhd", metaGrid + "HeaderSize = -1\nElementDataFile = box.raw\n");
  for (const std::string name : { "end.nrrd", "skip.nhdr", "box.nrrd", "skip.mhd", "end.mhd" })
  {
    const RunResult r = runSliceMesh(quoted((f.inputs / name).string()) + " " + quoted((f.outputs / "box.vtp").string()));
    EXPECT_EQ(r.exitCode, cli::Success) << name << ": " << r.err;
  }
  fs::remove(f.outputs / "box.vtp");
  writeText(f.inputs / "over.nhdr", "NRRD0004\n" + boxGrid + "encoding: raw\ndata file: box.raw\nbyte skip: 17\n\n");
  expectFailure(f.outputs, (f.inputs / "over.nhdr").string(), cli::UnreadableInput,
                "' holds 511 bytes of voxel data where its header claims 512");
}

TEST(ErrorHandling, TwoAndFourDimensionalImages)
{
  const Folders f = foldersFor("dimensions");
  writeMetaImageWith(f.inputs / "flat.mha", "NDims = 2\nDimSize = 8 8\nElementSpacing = 1 1\n", 64);
  writeMetaImageWith(f.inputs / "series.mha", "NDims = 4\nDimSize = 8 8 8 3\nElementSpacing = 1 1 1 1\n", 1536);
  expectFailure(f.outputs, (f.inputs / "flat.mha").string(), cli::UnreadableInput, "a 2-D image; SliceMesh needs a 3-D volume");
  expectFailure(f.outputs, (f.inputs / "series.mha").string(), cli::UnreadableInput, "a 4-D image; SliceMesh needs a 3-D volume");
}

TEST(ErrorHandling, ZeroNegativeAndNonFiniteSpacing)
{
  const Folders f = foldersFor("spacing");
  writeMetaImageWith(f.inputs / "zero.mha", "NDims = 3\nDimSize = 8 8 8\nElementSpacing = 1 0 1\n", 512);
  writeMetaImageWith(f.inputs / "negative.mha", "NDims = 3\nDimSize = 8 8 8\nElementSpacing = 1 1 -2\n", 512);
  writeNrrd(f.inputs / "zero.nrrd", "(0,0,0) (0,1,0) (0,0,1)");
  expectFailure(f.outputs, (f.inputs / "zero.mha").string(), cli::UnreadableInput, "spacing along axis 1 is 0");
  expectFailure(f.outputs, (f.inputs / "negative.mha").string(), cli::UnreadableInput, "spacing along axis 2 is -2");
  expectFailure(f.outputs, (f.inputs / "zero.nrrd").string(), cli::UnreadableInput, "spacing along axis 0 is 0");
  // NIfTI carries the spacing as binary floats: NaN and infinity get through the format.
  expectFailure(f.outputs, niftiWithSpacing(f.inputs, "nan.nii", 1, std::nanf("")).string(), cli::UnreadableInput,
                "spacing");
  expectFailure(f.outputs,
                niftiWithSpacing(f.inputs, "inf.nii", 2, std::numeric_limits<float>::infinity()).string(),
                cli::UnreadableInput, "spacing");
  expectFailure(f.outputs, niftiWithSpacing(f.inputs, "zero.nii", 0, 0.0f).string(), cli::UnreadableInput, "spacing");
  // NRRD cannot even parse a non-finite spacing: it still fails on one line.
  writeNrrd(f.inputs / "nan.nrrd", "(nan,0,0) (0,1,0) (0,0,1)");
  expectFailure(f.outputs, (f.inputs / "nan.nrrd").string(), cli::UnreadableInput, "nan.nrrd");
}

TEST(ErrorHandling, AMetaImageWhoseSpacingOrOffsetIsNotFiniteNamesTheField)
{
  // MetaIO refused these with "File cannot be read ... Reason: Invalid argument", as if the file
  // could not be opened.
  const Folders f = foldersFor("metaimage-geometry");
  const std::string grid = "NDims = 3\nDimSize = 8 8 8\n";
  writeMetaImageWith(f.inputs / "nan.mha", grid + "ElementSpacing = 1 nan 1\n", 512);
  writeMetaImageWith(f.inputs / "inf.mha", grid + "ElementSpacing = 1 1 inf\n", 512);
  writeMetaImageWith(f.inputs / "offset.mha", grid + "ElementSpacing = 1 1 1\nOffset = 0 -inf 0\n", 512);
  writeText(f.inputs / "origin.raw", std::string(512, '\1'));
  writeText(f.inputs / "origin.mhd", "ObjectType = Image\n" + grid + "ElementSpacing = 1 1 1\nOrigin = nan 0 0\n"
                                     "ElementType = MET_UCHAR\nElementDataFile = origin.raw\n");
  const std::vector<std::pair<std::string, std::string>> cases{
    { "nan.mha", "its ElementSpacing holds 'nan', which is not a finite number" },
    { "inf.mha", "its ElementSpacing holds 'inf', which is not a finite number" },
    { "offset.mha", "its Offset holds '-inf', which is not a finite number" },
    { "origin.mhd", "its Origin holds 'nan', which is not a finite number" },
  };
  for (const auto& [name, message] : cases)
  {
    expectFailure(f.outputs, (f.inputs / name).string(), cli::UnreadableInput, (f.inputs / name).string() + ": " + message);
    const RunResult r = runSliceMesh(quoted((f.inputs / name).string()) + " " + quoted((f.outputs / "out.vtp").string()));
    EXPECT_EQ(r.err.find("cannot be read"), std::string::npos) << r.err;
  }
  // The same where the image is only read for its geometry (contours given).
  const fs::path contours = f.inputs / "contours.json";
  writeText(contours, R"({"rois": [{"name": "A", "slices": [{"z": 0, "polygons": [[[0, 0], [5, 0], [5, 5]]]}]}]})");
  expectFailure(f.outputs, (f.inputs / "offset.mha").string(), cli::UnreadableInput, "its Offset holds '-inf'",
                "--inputContours " + quoted(contours.string()));
}

TEST(ErrorHandling, SingularDirection)
{
  const Folders f = foldersFor("direction");
  writeMetaImageWith(f.inputs / "singular.mha",
                     "NDims = 3\nDimSize = 8 8 8\nElementSpacing = 1 1 1\nTransformMatrix = 1 0 0 1 0 0 0 0 1\n", 512);
  writeNrrd(f.inputs / "singular.nrrd", "(1,0,0) (2,0,0) (0,0,1)");
  expectFailure(f.outputs, (f.inputs / "singular.mha").string(), cli::UnreadableInput, "direction matrix is singular");
  expectFailure(f.outputs, (f.inputs / "singular.nrrd").string(), cli::UnreadableInput, "direction matrix is singular");
}

TEST(ErrorHandling, EmptyMaskAndAbsentLabel)
{
  const Folders f = foldersFor("empty");
  writeMetaImage(f.inputs / "zeros.mha", { 6, 6, 6 }, { 1, 1, 1 }, [](int, int, int) { return 0; });
  writeMetaImage(f.inputs / "labels.mha", { 8, 8, 8 }, { 1, 1, 1 },
                 [](int i, int, int k) -> unsigned char { return k > 1 && k < 6 ? (i < 4 ? 2 : 5) : 0; });
  expectFailure(f.outputs, (f.inputs / "zeros.mha").string(), cli::EmptySegmentation, "nothing to mesh");
  expectFailure(f.outputs, (f.inputs / "labels.mha").string(), cli::EmptySegmentation, "2", "--label 3");
  const RunResult r = runSliceMesh("--label 3 " + quoted((f.inputs / "labels.mha").string()) + " " +
                                   quoted((f.outputs / "x.vtp").string()));
  EXPECT_NE(r.err.find("2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("5"), std::string::npos) << "lists the labels present: " << r.err;
}

TEST(ErrorHandling, EverythingSmallerThanTheMinimumComponentVolume)
{
  const Folders f = foldersFor("specks");
  writeMetaImage(f.inputs / "specks.mha", { 12, 12, 12 }, { 1, 1, 1 },
                 [](int i, int j, int k) -> unsigned char { return i % 3 == 1 && j % 3 == 1 && k % 3 == 1; });
  expectFailure(f.outputs, (f.inputs / "specks.mha").string(), cli::EmptySegmentation, "minimum component volume",
                "--minimumComponentVolume 2");
  // With a minimum the specks go and the run succeeds on what is left.
  writeMetaImage(f.inputs / "block.mha", { 14, 14, 14 }, { 1, 1, 1 },
                 [](int i, int j, int k) -> unsigned char
                 { return (i % 3 == 1 && j % 3 == 1 && k % 3 == 1) || (i >= 5 && i < 9 && j >= 5 && j < 9 && k >= 5 && k < 9); });
  const RunResult r = runSliceMesh("--minimumComponentVolume 2 " + quoted((f.inputs / "block.mha").string()) + " " +
                                   quoted((f.outputs / "block.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::Success) << r.err;
}

TEST(ErrorHandling, OutputFolderMissingOrNotWritable)
{
  const Folders f = foldersFor("output-folder");
  const std::string input = quoted(writeBoxInput(f.inputs));
  RunResult r = runSliceMesh(input + " " + quoted((f.outputs / "nowhere" / "out.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::WriteFailed);
  EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;

  // /proc takes no new files, even from root.
  r = runSliceMesh(input + " /proc/slicemesh-out.vtp");
  EXPECT_EQ(r.exitCode, cli::WriteFailed);
  EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("not writable"), std::string::npos) << r.err;

  // One mesh per label into a folder nothing can be written to: refused before any work, in one line
  // without a VTK object address or a temporary file name; the output model is not written either.
  r = runSliceMesh("--outputDirectory /proc/slicemesh-labels " + input + " " + quoted((f.outputs / "merged.vtp").string()));
  EXPECT_EQ(r.exitCode, cli::WriteFailed);
  EXPECT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_EQ(r.err.find("0x"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("partial"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("<filter-start>"), std::string::npos) << "no stage may start: " << r.out;
  EXPECT_FALSE(fs::exists(f.outputs / "merged.vtp"));

  if (::geteuid() != 0) // root writes into a read-only folder regardless
  {
    const fs::path locked = f.outputs / "locked";
    fs::create_directory(locked);
    std::ofstream(locked / "out.vtp") << precious;
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
    r = runSliceMesh(input + " " + quoted((locked / "out.vtp").string()));
    fs::permissions(locked, fs::perms::owner_all);
    EXPECT_EQ(r.exitCode, cli::WriteFailed) << r.err;
    EXPECT_NE(r.err.find("not writable"), std::string::npos) << r.err;
    EXPECT_EQ(fileText(locked / "out.vtp"), precious);
  }
}

/** Every name in `folder` with its bytes, hidden files too, sub-folders as "<folder>". */
std::map<std::string, std::string> folderContents(const fs::path& folder)
{
  std::map<std::string, std::string> contents;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder))
    contents[entry.path().filename().string()] = entry.is_directory() ? "<folder>" : readBytes(entry.path());
  return contents;
}

TEST(ErrorHandling, OneMeshPerLabelIsWrittenWholeOrNotAtAll)
{
  // A label's file that could not be written (a full disk) failed the run, but the files written
  // before it stayed, replacing the user's earlier files of their names. Now every file goes to its
  // temporary first and all are moved into place together: the earlier files are as they were, and
  // no new or temporary file is left. Labels 1 and 2 are boxes of 4^3 voxels (files of some 6 kB),
  // label 3 a ball of radius 12 (some 70 kB).
  const Folders f = foldersFor("labels-whole-or-none");
  const fs::path input = f.inputs / "labels.mha";
  writeMetaImage(input, { 40, 40, 40 }, { 1, 1, 1 }, [](int i, int j, int k) -> unsigned char {
    if (j >= 2 && j < 6 && k >= 2 && k < 6 && i >= 2 && i < 12 && (i < 6 || i >= 8))
      return i < 6 ? 1 : 2;
    return (i - 25) * (i - 25) + (j - 22) * (j - 22) + (k - 20) * (k - 20) < 144 ? 3 : 0;
  });
  const fs::path meshes = f.outputs / "meshes";
  const auto earlierRun = [&]
  {
    fs::remove_all(f.outputs);
    fs::create_directories(meshes);
    std::ofstream(f.outputs / "all.vtp") << precious;
    std::ofstream(meshes / "001_Label_1.vtp") << "an earlier run's label 1";
    std::ofstream(meshes / "007_Label_7.vtp") << "an earlier run's label 7";
  };
  const std::string run = quoted(SLICEMESH_EXECUTABLE) + " --outputDirectory " + quoted(meshes.string()) + " " +
                          quoted(input.string()) + " " + quoted((f.outputs / "all.vtp").string());

  // A full disk: files of more than 16 kB (32 blocks of 512 bytes; of 1 kB in some shells, 32 kB) cut short.
  earlierRun();
  const std::map<std::string, std::string> before = folderContents(meshes);
  const RunResult full = runCommand("trap '' XFSZ; ulimit -f 32; " + run);
  EXPECT_EQ(full.exitCode, cli::WriteFailed) << full.err;
  ASSERT_EQ(linesOf(full.err).size(), 1u) << full.err;
  EXPECT_NE(full.err.find("cannot write mesh '" + (meshes / "003_Label_3.vtp").string() + "': "), std::string::npos)
    << full.err;
  EXPECT_EQ(folderContents(meshes), before);
  EXPECT_EQ(fileText(f.outputs / "all.vtp"), precious);

  // A folder where label 3's file goes.
  earlierRun();
  fs::create_directories(meshes / "003_Label_3.vtp" / "inside");
  const std::map<std::string, std::string> withFolder = folderContents(meshes);
  const RunResult blocked = runCommand(run);
  EXPECT_EQ(blocked.exitCode, cli::WriteFailed) << blocked.err;
  EXPECT_NE(blocked.err.find("003_Label_3.vtp': it is a folder"), std::string::npos) << blocked.err;
  EXPECT_EQ(folderContents(meshes), withFolder);
  EXPECT_EQ(fileText(f.outputs / "all.vtp"), precious);

  // Written whole, every file is replaced.
  fs::remove_all(meshes / "003_Label_3.vtp");
  const RunResult whole = runCommand(run);
  ASSERT_EQ(whole.exitCode, cli::Success) << whole.err;
  const std::map<std::string, std::string> after = folderContents(meshes);
  std::vector<std::string> names;
  for (const auto& [name, bytes] : after)
    names.push_back(name);
  EXPECT_EQ(names, (std::vector<std::string>{ "001_Label_1.vtp", "002_Label_2.vtp", "003_Label_3.vtp", "007_Label_7.vtp" }));
  EXPECT_NE(after.at("001_Label_1.vtp"), "an earlier run's label 1");
  EXPECT_EQ(after.at("007_Label_7.vtp"), "an earlier run's label 7");
  EXPECT_NE(fileText(f.outputs / "all.vtp"), precious);
}

TEST(ErrorHandling, ReportReturnParameterAndSnapshotFoldersAreCheckedBeforeAnyWork)
{
  // The files written after the mesh: a missing folder is refused as the output's is, before any
  // stage starts, and the mesh is not written either (it was, after the whole run, then exit 6).
  const Folders f = foldersFor("result-folders");
  const std::string input = writeBoxInput(f.inputs);
  const std::string missing = (f.outputs / "nowhere").string();
  const std::vector<std::pair<std::string, std::string>> cases{
    { "--report", "cannot write report '" + missing + "/r.json': folder '" + missing + "' does not exist" },
    { "--returnparameterfile",
      "cannot write the return-parameter file '" + missing + "/r.txt': folder '" + missing + "' does not exist" },
    { "--snapshot", "cannot write snapshot '" + missing + "/s.png': folder '" + missing + "' does not exist" },
  };
  const std::vector<std::string> files{ "r.json", "r.txt", "s.png" };
  for (std::size_t c = 0; c < cases.size(); ++c)
  {
    const std::string options = cases[c].first + " " + quoted(missing + "/" + files[c]);
    expectFailure(f.outputs, input, cli::WriteFailed, cases[c].second, options);
    expectFailure(f.outputs, input, cli::WriteFailed, cases[c].second, "--splitLabels " + options);
    const RunResult r = runSliceMesh(options + " " + quoted(input) + " " + quoted((f.outputs / "out.vtp").string()));
    EXPECT_EQ(r.out.find("<filter-start>"), std::string::npos) << "no stage may start: " << r.out;
  }
}

TEST(ErrorHandling, AnUnreadableColourTableIsRefusedInEveryRun)
{
  // A single-label run ignored a colour table it could not open; one mesh per label refused it.
  const Folders f = foldersFor("colour-table");
  const std::string input = writeBoxInput(f.inputs);
  const std::string table = (f.inputs / "no-such-table.txt").string();
  for (const std::string run : { "", "--splitLabels ", "--label 1 " })
    expectFailure(f.outputs, input, cli::BadArguments, table + ": cannot open the colour table",
                  run + "--colorTable " + quoted(table));
  writeText(f.inputs / "bad-table.txt", "Box 1\n");
  expectFailure(f.outputs, input, cli::BadArguments, "expected 'value name [r g b [a]]'",
                "--colorTable " + quoted((f.inputs / "bad-table.txt").string()));
}

TEST(ErrorHandling, LengthsUnderATwentiethOfTheSmallestVoxelSideAreRefused)
{
  // In the XML's range (0 .. 50) but far under the voxels: --targetEdgeLength 1e-300 grew without
  // bound, 0.005 mm on a 1 mm grid to gigabytes. The smallest side here is 0.5 mm: 0.025 mm. (Just
  // under it, so that without the limit this fails fast instead of hanging.)
  const Folders f = foldersFor("tiny-lengths");
  writeMetaImage(f.inputs / "box.mha", { 8, 8, 8 }, { 1, 1, 0.5 },
                 [](int i, int j, int k) -> unsigned char { return i > 1 && i < 5 && j > 1 && j < 5 && k > 1 && k < 6; });
  const std::string input = (f.inputs / "box.mha").string();
  for (const std::string option : { "--targetEdgeLength", "--maxEdgeLength", "--wallRowHeight", "--contourPointSpacing" })
  {
    expectFailure(f.outputs, input, cli::BadArguments, option + " (", option + " 0.024");
    expectFailure(f.outputs, input, cli::BadArguments,
                  "0.02 mm is under a twentieth of the smallest voxel side (0.5 mm): use at least 0.025 mm",
                  "--splitLabels " + option + " 0.02");
    const RunResult r = runSliceMesh(option + " 0.025 " + quoted(input) + " " + quoted((f.outputs / "fine.vtp").string()));
    EXPECT_EQ(r.exitCode, cli::Success) << option << ": " << r.err;
    fs::remove(f.outputs / "fine.vtp");
  }
}

TEST(ErrorHandling, UnknownOutputExtension)
{
  const Folders f = foldersFor("extension");
  writeMetaImage(f.inputs / "box.mha", { 6, 6, 6 }, { 1, 1, 1 }, [](int, int, int) { return 1; });
  expectFailure(f.outputs, (f.inputs / "box.mha").string(), cli::BadArguments, ".vtp", "", "out.mesh");
  expectFailure(f.outputs, (f.inputs / "box.mha").string(), cli::BadArguments, ".vtp", "", "out");
}

TEST(ErrorHandling, OutOfRangeAndMalformedParameters)
{
  const Folders f = foldersFor("parameters");
  writeMetaImage(f.inputs / "box.mha", { 6, 6, 6 }, { 1, 1, 1 }, [](int, int, int) { return 1; });
  const std::string input = (f.inputs / "box.mha").string();
  expectFailure(f.outputs, input, cli::BadArguments, "wallRowHeight", "--wallRowHeight -1");
  expectFailure(f.outputs, input, cli::BadArguments, "wallRowHeight", "--wallRowHeight 51");
  expectFailure(f.outputs, input, cli::BadArguments, "wallRowHeight", "--wallRowHeight nan");
  expectFailure(f.outputs, input, cli::BadArguments, "minimumComponentVolume", "--minimumComponentVolume -5");
  expectFailure(f.outputs, input, cli::BadArguments, "label", "--label 1.5");
  expectFailure(f.outputs, input, cli::BadArguments, "threshold", "--threshold abc");
  expectFailure(f.outputs, input, cli::BadArguments, "inputKind", "--inputKind Mesh");
}

TEST(ErrorHandling, VolumeLargerThanTheMemoryAvailableIsAClearError)
{
  const Folders f = foldersFor("memory");
  const fs::path out = f.outputs / "out.vtp";
  std::ofstream(out) << precious;
  const RunResult r = runCommand("SLICEMESH_MEMORY_LIMIT_MB=1 " + quoted(SLICEMESH_EXECUTABLE) + " " +
                                 quoted(SLICEMESH_DATA_DIR "/sample-labelmap.nii.gz") + " " + quoted(out.string()));
  EXPECT_EQ(r.exitCode, cli::UnreadableInput);
  ASSERT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("of memory"), std::string::npos) << r.err;
  EXPECT_EQ(fileText(out), precious);
}

TEST(ErrorHandling, AMemoryLimitThatIsNotAPlainPositiveNumberIsAMalformedValue)
{
  // Read as far as it went, "8GB" limited the run to 8 MiB, "100abc" to 100, "0x10" to 16 and "1e2"
  // to 100; "abc", "0", "-5" and an empty value left the limit to the machine without a word.
  const Folders f = foldersFor("memory-limit");
  const std::string input = writeBoxInput(f.inputs);
  const char* previous = std::getenv("SLICEMESH_MEMORY_LIMIT_MB");
  const std::string saved = previous ? previous : "";
  for (const std::string value : { "8GB", "100abc", "0x10", "1e2", "abc", "0", "0.0", "-5", "", " 100", "1.2.3", ".",
                                   "inf", "nan", "99999999999999999999999999999999999999999999999999999999999999999999"
                                                 "99999999999999999999999999999999999999999999999999999999999999999999"
                                                 "99999999999999999999999999999999999999999999999999999999999999999999"
                                                 "99999999999999999999999999999999999999999999999999999999999999999999"
                                                 "99999999999999999999999999999999999999999999999999999999999999999999" })
  {
    ::setenv("SLICEMESH_MEMORY_LIMIT_MB", value.c_str(), 1);
    SCOPED_TRACE("SLICEMESH_MEMORY_LIMIT_MB='" + value + "'");
    const std::string shown = value.size() > 60 ? value.substr(0, 57) + "..." : value;
    expectFailure(f.outputs, input, cli::BadArguments, "SLICEMESH_MEMORY_LIMIT_MB is '" + shown + "'; it takes a positive number of MiB");
  }
  // A plain number, whole or with a fraction, is a limit.
  for (const std::string value : { "4096", "4096.5", "512." })
  {
    ::setenv("SLICEMESH_MEMORY_LIMIT_MB", value.c_str(), 1);
    const RunResult r = runSliceMesh(quoted(input) + " " + quoted((f.outputs / "box.vtp").string()));
    EXPECT_EQ(r.exitCode, cli::Success) << value << ": " << r.err;
  }
  if (previous)
    ::setenv("SLICEMESH_MEMORY_LIMIT_MB", saved.c_str(), 1);
  else
    ::unsetenv("SLICEMESH_MEMORY_LIMIT_MB");
}

TEST(ErrorHandling, EdgesFoundIn3DAreCheckedAgainstTheMemoryAvailable)
{
  // A 100^3 byte volume: its reading needs about 74 MiB, edges found in 3D about 85 (they peaked at
  // twice the reading's estimate and passed its check). Under 78 MiB the run stops before them.
  const Folders f = foldersFor("memory-edges");
  writeMetaImage(f.inputs / "ball.mha", { 100, 100, 100 }, { 1, 1, 1 }, [](int i, int j, int k) -> unsigned char
                 { return (i - 50) * (i - 50) + (j - 50) * (j - 50) + (k - 50) * (k - 50) < 900 ? 200 : 20; });
  const fs::path out = f.outputs / "out.vtp";
  std::ofstream(out) << precious;
  const std::string run = quoted(SLICEMESH_EXECUTABLE) + " --inputKind Grayscale --regionMode Edges --processing Volume " +
                          quoted((f.inputs / "ball.mha").string()) + " " + quoted(out.string());
  const RunResult r = runCommand("SLICEMESH_MEMORY_LIMIT_MB=78 " + run);
  EXPECT_EQ(r.exitCode, cli::UnreadableInput) << r.err;
  ASSERT_EQ(linesOf(r.err).size(), 1u) << r.err;
  EXPECT_NE(r.err.find("edges found in 3D needs about 85 MiB of memory"), std::string::npos) << r.err;
  EXPECT_EQ(fileText(out), precious);
  // Per slice, the same volume fits.
  const RunResult perSlice = runCommand("SLICEMESH_MEMORY_LIMIT_MB=78 " + quoted(SLICEMESH_EXECUTABLE) +
                                        " --inputKind Grayscale --regionMode Edges " +
                                        quoted((f.inputs / "ball.mha").string()) + " " + quoted(out.string()));
  EXPECT_EQ(perSlice.exitCode, cli::Success) << perSlice.err;
}

} // namespace
} // namespace slicemesh::testing
