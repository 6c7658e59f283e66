# bench_clip: boolean operations, cg against Clipper 6.4 (libpolyclipping)
# and GEOS (C API); a peer that is not installed is left out and said so.
add_executable(bench_clip ${CMAKE_CURRENT_LIST_DIR}/bench_clip.c
                          ${CMAKE_CURRENT_LIST_DIR}/bench_clip_peers.cpp)
target_compile_options(bench_clip PRIVATE $<$<COMPILE_LANGUAGE:C>:${CG_WARNINGS}>)
target_link_libraries(bench_clip PRIVATE cg_static)
find_path(CG_CLIPPER_INCLUDE NAMES polyclipping/clipper.hpp)
find_library(CG_CLIPPER_LIBRARY NAMES polyclipping)
cg_bench_peer(bench_clip
              WHEN CG_CLIPPER_INCLUDE AND CG_CLIPPER_LIBRARY
              DEFINE CG_HAVE_CLIPPER
              INCLUDE ${CG_CLIPPER_INCLUDE}
              LINK ${CG_CLIPPER_LIBRARY}
              MESSAGE "Clipper (libpolyclipping-dev) not found: bench_clip runs without it")
find_path(CG_GEOS_INCLUDE_BENCH NAMES geos_c.h)
find_library(CG_GEOS_LIBRARY_BENCH NAMES geos_c)
cg_bench_peer(bench_clip
              WHEN CG_GEOS_INCLUDE_BENCH AND CG_GEOS_LIBRARY_BENCH
              DEFINE CG_HAVE_GEOS
              INCLUDE ${CG_GEOS_INCLUDE_BENCH}
              LINK ${CG_GEOS_LIBRARY_BENCH}
              MESSAGE "GEOS (libgeos-dev) not found: bench_clip runs without it")
