# bench_draw_script: scripts run by the cg tool (`cg draw --repeat`) against
# the library calls they make and against OpenCV (libopencv-dev), AGG
# (libagg-dev) and Cairo (libcairo2-dev) drawing the same shapes; a peer that
# is not installed is skipped with a row saying so.
pkg_check_modules(DRAW_SCRIPT_CAIRO QUIET IMPORTED_TARGET cairo)
pkg_check_modules(DRAW_SCRIPT_AGG QUIET IMPORTED_TARGET libagg)
find_package(OpenCV QUIET COMPONENTS core imgproc)
add_executable(bench_draw_script ${CMAKE_CURRENT_SOURCE_DIR}/bench_draw_script.c
                                 ${CMAKE_CURRENT_SOURCE_DIR}/bench_draw_script_peers.cpp)
target_compile_options(bench_draw_script PRIVATE $<$<COMPILE_LANGUAGE:C>:${CG_WARNINGS}>)
target_compile_definitions(bench_draw_script PRIVATE CG_TOOL="$<TARGET_FILE:cg>"
                                                     _POSIX_C_SOURCE=200809L _DEFAULT_SOURCE)
target_link_libraries(bench_draw_script PRIVATE cg_static m)
add_dependencies(bench_draw_script cg)
cg_bench_peer(bench_draw_script
              WHEN DRAW_SCRIPT_CAIRO_FOUND
              DEFINE CG_BENCH_HAVE_CAIRO
              LINK PkgConfig::DRAW_SCRIPT_CAIRO
              MESSAGE "bench_draw_script: Cairo not found, its rows are skipped")
cg_bench_peer(bench_draw_script
              WHEN DRAW_SCRIPT_AGG_FOUND
              DEFINE CG_BENCH_HAVE_AGG
              LINK PkgConfig::DRAW_SCRIPT_AGG
              MESSAGE "bench_draw_script: AGG (libagg-dev) not found, its rows are skipped")
cg_bench_peer(bench_draw_script
              WHEN OpenCV_FOUND
              DEFINE CG_BENCH_HAVE_OPENCV
              INCLUDE ${OpenCV_INCLUDE_DIRS}
              LINK opencv_core opencv_imgproc
              MESSAGE "bench_draw_script: OpenCV not found, its rows are skipped")
