// Compile OpenFOAM v1912's metisDecomp.C unchanged (see Make/files)
#include "metisDecomp.C"
