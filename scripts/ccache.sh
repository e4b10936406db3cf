# Sourced by build.sh and test.sh: compile through ccache where it is installed, so a
# rebuild in another clone of the same sources (CI's, a second worktree) reuses the
# objects compiled before. Paths are hashed relative to the checkout, and the compiler's
# working directory is left out of the hash, so the clone's folder does not matter.
# Sets ccache_args to the CMake arguments that turn it on (empty without ccache).
ccache_args=()
if command -v ccache >/dev/null; then
  ccache_args=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$root"
  export CCACHE_NOHASHDIR=1
  # The precompiled headers of the Qt suites are cacheable only with these.
  export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
fi
