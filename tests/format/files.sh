# Sourced by check.sh and apply.sh: the C++ files under clang-format, one per line (tracked files only).
format_files() {
  git -C "$1" ls-files -- 'core/*.h' 'core/*.cpp' 'wasm/*.h' 'wasm/*.cpp' 'tests/*.h' 'tests/*.cpp'
}
format_tool() {
  command -v clang-format >/dev/null || { echo "format: clang-format not found (apt-get install clang-format; .ci/install does)" >&2; return 1; }
  echo clang-format
}
