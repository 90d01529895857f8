// An ITK exception as the cause of an error message: one line, without ITK's class name, object
// address and source location, and for NRRD files the NRRD library's own reason.
#ifndef ItkErrorText_h
#define ItkErrorText_h

#include "itkMacro.h"

#include <string>

namespace slicemesh
{

/** What went wrong, in a few words on one line: ITK's "itk::ERROR: NrrdImageIO(0x55d0...): " prefix
 *  dropped, and of the NRRD library's chain of "[nrrd] function: trouble" messages only the last
 *  link, which says what is wrong ("fread got only 42 1-sized things, not 512"). At most 200
 *  characters; "unknown ITK error" when the exception says nothing. */
std::string itkErrorText(const itk::ExceptionObject& error);

/** Runs of white space (line breaks included) as one space, trimmed: several lines of a library's
 *  complaints on one. */
std::string collapsedWhitespace(const std::string& text);

} // namespace slicemesh

#endif
