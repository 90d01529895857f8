// The module's Slicer Execution Model XML, compiled in from SliceMesh.xml at build time.
#ifndef ModuleXml_h
#define ModuleXml_h

namespace slicemesh::cli
{

/** The exact text of SliceMesh.xml; starts with "<?xml". */
const char* moduleXml();

} // namespace slicemesh::cli

#endif
