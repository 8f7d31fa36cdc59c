// Compile OpenFOAM v1912's scotchDecomp.C unchanged (see Make/files)
#include "scotchDecomp.C"
