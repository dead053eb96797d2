// Fuzz target: the STL reader (read_mesh_buffer by extension), then diagnosis and repair.
#include "tests/fuzz/fuzz_mesh.h"
#include "tests/fuzz/fuzz_target.h"

ZOME_FUZZ_TARGET(stl) { return zomeify::fuzz::fuzz_mesh_input(data, size, "input.stl"); }
