// SliceMesh as a library call: exactly what the SliceMesh executable does, for tests and for
// programs that embed the module (as Slicer's own CLI modules are built).
#ifndef ModuleEntryPoint_h
#define ModuleEntryPoint_h

/** Parses argv against SliceMesh.xml and runs the pipeline; returns an exit code (ExitCodes.h). */
int ModuleEntryPoint(int argc, char* argv[]);

#endif
