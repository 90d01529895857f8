// The files an input volume's header names as holding its voxels: read with the volume, so an
// output must not be one of them (DistinctFiles).
#ifndef DetachedDataFiles_h
#define DetachedDataFiles_h

#include <string>
#include <vector>

namespace slicemesh::cli
{

/** The files the volume header at `volumePath` names as its data, each as a path (a relative name
 *  from the header's folder, as the readers take it):
 *  - a NRRD's `data file:` (or `datafile:`): one file, `LIST` and the lines after it, or a format
 *    string with its min, max and step (`slice%03d.raw 1 40 1`; the first 10000 names);
 *  - a MetaImage's `ElementDataFile`, but for LOCAL: the same three forms;
 *  - an Analyze or NIfTI pair's other half: the `.img` beside a `.hdr`, the `.hdr` beside an `.img`.
 *  Empty for any other input, and for a header that cannot be read (its reader says why). Only the
 *  header's text is read, not its voxels. */
std::vector<std::string> detachedDataFiles(const std::string& volumePath);

} // namespace slicemesh::cli

#endif
