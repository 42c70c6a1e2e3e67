# Sourced by the build scripts: compile through ccache when it is installed, so a second
# build of the same sources (another clone, CI on the same machine) reuses the objects.
# Paths inside the clone are rewritten relative to the build directory (CCACHE_BASEDIR), and
# CMakeLists.txt maps the source directory out of __FILE__ and debug information
# (-ffile-prefix-map), so objects do not depend on where the clone lives. Paths the code needs
# stay out of compile definitions for the same reason: the tests' come from one generated file
# (tests/test_paths.h), the CLI's default data directory only from app/cli_options.cpp.
ccache_args=()
if command -v ccache >/dev/null; then
  export CCACHE_BASEDIR="$PWD"
  export CCACHE_NOHASHDIR=1
  ccache_args=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
