#pragma once
//! \file shared_paths.h
//! Where the shared data folder is, without GoogleTest (benchmarks use it too; tests include paths.h).

#include <cstdlib>
#include <filesystem>
#include <string>

namespace zomeify::test {

//! The shared data folder: $ZOMEIFY_SHARED when set, else ../shared beside the project (ZOME_SHARED_DIR).
inline std::string shared_dir()
{
    const char* env = std::getenv("ZOMEIFY_SHARED");
    return env && *env ? std::string(env) : std::string(ZOME_SHARED_DIR);
}

inline std::string shared_path(const std::string& rel) { return shared_dir() + "/" + rel; }

//! True when the shared meshes and models are there (a user's clone has no ../shared).
inline bool shared_available() { return std::filesystem::is_directory(shared_path("data")); }

} // namespace zomeify::test
