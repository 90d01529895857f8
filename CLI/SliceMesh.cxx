// The SliceMesh executable: a thin wrapper, as in Slicer's SEMCommandLineLibraryWrapper.
#include "ModuleEntryPoint.h"

int main(int argc, char* argv[])
{
  return ModuleEntryPoint(argc, argv);
}
