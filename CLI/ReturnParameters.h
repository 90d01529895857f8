// The file 3D Slicer passes as --returnparameterfile: one "name = value" line per result.
#ifndef ReturnParameters_h
#define ReturnParameters_h

#include <string>
#include <utility>
#include <vector>

namespace slicemesh::cli
{

using ReturnValues = std::vector<std::pair<std::string, std::string>>;

/** Writes "name = value" lines (ModuleDescription::ReadParameterFile splits at the first '=').
 *  Throws slicemesh::Error when the file cannot be written. */
void writeReturnParameters(const std::string& path, const ReturnValues& values);

} // namespace slicemesh::cli

#endif
