# bench_fill: polygon fill (aliased, anti-aliased), paths and flood fill
# against Cairo, AGG and OpenCV; each peer is skipped when not installed.
pkg_check_modules(BENCH_FILL_CAIRO IMPORTED_TARGET cairo)
pkg_check_modules(BENCH_FILL_AGG IMPORTED_TARGET libagg)
find_package(OpenCV QUIET COMPONENTS core imgproc)
add_executable(bench_fill ${CMAKE_CURRENT_SOURCE_DIR}/bench_fill.c
                          ${CMAKE_CURRENT_SOURCE_DIR}/bench_fill_peers.cpp)
target_compile_options(bench_fill PRIVATE $<$<COMPILE_LANGUAGE:C>:${CG_WARNINGS}>)
target_link_libraries(bench_fill PRIVATE cg_static)
cg_bench_peer(bench_fill
              WHEN BENCH_FILL_CAIRO_FOUND
              DEFINE CG_BENCH_HAVE_CAIRO
              LINK PkgConfig::BENCH_FILL_CAIRO
              MESSAGE "bench_fill: Cairo not found, its rows are skipped")
cg_bench_peer(bench_fill
              WHEN BENCH_FILL_AGG_FOUND
              DEFINE CG_BENCH_HAVE_AGG
              LINK PkgConfig::BENCH_FILL_AGG
              MESSAGE "bench_fill: AGG (libagg-dev) not found, its rows are skipped")
cg_bench_peer(bench_fill
              WHEN OpenCV_FOUND
              DEFINE CG_BENCH_HAVE_OPENCV
              INCLUDE ${OpenCV_INCLUDE_DIRS}
              LINK opencv_core opencv_imgproc
              MESSAGE "bench_fill: OpenCV not found, its rows are skipped")
