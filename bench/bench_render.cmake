# Rendering speed at 1920x1080: cg's z-buffer pipeline against Mesa's
# OSMesa (llvmpipe as Debian builds it) on the same scenes.  Without OSMesa
# the benchmark runs cg alone.
pkg_check_modules(OSMESA_BENCH IMPORTED_TARGET osmesa)
add_executable(bench_render ${CMAKE_CURRENT_SOURCE_DIR}/bench_render.c)
target_compile_options(bench_render PRIVATE ${CG_WARNINGS})
target_compile_definitions(bench_render PRIVATE CG_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
target_link_libraries(bench_render PRIVATE cg_static)
cg_bench_peer(bench_render
              WHEN OSMESA_BENCH_FOUND
              DEFINE CG_HAVE_OSMESA=1
              LINK PkgConfig::OSMESA_BENCH
              MESSAGE "OSMesa (libosmesa6-dev) not found: bench_render runs without its peer")
