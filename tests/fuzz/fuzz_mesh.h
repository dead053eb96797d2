#pragma once
//! \file fuzz_mesh.h
//! The shared body of the mesh-format targets: read_mesh_buffer on the bytes, then (when the soup is
//! small enough to keep executions fast) the whole diagnosis and repair path on what was read.

#include <cstddef>
#include <cstdint>

namespace zomeify::fuzz {

//! Reads `data` as a file called `file_name` (which picks the format). Only the core's documented
//! errors may escape the readers; they are caught here, anything else is a finding.
int fuzz_mesh_input(const uint8_t* data, size_t size, const char* file_name);

} // namespace zomeify::fuzz
