// Compile OpenFOAM v1912's ptscotchDecomp.C unchanged (see Make/files)
#include "ptscotchDecomp.C"
