#pragma once
//! \file file_bytes.h
//! Whole-file reading and writing with clear errors and a size limit.

#include <cstddef>
#include <string>

namespace zomeify {

//! Files larger than this are refused before reading (1 GiB).
inline constexpr size_t kMaxInputFileBytes = size_t{1} << 30;

//! The file's bytes; IoError if it cannot be opened or is too large.
std::string read_file_bytes(const std::string& path);
//! Writes the bytes; IoError on failure.
void write_file_bytes(const std::string& path, const std::string& bytes);
//! Lower-cased file name extension(s): "model.Zome.JSON" → ".zome.json", "a.vef" → ".vef".
std::string model_extension(const std::string& path);

} // namespace zomeify
