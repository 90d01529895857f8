// Text for people at a terminal, generated from the parameter table: --help and --echo.
#ifndef HelpText_h
#define HelpText_h

#include "CommandLine.h"
#include "ModuleDescription.h"

#include <string>

namespace slicemesh::cli
{

/** Usage line, description, then every group with each option's flags, value kind, label,
 *  description (which carries the unit), default, allowed values and range; then the built-in flags. */
std::string helpText(const ModuleDescription& module, const std::string& programName);

/** "name = value" for every parameter, in XML order, as --echo prints them. */
std::string echoText(const ModuleDescription& module, const ParsedArguments& arguments);

} // namespace slicemesh::cli

#endif
